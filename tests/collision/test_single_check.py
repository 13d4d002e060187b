"""One configuration (jogging, the gizmo): the scalar DH chain against the batched one and
pinocchio, and the fast `CollisionEngine.check` against the exact checker (issue 14 part 3)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest
from block_cell import block_cell

from workbench.collision.engine import CollisionEngine
from workbench.kinematics.dh_chain import dh_frames, dh_frames_one
from workbench.kinematics.dh_robot import DHRobot
from workbench.kinematics.presets import MZ07_DH, MZ07_LIMITS
from workbench.service import Workbench

PROJECT = block_cell(
    {"name": "post", "shape": "cylinder", "radius": 60, "height": 900,
     "pose": {"xyz": [0, -550, 450]}}
)  # fmt: skip


def test_scalar_chain_equals_the_batched_chain_and_pinocchio() -> None:
    robot = DHRobot(MZ07_DH, MZ07_LIMITS)
    model, data = robot.pinocchio_model()
    rng = np.random.default_rng(3)
    for q in rng.uniform(-np.pi, np.pi, (200, 6)):
        one = dh_frames_one(robot.dh.tolist(), q.tolist())
        np.testing.assert_allclose(one, dh_frames(robot.dh, q[None])[0], atol=1e-12)
        # link_transforms takes the scalar path for (6,) and (1, 6), the batched one for more.
        np.testing.assert_array_equal(robot.link_transforms(q), one)
        np.testing.assert_array_equal(robot.link_transforms(q[None])[0], one)
        pin.forwardKinematics(model, data, q)
        for i in range(1, 7):  # pinocchio's joint i turns about DH frame i-1's z axis
            np.testing.assert_allclose(one[i - 1][:3, 3], data.oMi[i].translation, atol=1e-12)
            np.testing.assert_allclose(one[i - 1][:3, 2], data.oMi[i].rotation[:, 2], atol=1e-12)
        np.testing.assert_allclose(one[6], robot.fk(q), atol=1e-12)  # pinocchio's flange
    qs = rng.uniform(-np.pi, np.pi, (5, 6))
    np.testing.assert_allclose(
        robot.link_transforms(qs), np.stack([dh_frames_one(robot.dh.tolist(), x) for x in qs.tolist()]),
        atol=1e-12,
    )  # fmt: skip


@pytest.fixture(scope="module")
def post_cell(engine_cache: Path) -> tuple[Workbench, CollisionEngine]:
    wb = Workbench.from_dict(PROJECT)
    eng = CollisionEngine(
        wb.checker, "spheres", spheres_per_link=4, resolution=32, cache_dir=str(engine_cache)
    )
    return wb, eng


def test_single_check_equals_the_exact_check(post_cell: tuple[Workbench, CollisionEngine]) -> None:
    """Twin: python-fcl (meshes plus containment) at 300 configurations near the cell, free
    and colliding, self pairs included: the same verdict; a free configuration's clearance is
    a lower bound of fcl's distance, within the pair tables' tolerance."""
    wb, eng = post_cell
    rng = np.random.default_rng(5)
    lim = wb.robot.limits
    qs = rng.uniform(lim[:, 0], lim[:, 1], (300, 6))
    qs[:, 1:3] = rng.uniform(-1.2, 1.2, (300, 2))
    hits = 0
    for q in qs:
        got, want = eng.check(q), wb.checker.check(q)
        assert got.colliding == want.in_collision, q
        if got.colliding:
            hits += 1
            assert (got.link, got.obstacle) in set(want.colliding)
        else:
            assert 0.0 <= got.clearance <= want.min_distance + 1e-9
    assert 20 < hits < 280  # both kinds


def test_containment_of_one_configuration_equals_the_batched_test(
    post_cell: tuple[Workbench, CollisionEngine],
) -> None:
    wb, eng = post_cell
    rng = np.random.default_rng(6)
    lim = wb.robot.limits
    qs = rng.uniform(lim[:, 0], lim[:, 1], (200, 6))
    batched = eng.contained(qs)
    one = np.stack([eng.containment.contained_one(eng.poses(q[None])[0]) for q in qs])
    np.testing.assert_array_equal(one, batched)
    assert batched.any()  # some probe does fall inside (adjacent links overlap)


def test_items_of_one_configuration_equal_the_batched_items(
    post_cell: tuple[Workbench, CollisionEngine],
) -> None:
    """Twin: `SpheresMode.items_one` (one gather, the fused field look-up, one pair norm)
    against the batched `items` at 200 configurations: the same values to rounding, hence
    the same flagged groups."""
    wb, eng = post_cell
    rng = np.random.default_rng(7)
    lim = wb.robot.limits
    qs = rng.uniform(lim[:, 0], lim[:, 1], (200, 6))
    batched = eng.items(qs)[0]
    one = np.stack([eng.checker.items_one(eng.bodies.poses_one(q)) for q in qs])
    np.testing.assert_allclose(one, batched, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(one <= 0, batched <= 0)
    assert (batched <= 0).any() and (batched > 0).any()


def test_fast_field_query_equals_the_checked_query(
    post_cell: tuple[Workbench, CollisionEngine],
) -> None:
    """Twin: `SparseSDF.query_fast` against `query` in the band, in far blocks and outside
    the grid (where it hands over to `query`)."""
    _, eng = post_cell
    sdf = eng.sdf
    assert sdf is not None
    lo, hi = sdf.mesh_bounds
    rng = np.random.default_rng(8)
    inside = rng.uniform(lo, hi, (5000, 3))
    np.testing.assert_allclose(sdf.query_fast(inside), sdf.query(inside), rtol=0, atol=1e-12)
    near = inside[np.abs(sdf.query(inside)) < sdf.band]
    assert len(near) > 100
    np.testing.assert_allclose(sdf.query_fast(near[:42]), sdf.query(near[:42]), rtol=0, atol=1e-12)
    wide = rng.uniform(lo - 1.0, hi + 1.0, (2000, 3))
    np.testing.assert_array_equal(sdf.query_fast(wide), sdf.query(wide))
