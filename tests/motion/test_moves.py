"""Moves through IK: a gantry with a Z-Y-X wrist (two IK branches) stands in for the robot."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import PlanningError
from workbench.geometry.transforms import make_transform, matrix_to_rpy, rpy_to_matrix
from workbench.motion.moves import corner_poses, line_poses, plan_program, time_program
from workbench.motion.program import Move, Program
from workbench.motion.validation import validate_trajectory


class Gantry:
    """q = (x, y, z [m], yaw, pitch, roll [rad]); flange R = Rz(yaw) Ry(pitch) Rx(roll)."""

    name = "gantry"
    dof = 6
    is_analytic = False  # per-pose IK (two rows), no branches
    limits = np.array([[-2, 2]] * 3 + [[-np.pi, np.pi]] * 3, float)

    def fk(self, q):
        q = np.asarray(q, float)
        return make_transform(rpy_to_matrix(q[..., [5, 4, 3]]), q[..., :3])

    def ik(self, T, *, q_near=None):
        roll, pitch, yaw = matrix_to_rpy(T[:3, :3])
        wrap = lambda a: (a + np.pi) % (2 * np.pi) - np.pi  # noqa: E731
        a = np.array([*T[:3, 3], yaw, pitch, roll])
        b = np.array([*T[:3, 3], wrap(yaw + np.pi), wrap(np.pi - pitch), wrap(roll + np.pi)])
        return np.stack([a, b])


V, A, J = np.full(6, 1.0), np.full(6, 4.0), np.full(6, 40.0)


def _pose(xyz, rpy_deg):
    return make_transform(rpy_to_matrix(np.radians(rpy_deg)), xyz)


def test_gantry_ik_is_right():
    rng = np.random.default_rng(0)
    robot = Gantry()
    for q in rng.uniform(-1, 1, (50, 6)):
        for sol in robot.ik(robot.fk(q)):
            np.testing.assert_allclose(robot.fk(sol), robot.fk(q), atol=1e-12)


def test_linear_move_stays_on_the_line_with_one_branch():
    robot = Gantry()
    q0 = np.array([0.0, 0.0, 0.5, 0.1, 0.2, 0.3])
    target = _pose([0.4, 0.2, 0.3], np.degrees([0.5, -0.2, 0.4]))
    prog = Program("lin", (Move.linear(target, speed=0.2, name="L1"),))
    path = plan_program(robot, prog, q0, V, step=0.01)
    T = robot.fk(path.positions)
    p0, p1 = robot.fk(q0)[:3, 3], target[:3, 3]
    u = (p1 - p0) / np.linalg.norm(p1 - p0)
    off = (T[:, :3, 3] - p0) - ((T[:, :3, 3] - p0) @ u)[:, None] * u
    assert np.abs(off).max() < 1e-12  # every sample on the straight line
    np.testing.assert_allclose(T[-1], target, atol=1e-12)
    assert np.abs(np.diff(path.positions, axis=0)).max() < 0.05  # no branch flip
    tr = time_program(path, A, J)
    rep = validate_trajectory(tr, max_velocity=V, max_acceleration=A, max_jerk=J)
    assert rep.ok
    # TCP speed at most the programmed 0.2 m/s (checked by FK of dense samples)
    t, q, _, _ = tr.sample(0.002)
    x = robot.fk(q)[:, :3, 3]
    speed = np.linalg.norm(np.diff(x, axis=0), axis=1) / np.diff(t)
    assert speed.max() <= 0.2 * 1.02 and speed.max() > 0.1


def test_blend_leaves_line_before_corner_within_zone():
    robot = Gantry()
    q0 = np.array([0.0, 0.0, 0.5, 0.0, 0.0, 0.0])
    c, e = _pose([0.3, 0.0, 0.5], [0, 0, 0]), _pose([0.3, 0.3, 0.5], [0, 0, 0])
    prog = Program("blend", (Move.linear(c, zone=0.05, name="c"), Move.linear(e, name="e")))
    path = plan_program(robot, prog, q0, V, step=0.005)
    xyz = robot.fk(path.positions)[:, :3, 3]
    dist_to_corner = np.linalg.norm(xyz - c[:3, 3], axis=1)
    assert dist_to_corner.min() > 0.01  # the corner itself is not passed
    # near the corner every point lies inside the zone's square [0.25, 0.3] x [0, 0.05]
    near = dist_to_corner < 0.05
    assert np.all(xyz[near, 0] <= 0.3 + 1e-12) and np.all(xyz[near, 1] >= -1e-12)
    assert len(path.stop_indices) == 2  # start and the final fine point, not the corner
    tr = time_program(path, A, J)
    assert validate_trajectory(tr, max_velocity=V, max_acceleration=A, max_jerk=J).ok


def test_corner_curve_is_the_quadratic_bezier():
    a, c, b = _pose([0, 0, 0], [0, 0, 0]), _pose([1, 0, 0], [0, 0, 0]), _pose([1, 1, 0], [0, 0, 0])
    P = corner_poses(a, c, b, 0.1, 1.0)[:, :3, 3]
    s = np.arange(1, P.shape[0] + 1) / P.shape[0]
    np.testing.assert_allclose(P[:, 0], 2 * s * (1 - s) + s**2)
    np.testing.assert_allclose(P[:, 1], s**2)
    assert line_poses(a, c, 0.1, 1.0).shape == (10, 4, 4)


def test_joint_moves_exact_stops_and_speed_fraction():
    robot = Gantry()
    q0 = np.zeros(6)
    prog = Program(
        "ptp",
        (Move.joint(np.full(6, 0.5), speed=0.5, zone=0.01), Move.joint(np.full(6, 1.0), speed=0.5)),
    )
    path = plan_program(robot, prog, q0, V)
    assert path.stop_indices == (0, 2)
    tr = time_program(path, A, J)
    _, v, _ = tr.at(np.linspace(0, tr.duration, 500))
    assert np.abs(v).max() <= 0.5 + 1e-9


def test_flip_through_gimbal_lock_and_unreachable_name_the_point():
    robot = Gantry()
    q0 = np.array([0.0, 0.0, 0.5, 0.0, 1.3, 0.0])
    over = _pose([0.0, 0.0, 0.5], [0, 0, 0]) @ make_transform(
        rpy_to_matrix([0, np.radians(110), 0]), [0, 0, 0]
    )
    # With both branches the wrist passes pitch 90 deg smoothly on branch b ...
    path = plan_program(robot, Program("flip", (Move.linear(over, name="over"),)), q0, V)
    assert np.abs(np.diff(path.positions, axis=0)).max() < 0.1

    class OneBranch(Gantry):
        def ik(self, T, *, q_near=None):
            return super().ik(T)[:1]  # pitch within +-90 deg only: yaw and roll must flip by pi

    with pytest.raises(PlanningError, match=r"move 0 \(over\): point \d+ .*joint jump"):
        plan_program(OneBranch(), Program("flip", (Move.linear(over, name="over"),)), q0, V)

    class Short(Gantry):
        def ik(self, T, *, q_near=None):
            return np.zeros((0, 6)) if T[0, 3] > 0.2 else super().ik(T)

    far = _pose([0.4, 0.0, 0.5], np.degrees([0.0, 1.3, 0.0])[::-1])
    with pytest.raises(PlanningError, match="point .* unreachable"):
        plan_program(Short(), Program("far", (Move.linear(far, name="far"),)), q0, V)


def test_a_jump_from_the_moves_start_to_its_first_point_is_refused():
    """The first sample of a linear move is checked against the joints it starts from."""

    class OneBranch(Gantry):
        def ik(self, T, *, q_near=None):
            return super().ik(T)[:1]  # branch a only

    # The start in branch b (yaw, roll + pi, pitch mirrored): every sample of the line is
    # reached smoothly in branch a, but the first one only by flipping the wrist.
    q0 = np.array([0.0, 0.0, 0.5, 0.1 - np.pi, np.pi - 0.2, 0.3 - np.pi])
    target = _pose([0.1, 0.0, 0.5], np.degrees([0.3, 0.2, 0.1]))
    prog = Program("lin", (Move.linear(target, speed=0.2, name="L1"),))
    with pytest.raises(PlanningError, match=r"move 0 \(L1\): point 0 .*joint jump"):
        plan_program(OneBranch(), prog, q0, V, step=0.01)
    plan_program(Gantry(), prog, q0, V, step=0.01)  # with both branches it stays in b


def test_mz07_linear_and_blended_moves():
    kin = pytest.importorskip("workbench.kinematics")
    robot = kin.preset_robot("mz07")
    q0 = np.radians([0.0, 10.0, -10.0, 0.0, -60.0, 0.0])
    T0 = robot.fk(q0)
    T1 = T0.copy()
    T1[:3, 3] += [0.0, 0.15, -0.1]
    T2 = T1.copy()
    T2[:3, 3] += [0.1, 0.0, 0.0]
    prog = Program(
        "mz07",
        (Move.linear(T1, speed=0.3, zone=0.02, name="a"), Move.linear(T2, speed=0.3, name="b")),
    )
    vmax, amax, jmax = np.full(6, 2.0), np.full(6, 8.0), np.full(6, 60.0)
    path = plan_program(robot, prog, q0, vmax, step=0.005)
    T = robot.fk(path.positions)
    np.testing.assert_allclose(T[-1], T2, atol=1e-9)
    np.testing.assert_allclose(
        T[:, :3, :3], np.broadcast_to(T0[:3, :3], T[:, :3, :3].shape), atol=1e-9
    )
    assert np.abs(np.diff(path.positions, axis=0)).max() < 0.1  # one configuration throughout
    # first leg: on the line from T0 to T1 until 20 mm before the corner
    p = T[:, :3, 3]
    u = (T1[:3, 3] - T0[:3, 3]) / np.linalg.norm(T1[:3, 3] - T0[:3, 3])
    d0 = p - T0[:3, 3]
    along = d0 @ u
    first = along < np.linalg.norm(T1[:3, 3] - T0[:3, 3]) - 0.02 - 1e-9
    first &= path.move_index == 0
    off = d0[first] - along[first, None] * u
    assert first.sum() > 20 and np.abs(off).max() < 1e-9
    tr = time_program(path, amax, jmax, position_limits=robot.limits)
    rep = validate_trajectory(
        tr, max_velocity=vmax, max_acceleration=amax, max_jerk=jmax, position_limits=robot.limits
    )
    assert rep.ok
