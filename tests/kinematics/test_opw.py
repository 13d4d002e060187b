"""Analytic OPW IK: FK -> IK -> FK round trips (opw_kinematics style), batch vs single, branches."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.kinematics import DHRobot
from workbench.kinematics.numeric_ik import numeric_ik
from workbench.kinematics.opw import opw_geometry, solve_batch
from workbench.kinematics.opw_single import solve_single
from workbench.kinematics.presets import MZ07_DH
from workbench.kinematics.robot_library import preset_robot

TWO_PI = 2 * math.pi


@pytest.fixture(scope="module")
def robot() -> DHRobot:
    return preset_robot("mz07")


def angle_diff(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Max over the last axis of the angular distance modulo 2 pi."""
    return np.abs((a - b + math.pi) % TWO_PI - math.pi).max(axis=-1)


def pose_error(Ta: np.ndarray, Tb: np.ndarray) -> tuple[float, float]:
    """Return (position error m, rotation angle error rad) between two poses."""
    dp = float(np.linalg.norm(Ta[:3, 3] - Tb[:3, 3]))
    c = (np.trace(Ta[:3, :3].T @ Tb[:3, :3]) - 1) / 2
    s = np.linalg.norm(Ta[:3, :3].T @ Tb[:3, :3] - np.eye(3)) / math.sqrt(2)
    return dp, float(math.atan2(s, c))


def test_round_trip_1000_random_configurations(robot: DHRobot) -> None:
    rng = np.random.default_rng(0)
    Q = rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (1000, 6))
    T = robot.fk(Q)
    lo, hi = robot.limits[:, 0], robot.limits[:, 1]
    worst_p = worst_r = 0.0
    for q, Tq in zip(Q, T, strict=False):
        sols = robot.ik(Tq)
        assert 1 <= len(sols) <= 8
        assert np.all(sols >= lo) and np.all(sols <= hi)
        for s in sols:
            dp, dr = pose_error(robot.fk(s), Tq)
            worst_p, worst_r = max(worst_p, dp), max(worst_r, dr)
        # The original configuration is among the solutions, modulo the turn of joints 4, 6.
        assert angle_diff(sols, q).min() < 1e-9
    assert worst_p < 1e-9 and worst_r < 1e-9


def test_ik_all_contains_the_original_exactly(robot: DHRobot) -> None:
    rng = np.random.default_rng(1)
    Q = rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (200, 6))
    for q, Tq in zip(Q, robot.fk(Q), strict=False):
        sols = robot.ik_all(Tq)
        assert np.abs(sols - q).max(axis=1).min() < 1e-9
        np.testing.assert_allclose(
            robot.fk(sols), np.broadcast_to(Tq, sols.shape[:1] + (4, 4)), atol=1e-9
        )
        # Variants: joint 6 spans 720 deg, so every solution appears twice at least.
        assert len(sols) >= 2 * len(robot.ik(Tq))


def test_batch_equals_single(robot: DHRobot) -> None:
    rng = np.random.default_rng(2)
    Q = rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (500, 6))
    T = robot.fk(Q)
    qb, valid = robot.ik_batch(T)
    assert qb.shape == (500, 8, 6) and valid.shape == (500, 8)
    assert np.all(np.isnan(qb[~valid])) and not np.any(np.isnan(qb[valid]))
    for i in range(500):
        single = robot.ik(T[i])
        batch = qb[i][valid[i]]
        assert len(single) == len(batch)
        np.testing.assert_allclose(single, batch, atol=1e-12)
    # The raw solvers agree branch by branch.
    g = opw_geometry(robot.dh)
    assert g is not None
    theta, res = solve_batch(g, T[:50])
    for i in range(50):
        rows = np.array(solve_single(g, T[i]))
        ok = rows[:, 6] < 1e-9
        np.testing.assert_array_equal(ok, res[i] < 1e-9)
        np.testing.assert_allclose(angle_diff(rows[ok, :6], theta[i][ok]), 0.0, atol=1e-12)


def test_all_eight_branches_when_limits_allow() -> None:
    wide = DHRobot(MZ07_DH, np.tile([-TWO_PI, TWO_PI], (6, 1)))
    T = wide.fk(np.radians([10.0, 20.0, 60.0, 40.0, 50.0, 60.0]))  # wrist centre near the axis
    sols = wide.ik(T)
    assert len(sols) == 8
    qb, valid = wide.ik_batch(T[None])
    assert valid.all()
    # Eight distinct branches: shoulder, elbow and wrist each take two values.
    assert len({tuple(np.round(s, 6)) for s in sols}) == 8


def test_q_near_sorts_and_picks_turns(robot: DHRobot) -> None:
    q = np.radians([20.0, -30.0, 40.0, 170.0, -60.0, 300.0])
    T = robot.fk(q)
    sols = robot.ik(T, q_near=q)
    np.testing.assert_allclose(sols[0], q, atol=1e-9)  # nearest first, joint 6 at +300 deg
    d = np.linalg.norm(sols - q, axis=1)
    assert np.all(np.diff(d) >= 0)
    # Without q_near joint 6 takes the turn nearest 0: -60 deg.
    plain = robot.ik(T)
    assert np.any(np.abs(plain[:, 5] - math.radians(-60.0)) < 1e-9)
    qb, valid = robot.ik_batch(T[None], q_near=q)
    assert np.abs(qb[0][valid[0]] - q).max(axis=1).min() < 1e-9


def test_wrist_singular_pose_keeps_joint4_near_reference(robot: DHRobot) -> None:
    # theta5 = q5 + 90 deg = 0: joints 4 and 6 are aligned; only q4 + q6 matters.
    q = np.radians([10.0, -20.0, 30.0, 25.0, -90.0, 15.0])
    T = robot.fk(q)
    sols = robot.ik(T, q_near=q)
    for s in sols:
        np.testing.assert_allclose(robot.fk(s), T, atol=1e-9)
    np.testing.assert_allclose(sols[0], q, atol=1e-9)
    qb, valid = robot.ik_batch(T[None], q_near=q)
    assert valid.any()
    np.testing.assert_allclose(
        robot.fk(qb[0][valid[0]]), np.broadcast_to(T, (valid.sum(), 4, 4)), atol=1e-9
    )


def test_shoulder_singular_pose_wrist_centre_on_axis(robot: DHRobot) -> None:
    # Flange pointing along +x, wrist centre on the joint-1 axis at 0.8 m (q5 = 0).
    T = np.array(
        [[0.0, 0.0, 1.0, 0.078], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.8], [0, 0, 0, 1.0]]
    )
    sols = robot.ik(T)
    assert len(sols) >= 1
    np.testing.assert_allclose(robot.fk(sols), np.broadcast_to(T, (len(sols), 4, 4)), atol=1e-9)


def test_other_sign_conventions_and_offsets() -> None:
    # Same family with negative alphas, alpha2 = 180 deg, lateral offset and odd theta offsets.
    dh = np.array(
        [
            [0.3, 0.4, 0.1, -math.pi / 2],
            [-0.2, 0.05, 0.5, math.pi],
            [0.1, 0.02, -0.06, math.pi / 2],
            [0.4, 0.45, 0.0, -math.pi / 2],
            [-0.5, 0.0, 0.0, math.pi / 2],
            [0.25, 0.1, 0.0, 0.7],
        ]
    )
    r = DHRobot(dh, np.tile([-math.pi, math.pi], (6, 1)))
    assert r.is_analytic
    rng = np.random.default_rng(3)
    Q = rng.uniform(-math.pi, math.pi, (300, 6))
    T = r.fk(Q)
    qb, valid = r.ik_batch(T)
    for i in range(300):
        assert angle_diff(qb[i][valid[i]], Q[i]).min() < 1e-9
        got = r.fk(qb[i][valid[i]])
        np.testing.assert_allclose(got, np.broadcast_to(T[i], got.shape), atol=1e-9)


def test_analytic_solutions_are_complete_against_numeric_search(robot: DHRobot) -> None:
    # Slow twin: CLIK from many random seeds never finds a solution the analytic IK misses.
    model, data = robot.pinocchio_model()
    fid = model.getFrameId("flange")
    rng = np.random.default_rng(4)
    lo, hi = robot.limits[:, 0], robot.limits[:, 1]
    for q in rng.uniform(lo, hi, (6, 6)):
        T = robot.fk(q)
        found = numeric_ik(model, data, fid, T, rng.uniform(lo, hi, (12, 6)))
        assert len(found) >= 1
        ours = robot.ik_all(T)
        for f in found:
            assert np.abs(ours - f).max(axis=1).min() < 1e-5


def test_non_opw_rows_are_detected() -> None:
    assert opw_geometry(MZ07_DH) is not None
    ur_like = MZ07_DH.copy()
    ur_like[3, 2] = 0.1  # a4 != 0: wrist no longer spherical
    assert opw_geometry(ur_like) is None
    assert opw_geometry(MZ07_DH[:5]) is None


def test_batch_round_trip_over_several_chunks(robot: DHRobot) -> None:
    rng = np.random.default_rng(5)
    Q = rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (5000, 6))
    T = robot.fk(Q)
    qb, valid = robot.ik_batch(T, q_near=Q)
    # With q_near = the original, the original itself (turns included) is a valid row.
    assert np.all(np.nanmin(np.abs(qb - Q[:, None, :]).max(axis=-1), axis=1) < 1e-9)
    got = robot.fk(np.where(valid[..., None], qb, 0.0))
    assert np.abs(got - T[:, None])[valid].max() < 1e-9
    assert np.all(qb[valid] >= robot.limits[:, 0]) and np.all(qb[valid] <= robot.limits[:, 1])
