"""TCP frames along a path and IK in one configuration (`robot_path.py`).

Twins: a brute-force search over the free turn about the tool axis; the robot's own FK;
per-pose `ik()` (every solution) for the branch check.
"""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError, PlanningError, UnreachableError
from workbench.kinematics import DHRobot
from workbench.kinematics.robot_library import preset_robot
from workbench.polishing.robot_path import solve_path_ik, tool_frames


def test_tool_frames_are_rotations_with_z_along_the_axis_and_x_nearest_the_reference() -> None:
    rng = np.random.default_rng(0)
    z = rng.normal(size=(50, 3))
    z /= np.linalg.norm(z, axis=1, keepdims=True)
    p = rng.normal(size=(50, 3))
    x_ref = np.array([0.3, -0.8, 0.2])
    T = tool_frames(p, z, x_ref)
    R = T[:, :3, :3]
    np.testing.assert_allclose(
        R @ R.transpose(0, 2, 1), np.broadcast_to(np.eye(3), R.shape), atol=1e-12
    )
    np.testing.assert_allclose(np.linalg.det(R), 1.0, atol=1e-12)
    np.testing.assert_allclose(T[:, :3, 2], z, atol=1e-12)
    np.testing.assert_allclose(T[:, :3, 3], p)
    # Brute force: turning x about z never brings it closer to x_ref.
    ang = np.linspace(-np.pi, np.pi, 3601)
    for Ti in T[:5]:
        x, y = Ti[:3, 0], Ti[:3, 1]
        best = np.max(np.cos(ang) * (x @ x_ref) + np.sin(ang) * (y @ x_ref))
        assert x @ x_ref >= best - 1e-9


def test_tool_frames_handle_an_axis_parallel_to_the_reference() -> None:
    T = tool_frames(np.zeros((2, 3)), np.array([[1.0, 0, 0], [0, 0, -1.0]]), np.array([1.0, 0, 0]))
    assert np.isfinite(T).all()
    np.testing.assert_allclose(T[0, :3, 2], [1, 0, 0])
    with pytest.raises(InputError, match="tool_z"):
        tool_frames(np.zeros((1, 3)), np.zeros((1, 3)), np.array([1.0, 0, 0]))
    with pytest.raises(InputError, match="points and tool_z"):
        tool_frames(np.zeros((2, 3)), np.zeros((3, 3)), np.array([1.0, 0, 0]))


def _line(robot: DHRobot, n: int = 40, x: float = 0.45) -> np.ndarray:
    """Flange poses along a 200 mm line, flange z down."""
    p = np.stack([np.full(n, x), np.linspace(-0.1, 0.1, n), np.full(n, 0.25)], axis=1)
    return tool_frames(p, np.tile([0.0, 0.0, -1.0], (n, 1)), np.array([1.0, 0.0, 0.0]))


def test_ik_in_one_configuration_reproduces_the_poses() -> None:
    robot = preset_robot("mz07")
    T = _line(robot)
    q0 = np.radians([0.0, 10.0, 10.0, 0.0, -70.0, 0.0])
    q, label = solve_path_ik(robot, T, q0)
    np.testing.assert_allclose(robot.fk(q), T, atol=1e-9)
    assert np.abs(np.diff(q, axis=0)).max() < 0.2
    # Every joint set is one of ik()'s solutions, and the same one by configuration: the
    # solution nearest it among all of ik()'s is itself (no flips between branches).
    for Ti, qi in zip(T, q, strict=True):
        sols = np.asarray(robot.ik_all(Ti), float)
        assert np.min(np.abs(sols - qi).max(axis=1)) < 1e-9
    assert "/" in label
    # From a start at any solution of the first pose, the path is the one-configuration path
    # that begins nearest it: of all the paths found from all the starts, none begins
    # nearer. That keeps the start's configuration, except where keeping it would turn a
    # wide joint a whole turn first (its nearest turn leaves the limits along the line).
    # Starts whose own branch leaves the limits along the line (the MZ07's J3 reaches 190 deg,
    # so the arm also reaches the first pose over its head with J1 near its 170 deg limit)
    # cannot be kept: the brute-force twin `_followable` tells them apart.
    found = [(qa, *solve_path_ik(robot, T, qa)) for qa in robot.ik_all(T[0])]
    kept = followable = 0
    for qa, qq, _ in found:
        nearest = min(float(np.linalg.norm(p[0] - qa)) for _, p, _ in found)
        assert np.linalg.norm(qq[0] - qa) <= nearest + 1e-9
        d = (qq[0] - qa + np.pi) % (2 * np.pi) - np.pi
        can = _followable(robot, T, qa)
        followable += can
        kept += bool(can and np.abs(d).max() < 1e-6)
    assert followable >= 4 and kept >= followable - 1 and len({lab for *_, lab in found}) > 1


def _followable(robot: DHRobot, T: np.ndarray, q: np.ndarray, step: float = 0.2) -> bool:
    """Brute force: from `q`, step to the nearest of ik_all()'s solutions of each next pose;
    True when every step is below `step` [rad] (the branch stays within the limits)."""
    for Ti in T[1:]:
        sols = np.asarray(robot.ik_all(Ti), float)
        if not len(sols):
            return False
        nxt = sols[np.argmin(np.abs(sols - q).max(axis=1))]
        if np.abs(nxt - q).max() > step:
            return False
        q = nxt
    return True


def test_unreachable_points_are_named() -> None:
    robot = preset_robot("mz07")
    T = _line(robot)
    T[7, :3, 3] = [2.0, 0.0, 0.25]
    labels = [f"process point {i + 1}" for i in range(len(T))]
    with pytest.raises(UnreachableError, match=r"process point 8 at \[2000.0, 0.0, 250.0\] mm"):
        solve_path_ik(robot, T, np.zeros(6), labels=labels)


def test_a_joint_jump_is_refused() -> None:
    robot = preset_robot("mz07")
    T = _line(robot, n=3)
    with pytest.raises(PlanningError, match="joint jump"):
        solve_path_ik(robot, T, np.radians([0, 10, 10, 0, -70, 0]), max_joint_step=1e-4)
