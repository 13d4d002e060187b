"""Tool-axis orientation for the polishing controller (seed 004, eq. 7, derived again).

The error between the tool axis z and its target z_d is the rotation vector of the
shortest rotation taking z to z_d: unit axis (z × z_d)/|z × z_d| times the angle
atan2(|z × z_d|, z·z_d). The seed's f_01 = ||n_0 × n_1||₂ ω_01 takes the norm of the cross
product (a scalar) as the axis; geometry needs the unit cross product, and the angle
rather than its sine (|z × z_d| = sin θ saturates at 90° and loses the sign beyond it).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


def rotation_vectors(a: F64, b: F64) -> F64:
    """Return the rotation vectors (..., 3) [rad] of the shortest rotations taking unit a to unit b (..., 3).

    Antiparallel pairs (no unique axis) get the zero vector; they do not occur for a tool
    axis that follows a surface normal."""
    c = np.cross(a, b)
    s = np.linalg.norm(c, axis=-1, keepdims=True)
    ang = np.arctan2(s, np.sum(a * b, axis=-1, keepdims=True))
    return np.where(s > 1e-300, c * (ang / np.where(s > 1e-300, s, 1.0)), 0.0)


def rotation_vector3(
    ax: float, ay: float, az: float, bx: float, by: float, bz: float
) -> tuple[float, float, float, float]:
    """Return (ex, ey, ez, angle [rad]) of the rotation taking unit a to unit b (scalar twin
    of `rotation_vectors`, for the per-cycle simulation loop)."""
    cx, cy, cz = ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx
    s = math.sqrt(cx * cx + cy * cy + cz * cz)
    ang = math.atan2(s, ax * bx + ay * by + az * bz)
    if s <= 1e-300:
        return 0.0, 0.0, 0.0, ang
    f = ang / s
    return cx * f, cy * f, cz * f, ang


def rotate3(
    zx: float, zy: float, zz: float, wx: float, wy: float, wz: float
) -> tuple[float, float, float]:
    """Return the unit vector z rotated by the rotation vector w [rad] (Rodrigues' formula, exact)."""
    th = math.sqrt(wx * wx + wy * wy + wz * wz)
    if th <= 0.0:
        return zx, zy, zz
    kx, ky, kz = wx / th, wy / th, wz / th
    c, s = math.cos(th), math.sin(th)
    kd = (kx * zx + ky * zy + kz * zz) * (1.0 - c)
    rx = zx * c + (ky * zz - kz * zy) * s + kx * kd
    ry = zy * c + (kz * zx - kx * zz) * s + ky * kd
    rz = zz * c + (kx * zy - ky * zx) * s + kz * kd
    n = math.sqrt(rx * rx + ry * ry + rz * rz)  # keep it unit against round-off drift
    return rx / n, ry / n, rz / n


def orientation_loop_poles(
    kop: float, kod: float, koi: float, dt: float, lag: int
) -> NDArray[np.complex128]:
    """Return the closed-loop poles (z-plane) of the orientation loop for a tilt about a fixed axis.

    Per cycle θ_{k+1} = θ_k - dt u_{k-lag}, u_k = kop θ_k + kod (θ_k - θ_{k-1})/dt
    + koi dt Σ_{j<=k} θ_j (gains in 1/s, -, 1/s²; dt [s]; lag in cycles). Multiplying
    (z - 1) + dt z^-lag C(z) = 0 by z^(lag+1) (z - 1) gives
    z^(lag+1) (z-1)² + dt kop z (z-1) + kod (z-1)² + koi dt² z² = 0; with koi = 0 the common
    factor (z - 1) is divided out. The loop is stable when every pole lies inside |z| < 1.
    """
    zl = np.zeros(lag + 2)
    zl[0] = 1.0  # z^(lag+1)
    if koi == 0.0:
        # z^(lag+1) (z - 1) + dt kop z + kod (z - 1)
        poly = np.polymul(zl, [1.0, -1.0])
        poly = np.polyadd(poly, [dt * kop + kod, -kod])
    else:
        poly = np.polymul(zl, [1.0, -2.0, 1.0])
        poly = np.polyadd(poly, np.polymul([dt * kop, 0.0], [1.0, -1.0]))
        poly = np.polyadd(poly, [kod, -2.0 * kod, kod])
        poly = np.polyadd(poly, [koi * dt * dt, 0.0, 0.0])
    return np.asarray(np.roots(poly), dtype=np.complex128)
