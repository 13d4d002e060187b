"""Closed-form inverse kinematics of the Universal Robots arm family (up to 8 solutions).

The family (UR3/5/10/16/20/30 and their e-Series): standard DH rows

    row  d    a    alpha
    1    d1   0    +90 deg
    2    0    a2   0
    3    0    a3   0
    4    d4   0    +90 deg
    5    d5   0    -90 deg
    6    d6   0    0

with any theta offsets. Axes 2, 3 and 4 are parallel and the wrist is not spherical (an
offset wrist), so the OPW solver does not apply. The solution (K. P. Hawkins, "Analytic
inverse kinematics for the Universal Robots UR-5/UR-10 arms", Georgia Tech, 2013):

- the origin of frame 5, p05 = p - d6 z6, lies at distance d4 from the plane of axis 1 and
  the arm: theta1 = atan2(p05y, p05x) +- acos(d4 / |p05_xy|) + 90 deg (two shoulder branches);
- the flange's position along the normal of that plane gives cos theta5 =
  (px sin t1 - py cos t1 - d4) / d6 (two wrist branches +-);
- theta6 from the flange's rotation, (-R01 s1 + R11 c1) / s5, (R00 s1 - R10 c1) / s5 (free
  when sin theta5 = 0: set to a reference);
- what is left, frames 1 -> 4, is a planar 2R arm (a2, a3) plus the sum theta2 + theta3 +
  theta4: the law of cosines gives theta3 (two elbow branches), then theta2 and theta4.

Every candidate is checked by the caller against the forward kinematics.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
_STRUCT_TOL = 1e-9
_WRIST_SINGULAR = 1e-10
_ALPHAS = (math.pi / 2, 0.0, 0.0, math.pi / 2, -math.pi / 2, 0.0)


@dataclass(frozen=True)
class URGeometry:
    """Constants of a UR-family arm read from its DH rows (lengths in m, offsets in rad)."""

    offsets: tuple[float, ...]
    d1: float
    a2: float
    a3: float
    d4: float
    d5: float
    d6: float


def ur_geometry(dh: FloatArray) -> URGeometry | None:
    """Return the UR constants of DH rows (6, 4), or None when the rows are not of that family."""
    if dh.shape != (6, 4):
        return None
    off, d, a, al = dh[:, 0], dh[:, 1], dh[:, 2], dh[:, 3]
    tol = _STRUCT_TOL
    angles = all(abs(math.remainder(al[i] - _ALPHAS[i], 2 * math.pi)) < tol for i in range(6))
    zeros = all(abs(x) < tol for x in (a[0], a[3], a[4], a[5], d[1], d[2]))
    if not (angles and zeros) or abs(a[1]) < tol or abs(a[2]) < tol or abs(d[5]) < tol:
        return None
    return URGeometry(
        offsets=tuple(float(x) for x in off),
        d1=float(d[0]),
        a2=float(a[1]),
        a3=float(a[2]),
        d4=float(d[3]),
        d5=float(d[4]),
        d6=float(d[5]),
    )


def _a_inv(theta: float, d: float, a: float, alpha: float) -> FloatArray:
    """Return the inverse of the DH link transform Rz(theta) Tz(d) Tx(a) Rx(alpha) (4, 4)."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    R = np.array([[ct, -st * ca, st * sa], [st, ct * ca, -ct * sa], [0.0, sa, ca]])
    p = np.array([a * ct, a * st, d])
    out = np.eye(4)
    out[:3, :3] = R.T
    out[:3, 3] = -R.T @ p
    return out


def ur_solutions(g: URGeometry, T: FloatArray, theta6_ref: float = 0.0) -> FloatArray:
    """Return candidate DH angles (k, 6) [rad], k <= 8, of base -> flange pose T (4, 4).

    Order: shoulder (+, -) x wrist (+, -) x elbow (+, -). `theta6_ref` sets theta6 where the
    wrist is singular (sin theta5 = 0). Candidates are not checked: the caller compares
    fk(candidate) with T and applies the joint limits.
    """
    R, p = T[:3, :3], T[:3, 3]
    p05 = p - g.d6 * R[:, 2]
    rho = math.hypot(p05[0], p05[1])
    if rho < abs(g.d4) or rho == 0.0:
        return np.zeros((0, 6))
    psi = math.atan2(p05[1], p05[0])
    phi = math.acos(max(-1.0, min(1.0, g.d4 / rho)))
    rows: list[list[float]] = []
    for t1 in (psi + phi + math.pi / 2, psi - phi + math.pi / 2):
        s1, c1 = math.sin(t1), math.cos(t1)
        c5 = (p[0] * s1 - p[1] * c1 - g.d4) / g.d6
        if abs(c5) > 1.0 + 1e-9:
            continue
        base5 = math.acos(max(-1.0, min(1.0, c5)))
        for t5 in (base5, -base5):
            s5 = math.sin(t5)
            if abs(s5) < _WRIST_SINGULAR:
                t6 = theta6_ref + g.offsets[5]
            else:
                t6 = math.atan2(
                    (-R[0, 1] * s1 + R[1, 1] * c1) / s5, (R[0, 0] * s1 - R[1, 0] * c1) / s5
                )
            T14 = (
                _a_inv(t1, g.d1, 0.0, math.pi / 2)
                @ T
                @ _a_inv(t6, g.d6, 0.0, 0.0)
                @ _a_inv(t5, g.d5, 0.0, -math.pi / 2)
            )
            # origin of frame 3 in frame 1: frame 4's origin moved back by d4 along its y
            x, y = T14[0, 3] - g.d4 * T14[0, 1], T14[1, 3] - g.d4 * T14[1, 1]
            r = math.hypot(x, y)
            c3 = (r * r - g.a2 * g.a2 - g.a3 * g.a3) / (2.0 * g.a2 * g.a3)
            if abs(c3) > 1.0 + 1e-9 or r == 0.0:
                continue
            base3 = math.acos(max(-1.0, min(1.0, c3)))
            for t3 in (base3, -base3):
                t2 = math.atan2(y, x) - math.atan2(g.a3 * math.sin(t3), g.a2 + g.a3 * math.cos(t3))
                # theta2 + theta3 + theta4 is the angle of frame 4's x axis in frame 1
                t4 = math.atan2(T14[1, 0], T14[0, 0]) - t2 - t3
                rows.append([t1, t2, t3, t4, t5, t6])
    if not rows:
        return np.zeros((0, 6))
    out = np.array(rows)
    return np.asarray((out + math.pi) % (2 * math.pi) - math.pi, float)
