"""Tests of workbench/motion/program.py: a motion program's moves refuse bad input; where a
program without start joints starts (`program_start`), and pose targets solved in their
stored configuration (`pose_joints`), against every IK solution of the pose."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.kinematics.arm_configuration import every_solution
from workbench.kinematics.robot_library import preset_robot
from workbench.kinematics.target_configuration import (
    TargetConfiguration,
    target_configuration,
)
from workbench.motion.program import Move, Program, program_start

ROBOT = preset_robot("irb1200_7_70")
Q_FILE = np.radians([0.0, 10.0, 10.0, 0.0, 60.0, 0.0])  # the joints a project file stores


@dataclass
class Item:
    """A program move as `motion_program` reads it."""

    type: str
    joints: np.ndarray | None = None
    T_world_tcp: np.ndarray | None = None
    configuration: TargetConfiguration | None = None
    name: str = ""
    speed: float = 1.0
    zone: float = 0.0
    wobj: str = "base"


def _start(*items: Item) -> np.ndarray:
    return program_start(list(items), ROBOT, np.eye(4), np.eye(4), Q_FILE)


def test_a_pose_starts_in_its_configuration_else_nearest_the_files_joints() -> None:
    q = np.radians([20.0, 30.0, -10.0, 40.0, 50.0, 60.0])
    T = ROBOT.fk(q)
    sols = every_solution(ROBOT, T)
    nearest = sols[np.argmin(np.linalg.norm(sols - Q_FILE, axis=1))]  # brute force
    home = Item("joint", joints=Q_FILE)
    assert np.allclose(_start(Item("joint", T_world_tcp=T), home), nearest, atol=1e-9)
    for s in sols[:: max(1, len(sols) // 5)]:  # each stored configuration: its own solution
        conf = target_configuration(ROBOT, s)
        got = _start(Item("linear", T_world_tcp=T, configuration=conf), home)
        assert np.allclose(got, s, atol=1e-9)


def test_a_joint_target_first_is_the_start_and_one_move_alone_is_refused() -> None:
    q = np.radians([5.0, 0.0, 0.0, 0.0, 30.0, 0.0])
    assert np.array_equal(_start(Item("joint", joints=q), Item("joint", joints=Q_FILE)), q)
    with pytest.raises(InputError, match="does not move") as exc:
        _start(Item("joint", joints=q))
    assert exc.value.field == "program.start"


def test_bad_program_inputs():
    with pytest.raises(InputError, match="speed"):
        Move.joint(np.zeros(6), speed=1.5)
    with pytest.raises(InputError, match="zone"):
        Move.joint(np.zeros(6), zone=-0.01)
    with pytest.raises(InputError, match="target"):
        Move.joint(np.zeros(5))
    with pytest.raises(InputError, match="rotation"):
        Move.linear(np.diag([1.0, 1.0, -1.0, 1.0]))
    with pytest.raises(InputError, match="name"):
        Program("2bad name", (Move.joint(np.zeros(6)),))
