"""Tests of workbench/geometry/subdivide.py: long triangles split at their edge midpoints.

Twins: the area is kept (closed form, half the cross product, summed); every piece lies in
its source triangle (barycentric coordinates in [0, 1]); a recursive 1 -> 4 split written
here gives the same set of pieces.
"""

from __future__ import annotations

import numpy as np

from workbench.geometry.subdivide import split_long_triangles


def _area(tri: np.ndarray) -> float:
    return float(
        0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1).sum()
    )


def _edges(tri: np.ndarray) -> np.ndarray:
    return np.linalg.norm(tri - np.roll(tri, 1, axis=1), axis=2).max(axis=1)


def _recursive(t: np.ndarray, max_edge: float) -> list[np.ndarray]:
    if _edges(t[None])[0] <= max_edge:
        return [t]
    a, b, c = t
    ab, bc, ca = (a + b) / 2, (b + c) / 2, (c + a) / 2
    out = []
    for p in ((a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)):
        out += _recursive(np.array(p), max_edge)
    return out


def _key(tris) -> list:
    return sorted(tuple(np.round(np.sort(t.reshape(-1)), 9)) for t in tris)


def test_split_matches_recursion_keeps_area_and_stays_inside() -> None:
    rng = np.random.default_rng(0)
    tri = rng.uniform(0, 1, (12, 3, 3))
    out = split_long_triangles(tri, 0.3)
    assert np.all(_edges(out) <= 0.3)
    assert abs(_area(out) - _area(tri)) < 1e-12
    want = [p for t in tri for p in _recursive(t, 0.3)]
    assert _key(out) == _key(want)
    # every vertex of a piece is a convex combination of its source triangle's vertices
    for t in tri:
        M = np.c_[t, np.ones(3)].T  # barycentric solve in the triangle's affine hull
        pieces = [p for p in _recursive(t, 0.3)]
        for p in pieces:
            w, *_ = np.linalg.lstsq(M, np.c_[p, np.ones(3)].T, rcond=None)
            assert np.all(w >= -1e-9) and np.all(w <= 1 + 1e-9)


def test_short_triangles_are_kept_and_the_limit_stops_early() -> None:
    small = np.array([[[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0]]], float)
    assert np.array_equal(split_long_triangles(small, 0.5), small)
    big = np.array([[[0, 0, 0], [8, 0, 0], [0, 8, 0]]], float)
    out = split_long_triangles(big, 0.5, limit=20)
    assert len(out) == 16  # 1 -> 4 -> 16; the next round would pass 20
    assert abs(_area(out) - _area(big)) < 1e-9
    assert len(split_long_triangles(big, 0.5, rounds=1)) == 4
