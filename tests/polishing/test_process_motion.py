"""The robot's motion along a polishing path (`process_motion.py`): IK in one configuration,
joint speeds from the feed, jerk-limited timing, the program of moves.

Twins: the robot's own FK; the per-segment speed formula in a loop; the trajectory's
velocity at the exact stops.
"""

from __future__ import annotations

import numpy as np
import pytest

from workbench.kinematics.robot_library import preset_robot
from workbench.motion.program import JOINT, LINEAR
from workbench.polishing.process_motion import ZONE, plan_process_motion, segment_speeds
from workbench.polishing.robot_path import tool_frames


def _tcp_line(n: int = 25) -> np.ndarray:
    p = np.stack([np.full(n, 0.45), np.linspace(-0.06, 0.06, n), np.full(n, 0.15)], axis=1)
    p[:2, 2] += [0.02, 0.01]  # two lead-in points above the line
    return tool_frames(p, np.tile([0.0, 0.0, -1.0], (n, 1)), np.array([1.0, 0.0, 0.0]))


def test_segment_speeds_move_the_tcp_at_the_feed_within_the_limits() -> None:
    rng = np.random.default_rng(1)
    q = np.cumsum(rng.normal(scale=0.02, size=(20, 6)), axis=0)
    tcp = np.cumsum(rng.uniform(0.001, 0.003, size=(20, 3)), axis=0)
    tcp[5] = tcp[4]  # a zero-length segment: joint speeds at the limit, not inf
    vmax = np.full(6, 2.0)
    v = segment_speeds(q, tcp, 0.03, vmax)
    for i in range(19):
        ds = max(float(np.linalg.norm(tcp[i + 1] - tcp[i])), 1e-9)
        for j in range(6):
            want = abs(q[i + 1, j] - q[i, j]) * 0.03 / ds
            assert v[i, j] == pytest.approx(min(max(want, 2e-3), 2.0), rel=1e-12)


def test_motion_follows_the_poses_in_one_configuration_with_one_move_per_point() -> None:
    robot = preset_robot("mz07")
    T_world_base = np.eye(4)
    T_world_base[:3, 3] = [0.0, 0.0, 0.05]
    T_flange_tcp = np.eye(4)
    T_flange_tcp[2, 3] = 0.1
    T_world_tcp = _tcp_line()
    q0 = np.radians([0.0, 10.0, 10.0, 0.0, -70.0, 0.0])
    m = plan_process_motion(robot, T_world_tcp, T_world_base, T_flange_tcp, q0, 0.02, n_lead=2)
    T_fk = T_world_base @ robot.fk(m.q) @ T_flange_tcp
    np.testing.assert_allclose(T_fk, T_world_tcp, atol=1e-9)
    assert "/" in m.configuration
    traj = m.trajectory
    pos, vel, _ = traj.at(traj.waypoint_times)
    np.testing.assert_allclose(pos, m.q, atol=1e-6)
    assert np.abs(vel[[0, 2, -1]]).max() < 1e-9  # exact stops: start, first process point, end
    moves = m.program.moves
    assert [mv.kind for mv in moves] == [JOINT] + [LINEAR] * (len(T_world_tcp) - 1)
    np.testing.assert_allclose(moves[0].target, m.q[0])
    T_base_tcp = np.linalg.inv(T_world_base) @ T_world_tcp
    for mv, T in zip(moves[1:], T_base_tcp[1:], strict=True):
        np.testing.assert_allclose(np.reshape(mv.target, (4, 4)), T, atol=1e-12)
        assert mv.speed == 0.02
    assert [mv.zone for mv in moves[1:]] == [0.0] + [ZONE] * (len(moves) - 3) + [0.0]
    assert m.sample_dt() == max(0.02, traj.duration / 600) and m.sample_dt(0.05) == 0.05
    assert m.validate_dt == max(0.01, traj.duration / 5000)
