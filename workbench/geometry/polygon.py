"""Planar polygon helpers for flanges: area, clean-up, ear-clipping triangulation, minimum-area rectangle."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial import ConvexHull, QhullError


def signed_area(poly: NDArray[np.float64]) -> float:
    """Return the signed area [m²] of a polygon (n, 2); positive when counter-clockwise."""
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def clean_ring(
    points: ArrayLike, tol: float = 1e-9, keep: ArrayLike | None = None
) -> NDArray[np.float64]:
    """Return (n, 2) ring points without repeats or collinear vertices (except those in `keep`)."""
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    kept = np.zeros((0, 2)) if keep is None else np.asarray(keep, dtype=float).reshape(-1, 2)
    changed = True
    while changed and len(p) >= 3:
        changed = False
        keep_mask = np.linalg.norm(p - np.roll(p, -1, axis=0), axis=1) > tol
        if not keep_mask.all():
            p, changed = p[keep_mask], True
            continue
        prev, nxt = np.roll(p, 1, axis=0), np.roll(p, -1, axis=0)
        u, v = p - prev, nxt - p
        cross = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
        off = np.abs(cross) / np.maximum(np.linalg.norm(nxt - prev, axis=1), 1e-300)
        straight = (off < tol) & (np.sum(u * v, axis=1) > 0)
        if len(kept):
            near = np.linalg.norm(p[:, None, :] - kept[None, :, :], axis=2).min(axis=1)
            straight &= near > 10 * tol
        if straight.any():
            p, changed = np.delete(p, int(np.argmax(straight)), axis=0), True
    return p


def triangulate(poly: NDArray[np.float64]) -> NDArray[np.int64]:
    """Return (n - 2, 3) counter-clockwise vertex triples covering a simple CCW polygon (ear clipping)."""
    idx = list(range(len(poly)))
    tris: list[tuple[int, int, int]] = []

    def cross(o: int, a: int, b: int) -> float:
        return float(
            (poly[a, 0] - poly[o, 0]) * (poly[b, 1] - poly[o, 1])
            - (poly[a, 1] - poly[o, 1]) * (poly[b, 0] - poly[o, 0])
        )

    guard = 0
    while len(idx) > 3 and guard < 10 * len(poly) ** 2:
        guard += 1
        m = len(idx)
        for k in range(m):
            a, b, c = idx[k - 1], idx[k], idx[(k + 1) % m]
            if cross(a, b, c) <= 1e-18:
                continue  # reflex or degenerate corner
            inside = False
            for j in idx:
                if j in (a, b, c):
                    continue
                if cross(a, b, j) >= 0 and cross(b, c, j) >= 0 and cross(c, a, j) >= 0:
                    inside = True
                    break
            if not inside:
                tris.append((a, b, c))
                idx.pop(k)
                break
        else:
            break  # no ear found (degenerate input); fall back to a fan below
    if len(idx) > 3:
        tris.extend((idx[0], idx[i], idx[i + 1]) for i in range(1, len(idx) - 1))
    elif len(idx) == 3:
        tris.append((idx[0], idx[1], idx[2]))
    return np.array(tris, dtype=np.int64)


def min_area_rect(
    points: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Return (axes (2, 2) as columns, centre (2,), half sizes (2,)) [m] of the least-area enclosing rectangle."""
    try:
        hull = points[ConvexHull(points).vertices]
    except (QhullError, ValueError):
        hull = points
    edges = np.roll(hull, -1, axis=0) - hull
    lengths = np.linalg.norm(edges, axis=1)
    dirs = edges[lengths > 1e-15] / lengths[lengths > 1e-15, None]
    if len(dirs) == 0:
        dirs = np.array([[1.0, 0.0]])
    normals = np.stack([-dirs[:, 1], dirs[:, 0]], axis=1)
    pu, pv = hull @ dirs.T, hull @ normals.T  # (n, k)
    area = (pu.max(0) - pu.min(0)) * (pv.max(0) - pv.min(0))
    k = int(np.argmin(area))
    axes = np.stack([dirs[k], normals[k]], axis=1)
    lo = np.array([pu[:, k].min(), pv[:, k].min()])
    hi = np.array([pu[:, k].max(), pv[:, k].max()])
    return axes, axes @ ((lo + hi) / 2), (hi - lo) / 2
