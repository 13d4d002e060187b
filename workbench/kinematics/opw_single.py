"""Analytic OPW inverse kinematics for one pose in scalar math (see `opw.py` for the derivation).

Plain floats and the `math` module: for a single pose numpy's per-call overhead (~1 us per
operation) would cost more than the arithmetic.
"""

from __future__ import annotations

import math

import numpy as np

from workbench.kinematics.opw import _COINCIDE, _WRIST_SINGULAR, FloatArray, OPWGeometry


def solve_single(
    g: OPWGeometry,
    T: FloatArray | list[list[float]],
    theta4_ref: float = 0.0,
    distinct: bool = False,
) -> list[tuple[float, float, float, float, float, float, float]]:
    """Return 8 tuples (t1..t6 [rad], residual) for one pose T (4, 4): `solve_batch` in scalar math.

    Same branch order and residual as `solve_batch`; T may be given as nested lists (rows).
    Tuples come in (no flip, flip) pairs sharing t1..t3. With `distinct`, branch pairs that
    coincide (wrist centre on the shoulder's boundary, or elbow stretched) are given once.
    Plain floats and the math module: numpy's per-call overhead would dominate one pose.
    """
    rows = T.tolist() if isinstance(T, np.ndarray) else T
    (r00, r01, r02, px), (r10, r11, r12, py), (r20, r21, r22, pz) = rows[:3]
    (
        ca6,
        sa6,
        w1,
        w2,
        k,
        d1,
        a1,
        a2,
        a3,
        s3d4,
        e2,
        K2a2,
        a2K2,
        cphi,
        sphi,
        phi,
        sig1,
        sig4,
        sig5,
        ss4,
        sg23,
        Py,
    ) = g.scalar_constants
    atan2, sqrt, pi = math.atan2, math.sqrt, math.pi
    G00, G01, G02 = r00, r10, r20
    G20, G21, G22 = sa6 * r01 + ca6 * r02, sa6 * r11 + ca6 * r12, sa6 * r21 + ca6 * r22
    x = px - r01 * w1 - r02 * w2
    y = py - r11 * w1 - r12 * w2
    z = pz - r21 * w1 - r22 * w2
    shoulders = _shoulders(x, y, k, a1, distinct)
    py1 = sig1 * (z - d1)
    G = (G00, G01, G02, G20, G21, G22)
    wc = (e2, sig1, sig4, sig5, ss4, sg23)
    out = []
    for t1, c1, s1, px1 in shoulders:
        r2 = px1 * px1 + py1 * py1
        cg = min(1.0, max(-1.0, (r2 - K2a2) / a2K2))
        sg = sqrt(1.0 - cg * cg)
        gam = math.acos(cg)
        elbows = [(phi - gam, cphi * cg + sphi * sg, sphi * cg - cphi * sg)]
        if not distinct or gam >= _COINCIDE:
            elbows.append((phi + gam, cphi * cg - sphi * sg, sphi * cg + cphi * sg))
        for t3, c3, s3 in elbows:
            u = a2 + a3 * c3 + s3d4 * s3
            w = e2 * (a3 * s3 - s3d4 * c3)
            den = sqrt(r2 * (u * u + w * w)) or 1.0
            c2 = (px1 * u + py1 * w) / den
            s2 = (py1 * u - px1 * w) / den
            t2 = atan2(s2, c2)
            Px = a1 + c2 * u - s2 * w
            Pz = d1 + sig1 * (s2 * u + c2 * w)
            centre = (abs(c1 * Px - s1 * Py - x), abs(s1 * Px + c1 * Py - y), abs(Pz - z))
            t4, t5, t6, err = _wrist(wc, G, (c1, s1, c2, s2, c3, s3), theta4_ref, centre)
            out.append((t1, t2, t3, t4, t5, t6, err))
            out.append((t1, t2, t3, t4 + pi, -t5, t6 + pi, err))
    return out


def _shoulders(
    x: float, y: float, k: float, a1: float, distinct: bool
) -> list[tuple[float, float, float, float]]:
    """Return the shoulder branches (t1 [rad], cos t1, sin t1, px1 [m]) of the wrist centre
    (x, y) [m] (front, back; with `distinct`, back only where it differs from front)."""
    atan2, hypot, sqrt, pi = math.atan2, math.hypot, math.sqrt, math.pi
    rho = hypot(x, y)
    if rho > 0.0:
        cpsi, spsi = x / rho, y / rho
        sb = min(1.0, max(-1.0, k / rho))
    else:
        cpsi, spsi, sb = 1.0, 0.0, 0.0
    cb = sqrt(1.0 - sb * sb)
    psi, beta = atan2(y, x), math.asin(sb)
    shoulders = [
        (psi - beta, cpsi * cb + spsi * sb, spsi * cb - cpsi * sb, rho * cb - a1),
        (psi - pi + beta, spsi * sb - cpsi * cb, -(spsi * cb + cpsi * sb), -rho * cb - a1),
    ]
    if distinct and cb < _COINCIDE:
        del shoulders[1]
    return shoulders


Six = tuple[float, float, float, float, float, float]


def _wrist(
    wc: Six, G: Six, arm: Six, theta4_ref: float, centre: tuple[float, float, float]
) -> tuple[float, float, float, float]:
    """Return t4, t5, t6 [rad] and the branch's residual, for the constants
    wc = (e2, sig1, sig4, sig5, ss4, sg23) of `OPWGeometry.scalar_constants`, the target's
    columns 0 and 2 `G` = (G00, G01, G02, G20, G21, G22) and the arm's (c1, s1, c2, s2, c3,
    s3): the largest of the wrist centre's deviations `centre` and the wrist rotation's
    (inf where t6 is undefined)."""
    atan2, hypot = math.atan2, math.hypot
    e2, sig1, sig4, sig5, ss4, sg23 = wc
    G00, G01, G02, G20, G21, G22 = G
    c1, s1, c2, s2, c3, s3 = arm
    es3 = e2 * s3
    c23, s23 = c2 * c3 - s2 * es3, s2 * c3 + c2 * es3
    a0, a1_, a2_ = c1 * c23, s1 * c23, sig1 * s23
    b0, b1 = sg23 * sig1 * s1, -sg23 * sig1 * c1
    d0, d1_, d2_ = sg23 * c1 * s23, sg23 * s1 * s23, -sg23 * sig1 * c23
    M00 = a0 * G00 + a1_ * G01 + a2_ * G02
    M10 = b0 * G00 + b1 * G01
    M20 = d0 * G00 + d1_ * G01 + d2_ * G02
    M02 = a0 * G20 + a1_ * G21 + a2_ * G22
    M12 = b0 * G20 + b1 * G21
    M22 = d0 * G20 + d1_ * G21 + d2_ * G22
    c5 = -ss4 * M22
    c5 = 1.0 if c5 > 1.0 else -1.0 if c5 < -1.0 else c5
    s5 = hypot(M02, M12)
    t5 = atan2(s5, c5)
    if s5 < _WRIST_SINGULAR:
        t4 = theta4_ref
        c4, s4 = math.cos(t4), math.sin(t4)
    else:
        c4, s4 = sig5 * M02 / s5, sig5 * M12 / s5
        t4 = atan2(s4, c4)
    c6 = c5 * (c4 * M00 + s4 * M10) + sig4 * s5 * M20
    s6 = ss4 * (s4 * M00 - c4 * M10)
    t6 = atan2(s6, c6)
    n6 = hypot(c6, s6)
    if n6 > 0.0:
        c6, s6 = c6 / n6, s6 / n6
        err = max(
            *centre,
            abs(sig5 * c4 * s5 - M02),
            abs(sig5 * s4 * s5 - M12),
            abs(-ss4 * c5 - M22),
            abs(c6 * c4 * c5 + s6 * ss4 * s4 - M00),
            abs(c6 * s4 * c5 - s6 * ss4 * c4 - M10),
            abs(c6 * sig4 * s5 - M20),
        )
    else:
        err = math.inf
    return t4, t5, t6, err
