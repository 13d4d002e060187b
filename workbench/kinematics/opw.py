"""Analytic inverse kinematics of the "OPW" arm family, derived from standard DH rows.

The family: 6R, shoulder axis 2 perpendicular to axis 1 (alpha1 = +-90 deg), axes 2 and 3
parallel (alpha2 = 0 or 180 deg), then a spherical wrist (a4 = a5 = d5 = 0, alpha3, alpha4,
alpha5 = +-90 deg) and any flange row with a6 = 0. Offsets a1, d1, a2, a3, d4 and the
lateral offset d2 + d3 may take any value and sign. All angles below are DH angles
theta_i = q_i + offset_i; callers subtract the offsets.

Derivation (frames of the DH chain):
- wrist centre pc = p - R @ (d6 * [0, sin a6, cos a6]) (frame 5's origin, independent of q6);
- in frame 1 the wrist centre is Rz(t2) @ [a2 + x3, e2*y3, b] with
  x3 = a3 cos t3 + s3 d4 sin t3, y3 = a3 sin t3 - s3 d4 cos t3, b = d2 + e2 d3; so
  |p1_xy|^2 = a2^2 + K^2 + 2 a2 x3 gives t3 (two elbow branches), then t2 from the angle;
- Rz(-t1) pc has y = -s1 b: two shoulder branches t1 = psi - beta, psi - pi + beta;
- the wrist rotation M = R03^T R Rx(-a6) = Rz(t4) Rx(a4) Rz(t5) Rx(a5) Rz(t6) has third column
  (s5' c4 s5, s5' s4 s5, -s4' s5' c5): t5 from M22 (two wrist branches), t4 from M02, M12,
  and t6 from the first column of (Rz(t4) Rx(a4) Rz(t5) Rx(a5))^T M, which stays exact when
  sin t5 = 0 (t4 is then free and set to a reference).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
_STRUCT_TOL = 1e-9
# Branch index = 4 * shoulder + 2 * elbow + wrist (each 0 or 1).
N_BRANCHES = 8
# Below this |sin t5| the wrist counts as singular and t4 is set to the reference.
_WRIST_SINGULAR = 1e-10
# Branch pairs closer than this [rad] count as one solution.
_COINCIDE = 1e-9


@dataclass(frozen=True)
class OPWGeometry:
    """Constants of an OPW arm read from its DH rows (lengths in m, signs +-1)."""

    offsets: tuple[float, ...]
    d1: float
    a1: float
    sig1: float  # sin(alpha1)
    a2: float
    e2: float  # cos(alpha2)
    b: float  # lateral offset d2 + e2 * d3
    a3: float
    s3: float  # sin(alpha3)
    d4: float
    sig4: float
    sig5: float
    alpha6: float
    w6: tuple[float, float, float]  # flange -> wrist centre offset, in the flange frame

    @functools.cached_property
    def scalar_constants(self) -> tuple[float, ...]:
        """Return the constants `solve_single` unpacks into locals (attribute lookups are slow)."""
        K = self.K
        return (
            math.cos(self.alpha6),
            math.sin(self.alpha6),
            self.w6[1],
            self.w6[2],
            -self.sig1 * self.b,
            self.d1,
            self.a1,
            self.a2,
            self.a3,
            self.s3 * self.d4,
            self.e2,
            self.a2 * self.a2 + K * K,
            2.0 * self.a2 * K,
            math.cos(self.phi),
            math.sin(self.phi),
            self.phi,
            self.sig1,
            self.sig4,
            self.sig5,
            self.sig4 * self.sig5,
            self.e2 * self.s3,
            -self.sig1 * self.b,
        )

    @property
    def K(self) -> float:
        """Return the elbow-to-wrist-centre distance sqrt(a3^2 + d4^2) [m]."""
        return math.hypot(self.a3, self.d4)

    @property
    def phi(self) -> float:
        """Return atan2(s3 d4, a3) [rad], the forearm angle in the elbow frame."""
        return math.atan2(self.s3 * self.d4, self.a3)


def opw_geometry(dh: FloatArray) -> OPWGeometry | None:
    """Return the OPW constants of DH rows (6, 4), or None when the rows are not of that family."""
    if dh.shape != (6, 4):
        return None
    off, d, a, al = dh[:, 0], dh[:, 1], dh[:, 2], dh[:, 3]
    tol = _STRUCT_TOL
    perp = [abs(math.cos(al[i])) < tol for i in (0, 2, 3, 4)]
    par = abs(math.sin(al[1])) < tol
    zeros = [abs(x) < tol for x in (a[3], a[4], d[4], a[5])]
    if not (all(perp) and par and all(zeros)) or abs(a[1]) < tol or math.hypot(a[2], d[3]) < tol:
        return None
    e2 = float(np.sign(math.cos(al[1])))
    return OPWGeometry(
        offsets=tuple(float(x) for x in off),
        d1=float(d[0]),
        a1=float(a[0]),
        sig1=float(np.sign(math.sin(al[0]))),
        a2=float(a[1]),
        e2=e2,
        b=float(d[1] + e2 * d[2]),
        a3=float(a[2]),
        s3=float(np.sign(math.sin(al[2]))),
        d4=float(d[3]),
        sig4=float(np.sign(math.sin(al[3]))),
        sig5=float(np.sign(math.sin(al[4]))),
        alpha6=float(al[5]),
        w6=(0.0, float(d[5] * math.sin(al[5])), float(d[5] * math.cos(al[5]))),
    )


def solve_batch(
    g: OPWGeometry,
    T: FloatArray,
    theta4_ref: FloatArray | None = None,
    joint_map: Callable[[int, FloatArray], tuple[FloatArray, NDArray[np.bool_]]] | None = None,
) -> tuple[FloatArray, FloatArray]:
    """Return DH angles (N, 8, 6) [rad] and residuals (N, 8) [m or unitless] for poses T (N, 4, 4).

    The residual is the max deviation of the recomputed wrist centre and wrist rotation from
    the target; it is zero (to rounding) exactly when fk(solution) == T. `theta4_ref` (N,)
    sets t4 where the wrist is singular (sin t5 = 0). `joint_map(j, theta)` may turn the angles
    of joint j (any shape, batch last) into joint values and a fit mask; rows that do not fit
    get an infinite residual. Cosines and sines come from algebra,
    not from the angles: only 20 inverse-trig evaluations per pose.
    """
    N = T.shape[0]
    ca6, sa6 = math.cos(g.alpha6), math.sin(g.alpha6)
    Tt = np.moveaxis(T[:, :3, :], 0, -1)  # (3, 4, N): rows, columns, batch
    G0 = np.ascontiguousarray(Tt[:, 0])
    G2 = sa6 * Tt[:, 1] + ca6 * Tt[:, 2]
    pc = Tt[:, 3] - (Tt[:, 1] * g.w6[1] + Tt[:, 2] * g.w6[2])
    x, y, z = pc[0], pc[1], pc[2]
    c1, s1, t1, px1, py1 = _shoulder(g, x, y, z)
    c2, s2, t2, c3, s3, t3, u, w = _elbow(g, px1, py1)
    c1e, s1e = c1[:, None], s1[:, None]
    err = _wrist_centre_error(g, c1e, s1e, c2, s2, u, w, pc)
    M = _wrist_matrix(g, c1e, s1e, c2, s2, c3, s3, G0, G2)
    t4, t5, t6 = _wrist(g, M, theta4_ref, N, err)
    per_joint = (
        t1[:, None, None, :],
        t2[:, :, None, :],
        t3[:, :, None, :],
        np.stack([t4, t4 + np.pi], axis=2),
        np.stack([t5, -t5], axis=2),
        np.stack([t6, t6 + np.pi], axis=2),
    )
    return _assemble(per_joint, err, N, joint_map)


def _shoulder(
    g: OPWGeometry, x: FloatArray, y: FloatArray, z: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray]:
    """Return cos, sin and angle of joint 1 (2, N) (axis 0 = front/back) for wrist centres
    (x, y, z) (N,) [m], and the wrist centre in the shoulder's plane: px1 (2, N), py1 (N,)."""
    rho = np.hypot(x, y)
    pos = rho > 0.0
    inv = 1.0 / np.where(pos, rho, 1.0)
    cpsi, spsi = np.where(pos, x * inv, 1.0), y * inv
    psi = np.arctan2(y, x)
    k = -g.sig1 * g.b
    sb: FloatArray | float
    cb: FloatArray | float
    beta: FloatArray | float
    if k == 0.0:
        sb, cb, beta = 0.0, 1.0, 0.0
    else:
        sb = np.clip(k * inv, -1.0, 1.0)
        cb = np.sqrt(1.0 - sb * sb)
        beta = np.arcsin(sb)
    c1 = np.stack([cpsi * cb + spsi * sb, spsi * sb - cpsi * cb])
    s1 = np.stack([spsi * cb - cpsi * sb, -(spsi * cb + cpsi * sb)])
    t1 = np.stack([psi - beta, psi - np.pi + beta])
    rcb = rho * cb
    px1 = np.stack([rcb, -rcb]) - g.a1
    py1 = g.sig1 * (z - g.d1)
    return c1, s1, t1, px1, py1


def _elbow(g: OPWGeometry, px1: FloatArray, py1: FloatArray) -> tuple[FloatArray, ...]:
    """Return c2, s2, t2, c3, s3, t3 (2, 2, N) (axes = shoulder, elbow) and the forearm's
    reach u, w in the upper arm's frame, for the wrist centre (px1, py1) in the shoulder's plane."""
    K, phi = g.K, g.phi
    r2 = px1 * px1 + py1 * py1
    cg = np.clip((r2 - g.a2 * g.a2 - K * K) / (2.0 * g.a2 * K), -1.0, 1.0)
    sg = np.sqrt(1.0 - cg * cg)
    gam = np.arccos(cg)
    cphi, sphi = math.cos(phi), math.sin(phi)
    t3 = np.stack([phi - gam, phi + gam], axis=1)
    c3 = np.stack([cphi * cg + sphi * sg, cphi * cg - sphi * sg], axis=1)
    s3 = np.stack([sphi * cg - cphi * sg, sphi * cg + cphi * sg], axis=1)
    u = g.a2 + g.a3 * c3 + (g.s3 * g.d4) * s3
    w = g.e2 * (g.a3 * s3 - (g.s3 * g.d4) * c3)
    px1e, py1e = px1[:, None], py1
    den = np.sqrt(r2[:, None] * (u * u + w * w))
    den = np.where(den > 0.0, den, 1.0)
    c2 = (px1e * u + py1e * w) / den
    s2 = (py1e * u - px1e * w) / den
    t2 = np.arctan2(s2, c2)
    return c2, s2, t2, c3, s3, t3, u, w


def _wrist_centre_error(
    g: OPWGeometry,
    c1e: FloatArray,
    s1e: FloatArray,
    c2: FloatArray,
    s2: FloatArray,
    u: FloatArray,
    w: FloatArray,
    pc: FloatArray,
) -> FloatArray:
    """Return the largest deviation (2, 2, N) [m] of the forward wrist centre from `pc` (3, N)."""
    Px = g.a1 + c2 * u - s2 * w
    Py = -g.sig1 * g.b
    Pz = g.d1 + g.sig1 * (s2 * u + c2 * w)
    err = np.abs(c1e * Px - s1e * Py - pc[0])
    np.maximum(err, np.abs(s1e * Px + c1e * Py - pc[1]), out=err)
    np.maximum(err, np.abs(Pz - pc[2]), out=err)
    return err


def _wrist_matrix(
    g: OPWGeometry,
    c1e: FloatArray,
    s1e: FloatArray,
    c2: FloatArray,
    s2: FloatArray,
    c3: FloatArray,
    s3: FloatArray,
    G0: FloatArray,
    G2: FloatArray,
) -> tuple[FloatArray, ...]:
    """Return the needed entries M00, M10, M20, M02, M12, M22 (2, 2, N) of M = R03^T G,
    from R03's columns and the target's columns 0 and 2 (G0, G2 (3, N))."""
    es3 = g.e2 * s3
    c23, s23 = c2 * c3 - s2 * es3, s2 * c3 + c2 * es3
    sg23 = g.e2 * g.s3
    a0, a1_, a2_ = c1e * c23, s1e * c23, g.sig1 * s23
    b0, b1 = (sg23 * g.sig1) * s1e, (-sg23 * g.sig1) * c1e
    d0, d1_, d2_ = sg23 * c1e * s23, sg23 * s1e * s23, (-sg23 * g.sig1) * c23
    M00 = a0 * G0[0] + a1_ * G0[1] + a2_ * G0[2]
    M10 = b0 * G0[0] + b1 * G0[1]
    M20 = d0 * G0[0] + d1_ * G0[1] + d2_ * G0[2]
    M02 = a0 * G2[0] + a1_ * G2[1] + a2_ * G2[2]
    M12 = b0 * G2[0] + b1 * G2[1]
    M22 = d0 * G2[0] + d1_ * G2[1] + d2_ * G2[2]
    return M00, M10, M20, M02, M12, M22


def _wrist(
    g: OPWGeometry,
    M: tuple[FloatArray, ...],
    theta4_ref: FloatArray | None,
    N: int,
    err: FloatArray,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Return t4, t5, t6 (2, 2, N) of the wrist rotation M; raises `err` in place to the
    wrist rotation's residual (columns 2 and 0 of the model against M; inf where undefined)."""
    M00, M10, M20, M02, M12, M22 = M
    ss4 = g.sig4 * g.sig5
    # sin t5 = |(M02, M12)|: accurate near the wrist singularity, unlike sqrt(1 - c5^2).
    c5 = np.clip(-ss4 * M22, -1.0, 1.0)
    s5 = np.hypot(M02, M12)
    t5 = np.arctan2(s5, c5)
    sing = s5 < _WRIST_SINGULAR
    n45 = np.where(sing, 1.0, s5)
    c4, s4 = g.sig5 * M02 / n45, g.sig5 * M12 / n45
    if np.any(sing):
        ref = np.zeros(N) if theta4_ref is None else np.asarray(theta4_ref, float)
        c4 = np.where(sing, np.cos(ref), c4)
        s4 = np.where(sing, np.sin(ref), s4)
    t4 = np.arctan2(s4, c4)
    c6 = c5 * (c4 * M00 + s4 * M10) + g.sig4 * s5 * M20
    s6 = ss4 * (s4 * M00 - c4 * M10)
    t6 = np.arctan2(s6, c6)
    n6 = np.hypot(c6, s6)
    n6 = np.where(n6 > 0.0, n6, np.nan)
    c6, s6 = c6 / n6, s6 / n6
    for e in (
        g.sig5 * c4 * s5 - M02,
        g.sig5 * s4 * s5 - M12,
        -ss4 * c5 - M22,
        c6 * c4 * c5 + s6 * ss4 * s4 - M00,
        c6 * s4 * c5 - s6 * ss4 * c4 - M10,
        c6 * g.sig4 * s5 - M20,
    ):
        np.maximum(err, np.abs(e), out=err)
    err[np.isnan(n6)] = np.inf
    return t4, t5, t6


def _assemble(
    per_joint: tuple[FloatArray, ...],
    err: FloatArray,
    N: int,
    joint_map: Callable[[int, FloatArray], tuple[FloatArray, NDArray[np.bool_]]] | None,
) -> tuple[FloatArray, FloatArray]:
    """Return (N, 8, 6) joints and (N, 8) residuals of the per-joint arrays (shoulder, elbow,
    wrist, N), each joint mapped on its own compact array; misfits get an infinite residual."""
    # Built joint-major (6, 2, 2, 2, N), contiguous writes; returned as an (N, 8, 6) view.
    out = np.empty((6, 2, 2, 2, N))
    ok = np.isfinite(err)[:, :, None, :]
    for j, t in enumerate(per_joint):
        if joint_map is not None:
            t, ok_j = joint_map(j, t)
            ok = ok & ok_j
        out[j] = t
    err4 = np.where(ok, np.broadcast_to(err[:, :, None, :], (2, 2, 2, N)), np.inf)
    return out.reshape(6, N_BRANCHES, N).T, err4.reshape(N_BRANCHES, N).T
