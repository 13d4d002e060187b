"""The press-brake process of `Workbench.bending`: the sequence and grasp search and the
planned cycle, built from the project's `bending` section (SI through `BendingSpec.to_si`).

Orchestration only: it hands the project's SI values, the robot and the cell to
`workbench.pressbrake` (`cycle_plan`, `cycle_search`) and returns their results.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from workbench.batch import check_engine
from workbench.errors import InputError
from workbench.pressbrake.bend_eval import SweepContext
from workbench.pressbrake.cycle import BendingCycle
from workbench.pressbrake.cycle_path import CycleCell, CycleStep, T_world_part_on_die
from workbench.pressbrake.cycle_plan import CycleRobot, checked_press, default_steps
from workbench.pressbrake.cycle_search import search_cycles
from workbench.pressbrake.cycle_search import sweep_context as search_context
from workbench.pressbrake.die import DiePlacement
from workbench.pressbrake.die import die_part_pose as transfer_die_pose
from workbench.pressbrake.press import PressBrake
from workbench.pressbrake.sequencing import SearchResult, SearchSettings, SequencePlan
from workbench.pressbrake.transfer_plan import placements
from workbench.project.bending import BendingSI, BendStepSI

if TYPE_CHECKING:
    from workbench.service.bending import BendingService

Progress = Callable[[float, str], None]
F64 = NDArray[np.float64]


def press_of(si: BendingSI) -> PressBrake:
    """Return the project's press; InputError naming `bending.press` when there is none."""
    if si.press is None:
        raise InputError(
            "bending.press: the project has no press brake model; add one (punch, die, "
            "back-gauge, ram: see docs/sheetmetal.md) to plan the bending process"
        )
    return si.press


def cycle_robot(svc: BendingService) -> CycleRobot:
    """Return the project's robot in its cell, the press left out of the part's bodies."""
    wb = svc.wb
    setup = wb.setup
    return CycleRobot(
        wb.robot,
        setup.T_world_base,
        setup.T_flange_tcp,
        wb.checker,
        wb.collision_policy,
        svc.part_cell_bodies(),
    )


def sweep_context(svc: BendingService) -> SweepContext:
    """Return the search's context: the part, press, cell, robot and candidate grasps."""
    si, wb = svc.si(), svc.wb
    press = press_of(si)
    press = checked_press(svc.part, press)
    return search_context(
        si.part,
        svc.part,
        press,
        cycle_robot(svc),
        wb.setup.q0,
        wb.setup.tool_mesh,
        wb.setup.link_meshes,
        si.grasp_grid,
        T_world_blank=si.blank,
        T_world_pallet=si.transfer.T_world_pallet,
        lift=si.lift,
        approach=si.approach,
        T_world_regrip=si.regrip,
    )


def cycle_cell(svc: BendingService) -> CycleCell:
    """Return the cycle's cell from the project: press, stack, station, pallet, transfer."""
    si = svc.si()
    press = press_of(si)
    return CycleCell(
        checked_press(svc.part, press),
        si.blank,
        si.regrip,
        si.transfer.T_world_pallet,
        si.transfer.T_world_vias,
        si.approach,
        si.lift,
        si.follow,
        svc.wb.setup.q0,
        settle=svc.settle_time(close=True),
        release=svc.settle_time(close=False),
    )


def cycle_steps(svc: BendingService) -> list[CycleStep]:
    """Return the project's steps (grasp and station per bend), or the section's grasp for
    every bend at the first station that fits it."""
    si, part = svc.si(), svc.part
    if si.steps is not None:
        return [CycleStep(s.bend, s.grasp, s.station) for s in si.steps]
    return default_steps(part, si.grasp, press_of(si))


def plan_cycle(svc: BendingService, progress: Progress | None = None) -> BendingCycle:
    """Return the planned and checked cycle of the project's sequence and steps."""
    return cycle_robot(svc).check_cycle(svc.part, cycle_steps(svc), cycle_cell(svc), progress)


def die_placements(svc: BendingService) -> tuple[tuple[DiePlacement, ...], str]:
    """Return each bend on the die with one arm configuration, and its label: with a press,
    against its stop as `plan_cycle` plans it (the steps' grasps and stations, the cycle's
    inverse kinematics); without, on the section's die with its grasp (what Plan uses).
    UnreachableError names what the robot cannot reach."""
    si, setup = svc.si(), svc.wb.setup
    if si.press is None:
        return placements(setup, svc.part, si.die, svc.grasp, setup.q0)
    return cycle_robot(svc).die_placements(svc.part, cycle_steps(svc), cycle_cell(svc))


def die_part_pose(svc: BendingService, k: int) -> F64:
    """Return T_world_part (4, 4) [m] of bend k on the die (as `die_placements` puts it)."""
    si = svc.si()
    if si.press is None:
        return transfer_die_pose(svc.part, k, si.die, svc.grasp)
    return T_world_part_on_die(svc.part, k, cycle_steps(svc)[k], press_of(si))


def search(
    svc: BendingService,
    *,
    engine: str,
    address: str | None,
    time_limit: float | None,
    progress: Progress | None,
    cancel: Callable[[], bool] | None,
    settings: SearchSettings | None,
) -> SearchResult:
    """Return the ranked plans of the project's part; each is checked as a full cycle."""
    check_engine(engine, address)  # before the set-up: an unusable engine fails at once
    ctx = sweep_context(svc)
    return search_cycles(
        ctx,
        cycle_cell(svc),
        cycle_robot(svc),
        engine=engine,
        address=address,
        time_limit=time_limit,
        progress=progress,
        cancel=cancel,
        settings=settings,
    )


def steps_of(plan: SequencePlan) -> list[BendStepSI]:
    """Return a plan's steps (grasp and station per bend) in the project's SI form."""
    return [
        BendStepSI(b, g, s)
        for b, g, s in zip(plan.sequence, plan.grasps, plan.stations, strict=True)
    ]
