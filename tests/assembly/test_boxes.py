from __future__ import annotations

import fcl
import numpy as np

from workbench.assembly.boxes import box_triangle_overlap, boxes_overlap, obb_aabb_overlap
from workbench.geometry.transforms import rpy_to_matrix


def _fcl_boxes(c1, R1, h1, c2, R2, h2) -> bool:
    a = fcl.CollisionObject(fcl.Box(*(2 * h1)), fcl.Transform(R1, c1))
    b = fcl.CollisionObject(fcl.Box(*(2 * h2)), fcl.Transform(R2, c2))
    return fcl.collide(a, b, fcl.CollisionRequest(), fcl.CollisionResult()) > 0


def test_boxes_overlap_matches_fcl_on_random_boxes():
    rng = np.random.default_rng(0)
    n = 2000
    c1, c2 = rng.uniform(-1, 1, (n, 3)), rng.uniform(-1, 1, (n, 3))
    R1, R2 = (
        rpy_to_matrix(rng.uniform(-np.pi, np.pi, (n, 3))),
        rpy_to_matrix(rng.uniform(-np.pi, np.pi, (n, 3))),
    )
    h1, h2 = rng.uniform(0.05, 0.6, (n, 3)), rng.uniform(0.05, 0.6, (n, 3))
    ours = boxes_overlap(c1, R1, h1, c2, R2, h2)
    ref = np.array([_fcl_boxes(c1[i], R1[i], h1[i], c2[i], R2[i], h2[i]) for i in range(n)])
    assert 0.1 < ref.mean() < 0.8
    assert np.array_equal(ours, ref)


def test_obb_aabb_overlap_matches_general_test():
    rng = np.random.default_rng(1)
    n = 3000
    ca, cb = rng.uniform(-1, 1, (n, 3)), rng.uniform(-1, 1, (n, 3))
    R = rpy_to_matrix(rng.uniform(-np.pi, np.pi, (n, 3)))
    ours = obb_aabb_overlap(ca, R, 0.4, cb, 0.3)
    ref = boxes_overlap(ca, R, np.full(3, 0.4), cb, np.eye(3), np.full(3, 0.3))
    assert np.array_equal(ours, ref)


def test_box_triangle_overlap_matches_fcl():
    rng = np.random.default_rng(2)
    n = 1500
    centers = rng.uniform(-0.5, 0.5, (n, 3))
    tris = rng.uniform(-1, 1, (n, 3, 3))
    ours = box_triangle_overlap(centers, 0.25, tris)
    ref = []
    for i in range(n):
        m = fcl.BVHModel()
        m.beginModel(3, 1)
        m.addSubModel(tris[i], np.array([[0, 1, 2]], np.int32))
        m.endModel()
        a = fcl.CollisionObject(m, fcl.Transform())
        b = fcl.CollisionObject(fcl.Box(0.5, 0.5, 0.5), fcl.Transform(centers[i]))
        ref.append(fcl.collide(a, b, fcl.CollisionRequest(), fcl.CollisionResult()) > 0)
    ref = np.array(ref)
    assert 0.2 < ref.mean() < 0.9
    assert np.array_equal(ours, ref)
