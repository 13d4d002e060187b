"""Iso-parametric stepping along chart polylines, lifted onto the fitted Bézier surface.

Each next point is the one on the surface curve whose straight-line (chord) distance from
the last is `step` (seed 004, Fig. 4).

The chain of chord equations |X(t_k) - X(t_{k-1})| = S (X the lifted polyline, t a
fractional vertex index) is solved for all points at once by Newton's method: linearised,
α_k δ_k - β_k δ_{k-1} = r_k = S - c_k with α_k = e_k·X'(t_k), β_k = e_k·X'(t_{k-1}) (e_k the
unit chord) is a first-order linear recurrence, δ_k = (β_k/α_k) δ_{k-1} + r_k/α_k, solved
with cumulative products and sums (`linear_recurrence`), restarted wherever the running
product Π β_i/α_i would leave [1e-150, 1e150]: a chord perpendicular to the previous
tangent (β = 0), or many nearly so, would otherwise make it 0 and the step NaN (and the
path take the dense walk). Only the stepped points are lifted (a few iterations), not a
dense copy of the path; where that cannot be done (a polyline vertex off the mesh, no
convergence) the dense walk (`chord_parameters`) runs.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.polishing.bezier import BezierSurface
from workbench.polishing.chart import SurfaceChart

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]


def lift(chart: SurfaceChart, surface: BezierSurface, uv: F64) -> tuple[F64, F64, I64, F64]:
    """Return (points (N,3), normals (N,3), face (N,), bary (N,3)) of chart points on the surface;
    points off the mesh are dropped."""
    face, bary = chart.locate(uv)
    ok = face >= 0
    face, bary = face[ok], bary[ok]
    pts, nrm = surface.evaluate_with_normal(face, bary)
    return pts, nrm, face, bary


def chord_parameters(p: F64, step: float) -> F64:
    """Return fractional indices into the dense polyline p (M, 3) [m] of points spaced by chord `step`.

    Each next point is the first point of the polyline (after the current one) whose
    straight-line distance from the current point equals `step`: dense points are walked
    until one lies `step` or farther away, then the crossing is solved exactly on that
    segment (a quadratic). The polyline's end is appended when the remainder is longer
    than 1e-3 step. A plain loop over floats: each step visits only a few dense points.
    """
    xs, ys, zs = (p[:, i].tolist() for i in range(3))
    m = len(xs)
    s2 = step * step
    out = [0.0]
    cx, cy, cz = xs[0], ys[0], zs[0]
    pos = 0.0
    j = 1
    while j < m:
        dx, dy, dz = xs[j] - cx, ys[j] - cy, zs[j] - cz
        if dx * dx + dy * dy + dz * dz < s2:
            j += 1
            continue
        # Crossing on the segment from a (the current point if on this segment, else p[j-1]) to p[j].
        if pos > j - 1:
            ax, ay, az, base, span = cx, cy, cz, pos, j - pos
        else:
            ax, ay, az, base, span = xs[j - 1], ys[j - 1], zs[j - 1], float(j - 1), 1.0
        ex, ey, ez = xs[j] - ax, ys[j] - ay, zs[j] - az
        fx, fy, fz = ax - cx, ay - cy, az - cz
        qa = ex * ex + ey * ey + ez * ez
        qb = 2.0 * (fx * ex + fy * ey + fz * ez)
        qc = fx * fx + fy * fy + fz * fz - s2
        disc = qb * qb - 4.0 * qa * qc
        tau = (-qb + (disc if disc > 0.0 else 0.0) ** 0.5) / (2.0 * qa) if qa > 0 else 1.0
        tau = 0.0 if tau < 0.0 else (1.0 if tau > 1.0 else tau)
        pos = base + tau * span
        cx, cy, cz = ax + tau * ex, ay + tau * ey, az + tau * ez
        out.append(pos)
    dx, dy, dz = xs[-1] - cx, ys[-1] - cy, zs[-1] - cz
    if (dx * dx + dy * dy + dz * dz) ** 0.5 > 1e-3 * step:
        out.append(float(m - 1))
    return np.asarray(out)


def densify(uv: F64, ds: float) -> F64:
    """Return the polyline uv (M, 2) with points inserted so no segment is longer than ds [m]."""
    seg = np.linalg.norm(np.diff(uv, axis=0), axis=1)
    k = np.maximum(np.ceil(seg / ds).astype(np.int64), 1)
    start = np.repeat(uv[:-1], k, axis=0)
    delta = np.repeat(np.diff(uv, axis=0) / k[:, None], k, axis=0)
    i = (np.arange(k.sum()) - np.repeat(np.cumsum(k) - k, k))[:, None]
    return np.vstack([start + i * delta, uv[-1:]])


def linear_recurrence(a: F64, b: F64, *, window: int = 4096) -> F64:
    """Return x (n,) with x_0 = b_0 and x_k = a_k x_{k-1} + b_k, for a, b (n,).

    Vectorised by segments: from a start s, x_k = c_k (Σ_{s<=j<=k} b_j/c_j + a_s x_{s-1}) with
    c_k = Π_{s<i<=k} a_i. A segment ends before the first c outside [1e-150, 1e150] (a zero
    or tiny a_k, or a product drifting away) and the next starts there, so no c is 0, inf or
    subnormal (tests: equal to the plain loop to 1e-12 of the terms' magnitudes). At most
    `window` terms per segment bound the work to O(n) even when every a_k is tiny.
    """
    n = len(a)
    x = np.empty(n)
    s, carry = 0, 0.0  # carry: x_{s-1}
    while s < n:
        w = min(n, s + window)
        c = np.empty(w - s)
        c[0] = 1.0
        with np.errstate(over="ignore", under="ignore"):  # cut off below, never used
            np.cumprod(a[s + 1 : w], out=c[1:])
        m = np.abs(c)
        if m.min() > 1e-150 and m.max() < 1e150:  # the usual case: one segment (NaN fails)
            e = w
        else:  # the first c out of range (NaN too); never c[0]
            e = s + int(np.flatnonzero(~((m > 1e-150) & (m < 1e150)))[0])
            c = c[: e - s]
        x[s:e] = c * (np.cumsum(b[s:e] / c) + a[s] * carry)
        s, carry = e, float(x[e - 1])
    return x


def chord_step(
    chart: SurfaceChart, surface: BezierSurface, uv: F64, step: float
) -> tuple[F64, F64, I64, F64]:
    """Return (points (N,3), normals (N,3), face (N,), bary (N,3)) along the chart polyline
    `uv` (M, 2), lifted onto the surface, consecutive points `step` [m] apart (chord).

    Newton on the whole chain (module docstring); consecutive chords equal `step` to 1e-9
    of it, the last one may be shorter. Falls back to `chord_step_dense` for a polyline
    that leaves the mesh (inner holes: those points are dropped there) or does not converge.
    """
    out = _chord_step_newton(chart, surface, np.asarray(uv, dtype=float), float(step))
    return out if out is not None else chord_step_dense(chart, surface, uv, step)


def _lift_at(
    chart: SurfaceChart, surface: BezierSurface, uv: F64, t: F64, hint: I64
) -> tuple[F64, F64, I64, F64, F64]:
    """Return (X (K,3), dX/dt (K,3), face, bary, normals) at fractional vertex indices t (K,);
    hint (K,) or (K, k): faces to try first (`SurfaceChart.locate_near`)."""
    j = np.minimum(t.astype(np.int64), len(uv) - 2)
    f = (t - j)[:, None]
    duv = uv[j + 1] - uv[j]
    face, bary = chart.locate_near(uv[j] + f * duv, hint)
    ok = face >= 0
    fc = np.where(ok, face, 0)
    x, d_du, d_dv, nrm = surface.evaluate_with_derivatives(
        fc, bary if ok.all() else np.where(ok[:, None], bary, 1 / 3)
    )
    rate = chart.bary_rate(fc, duv)
    dx = d_du * rate[:, :1] + d_dv * rate[:, 1:]
    return x, dx, face, bary, nrm


def _chord_step_newton(
    chart: SurfaceChart, surface: BezierSurface, uv: F64, step: float, *, max_iter: int = 12
) -> tuple[F64, F64, I64, F64] | None:
    """Return `chord_step`'s result by Newton on the chord chain, or None where it cannot."""
    if uv.ndim != 2 or len(uv) < 2:
        return None
    seg = np.linalg.norm(np.diff(uv, axis=0), axis=1)
    uv = uv[np.concatenate([[True], seg > 0])]  # repeated vertices give no direction
    m = len(uv)
    if m < 2:
        return None
    face_v, bary_v = chart.locate(uv)
    if (face_v < 0).any():
        return None
    pv = surface.evaluate(face_v, bary_v)
    end = float(m - 1)
    # First guess: chord steps on the polyline of the lifted vertices (exact at its corners,
    # off by its sagitta between them), with spare points at the end for the chain to grow into.
    t = chord_parameters(pv, step)
    t = np.concatenate([t[t < end], np.full(3, end)])
    # Hints: the faces of the vertices at both ends of each point's polyline segment.
    j0 = np.minimum(t.astype(np.int64), m - 2)
    hint = np.stack([face_v[j0], face_v[j0 + 1]], axis=1)
    tol = 1e-9 * step
    for _ in range(max_iter):
        x, dx, face, bary, nrm = _lift_at(chart, surface, uv, t, hint)
        if (face < 0).any():
            return None
        hint = face
        # Points from the first one at the end on only carry the end: not part of the chain.
        inside = t[1:] < end
        n_in = int(np.argmin(inside)) if not inside.all() else len(inside)
        if n_in == len(inside):
            return None  # the guess fell short of the end (not expected: chords <= arcs)
        d = x[1:] - x[:-1]
        c = np.linalg.norm(d, axis=1)
        if not (c[: n_in + 1] > 0).all():
            return None
        e = d / np.where(c > 0, c, 1.0)[:, None]
        r = step - c
        done = np.abs(r[:n_in]).max(initial=0.0) <= tol and r[n_in] >= -tol
        if done:
            break
        # The chain: chords 1 .. n_in + 1 (the last one reaching the first point at the end).
        q = n_in + 1
        alpha = np.sum(e[:q] * dx[1 : q + 1], axis=1)
        beta = np.sum(e[:q] * dx[:q], axis=1)
        if not (alpha > 0).all():
            return None
        delta = linear_recurrence(beta / alpha, r[:q] / alpha)
        if not np.isfinite(delta).all():
            return None
        t[1 : q + 1] = np.minimum(t[1 : q + 1] + delta, end)
        if not (np.diff(t[: n_in + 2]) > 0).all():
            return None
    else:
        return None
    keep = n_in + 1  # t[0 .. n_in] lie before the end, chords exactly `step`
    pts, nrm_k, face_k, bary_k = x[:keep], nrm[:keep], face[:keep], bary[:keep]
    if c[n_in] > 1e-3 * step:
        # The end itself, closer than `step` to the last point (r[n_in] >= 0).
        x_e, _, f_e, b_e, n_e = _lift_at(
            chart, surface, uv, np.array([end]), face[n_in + 1 : n_in + 2]
        )
        pts, nrm_k = np.vstack([pts, x_e]), np.vstack([nrm_k, n_e])
        face_k, bary_k = np.concatenate([face_k, f_e]), np.vstack([bary_k, b_e])
    return pts, nrm_k, face_k, bary_k


def chord_step_dense(
    chart: SurfaceChart, surface: BezierSurface, uv: F64, step: float
) -> tuple[F64, F64, I64, F64]:
    """Return surface points along the chart polyline `uv` (M, 2) spaced by chord `step` [m].

    Iso-parametric stepping (seed 004, Fig. 4): the polyline, densified to step/4, is lifted
    onto the surface; the chord-`step` points are found on that dense 3D polyline
    (`chord_parameters`); their chart coordinates are lifted again, so the points lie on
    the fitted surface exactly. Lifting moves a point off the dense polyline's straight
    pieces by about curvature * (step/4)² / 8, so chords equal `step` to a few 1e-7 m for
    step = 2 mm on the example panel (tests check 1e-6 m).
    """
    uv = densify(uv, step / 4.0)
    face, bary = chart.locate(uv)
    ok = face >= 0
    uv = uv[ok]
    p = surface.evaluate(face[ok], bary[ok])
    t = chord_parameters(p, step)
    j = np.minimum(np.floor(t).astype(np.int64), len(uv) - 2)
    f = (t - j)[:, None]
    return lift(chart, surface, (1.0 - f) * uv[j] + f * uv[j + 1])
