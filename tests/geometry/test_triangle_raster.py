"""Plane-slab rasters against brute force over every grid point of the triangle's box."""

from __future__ import annotations

import numpy as np

from workbench.geometry.distance import point_triangle_distance2
from workbench.geometry.triangle_raster import (
    band_points,
    plane_slabs,
    slab_point_counts,
    slab_points,
    triangle_box_overlap,
)


def _triangles(rng: np.random.Generator, n: int) -> np.ndarray:
    """Random triangles with axis-aligned, large, sliver and degenerate ones mixed in."""
    tri = rng.uniform(-1, 1, (n, 3, 3))
    tri[:10, :, 2] = 0.3  # in a grid-aligned plane
    tri[10:15, 2] = tri[10:15, 0]  # two equal vertices
    tri[15:20, 2] = (tri[15:20, 0] + tri[15:20, 1]) / 2  # collinear
    tri[20:25, 2] = tri[20:25, 1] + 1e-7 * rng.normal(size=(5, 3))  # slivers
    tri[25:30] *= 0.02  # small
    return tri


def _box(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    axes = [np.arange(lo[k], hi[k] + 1) for k in range(3)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)


def _grid(tri: np.ndarray, reach: float):
    origin, step = np.array([-1.3, -1.2, -1.1]), 0.05
    dims = np.array([52, 50, 49])
    lo = np.clip(np.ceil((tri.min(1) - reach - origin) / step).astype(int), 0, dims - 1)
    hi = np.clip(np.floor((tri.max(1) + reach - origin) / step).astype(int), 0, dims - 1)
    return origin, step, lo, hi


def test_band_points_find_every_point_within_reach_with_exact_distances() -> None:
    rng = np.random.default_rng(0)
    tri = _triangles(rng, 120)
    reach = 0.07
    origin, step, lo, hi = _grid(tri, reach)
    got: dict[tuple[int, int, int, int], float] = {}
    for t, i0, i1, i2, d2 in band_points(tri, lo, hi, origin, step, reach, 3.0, budget=3000):
        keys = zip(t.tolist(), i0.tolist(), i1.tolist(), i2.tolist(), strict=True)
        got.update(zip(keys, d2.tolist(), strict=True))
    near_total = 0
    for t in range(len(tri)):
        g = _box(lo[t], hi[t])
        p = origin + g * step
        d2 = point_triangle_distance2(p, *(np.broadcast_to(tri[t, k], p.shape) for k in range(3)))
        keys = [(t, *q) for q in g.tolist()]
        # Twin: every point of the box within reach is yielded ...
        near = d2 <= reach * reach
        near_total += int(near.sum())
        assert all(keys[i] in got for i in np.flatnonzero(near))
        # ... and the distances given (NaN: the caller computes them) are the exact ones.
        for i, key in enumerate(keys):
            if key in got and not np.isnan(got[key]):
                assert abs(got[key] - d2[i]) <= 1e-12
    assert near_total > 10_000
    # Only the degenerate and sliver triangles (10-24) leave distances to the caller.
    nan_tri = {key[0] for key, d in got.items() if np.isnan(d)}
    assert nan_tri <= set(range(10, 25)) and {10, 15} <= nan_tri
    # And far fewer points than the boxes hold.
    assert len(got) < 0.5 * sum(len(_box(lo[t], hi[t])) for t in range(len(tri)))


def test_slab_points_keep_every_cube_the_separating_axis_test_accepts() -> None:
    rng = np.random.default_rng(1)
    tri = _triangles(rng, 120)
    half = 0.06
    origin, step, lo, hi = _grid(tri, half)
    normal, offset, slab = plane_slabs(tri, half, cube=True, scale=3.0)
    counts = slab_point_counts(lo, hi, normal, slab, step)
    got = set()
    per = np.zeros(len(tri))
    for t, i0, i1, i2 in slab_points(lo, hi, normal, offset, slab, origin, step, budget=3000):
        got.update(zip(t.tolist(), i0.tolist(), i1.tolist(), i2.tolist(), strict=True))
        np.add.at(per, t, 1)
    assert np.all(per <= counts)
    hits = 0
    for t in range(len(tri)):
        g = _box(lo[t], hi[t])
        centre = origin + g * step
        v = np.broadcast_to(tri[t], (len(g), 3, 3))
        ok = triangle_box_overlap(v[:, 0], v[:, 1], v[:, 2], centre, half)
        hits += int(ok.sum())
        assert all((t, *q) in got for q in g[ok].tolist())
    assert hits > 5000 and len(got) < 0.6 * sum(len(_box(lo[t], hi[t])) for t in range(len(tri)))
