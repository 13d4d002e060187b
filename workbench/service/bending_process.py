"""The press-brake process of `Workbench.bending`: the sequence and grasp search and the
planned cycle, built from the project's `bending` section (SI through `BendingSpec.to_si`).

Orchestration only: it hands the project's SI values, the robot and the cell to
`workbench.sheetmetal` (`sequencing.find_sequences`, `cycle.check_cycle`) and returns their
results.
"""

from __future__ import annotations

import uuid
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from workbench.batch import check_engine
from workbench.collision.plan_check import shared_engine
from workbench.errors import InputError
from workbench.pressbrake.airbend import short_flanges
from workbench.pressbrake.bend_eval import Reach, SweepContext, fitting_station
from workbench.pressbrake.cycle import BendingCycle, PartScene, check_cycle
from workbench.pressbrake.cycle_path import CycleCell, CycleStep
from workbench.pressbrake.grasp_grid import grasp_grid
from workbench.pressbrake.press import PressBrake
from workbench.pressbrake.sequencing import (
    Rejected,
    SearchResult,
    SearchSettings,
    SequencePlan,
    find_sequences,
)
from workbench.project.bending import BendingSI, BendStepSI

if TYPE_CHECKING:
    from workbench.service.bending import BendingService

Progress = Callable[[float, str], None]


def press_of(si: BendingSI) -> PressBrake:
    """Return the project's press; InputError naming `bending.press` when there is none."""
    if si.press is None:
        raise InputError(
            "bending.press: the project has no press brake model; add one (punch, die, "
            "back-gauge, ram: see docs/sheetmetal.md) to plan the bending process"
        )
    return si.press


def checked_press(svc: BendingService) -> PressBrake:
    """Return the press after the part's fit on its die: InputError naming each flange too
    short to bridge the V-opening."""
    press = press_of(svc.si())
    problems = short_flanges(svc.part, press.die.v_opening)
    if problems:
        raise InputError("; ".join(problems))
    return press


def sweep_context(svc: BendingService) -> SweepContext:
    """Return the search's context: the part, press, cell, robot and candidate grasps."""
    wb = svc.wb
    si = svc.si()
    press = checked_press(svc)
    setup = wb.setup
    reach = Reach.of(
        wb.robot,
        setup.T_world_base,
        setup.T_flange_tcp,
        wb.joints,
        setup.tool_mesh,
        setup.link_meshes,
    )
    part = svc.part
    g = si.grasp_grid
    try:
        grasps = grasp_grid(part, spacing=g.spacing, inset=g.inset, yaws=g.yaws, faces=g.faces)
    except InputError as exc:
        raise InputError(f"bending.grasp_grid: {str(exc).removeprefix('grasp grid: ')}") from None
    return SweepContext(
        si.part,
        press,
        tuple(svc.part_cell_bodies()),
        reach,
        tuple(grasps),
        key=uuid.uuid4().hex,
        T_world_blank=si.blank,
        T_world_pallet=si.transfer.T_world_pallet,
        lift=si.lift,
        approach=si.approach,
        T_world_regrip=si.regrip,
    )


def cycle_cell(svc: BendingService) -> CycleCell:
    """Return the cycle's cell from the project: press, stack, station, pallet, transfer."""
    si = svc.si()
    return CycleCell(
        checked_press(svc),
        si.blank,
        si.regrip,
        si.transfer.T_world_pallet,
        si.transfer.T_world_vias,
        si.approach,
        si.lift,
        si.follow,
        svc.wb.joints,
        settle=svc.settle_time(close=True),
        release=svc.settle_time(close=False),
    )


def cycle_steps(svc: BendingService) -> list[CycleStep]:
    """Return the project's steps (grasp and station per bend), or the section's grasp for
    every bend at the first station that fits it."""
    si, part = svc.si(), svc.part
    if si.steps is not None:
        return [CycleStep(s.bend, s.grasp, s.station) for s in si.steps]
    press = press_of(si)
    return [
        CycleStep(b.name, si.grasp, fitting_station(press, float(part.bend_lengths[i])))
        for i, b in enumerate(part.bends)
    ]


def plan_cycle(svc: BendingService, progress: Progress | None = None) -> BendingCycle:
    """Return the planned and checked cycle of the project's sequence and steps."""
    wb = svc.wb
    setup = wb.setup
    return check_cycle(
        svc.part,
        cycle_steps(svc),
        cycle_cell(svc),
        model=wb.robot,
        T_world_base=setup.T_world_base,
        T_flange_tcp=setup.T_flange_tcp,
        checker=wb.checker,
        policy=wb.collision_policy,
        cell_bodies=svc.part_cell_bodies(),
        progress=progress,
    )


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
    wb = svc.wb
    setup = wb.setup
    cell = cycle_cell(svc)
    base = ctx.part()
    names = [b.name for b in base.bends]
    others = svc.part_cell_bodies()

    def verify(plan: SequencePlan) -> SequencePlan | Rejected:
        from dataclasses import replace

        from workbench.errors import WorkbenchError
        from workbench.sheetmetal.part import SheetMetalPart

        order = [names.index(b) for b in plan.sequence]
        part = SheetMetalPart(base.thickness, list(base.flanges), [base.bends[i] for i in order])
        steps = [
            CycleStep(b, g, s)
            for b, g, s in zip(plan.sequence, plan.grasps, plan.stations, strict=True)
        ]
        try:
            cyc = check_cycle(
                part,
                steps,
                cell,
                model=wb.robot,
                T_world_base=setup.T_world_base,
                T_flange_tcp=setup.T_flange_tcp,
                checker=wb.checker,
                policy=wb.collision_policy,
                cell_bodies=others,
            )
        except WorkbenchError as exc:
            return Rejected(f"full cycle: {exc}")
        if cyc.first_problem is not None:
            return Rejected(f"full cycle: {cyc.first_problem}", cyc.first_step)
        return replace(
            plan,
            cycle_time=cyc.cycle_time,
            regrips=cyc.regrips,
            verified=True,
            estimated=False,
        )

    fast, _ = shared_engine(wb.checker, wb.collision_policy)

    def robot_free(q: np.ndarray, lying: tuple[Any, np.ndarray] | None) -> np.ndarray:
        scene = None if lying is None else PartScene(wb.checker, *lying)

        def hits(qi: np.ndarray) -> bool:
            if fast is not None:
                return fast.check(qi).colliding
            return bool(wb.checker.check(qi, distance=False).colliding)

        return np.array(
            [not hits(qi) and (scene is None or scene.link_hit(qi) is None) for qi in q]
        )

    return find_sequences(
        ctx,
        verify=verify,
        robot_free=robot_free,
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
