"""A pose target's stored arm configuration in the project file: the IK branch and the turns of
the joints whose range exceeds +-180 deg (`kinematics.target_configuration`).

In the file: ``"configuration": {"front": true, "elbow_up": true, "wrist_flip": false,
"turns": {"J6": 1}}``; a joint left out of `turns` is on turn 0 (its controller value in
(-180, 180] deg), turn k puts it in (-180 + 360 k, 180 + 360 k] deg. It is set when a target is
taught (from the robot's joints), imported (from the program's confdata, Status/Turn or
CONFIG) or first planned, and every plan then solves the target in it.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated

import numpy as np
from pydantic import Field, StringConstraints

from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.kinematics.robot_library import LIBRARY
from workbench.kinematics.target_configuration import TargetConfiguration
from workbench.project import bounds as B
from workbench.project.common import StrictModel, field_error

if TYPE_CHECKING:
    from workbench.project.models import Project

MAX_TURNS = math.ceil((B.JOINT_DEG - 180.0) / 360.0)
"""The largest turn number a joint within the file's joint range (+-720 deg) can have."""
JointName = Annotated[str, StringConstraints(pattern=r"^J([1-9]|1[0-6])$")]
Turn = Annotated[int, Field(ge=-MAX_TURNS, le=MAX_TURNS)]


class ConfigurationSpec(StrictModel):
    """The arm configuration a pose target is solved in: branch flags and turns per joint."""

    front: bool  # the wrist centre in front of axis 1
    elbow_up: bool  # the forearm bends upward from the upper arm
    wrist_flip: bool  # J5 on the side the vendor calls flipped (ABB/KUKA/NACHI: negative)
    turns: dict[JointName, Turn] = Field(default_factory=dict)  # {"J6": 1}; absent: turn 0

    def to_si(self, dof: int) -> TargetConfiguration:
        """Return the configuration with a turn for each of `dof` joints."""
        turns = [0] * dof
        for name, k in self.turns.items():
            j = int(name[1:]) - 1
            if j < dof:
                turns[j] = int(k)
        return TargetConfiguration(
            ArmConfiguration(self.front, self.elbow_up, self.wrist_flip), tuple(turns)
        )

    @classmethod
    def of(cls, conf: TargetConfiguration) -> ConfigurationSpec:
        """Return the file's form of a configuration (turn-0 joints left out)."""
        return cls(
            front=conf.arm.front,
            elbow_up=conf.arm.elbow_up,
            wrist_flip=conf.arm.wrist_flip,
            turns={f"J{j + 1}": k for j, k in enumerate(conf.turns) if k != 0},
        )

    def label(self) -> str:
        """Return 'front/elbow up/no flip, J6 +1 turn'."""
        return self.to_si(B.MAX_DOF).label()


def _controller_limits_deg(project: Project) -> np.ndarray | None:
    robot = project.robot
    if robot.preset is not None:
        return np.asarray(LIBRARY[robot.preset].controller_limits_deg, float)
    if robot.dh is not None:
        return np.array([[r.min, r.max] for r in robot.dh], float)
    return None  # a URDF: its limits are known once loaded; the plan checks the turns


def check_turns(project: Project) -> None:
    """Raise a validation error at `program.moves[k].configuration.turns.Jn` where a turn names
    a joint the robot lacks, or lies outside the joint's limits (a joint whose range lies
    within +-180 deg has turn 0 only)."""
    program, limits = project.program, _controller_limits_deg(project)
    if program is None or limits is None:
        return
    for k, item in enumerate(program.moves):
        conf = getattr(item, "configuration", None)
        for name, turn in (conf.turns if conf is not None else {}).items():
            loc = ("program", "moves", k, "configuration", "turns", name)
            j = int(name[1:]) - 1
            if j >= len(limits):
                msg = f"the robot has {len(limits)} joints; remove {name}"
                raise field_error([(loc, msg, turn)])
            lo, hi = limits[j]
            # turn k: the controller's value in (-180 + 360 k, 180 + 360 k] deg
            k_lo, k_hi = math.ceil((lo - 180.0) / 360.0), math.ceil((hi + 180.0) / 360.0) - 1
            if not k_lo <= turn <= k_hi:
                allowed = (
                    "only turn 0 (leave it out)" if k_lo == k_hi == 0 else f"turns {k_lo} to {k_hi}"
                )
                msg = f"turn {turn} is outside {name}'s limits [{lo:g}, {hi:g}] deg: {allowed}"
                raise field_error([(loc, msg, turn)])
