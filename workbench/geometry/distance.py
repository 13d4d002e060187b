"""Exact closed-form distances between points, segments, triangles and rectangles, batched.

Seed 002 models robot links as capsules (cylinders with round caps) and obstacle faces as
rectangles. Its face test only looks at the capsule's end points; here the segment–rectangle
distance is exact: the minimum over (a) the segment against the rectangle's four edges,
(b) each end point projected onto the face when the projection lies inside the rectangle,
and (c) zero when the segment crosses the face. Those cases cover every place the minimum
can sit (a segment not parallel to the plane has its plane distance linear along it, so an
interior minimum means a crossing; a parallel one attains its minimum at an end point too).

All functions broadcast over leading batch dimensions; lengths in metres.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError

FloatArray = NDArray[np.float64]


def _vec3(name: str, value: ArrayLike) -> FloatArray:
    arr = np.asarray(value, dtype=float)
    if arr.ndim < 1 or arr.shape[-1] != 3:
        raise InputError(f"{name} must have shape (..., 3), got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise InputError(f"{name} contains NaN or inf; give finite coordinates in metres")
    return arr


def _dot(a: FloatArray, b: FloatArray) -> FloatArray:
    return np.einsum("...i,...i->...", a, b)


def closest_points_on_segments(points: ArrayLike, a: ArrayLike, b: ArrayLike) -> FloatArray:
    """Return the closest points (..., 3) on segments [a, b] to `points` [m] (degenerate ok)."""
    p, a_, b_ = (np.asarray(x, dtype=float) for x in (points, a, b))
    ab = b_ - a_
    den = _dot(ab, ab)
    t = np.clip(_dot(p - a_, ab) / np.where(den > 0.0, den, 1.0), 0.0, 1.0)
    return a_ + t[..., None] * ab


def _region_weights(
    d1: FloatArray,
    d2: FloatArray,
    d3: FloatArray,
    d4: FloatArray,
    d5: FloatArray,
    d6: FloatArray,
    ab2_ac2: FloatArray,
) -> tuple[FloatArray, FloatArray, NDArray[np.bool_]]:
    """Return (v, w, degenerate): the closest point is a + v*ab + w*ac (Ericson 5.1.5).

    d1..d6 are the dot products of the edges ab, ac with ap, bp, cp; `ab2_ac2` is
    |ab|^2 |ac|^2, the scale for calling a triangle degenerate (zero area).
    """
    va = d3 * d6 - d5 * d4
    vb = d5 * d2 - d1 * d6
    vc = d1 * d4 - d3 * d2
    denom = va + vb + vc
    degenerate = ~(denom > 1e-30 * np.maximum(ab2_ac2, 1e-300))
    safe = np.where(degenerate, 1.0, denom)
    # Every region's closest point is a + v*ab + w*ac: pick (v, w) per region, latest wins.
    v, w = vb / safe, vc / safe
    with np.errstate(divide="ignore", invalid="ignore"):
        t_bc = np.nan_to_num((d4 - d3) / ((d4 - d3) + (d5 - d6)))
        m = (va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0)
        v, w = np.where(m, 1.0 - t_bc, v), np.where(m, t_bc, w)
        m = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
        v, w = np.where(m, 0.0, v), np.where(m, np.nan_to_num(d2 / (d2 - d6)), w)
        m = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
        v, w = np.where(m, np.nan_to_num(d1 / (d1 - d3)), v), np.where(m, 0.0, w)
    m = (d6 >= 0) & (d5 <= d6)
    v, w = np.where(m, 0.0, v), np.where(m, 1.0, w)
    m = (d3 >= 0) & (d4 <= d3)
    v, w = np.where(m, 1.0, v), np.where(m, 0.0, w)
    m = (d1 <= 0) & (d2 <= 0)
    v, w = np.where(m, 0.0, v), np.where(m, 0.0, w)
    return v, w, degenerate


def closest_points_on_triangles(
    points: ArrayLike, a: ArrayLike, b: ArrayLike, c: ArrayLike
) -> FloatArray:
    """Return the closest points (..., 3) on triangles (a, b, c) to `points` [m].

    Ericson's Voronoi-region method (Real-Time Collision Detection, 5.1.5), evaluated for
    every region with masks. Zero-area triangles fall back to their three edges.
    """
    p, a_, b_, c_ = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (points, a, b, c)))
    ab, ac, ap = b_ - a_, c_ - a_, p - a_
    d1, d2 = _dot(ab, ap), _dot(ac, ap)
    bp = p - b_
    d3, d4 = _dot(ab, bp), _dot(ac, bp)
    cp = p - c_
    d5, d6 = _dot(ab, cp), _dot(ac, cp)
    v, w, degenerate = _region_weights(d1, d2, d3, d4, d5, d6, _dot(ab, ab) * _dot(ac, ac))
    out = a_ + ab * v[..., None] + ac * w[..., None]
    if np.any(degenerate):
        if out.ndim == 1:
            out, p, a_, b_, c_, degenerate = (x[None] for x in (out, p, a_, b_, c_, degenerate))
            return closest_points_on_triangles(p, a_, b_, c_)[0]
        idx = np.nonzero(degenerate)
        pd, ad, bd, cd = p[idx], a_[idx], b_[idx], c_[idx]
        cands = np.stack(
            [
                closest_points_on_segments(pd, ad, bd),
                closest_points_on_segments(pd, bd, cd),
                closest_points_on_segments(pd, cd, ad),
            ]
        )
        k = np.argmin(np.sum((cands - pd) ** 2, axis=-1), axis=0)
        out[idx] = cands[k, np.arange(len(k))]
    return out


def point_triangle_distance2(
    points: FloatArray, a: FloatArray, b: FloatArray, c: FloatArray
) -> FloatArray:
    """Return squared distances (P,) [m^2] from points (P,3) to triangles (P,3) x 3."""
    rows = (np.ascontiguousarray(np.asarray(x, dtype=float).T) for x in (points, a, b, c))
    return point_triangle_distance2_rows(*rows)


def point_triangle_distance2_rows(
    p_: FloatArray, a_: FloatArray, b_: FloatArray, c_: FloatArray
) -> FloatArray:
    """Return squared distances (P,) [m^2]; points and vertices as coordinate rows (3, P).

    Same regions as `closest_points_on_triangles`: numpy is much faster on long 1-D rows
    than on a trailing axis of length 3. Zero-area triangles fall back to the edges.
    """
    ab, ac, ap, bp, cp = b_ - a_, c_ - a_, p_ - a_, p_ - b_, p_ - c_

    def dot(x: FloatArray, y: FloatArray) -> FloatArray:
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]

    d1, d2, d3, d4, d5, d6 = (
        dot(ab, ap),
        dot(ac, ap),
        dot(ab, bp),
        dot(ac, bp),
        dot(ab, cp),
        dot(ac, cp),
    )
    v, w, degenerate = _region_weights(d1, d2, d3, d4, d5, d6, dot(ab, ab) * dot(ac, ac))
    r = ap - ab * v - ac * w
    out = dot(r, r)
    if np.any(degenerate):
        i = np.nonzero(degenerate)[0]
        pts = p_.T[i]
        cpt = closest_points_on_triangles(pts, a_.T[i], b_.T[i], c_.T[i])
        out[i] = np.sum((cpt - pts) ** 2, axis=1)
    return out


def segment_segment_closest(
    p0: ArrayLike, p1: ArrayLike, q0: ArrayLike, q1: ArrayLike
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Return (distance (...,) [m], closest point on [p0,p1] (...,3), closest on [q0,q1] (...,3)).

    Closed form of Ericson 5.1.9 with clamping; degenerate (zero-length) segments allowed.
    """
    p0_, p1_, q0_, q1_ = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (p0, p1, q0, q1))
    )
    d1, d2, r = p1_ - p0_, q1_ - q0_, p0_ - q0_
    a, e, f = _dot(d1, d1), _dot(d2, d2), _dot(d2, r)
    c, b = _dot(d1, r), _dot(d1, d2)
    tiny = 1e-300
    denom = a * e - b * b
    # General case: s from the infinite lines, clamped; parallel -> s = 0.
    par = denom <= 1e-14 * np.maximum(a * e, tiny)
    s = np.where(par, 0.0, np.clip((b * f - c * e) / np.where(par, 1.0, denom), 0.0, 1.0))
    e_safe = np.where(e > tiny, e, 1.0)
    t = (b * s + f) / e_safe
    # t outside [0, 1]: clamp it and recompute s.
    a_safe = np.where(a > tiny, a, 1.0)
    t_lo, t_hi = t < 0.0, t > 1.0
    s = np.where(t_lo, np.clip(-c / a_safe, 0.0, 1.0), s)
    s = np.where(t_hi, np.clip((b - c) / a_safe, 0.0, 1.0), s)
    t = np.clip(t, 0.0, 1.0)
    # Degenerate segments.
    a0, e0 = a <= tiny, e <= tiny
    s = np.where(a0, 0.0, s)
    t = np.where(a0 & ~e0, np.clip(f / e_safe, 0.0, 1.0), t)
    s = np.where(e0 & ~a0, np.clip(-c / a_safe, 0.0, 1.0), s)
    t = np.where(e0, 0.0, t)
    cp = p0_ + d1 * s[..., None]
    cq = q0_ + d2 * t[..., None]
    return np.linalg.norm(cp - cq, axis=-1), cp, cq


def segment_segment_distance(
    p0: ArrayLike, p1: ArrayLike, q0: ArrayLike, q1: ArrayLike
) -> FloatArray:
    """Return the distance (...,) [m] between segments [p0, p1] and [q0, q1]."""
    return segment_segment_closest(p0, p1, q0, q1)[0]


def _check_rectangle(
    center: ArrayLike, axes: ArrayLike, half_sizes: ArrayLike
) -> tuple[FloatArray, FloatArray, FloatArray]:
    c = _vec3("center", center)
    ax = np.asarray(axes, dtype=float)
    if ax.ndim < 2 or ax.shape[-2:] != (2, 3):
        raise InputError(
            f"axes must have shape (..., 2, 3) (two unit edge directions), got {ax.shape}"
        )
    if not np.all(np.isfinite(ax)):
        raise InputError("axes contains NaN or inf")
    norms = np.linalg.norm(ax, axis=-1)
    if np.any(np.abs(norms - 1.0) > 1e-6):
        raise InputError(
            f"axes must be unit vectors, got norms {norms.ravel()[:4]}; normalise them"
        )
    if np.any(np.abs(_dot(ax[..., 0, :], ax[..., 1, :])) > 1e-6):
        raise InputError("axes must be orthogonal (the rectangle's two edge directions)")
    hs = np.asarray(half_sizes, dtype=float)
    if hs.ndim < 1 or hs.shape[-1] != 2:
        raise InputError(f"half_sizes must have shape (..., 2), got {hs.shape}")
    if not np.all(np.isfinite(hs)) or np.any(hs < 0):
        raise InputError(f"half_sizes must be finite and >= 0 m, got {hs.ravel()[:4]}")
    return c, ax, hs


def segment_rectangle_distance(
    p0: ArrayLike, p1: ArrayLike, center: ArrayLike, axes: ArrayLike, half_sizes: ArrayLike
) -> FloatArray:
    """Return the exact distance (...,) [m] between segment [p0, p1] and a filled rectangle.

    The rectangle is ``center + u*axes[0] + v*axes[1]`` with |u| <= half_sizes[0],
    |v| <= half_sizes[1]; 0 when the segment touches or crosses it.
    """
    p0_, p1_ = _vec3("p0", p0), _vec3("p1", p1)
    c, ax, hs = _check_rectangle(center, axes, half_sizes)
    u, v = ax[..., 0, :], ax[..., 1, :]
    hu, hv = hs[..., 0, None], hs[..., 1, None]
    corners = [c + su * hu * u + sv * hv * v for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    best = np.full(
        np.broadcast_shapes(
            p0_.shape[:-1], p1_.shape[:-1], c.shape[:-1], ax.shape[:-2], hs.shape[:-1]
        ),
        np.inf,
    )
    for k in range(4):  # the four edges, as zero-radius capsules (seed 002, S3)
        best = np.minimum(
            best, segment_segment_distance(p0_, p1_, corners[k], corners[(k + 1) % 4])
        )
    n = np.cross(u, v)
    tol = 1e-12
    for p in (p0_, p1_):  # end points projected onto the face (S4)
        rel = p - c
        inside = (np.abs(_dot(rel, u)) <= hs[..., 0] + tol) & (
            np.abs(_dot(rel, v)) <= hs[..., 1] + tol
        )
        best = np.where(inside, np.minimum(best, np.abs(_dot(rel, n))), best)
    # The segment crossing the face between its end points (what the patent's S4 misses).
    h0, h1 = _dot(p0_ - c, n), _dot(p1_ - c, n)
    crosses = (h0 * h1 <= 0.0) & (h0 != h1)
    w = np.where(crosses, h0 / np.where(h0 != h1, h0 - h1, 1.0), 0.0)
    x = p0_ + (p1_ - p0_) * w[..., None] - c
    hit = (
        crosses
        & (np.abs(_dot(x, u)) <= hs[..., 0] + tol)
        & (np.abs(_dot(x, v)) <= hs[..., 1] + tol)
    )
    return np.where(hit, 0.0, best)


def capsule_rectangle_distance(
    p0: ArrayLike,
    p1: ArrayLike,
    radius: ArrayLike,
    center: ArrayLike,
    axes: ArrayLike,
    half_sizes: ArrayLike,
) -> FloatArray:
    """Return the distance (...,) [m] between a capsule's surface and a rectangle; <= 0 touching.

    Capsule: segment [p0, p1] (..., 3) swept by a ball of `radius` [m]. Rectangle: `center`
    (..., 3), `axes` (..., 2, 3) unit orthogonal edge directions, `half_sizes` (..., 2) [m].
    A negative value is minus the depth of the rectangle inside the capsule.
    """
    r = np.asarray(radius, dtype=float)
    if not np.all(np.isfinite(r)) or np.any(r < 0):
        raise InputError(f"radius must be finite and >= 0 m, got {r.ravel()[:4]}")
    return segment_rectangle_distance(p0, p1, center, axes, half_sizes) - r
