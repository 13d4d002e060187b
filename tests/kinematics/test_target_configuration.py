"""A stored configuration (branch and turns) selects exactly the joints it was taken from, checked
against brute force: every IK solution of the pose, labelled by an independent FK (pinocchio)."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from workbench.errors import UnreachableError
from workbench.kinematics.arm_configuration import ArmConfiguration, every_solution
from workbench.kinematics.pinocchio_dh import build_dh_model
from workbench.kinematics.robot_library import ROBOT_NAMES, preset_robot
from workbench.kinematics.target_configuration import (
    TargetConfiguration,
    solve_configuration,
    target_configuration,
)


def twin_configuration(
    robot, model: pin.Model, q: np.ndarray
) -> tuple[bool, bool, bool, tuple[int, ...]]:
    """The configuration from pinocchio's frames (`model`: the robot's twin) and the controller's
    joints, written out from the definitions (arm_configuration's docstring; turns: the
    controller's q - 360 k deg in (-180, 180])."""
    data = model.createData()
    pin.framesForwardKinematics(model, data, q)
    frame = {f: data.oMf[model.getFrameId(f)] for f in ("link_1", "link_2", "link_5")}
    x1 = frame["link_1"].rotation[:, 0]
    o1, o2, pc = (frame[f].translation for f in ("link_1", "link_2", "link_5"))
    front = float(pc @ x1) >= 0.0  # the base frame is the identity here
    elbow_up = float(np.cross(o2 - o1, pc - o2) @ np.cross([0.0, 0.0, 1.0], x1)) > 0.0
    qc_deg = np.degrees(robot.convention.to_controller(q))
    flip = qc_deg[4] * robot.convention.flip_sign > 0.0  # the vendor's flipped side of J5
    lim = np.degrees(robot.convention.limits_to_controller(robot.limits))
    wide = (lim[:, 0] < -180.0) | (lim[:, 1] > 180.0)
    turns = tuple(
        int(np.ceil((v - 180.0 - 1e-9) / 360.0)) if w else 0
        for v, w in zip(qc_deg, wide, strict=True)
    )
    return front, elbow_up, bool(flip), turns


@pytest.mark.parametrize("name", ROBOT_NAMES)
def test_every_solution_is_selected_back_by_its_configuration(name: str) -> None:
    robot = preset_robot(name)
    twin = build_dh_model(robot.dh, robot.limits, robot.max_velocity)
    rng = np.random.default_rng(11)
    lo, hi = robot.limits[:, 0] + 0.05, robot.limits[:, 1] - 0.05
    checked = 0
    for q0 in rng.uniform(lo, hi, size=(3, robot.dof)):
        T = robot.fk(q0)
        sols = every_solution(robot, T)  # the UR5e: 8 branches x 64 turns; 6 of them checked
        for q in sols[rng.permutation(len(sols))[:6]]:
            conf = target_configuration(robot, q)
            front, elbow, flip, turns = twin_configuration(robot, twin, q)
            assert conf == TargetConfiguration(ArmConfiguration(front, elbow, flip), turns)
            got = solve_configuration(robot, T, conf)
            assert np.max(np.abs(got - q)) < 1e-8  # the one solution with that label
            checked += 1
    assert checked >= 6


def test_a_configuration_the_pose_lacks_is_named_with_those_it_has() -> None:
    robot = preset_robot("irb1200_7_70")
    q = np.array([0.3, 0.2, 0.1, 0.4, 0.8, 0.2])
    T = robot.fk(q)
    conf = target_configuration(robot, q)
    far = TargetConfiguration(conf.arm, (0, 0, 0, 0, 0, 3))  # J6 has no third turn
    with pytest.raises(UnreachableError, match=r"moves\[2\].*J6 \+3 turns.*it has") as exc:
        solve_configuration(robot, T, far, where="program.moves[2].configuration")
    assert exc.value.field is None or "moves[2]" in str(exc.value)
    assert conf.label() in str(exc.value)
