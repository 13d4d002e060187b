"""The press-brake cycle set up for planning: the press checked against the part, the steps
a cycle takes when none are given, and the robot in its cell (`CycleRobot`) that plans and
checks a cycle (`cycle.check_cycle`) of any bend order.

SI units (m, rad, s).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.collision.plan_check import CollisionPolicy
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.errors import InputError
from workbench.kinematics.model import RobotModel
from workbench.pressbrake.airbend import short_flanges
from workbench.pressbrake.bend_eval import fitting_station
from workbench.pressbrake.bend_setup import Body
from workbench.pressbrake.cycle import BendingCycle, check_cycle, die_placements, waypoint_joints
from workbench.pressbrake.cycle_path import CycleCell, CycleStep
from workbench.pressbrake.die import DiePlacement
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.press import PressBrake
from workbench.sheetmetal.part import SheetMetalPart

F64 = NDArray[np.float64]
Progress = Callable[[float, str], None]


def checked_press(part: SheetMetalPart, press: PressBrake) -> PressBrake:
    """Return `press` after the part's fit on its die: InputError naming each flange too
    short to bridge the V-opening."""
    problems = short_flanges(part, press.die.v_opening)
    if problems:
        raise InputError("; ".join(problems))
    return press


def default_steps(part: SheetMetalPart, grasp: Grasp, press: PressBrake) -> list[CycleStep]:
    """Return one step per bend (sequence order): `grasp` throughout, each bend at the first
    station that fits its length."""
    return [
        CycleStep(b.name, grasp, fitting_station(press, float(part.bend_lengths[i])))
        for i, b in enumerate(part.bends)
    ]


def reordered(part: SheetMetalPart, sequence: Sequence[str]) -> SheetMetalPart:
    """Return `part` with its bends in the order of the bend names `sequence`."""
    names = [b.name for b in part.bends]
    order = [names.index(b) for b in sequence]
    return SheetMetalPart(part.thickness, list(part.flanges), [part.bends[i] for i in order])


@dataclass(frozen=True, eq=False)
class CycleRobot:
    """The robot in its cell as a cycle is planned with: model, base and TCP frames (4, 4)
    [m], its collision checker and policy (against the cell and the press) and the cell's
    colliding objects other than the press (world), which the part is checked against."""

    model: RobotModel
    T_world_base: F64
    T_flange_tcp: F64
    checker: RobotCollisionChecker
    policy: CollisionPolicy
    cell_bodies: list[Body]

    def check_cycle(
        self,
        part: SheetMetalPart,
        steps: list[CycleStep],
        cell: CycleCell,
        progress: Progress | None = None,
    ) -> BendingCycle:
        """Return the planned and checked cycle of `part` with `steps` (`cycle.check_cycle`)."""
        return check_cycle(
            part,
            steps,
            cell,
            model=self.model,
            T_world_base=self.T_world_base,
            T_flange_tcp=self.T_flange_tcp,
            checker=self.checker,
            policy=self.policy,
            cell_bodies=self.cell_bodies,
            progress=progress,
        )

    def die_placements(
        self, part: SheetMetalPart, steps: list[CycleStep], cell: CycleCell
    ) -> tuple[tuple[DiePlacement, ...], str]:
        """Return each bend against its stop as `check_cycle` plans it, and the arm
        configuration's label (`cycle.waypoint_joints`, `cycle.die_placements`)."""
        arm = (self.model, self.T_world_base, self.T_flange_tcp)
        path, q_wp, label = waypoint_joints(part, steps, cell, arm)
        return die_placements(part, path, q_wp, cell.press.T_world_die), label
