"""The configuration a Cartesian target stores: its arm branch and the turns of its wide joints,
and the one IK solution of a pose they select.

A pose has up to eight arm branches (`ArmConfiguration`: front/back, elbow up/down, wrist
flip), and a joint whose range spans more than one turn (J4 and J6 of most arms, +-360 deg) can
reach each branch's angle once per turn. `TargetConfiguration` pins both down: the branch and,
per joint, its turn k (`ik_report.joint_turn_numbers`: the controller's q - 360 k deg lies in
(-180, 180], 0 for joints within one turn). It is what a program target taught, imported or
planned once keeps, so that the same pose always plans to the same joints, wherever the arm
was before (as a controller's confdata, Status/Turn or CONFIG do).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import UnreachableError
from workbench.kinematics.arm_configuration import (
    ArmConfiguration,
    arm_configuration,
    arm_configurations,
    every_solution,
)
from workbench.kinematics.ik_report import branch_names, joint_turn_numbers, wide_joints
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]

SAME_JOINTS = 1e-6
"""Solutions closer than this [rad] in every joint are one (a boundary tie of the IK)."""


@dataclass(frozen=True)
class TargetConfiguration:
    """An arm branch and the turn k of every joint (dof,): the controller's q_j - 360 k_j deg
    lies in (-180, 180]; joints within one turn have k = 0."""

    arm: ArmConfiguration
    turns: tuple[int, ...]

    def label(self) -> str:
        """Return 'front/elbow up/no flip, J6 +1 turn' (the jog panel's label of this solution)."""
        extra = [
            f"J{j + 1} {k:+d} turn{'s' if abs(k) > 1 else ''}"
            for j, k in enumerate(self.turns)
            if k != 0
        ]
        return ", ".join([self.arm.label(), *extra])


def target_configuration(model: RobotModel, q_model: ArrayLike) -> TargetConfiguration:
    """Return the `TargetConfiguration` of joints q (dof,) [rad, model convention]."""
    q = np.asarray(q_model, float).reshape(model.dof)
    turns = joint_turn_numbers(model, q)
    wide = set(wide_joints(model).tolist())
    return TargetConfiguration(
        arm_configuration(model, q),
        tuple(int(turns[j]) if j in wide else 0 for j in range(model.dof)),
    )


def solve_configuration(
    model: RobotModel,
    T_base_flange: ArrayLike,
    configuration: TargetConfiguration,
    *,
    q_near: ArrayLike | None = None,
    where: str = "target",
) -> FloatArray:
    """Return the IK solution (dof,) [rad, model] of a flange pose in `configuration`.

    Every solution of the pose (each branch at each turn the limits allow) whose branch and
    turns are the stored ones; where the IK gives several distinct ones (a singular wrist), the
    one nearest `q_near` (default: the first). UnreachableError names `where`, the stored
    configuration and the configurations the pose has.
    """
    sols = every_solution(model, T_base_flange)
    if len(sols) == 0:
        raise UnreachableError(f"{where}: the pose has no IK solution within the joint limits")
    arms = arm_configurations(model, sols)
    turns = joint_turn_numbers(model, sols)
    wide = wide_joints(model)
    want = np.asarray(configuration.turns, np.int64)
    keep = np.array(
        [
            a == configuration.arm and bool(np.all(t[wide] == want[wide]))
            for a, t in zip(arms, turns, strict=True)
        ]
    )
    found = sols[keep]
    if len(found) == 0:
        have = ", ".join(sorted(set(branch_names(model, sols))))
        raise UnreachableError(
            f"{where}: the pose has no IK solution in its stored configuration"
            f" {configuration.label()}; it has {have} (teach the target again, or clear its"
            " configuration so the next plan chooses one)"
        )
    if q_near is None or len(found) == 1:
        return np.asarray(found[0], float)
    d = np.linalg.norm(found - np.asarray(q_near, float), axis=1)
    return np.asarray(found[int(np.argmin(d))], float)
