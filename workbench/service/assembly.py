"""The open project's virtual assembly (seed 003): parts, start and goal poses, planners, carried parts.

Builds the `Workcell` (parts, arms, the cell's fixed objects) from the project's `assembly`
section in SI (`AssemblySpec.to_si()`) and runs the domain (`workbench.assembly`) on it:
part moves (`part_moves`), the sequence's timed tasks (`tasks`), the timeline sampled and
checked under the project's collision policy (`timed_plan`), the exports (`programs`).
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.assembly import programs as ap
from workbench.assembly.arm import AssemblyArm
from workbench.assembly.arm_check import check_arm
from workbench.assembly.contacts import Contact
from workbench.assembly.part import AssemblyPart, primitive_mesh
from workbench.assembly.part_moves import PLANNER_CHOICES, PartPlan, Progress, plan_move
from workbench.assembly.programs import KEY_POINT_FORMATS, key_points_text
from workbench.assembly.robot_pairs import cross_contacts
from workbench.assembly.tasks import TaskPlan, plan_tasks
from workbench.assembly.timed_plan import timed_plan
from workbench.assembly.timeline import AssemblyPlan
from workbench.assembly.workcell import Workcell
from workbench.collision.engine import EnginePathReport
from workbench.errors import InputError, ProjectError, WorkbenchError
from workbench.geometry import check_transform
from workbench.project.assembly import AssemblyPartSI, AssemblySI, AssemblySpec, AssemblyTaskSI
from workbench.project.cad import step_tolerance
from workbench.project.program_io import program_settings
from workbench.service.mesh_files import load_mesh_file
from workbench.service.plan_limits import limited
from workbench.service.robot_setup import build_robot
from workbench.service.section import SectionService

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

# Result types and choices of the assembly, re-exported for the GUI.
__all__ = ["KEY_POINT_FORMATS", "PLANNER_CHOICES", "AssemblyArm", "AssemblyPart", "AssemblyPlan"]
__all__ += ["AssemblyService", "PartPlan", "TaskPlan", "Workcell"]


class AssemblyService(SectionService[AssemblySpec]):
    """`Workbench.assembly`: the assembly workflow of the open project (SI units)."""

    section = "assembly"
    missing = "add parts to it"

    def __init__(self, wb: Workbench) -> None:
        super().__init__(wb)
        self._lock = threading.RLock()
        self._cell: Workcell | None = None
        self._arms: dict[str, AssemblyArm] | None = None
        self.last_part_plan: PartPlan | None = None
        self.last_plan: AssemblyPlan | None = None

    # -- the section and the workcell ----------------------------------------------------
    @property
    def available(self) -> bool:
        """Return True when the project has an `assembly` section with at least one part."""
        spec = self._section()
        return spec is not None and bool(spec.parts)

    @property
    def si(self) -> AssemblySI:
        """Return the section in SI (m, rad; speed a fraction)."""
        return self.spec.to_si()

    @property
    def cell(self) -> Workcell:
        """Return the workcell: parts (meshes loaded, checked closed), arms, fixed obstacles."""
        with self._lock:
            if self._cell is None:
                si = self.si
                parts = {p.name: self._build_part(i, p) for i, p in enumerate(si.parts)}
                fixed = [
                    (b.name, b.mesh().copy().apply_transform(b.T_world_body))
                    for b in self.wb.cell
                    if b.collide
                ]
                self._cell = Workcell(
                    parts,
                    self.arms,
                    fixed,
                    [],
                    cell_size=si.planner.cell_size,
                    cell_size_field="assembly.planner.cell_size",
                    parts_field="assembly.parts",
                )
            self._cell.order = [t.part for t in self.sequence()]
            return self._cell

    @property
    def part_names(self) -> list[str]:
        """Return the part names in the order of the project file."""
        return [p.name for p in self.spec.parts]

    @property
    def parts(self) -> dict[str, AssemblyPart]:
        """Return every part by name, meshes loaded and checked closed (MeshError naming the field)."""
        return self.cell.parts

    def part(self, name: str) -> AssemblyPart:
        """Return the part called `name`; InputError listing the parts if there is none."""
        return self.cell.part(name)

    def _build_part(self, i: int, p: AssemblyPartSI) -> AssemblyPart:
        where = f"assembly.parts[{i}]"
        if p.shape == "mesh":
            assert p.path is not None
            tolerance = step_tolerance(self.wb.project.cad)
            mesh = load_mesh_file(
                p.path, self.wb.folders, p.scale, f"{where}.path", tolerance=tolerance
            )
        else:
            mesh = primitive_mesh(p.shape, p.size, p.radius, p.height)
        part = AssemblyPart(p.name, mesh, p.start, p.goal, p.grasp, p.robot, p.color)
        return part.check(where, list(self.arms))

    @property
    def arms(self) -> dict[str, AssemblyArm]:
        """Return the cell's robots by name: the project's robot first, then the section's `robots`."""
        with self._lock:
            if self._arms is None:
                wb = self.wb
                cell = [(b.solid, b.T_world_body) for b in wb.cell if b.collide]
                main = wb.project.robot.name
                arms = {
                    main: AssemblyArm(
                        main, wb.setup, wb.checker, wb.setup.q0, (235, 235, 240), main=True
                    )
                }
                for i, r in enumerate(self.si.robots):
                    if r.name in arms:
                        field = f"assembly.robots[{i}].name"
                        raise ProjectError(
                            f"{field}: {r.name!r} is already the project's robot; rename it",
                            [(field, "duplicate robot name")],
                        )
                    setup = build_robot(r.robot, r.tool, wb.folders, wb.project.cad)
                    arms[r.name] = AssemblyArm.build(r.name, setup, setup.q0, cell, r.color)
                self._arms = arms
            return self._arms

    def link_poses(self, robot: str, q: ArrayLike | None = None) -> NDArray[np.float64]:
        """Return robot `robot`'s link poses (dof + 1, 4, 4) in the world [m] at q [rad] (default home)."""
        arm = self.arms[robot]
        return arm.link_poses(arm.q_home if q is None else np.asarray(q, float))

    def sequence(self, parts: list[str] | None = None) -> list[AssemblyTaskSI]:
        """Return the part moves in order (the section's `sequence`, or every part as listed), SI;
        parts: only these parts' moves (InputError for an unknown part)."""
        for n in parts or []:
            self.part(n)
        return [t.to_si() for t in self.spec.tasks(parts)]

    def set_pose(self, name: str, which: str, T_world_part: ArrayLike) -> None:
        """Set part `name`'s `which` ("start" or "goal") pose (4, 4) [m]; stored in the project in mm/deg."""
        if which not in ("start", "goal"):
            raise InputError(f"which must be 'start' or 'goal', got {which!r}")
        T = check_transform(T_world_part, which)
        self.part(name)
        self.spec.parts[self.part_names.index(name)].set_pose(which, T)  # type: ignore[arg-type]
        with self._lock:
            self.cell.move(name, which, T)
            self.last_plan = None

    def interference(self, name: str, T_world_part: ArrayLike | None = None) -> list[str]:
        """Return the names of the obstacles part `name` interferes with at a pose (default: its start)."""
        part = self.part(name)
        T = part.start if T_world_part is None else check_transform(T_world_part, "T_world_part")
        return self.cell.interference(name, T)

    # -- planning ------------------------------------------------------------------------
    @limited("the assembly part plan")
    def plan_part(
        self,
        name: str,
        planner: str | None = None,
        *,
        cell_size: float | None = None,
        progress: Progress | None = None,
        q_start: ArrayLike | None = None,
        **options: Any,
    ) -> PartPlan:
        """Return the PartPlan of part `name` from its start to its goal, with its robot's joints.

        A refused plan leaves no last part plan (an export never writes an older one).
        planner: one of PLANNER_CHOICES (default: the section's); options override the
        section's planner options (SI); see `workbench.assembly.part_moves.plan_move`.
        """
        self.last_part_plan = None
        planner = planner or self.si.planner.name
        opts = {**self.si.planner.options(planner), **options}
        plan = plan_move(
            self.cell, name, planner, opts, cell_size=cell_size, q_start=q_start, report=progress
        )
        self.last_part_plan = plan
        return plan

    @limited("the assembly sequence")
    def plan_sequence(
        self,
        parts: list[str] | None = None,
        planner: str | None = None,
        *,
        cell_size: float | None = None,
        dt: float = 0.04,
        progress: Progress | None = None,
        **options: Any,
    ) -> AssemblyPlan:
        """Plan the sequence's tasks (`assembly.tasks`), sample them every dt [s] and check them.

        parts: only these parts' tasks (default: all); planner, cell_size, options: `plan_part`.
        """
        # a new plan replaces the last one, refused or not: an export never writes a plan
        # older than the last request
        self.last_plan = self.last_part_plan = None
        if not (np.isfinite(dt) and 0 < dt <= 0.1):
            raise InputError(f"dt: {dt!r} s must be in (0, 0.1]")
        sequence = self.sequence(parts)
        if not sequence:
            raise InputError("assembly.parts: there are no parts to assemble; add some")

        def move(name: str, q: NDArray[np.float64] | None, sub: Progress) -> PartPlan:
            return self.plan_part(
                name, planner, cell_size=cell_size, progress=sub, q_start=q, **options
            )

        report = progress or (lambda f, m: None)
        tasks = plan_tasks(
            self.cell,
            [(t.part, t.approach, t.retreat) for t in sequence],
            self.si.speed,
            joint_space=(planner or self.si.planner.name) == "joint_rrt_connect",
            plan_move=move,
            report=report,
        )
        report(0.95, "checking the timed motion")
        plan = timed_plan(self.cell, tasks, dt, self.wb.collision_policy)
        self.last_plan = plan
        report(1.0, plan.summary())
        return plan

    def check_robot(
        self,
        tasks: list[TaskPlan] | tuple[TaskPlan, ...],
        times: NDArray[np.float64],
        robot: str,
        *,
        joints: NDArray[np.float64] | None = None,
        progress: Progress | None = None,
    ) -> EnginePathReport | None:
        """Return robot `robot`'s check over its tasks at the plan's `times` (`check_arm`) under
        the project's collision policy; None if it has no task."""
        policy = self.wb.collision_policy
        return check_arm(self.arms[robot], tasks, times, policy, joints=joints, progress=progress)

    def cross_contacts(
        self,
        tasks: list[TaskPlan],
        times: NDArray[np.float64],
        joints: dict[str, NDArray[np.float64]],
        part_poses: dict[str, NDArray[np.float64]],
    ) -> tuple[Contact, ...]:
        """Return the robot–robot and robot–part contacts of sampled motions (`robot_pairs`)."""
        c = self.cell
        return cross_contacts(c.bodies(), c.arms, c.parts, tasks, times, joints, part_poses)

    # -- export --------------------------------------------------------------------------
    def robot_programs(self, plan: AssemblyPlan | None = None) -> list[ap.RobotProgram]:
        """Return each robot's program of the sequence (default: the last plan; `assembly.programs`)."""
        plan, s = plan or self.last_plan or self.plan_sequence(), program_settings(self.wb.project)
        return ap.assembly_programs(plan.tasks, self.arms, s, self.spec.tools())

    def export_key_points(self, fmt: str, plan: PartPlan | None = None) -> str:
        """Return the key points of a part plan (default: the last one) as CSV or JSON text (mm, deg)."""
        if fmt not in KEY_POINT_FORMATS:
            raise InputError(f"fmt must be one of {KEY_POINT_FORMATS}, got {fmt!r}")
        plan = plan or self.last_part_plan
        if plan is None:
            raise WorkbenchError("no part has been planned yet; plan a part first")
        return key_points_text(plan, fmt)
