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


GAINS = ("kop", "kod", "koi")
_UNITS = (" /s", "", " /s²")
# Where raising a gain that is 0 starts (then doubled): 1 /s, 0.01, 1 /s².
_ZERO_START = (1.0, 0.01, 1.0)
_STEPS = 12  # factors of 2 tried either way: a change of up to 4096x
# A suggested change must leave a margin: a pole at |z| = 0.999 halves a tilt only every
# 700 cycles (2.8 s at 250 Hz), stable on paper but no fix.
SUGGEST_BELOW = 0.98


def orientation_loop_radius(
    kop: float, kod: float, koi: float, control_rate: float, latency: float
) -> tuple[float, int]:
    """Return (rho, lag): the largest pole modulus |z| of the orientation loop and its latency
    in whole cycles.

    Gains in 1/s, -, 1/s²; control_rate [Hz]; latency [s], rounded to whole cycles as the
    simulation rounds it. The loop is stable when rho < 1."""
    dt = 1.0 / control_rate
    lag = int(round(latency / dt))
    return float(np.abs(orientation_loop_poles(kop, kod, koi, dt, lag)).max()), lag


def stabilising_changes(
    kop: float, kod: float, koi: float, control_rate: float, latency: float
) -> list[tuple[str, float, float]]:
    """Return (gain, value, rho) for each gain ('kop', 'kod', 'koi') that alone makes the loop
    stable with a margin when changed to `value` (the others kept): rho < `SUGGEST_BELOW`,
    the loop's largest pole there.

    Per gain the nearest such value in factors of 2 from the current one (up to 2**12 either
    way, lower first on a tie; a gain may be lowered to 0; a zero gain is raised from 1 /s,
    0.01 or 1 /s²); gains with none are left out. Sorted by how many factors of 2 the change
    takes. Which way helps depends on the gains: with an I term raising kop can be the fix
    (the P term damps the integral's oscillation), so no fixed advice is right."""
    gains = (kop, kod, koi)
    found: list[tuple[int, str, float, float]] = []
    for i, name in enumerate(GAINS):
        v = gains[i]
        if v > 0:
            tries = [(j, v * f) for j in range(1, _STEPS + 1) for f in (0.5**j, 2.0**j)]
            tries.append((_STEPS + 1, 0.0))
        else:
            tries = [(j + 1, _ZERO_START[i] * 2.0**j) for j in range(_STEPS + 1)]
        for dist, new in tries:
            g = list(gains)
            g[i] = new
            rho, _ = orientation_loop_radius(g[0], g[1], g[2], control_rate, latency)
            if rho < SUGGEST_BELOW:
                found.append((dist, name, new, rho))
                break
    found.sort(key=lambda x: x[0])
    return [(name, new, rho) for _, name, new, rho in found]


def instability_message(
    kop: float,
    kod: float,
    koi: float,
    control_rate: float,
    latency: float,
    names: tuple[str, str, str] = GAINS,
) -> str | None:
    """Return why the orientation gains make the loop unstable and which change of one gain
    fixes it, or None when the loop is stable (`orientation_loop_radius`).

    `names` are the caller's field names for kop, kod, koi (each layer names its own
    fields); gains in 1/s, -, 1/s², control_rate [Hz], latency [s]."""
    rho, lag = orientation_loop_radius(kop, kod, koi, control_rate, latency)
    if rho < 1.0:
        return None
    gains = (kop, kod, koi)
    head = (
        f"{names[0]} = {kop:g} /s, {names[1]} = {kod:g}, {names[2]} = {koi:g} /s² make the "
        f"orientation loop unstable at {control_rate:g} Hz with {lag} cycles of latency "
        f"(largest pole |z| = {rho:.3f}, stable below 1)"
    )
    fixes = []
    for name, new, r in stabilising_changes(kop, kod, koi, control_rate, latency):
        i = GAINS.index(name)
        way = "lower" if new < gains[i] else "raise"
        fixes.append(f"{way} {names[i]} to {new:g}{_UNITS[i]} (|z| = {r:.3f})")
    if not fixes:
        return (
            f"{head}; no change of one gain alone (up to {2**_STEPS}x) makes it stable: change "
            "the gains together, or lower the latency"
        )
    return f"{head}; " + ", or ".join(fixes)
