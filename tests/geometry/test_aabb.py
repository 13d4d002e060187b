"""Tests of workbench/geometry/aabb.py: boxes of posed point sets, and their union.

Twin: the placed points computed one by one (R p + t) and the box taken by a Python loop.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.geometry.aabb import aabb_union, world_aabb


def test_world_aabb_matches_a_loop() -> None:
    rng = np.random.default_rng(0)
    for _ in range(20):
        pts = rng.normal(size=(int(rng.integers(1, 30)), 3))
        T = np.eye(4)
        T[:3, :3] = Rotation.random(random_state=int(rng.integers(1000))).as_matrix()
        T[:3, 3] = rng.normal(size=3)
        placed = [T[:3, :3] @ p + T[:3, 3] for p in pts]
        lo = [min(p[k] for p in placed) for k in range(3)]
        hi = [max(p[k] for p in placed) for k in range(3)]
        assert np.allclose(world_aabb(pts, T), [lo, hi])
        assert np.allclose(world_aabb(pts), [pts.min(axis=0), pts.max(axis=0)])


@pytest.mark.parametrize(
    ("points", "T", "text"),
    [
        (np.zeros((0, 3)), None, r"points: expected \(N, 3\) with N > 0, got \(0, 3\)"),
        (np.zeros((4, 2)), None, r"got \(4, 2\)"),
        (np.zeros(3), None, r"got \(3,\)"),
        (np.zeros((4, 3)), np.eye(3), r"T_world_local: expected \(4, 4\), got \(3, 3\)"),
    ],
)
def test_world_aabb_refuses_bad_shapes(points, T, text) -> None:
    with pytest.raises(ValueError, match=text):
        world_aabb(points, T)


def test_union() -> None:
    a = [[0, 0, 0], [1, 1, 1]]
    b = [[-1, 0.5, 0.2], [0.5, 2, 0.3]]
    assert aabb_union([a, b]).tolist() == [[-1, 0, 0], [1, 2, 1]]
    assert aabb_union(iter([a])).tolist() == a
    with pytest.raises(ValueError, match="at least one box"):
        aabb_union([])
