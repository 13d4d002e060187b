"""The sequence and grasp search of a press-brake cycle with every plan verified as a full
cycle: the search's context (part, press, cell, robot reach, candidate grasps), the check of
a plan as a cycle, and the robot's collision check of joint vectors the search asks about.

SI units (m, rad, s). The search itself is `sequencing.find_sequences`.
"""

from __future__ import annotations

import uuid
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.collision.plan_check import shared_engine
from workbench.errors import InputError, WorkbenchError
from workbench.pressbrake.bend_eval import Reach, SweepContext
from workbench.pressbrake.cycle import PartScene
from workbench.pressbrake.cycle_path import CycleCell, CycleStep
from workbench.pressbrake.cycle_plan import CycleRobot, reordered
from workbench.pressbrake.grasp_grid import GridSettings, screened_grid
from workbench.pressbrake.press import PressBrake
from workbench.pressbrake.sequencing import (
    Rejected,
    SearchResult,
    SearchSettings,
    SequencePlan,
    find_sequences,
)
from workbench.sheetmetal.part import SheetMetalPart

F64 = NDArray[np.float64]
Progress = Callable[[float, str], None]


def sweep_context(
    part_spec: Any,
    part: SheetMetalPart,
    press: PressBrake,
    robot: CycleRobot,
    q_home: F64,
    tool_mesh: trimesh.Trimesh | None,
    link_meshes: list[trimesh.Trimesh],
    grid: GridSettings,
    *,
    T_world_blank: F64,
    T_world_pallet: F64,
    lift: float,
    approach: F64,
    T_world_regrip: F64,
) -> SweepContext:
    """Return the search's context: the part (`part_spec`, built as `part`), the press, the
    cell's bodies, the robot's reach from `q_home`, the candidate grasps of `grid` and where
    the part rests (blank stack, pallet, regrip station: T_world_part [m])."""
    reach = Reach.of(
        robot.model, robot.T_world_base, robot.T_flange_tcp, q_home, tool_mesh, link_meshes
    )
    g = grid
    try:
        grasps, refused = screened_grid(part, g)
    except InputError as exc:
        said = exc.detail if exc.field in ("grasp grid", "grasp spacing") else str(exc)
        where = ".spacing" if exc.field == "grasp spacing" else ""
        raise InputError(said, field=f"bending.grasp_grid{where}") from None
    return SweepContext(
        part_spec,
        press,
        tuple(robot.cell_bodies),
        reach,
        tuple(grasps),
        key=uuid.uuid4().hex,
        T_world_blank=T_world_blank,
        T_world_pallet=T_world_pallet,
        lift=lift,
        approach=approach,
        T_world_regrip=T_world_regrip,
        refused=tuple(refused),
    )


def verify_plan(
    plan: SequencePlan, part: SheetMetalPart, cell: CycleCell, robot: CycleRobot
) -> SequencePlan | Rejected:
    """Return `plan` with its full cycle's time and regrips (verified), or why the cycle of
    its order, grasps and stations fails (the step at fault where one is named)."""
    steps = [
        CycleStep(b, g, s)
        for b, g, s in zip(plan.sequence, plan.grasps, plan.stations, strict=True)
    ]
    try:
        cyc = robot.check_cycle(reordered(part, plan.sequence), steps, cell)
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


def robot_free(robot: CycleRobot) -> Callable[[F64, tuple[Any, F64] | None], NDArray[np.bool_]]:
    """Return `free(q, lying)`: which joint vectors (N, dof) leave the robot free of the cell
    (the fast shared engine where the policy has one, else the checker) and of the part
    lying as `lying` (mesh, T_world; None: no part)."""
    fast, _ = shared_engine(robot.checker, robot.policy)

    def free(q: F64, lying: tuple[Any, F64] | None) -> NDArray[np.bool_]:
        scene = None if lying is None else PartScene(robot.checker, *lying)

        def hits(qi: F64) -> bool:
            if fast is not None:
                return fast.check(qi).colliding
            return bool(robot.checker.check(qi, distance=False).colliding)

        return np.array(
            [not hits(qi) and (scene is None or scene.link_hit(qi) is None) for qi in q]
        )

    return free


def search_cycles(
    ctx: SweepContext,
    cell: CycleCell,
    robot: CycleRobot,
    *,
    engine: str,
    address: str | None,
    time_limit: float | None,
    progress: Progress | None,
    cancel: Callable[[], bool] | None,
    settings: SearchSettings | None,
) -> SearchResult:
    """Return the ranked plans of the part in the context `ctx`, each verified as a full
    cycle in `cell` (`sequencing.find_sequences` on `engine`)."""
    base = ctx.part()
    return find_sequences(
        ctx,
        verify=lambda plan: verify_plan(plan, base, cell, robot),
        robot_free=robot_free(robot),
        engine=engine,
        address=address,
        time_limit=time_limit,
        progress=progress,
        cancel=cancel,
        settings=settings,
    )
