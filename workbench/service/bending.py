"""`Workbench.bending`: the open project's press-brake bending (seed 000).

Builds the domain objects of `workbench.sheetmetal` and `workbench.pressbrake` from the
project's `bending` section (in SI through `BendingSpec.to_si`, once per change), calls them
and returns their results (SI units; a plan is a `pressbrake.BendingResult`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision import Solid
from workbench.errors import InputError
from workbench.motion import SampledMotion
from workbench.pressbrake.cycle import BendingCycle as BendingCycle  # re-exported (gui)
from workbench.pressbrake.die import DiePlacement, bend_on_die
from workbench.pressbrake.grasp import (
    Grasp,
    T_flange_grasp,
    check_flange,
    checked_grasp,
    grasp_point,
)
from workbench.pressbrake.obstacles import Obstacles, cell_obstacles
from workbench.pressbrake.plan import BendingPlan as BendingPlan  # re-exported (gui)
from workbench.pressbrake.program import RobotProgram
from workbench.pressbrake.result import BendingResult
from workbench.pressbrake.sequencing import SearchResult, SearchSettings, SequencePlan
from workbench.pressbrake.transfer import transfer_poses, world_tcp
from workbench.pressbrake.transfer_plan import plan_transfer
from workbench.project.bending import BendingSI, BendingSpec, PartSI, PartSpec
from workbench.project.program_io import program_settings
from workbench.service import bending_process as process
from workbench.service.plan_limits import limited
from workbench.service.section import SectionService
from workbench.sheetmetal import FoldedState, OBBTree, SheetMetalPart
from workbench.sheetmetal.check_cost import CheckCost, check_cost
from workbench.sheetmetal.sequence import check_sequence

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

Progress = Callable[[float, str], None]


class BendingService(SectionService[BendingSpec]):
    """`Workbench.bending`: the bending workflow of the open project (SI units)."""

    section = "bending"
    missing = "add one (see docs)"

    def __init__(self, wb: Workbench) -> None:
        super().__init__(wb)
        self._part: SheetMetalPart | None = None
        self._part_spec: PartSpec | None = None
        self._plan: BendingResult | None = None
        self._si: tuple[BendingSpec, BendingSI] | None = None  # (section converted, its SI)

    # -- project section ------------------------------------------------------------------
    def part_spec(self) -> PartSpec:
        """Return the part section (inline, or read from `part_file`, validated)."""
        if self._part_spec is None:
            self._part_spec = self.spec.read_part(self.wb.folders)
        return self._part_spec

    def si(self) -> BendingSI:
        """Return the `bending` section in SI units (its part and sequence resolved).

        Converted once per change: every setter here that changes the section calls
        `_changed`, and another project is another service (`Workbench._load`)."""
        spec = self.spec
        if self._si is None or self._si[0] is not spec:
            self._si = (spec, spec.to_si(self.part_spec()))
        return self._si[1]

    def _changed(self) -> None:
        """Forget what was derived from the section before it changed: its SI form, the plan."""
        self._si, self._plan = None, None

    @property
    def part(self) -> SheetMetalPart:
        """Return the part with the project's bend sequence (checked: no flange bent into another)."""
        if self._part is None:
            si = self.si()
            part = self._build_part(si.part)
            check_flange(part, si.grasp.flange, "bending.grasp.flange")
            self._part = part
        return self._part

    def _build_part(self, spec: PartSI) -> SheetMetalPart:
        try:
            return SheetMetalPart.from_spec(spec)
        except InputError as exc:
            raise exc.within("bending.part") from exc

    @property
    def sequence(self) -> list[str]:
        """Return the bend names in sequence order."""
        return [b.name for b in self.part.bends]

    def set_sequence(self, names: Sequence[str]) -> None:
        """Use bend sequence `names`; InputError if it repeats, misses or names unknown bends, or is infeasible."""
        part_si = self.si().part
        names = check_sequence([str(n).strip() for n in names], [b.name for b in part_si.bends])
        part = self._build_part(replace(part_si, sequence=tuple(names)))  # raises when infeasible
        self.spec.steps = None  # a plan's grasps and stations belong to its own order
        self.spec.sequence = names
        self._changed()
        self._part = part

    # -- grasp --------------------------------------------------------------------------
    @property
    def grasp(self) -> Grasp:
        """Return the grasp (SI): flange, offset [m] or None (centroid), yaw [rad]."""
        return self.spec.grasp.to_si()

    @property
    def grasp_flange(self) -> str:
        """Return the name of the gripped flange."""
        return self.spec.grasp.flange

    def grasp_offset(self) -> NDArray[np.float64]:
        """Return the grasp point (2,) [m] in the gripped flange's polygon frame."""
        return grasp_point(self.part, self.grasp)

    def set_grasp(
        self, flange: str, offset: ArrayLike | None = None, yaw: float | None = None
    ) -> None:
        """Grip `flange` at `offset` (2,) [m] in its polygon frame (None: centroid), gripper `yaw` [rad]."""
        grasp = checked_grasp(self.part, flange, offset, 0.0 if yaw is None else yaw)
        self.spec.steps = None  # the grasp chosen now serves every bend
        self.spec.grasp.set_si(grasp, keep_yaw=yaw is None)
        self._changed()

    def T_flange_grasp(self) -> NDArray[np.float64]:
        """Return the TCP pose (4, 4) [m] in the gripped flange's frame: on its top face, z into the sheet."""
        return T_flange_grasp(self.part, self.grasp)

    # -- part states and cell -------------------------------------------------------------
    def fold(self, step: float) -> FoldedState:
        """Return the part after `step` bends of the sequence (float: partway, for animation)."""
        return self.part.fold(step)

    def tree(self, step: int | None = None) -> OBBTree:
        """Return the OBB tree of the part after `step` bends (default: all), rooted at the grasp."""
        s = len(self.part.bends) if step is None else step
        return self.part.fold(s).obb_tree(self.grasp_flange)

    def tree_depth(self) -> int:
        """Return the number of levels of the deepest OBB tree of the folded part (any grasp)."""
        return self.part.fold(len(self.part.bends)).tree_depth()

    def obstacles(self) -> Obstacles:
        """Return the cell's colliding objects as OBBs [m] (cylinders and meshes confirmed exactly)."""
        return cell_obstacles((b.name, b.solid, b.T_world_body) for b in self.wb.cell if b.collide)

    # -- process ------------------------------------------------------------------------
    def bend_on_die(self, step: float) -> int:
        """Return the sequence index of the bend on the die with the part folded to `step`."""
        return bend_on_die(step, len(self.part.bends))

    def die_part_pose(self, step: int) -> NDArray[np.float64]:
        """Return T_world_part (4, 4) [m] with bend `step` on the die (a press: the cycle's)."""
        return process.die_part_pose(self, step)

    def world_tcp(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        """Return the TCP's world poses (..., 4, 4) [m] at joints (..., dof) [rad]."""
        setup = self.wb.setup
        return world_tcp(self.wb.robot, setup.T_world_base, setup.T_flange_tcp, q)

    def placements(self) -> tuple[tuple[DiePlacement, ...], str]:
        """Return each bend's die placement with one arm configuration, and its label (a
        press: as the cycle's plan holds it); UnreachableError names what is out of reach."""
        return process.die_placements(self)

    def transfer_poses(self, last: DiePlacement) -> tuple[NDArray[np.float64], list[str]]:
        """Return TCP poses (N, 4, 4) [m] of the transfer: retract, via poses, pallet; with names."""
        si = self.si()
        return transfer_poses(si.transfer, si.die, last, self.part, si.grasp)

    @limited("the bending plan")
    def plan(self, *, progress: Progress | None = None) -> BendingResult:
        """Plan the project's bending.

        With a press (`bending.press`): the whole cycle of the project's sequence and steps
        (`BendingCycle`: pick, every bend with the ram and back-gauge, regrips, transfer,
        pallet; every frame checked; `bending_process.plan_cycle`). Without: each bend placed
        on the die and the checked transfer to the pallet (`BendingPlan`,
        `pressbrake.transfer_plan.plan_transfer`), a `BendingResult`. `progress(fraction,
        message)` reports the stages; `cancel()` or `planning.time_limit` ends it."""
        plan: BendingResult
        self._plan = None  # a refused plan leaves no stale export
        si = self.si()
        if si.press is not None:
            plan = process.plan_cycle(self, progress)
        else:
            plan = plan_transfer(
                self.wb.setup,
                self.part,
                self.grasp,
                die=si.die,
                transfer=si.transfer,
                frames=si.frames,
                q_start=self.wb.setup.q0,
                obstacles=self.obstacles(),
                checker=self.wb.checker,
                policy=self.wb.collision_policy,
                progress=progress,
            )
        self._plan = plan
        return plan

    def find_sequences(
        self,
        engine: str = "serial",
        address: str | None = None,
        time_limit: float | None = None,
        progress: Progress | None = None,
        *,
        cancel: Callable[[], bool] | None = None,
        settings: SearchSettings | None = None,
    ) -> SearchResult:
        """Return ranked feasible plans of bend order, grasps and stations (best first), each
        checked as a full cycle; `rejected`, the first reason of every pruned branch;
        `stats`. `engine` "serial" or "ray" (`address`: a running cluster; None: a local Ray
        started for the job); `time_limit` [s] returns the best found so far, with a note."""
        return process.search(
            self,
            engine=engine,
            address=address,
            time_limit=time_limit,
            progress=progress,
            cancel=cancel,
            settings=settings,
        )

    def use_plan(self, plan: SequencePlan) -> None:
        """Put a plan's sequence, grasps and stations into the project: `plan()` then replays
        that cycle, and saving keeps it."""
        self.spec.set_steps_si(list(plan.sequence), process.steps_of(plan))
        self._changed()
        self._part = None

    def part_cell_bodies(self) -> list[tuple[str, Solid, NDArray[np.float64]]]:
        """Return the cell's colliding objects the part is checked against (world), the press
        left out (the process checks the part against the press as it moves)."""
        return [
            (b.name, b.solid, b.T_world_body)
            for b in self.wb.cell
            if b.collide and b.group != "press"
        ]

    def settle_time(self, *, close: bool) -> float:
        """Return the gripper's settle time [s] after closing or opening (io.gripper; 0
        without one)."""
        s = program_settings(self.wb.project)
        g = s.close if close else s.open
        return 0.0 if g is None else float(g.settle)

    @property
    def last_plan(self) -> BendingResult | None:
        """Return the latest plan (None before `plan`, or after the sequence or grasp changed)."""
        return self._plan

    def robot_programs(self, plan: BendingResult | None = None) -> list[RobotProgram]:
        """Return the plan (default: the last) as a robot program (`BendingResult.robot_program`)."""
        plan, s = plan or self.last_plan or self.plan(), program_settings(self.wb.project)
        return [plan.robot_program(self.wb.setup, self.si(), s, self.wb.setup.q0)]

    def check_cost(self, plan: BendingResult, repeat: int = 3) -> CheckCost | None:
        """Return OBB tests and check times per frame, tree vs flat loop (Fig. 12), on request;
        None for a result whose part no single tree checks (a cycle)."""
        T = plan.grasp_frames
        return None if T is None else check_cost(self.tree(), self.obstacles().boxes, T, repeat)

    def part_pose_at(self, plan: BendingResult, t: float) -> NDArray[np.float64]:
        """Return T_world_part (4, 4) [m] of the part at time `t` [s] (a cycle: at the last
        checked frame before t; its fold step is `part_step_at`)."""
        return plan.part_pose_at(t, self.world_tcp)

    def part_step_at(self, plan: BendingResult, t: float) -> float:
        """Return how far the part is folded at time `t` [s] (bends done, fractions partway)."""
        return plan.part_step_at(t)

    def press_poses_at(self, plan: BendingResult, t: float) -> dict[str, NDArray[np.float64]]:
        """Return the world poses (4, 4) [m] of the press's moving bodies at time `t` [s], by
        their cell names ("press punch", "press upper beam", "press back-gauge finger 1", ...);
        empty for a plan without a press."""
        poses = plan.press_poses_at(t, self.si().press)
        return {f"press {name}": T for name, T in poses.items()}

    def playback(self, plan: BendingResult, dt: float = 0.02) -> SampledMotion:
        """Return the plan sampled every `dt` [s] for the timeline, frames' verdicts carried over."""
        return plan.playback(self.world_tcp, dt)
