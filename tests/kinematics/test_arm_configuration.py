"""Arm configurations against brute force: every IK solution of a pose, told apart by branch and turns."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import UnreachableError
from workbench.kinematics import DHRobot
from workbench.kinematics.arm_configuration import (
    ArmConfiguration,
    arm_configuration,
    arm_configurations,
    every_solution,
    select_solution,
)
from workbench.kinematics.robot_library import preset_robot

DEG = np.pi / 180.0
QUARTER = np.pi / 2


def _quadrant_ranges(robot: DHRobot, q: np.ndarray) -> np.ndarray:
    """ABB-style ranges [rad, controller]: joints 1, 4, 6 in their quadrant, the others free."""
    lo = np.floor(robot.convention.to_controller(q) / QUARTER) * QUARTER
    rng = np.stack([lo, lo + QUARTER], axis=1)
    rng[[1, 2, 4]] = [-np.inf, np.inf]
    return rng


def test_branch_and_quadrants_select_the_planned_joints_among_every_solution() -> None:
    robot = preset_robot("mz07")
    rng = np.random.default_rng(7)
    Q = rng.uniform(robot.limits[:, 0] + 0.05, robot.limits[:, 1] - 0.05, size=(300, 6))
    confs = arm_configurations(robot, Q)
    seen = set()
    for q, c in zip(Q, confs, strict=True):
        T = robot.fk(q)
        sols = every_solution(robot, T)
        # brute force: the planned joints are among the solutions, and exactly the ones that
        # share its branch and quadrants
        assert np.min(np.max(np.abs(sols - q), axis=1)) < 1e-8
        got = select_solution(robot, T, c, _quadrant_ranges(robot, q))
        assert np.max(np.abs(got - q)) < 1e-8
        seen.add(c.label())
    assert len(seen) == 8  # every branch occurs in the sample


def test_configuration_of_the_upright_posture_and_its_mirror_images() -> None:
    robot = preset_robot("mz07")
    # model convention: upper arm vertical, forearm reaching forward, wrist bent 30 deg
    q = np.array([0.0, 0.0, 0.0, 0.0, -60.0, 0.0]) * DEG
    F = robot.link_transforms(q)
    assert F[5, 0, 3] > 0.3  # the wrist centre is well in front of axis 1
    assert abs(F[2, 0, 3] - F[1, 0, 3]) < 1e-9  # the upper arm is vertical
    c = arm_configuration(robot, q)
    assert c.front and c.elbow_up
    assert c.wrist_flip == bool(robot.convention.to_controller(q)[4] < 0)
    # turned half a turn about axis 1 with the shoulder leaning back: the same wrist centre
    # height, now behind axis 1
    back = arm_configuration(robot, q + np.array([180.0, 0, 0, 0, 0, 0]) * DEG)
    assert back.elbow_up and back.front  # still in front of its own shoulder direction


def test_a_configuration_the_pose_lacks_names_the_target_and_what_exists() -> None:
    robot = preset_robot("mz07")
    q = np.array([10.0, -20.0, 30.0, 40.0, -60.0, 20.0]) * DEG
    sols = every_solution(robot, robot.fk(q))
    have = {arm_configuration(robot, s) for s in sols}
    missing = [
        ArmConfiguration(f, e, w)
        for f in (True, False)
        for e in (True, False)
        for w in (True, False)
        if ArmConfiguration(f, e, w) not in have
    ]
    if not missing:
        pytest.skip("every branch reaches this pose")
    with pytest.raises(UnreachableError, match="p_x.*no IK solution in the stored configuration"):
        select_solution(robot, robot.fk(q), missing[0], where="p_x")


def test_without_turn_data_a_wide_joint_is_ambiguous_and_says_so() -> None:
    robot = preset_robot("mz07")
    q = np.array([10.0, -20.0, 30.0, 40.0, -60.0, 20.0]) * DEG
    with pytest.raises(UnreachableError, match="does not select one"):
        select_solution(robot, robot.fk(q), arm_configuration(robot, q))
