"""Inward offset curves built point by point (seed 004, Fig. 5), in a surface chart.

Each point q_j of the reference ring C_i is moved along its inward normal n_j by the
chart length l_j that corresponds to the 3D offset `distance` on the surface there
(l_j = distance / |J n_j|, J the face's chart-to-3D map), giving C_{i+1}(t_j). Fig. 5 then
keeps a new point only if its nearest point on C_i is its own foot point q_j, i.e. if it
is no closer than l_j to any other part of C_i: exactly the points where offsets of other
parts would cross it. Points closer than that (swallow-tails at bends tighter than l) are
dropped, and a tangle left where they were is cut to its largest simple loop, so rings
never cross. Where C_i turns away from the inside the nearest point stays at the corner
while the new curve steps on: the corner gets a fan of normals, an arc of radius l.
Spacing of the new points adapts to curvature the same way: foot points on C_i are
s (R - l)/R apart for new points s apart on a bend of radius R (closer on convex bends,
several per foot on concave ones); the caller resamples each ring at a fixed arc step.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray
from scipy.spatial import cKDTree
from shapely.geometry import LinearRing, LineString
from shapely.geometry.polygon import orient
from shapely.ops import polygonize, unary_union

from workbench.polishing.chart import SurfaceChart

F64 = NDArray[np.float64]


def resample_closed(ring: F64, ds: float) -> F64:
    """Return the closed polyline `ring` (n, 2) resampled at arc step <= ds, starting at ring[0]."""
    closed = np.vstack([ring, ring[:1]])
    seg = np.linalg.norm(np.diff(closed, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    n = max(int(np.ceil(s[-1] / ds)), 3)
    t = np.linspace(0.0, s[-1], n, endpoint=False)
    return np.stack([np.interp(t, s, closed[:, 0]), np.interp(t, s, closed[:, 1])], axis=1)


def inward_normals(ring: F64) -> F64:
    """Return unit inward normals (n, 2) of a counter-clockwise closed ring (n, 2)."""
    t = np.roll(ring, -1, axis=0) - np.roll(ring, 1, axis=0)
    t /= np.linalg.norm(t, axis=1, keepdims=True)
    return np.stack([-t[:, 1], t[:, 0]], axis=1)


def ring_area(ring: F64) -> float:
    """Return the signed area [m² of chart] of a closed ring (positive when counter-clockwise)."""
    x, y = ring[:, 0], ring[:, 1]
    return float(0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def _fans(ring: F64, nrm: F64, reach: float, ds: float) -> tuple[NDArray[np.int64], F64]:
    """Return (source index (m,), unit direction (m, 2)) of the offset candidates of each point.

    A point where the ring turns away from the inside (a reflex corner for an inward
    offset) gets a fan of directions from its incoming to its outgoing edge normal, so the
    offset follows the arc of radius l round it (Fig. 5: the nearest point stays at the
    corner while the new curve steps on); other points get their averaged normal."""
    t_in = ring - np.roll(ring, 1, axis=0)
    t_out = np.roll(ring, -1, axis=0) - ring
    t_in /= np.maximum(np.linalg.norm(t_in, axis=1, keepdims=True), 1e-300)
    t_out /= np.maximum(np.linalg.norm(t_out, axis=1, keepdims=True), 1e-300)
    a_in = np.arctan2(t_in[:, 0], -t_in[:, 1])  # angle of the inward normal (-t_y, t_x)
    turn = np.arctan2(
        t_in[:, 0] * t_out[:, 1] - t_in[:, 1] * t_out[:, 0], np.sum(t_in * t_out, axis=1)
    )
    # Right turns (turn < 0) fan out; a fan step of ds/4 along the arc of radius `reach`.
    gap = -turn * reach / (0.25 * ds)  # > 1 where neighbouring offsets would part by > ds/4
    k = np.where(gap > 1.0, np.ceil(gap).astype(np.int64) + 1, 1)
    src = np.repeat(np.arange(len(ring)), k)
    i = np.arange(k.sum()) - np.repeat(np.cumsum(k) - k, k)
    frac = i / np.maximum(np.repeat(k, k) - 1, 1)
    ang = np.repeat(a_in, k) + frac * np.repeat(turn, k)
    fan = np.stack([np.cos(ang), np.sin(ang)], axis=1)
    single = np.repeat(k == 1, k)
    fan[single] = nrm[src[single]]
    return src, fan


def offset_ring(chart: SurfaceChart, ring: F64, distance: float, ds: float) -> tuple[F64, F64, F64]:
    """Return (new_ring (m, 2), foot (m, 2), chart_offset (m,)) for the inward offset of `ring`.

    ring: counter-clockwise closed ring (n, 2) in chart coordinates [m], sampled at <= ds.
    distance: 3D offset on the surface [m]. The new ring is the largest loop of kept points,
    ordered as their foot points on `ring` (only the largest loop if the region splits);
    empty (0, 2) when nothing survives.
    """
    nrm = inward_normals(ring)
    face, _ = chart.locate(ring)
    inside = face >= 0
    # Points that fell just off the mesh (the boundary itself) use the nearest valid face's metric.
    if not inside.all():
        idx = np.nonzero(inside)[0]
        if len(idx) == 0:
            return np.zeros((0, 2)), np.zeros((0, 2)), np.zeros(0)
        near = idx[np.clip(np.searchsorted(idx, np.arange(len(ring))), 0, len(idx) - 1)]
        face = face[near]
    step = distance / chart.stretch(face, nrm)
    src, fan = _fans(ring, nrm, float(step.max()), ds)
    step = step[src]
    cand = ring[src] + step[:, None] * fan
    dist, _ = cKDTree(ring).query(cand)
    keep = dist >= 0.97 * step
    idx = np.nonzero(keep)[0]
    if len(idx) < 3:
        return np.zeros((0, 2)), np.zeros((0, 2)), np.zeros(0)
    # Kept points in their foot order; where dropped stretches leave a tangle (or the region
    # splits), the largest simple loop is kept.
    sel = idx
    new, foot, dist_ = cand[sel], ring[src[sel]], step[sel]
    if len(new) >= 4 and not LinearRing(new).is_simple:
        new, foot, dist_ = _untangle(new, foot, dist_)
    return new, foot, dist_


def _untangle(new: F64, foot: F64, dist: F64) -> tuple[F64, F64, F64]:
    """Return the ring cut to its largest simple loop (small loops left at crossings removed)."""
    merged = unary_union(LineString(np.vstack([new, new[:1]])))
    polys = list(polygonize(merged))
    if not polys:
        return np.zeros((0, 2)), np.zeros((0, 2)), np.zeros(0)
    best = orient(max(polys, key=lambda q: q.area), sign=1.0)
    pts = np.asarray(best.exterior.coords)[:-1]
    # Start where the old ring started, and keep each point's foot from its nearest old point.
    _, near = cKDTree(new).query(pts)
    start = int(np.argmin(near))
    pts, near = np.roll(pts, -start, axis=0), np.roll(near, -start)
    return pts, foot[near], dist[near]
