"""`Workbench`: one session over one project — the public API that the GUI, CLI and scripts use."""

from __future__ import annotations

import threading
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision import CollisionPolicy, ContactReport, RobotCollisionChecker
from workbench.errors import JointLimitError, WorkbenchError
from workbench.geometry.pose_check import check_transform
from workbench.geometry.transforms import invert_transform
from workbench.kinematics import DHRobot, RobotModel, Singularities
from workbench.kinematics.configurations import labelled_solutions, pick_solution
from workbench.kinematics.dh_chain import joint_vector
from workbench.motion.programs import ExportedProgram
from workbench.project import (
    Project,
    load_project,
    parse_project_json,
    project_from_dict,
    project_to_json,
)
from workbench.project.collision import CollisionSpec
from workbench.project.paths import PathArg, ProjectFolders
from workbench.project.units import to_deg
from workbench.service import program_edit, program_import, programs, project_imports, project_save
from workbench.service.assembly import AssemblyService
from workbench.service.bending import BendingService
from workbench.service.calibration import CalibrationService
from workbench.service.cell import CellBody, build_cell, press_cell
from workbench.service.collision_engine import CollisionService
from workbench.service.motion_plan import MotionPlan, Progress, plan_project
from workbench.service.plan_limits import limited
from workbench.service.polishing import PolishingService
from workbench.service.project_files import check_named_files
from workbench.service.project_zip import open_zip, project_zip
from workbench.service.robot_setup import RobotSetup, build_robot
from workbench.service.touchup import TouchupService
from workbench.service.workflow_slot import WorkflowSlot


@dataclass(frozen=True)
class IKSolution:
    """One inverse-kinematics solution [rad] with a human label of its configuration."""

    q: NDArray[np.float64]
    label: str


class Workbench:
    """One open project: its robot, tool and cell, the robot's state, and the checks on it.

    Units are SI (m, rad). Every method raises a `WorkbenchError` subclass on bad input.
    """

    def __init__(self, project: Project, *, base_dir: PathArg | None = None) -> None:
        self._lock = threading.RLock()
        self.folders = ProjectFolders.of(base_dir)  # base_dir may be a ProjectFolders
        self.base_dir = self.folders.base
        self.path: Path | None = None
        self._load(project)

    # -- construction -----------------------------------------------------------------
    @classmethod
    def open(cls, path: PathArg, *, allowed_dirs: list[PathArg] | tuple[()] = ()) -> Workbench:
        """Return a workbench on the project at `path`; the files it names stay in its folders."""
        project = load_project(path)
        wb = cls(project, base_dir=ProjectFolders(Path(path).resolve().parent, allowed_dirs))
        wb.path = Path(path)
        return wb

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, base_dir: PathArg | None = None) -> Workbench:
        """Return a workbench on a parsed project (the JSON as a dict)."""
        return cls(project_from_dict(data), base_dir=base_dir)

    def _load(self, project: Project) -> None:
        check_named_files(project, self.folders)  # lazily read files too: fail here, not at plan
        setup = build_robot(project.robot.to_si(), project.tool.to_si(), self.folders, project.cad)
        cell = build_cell(project.cell.to_si(), self.folders, project.cad)
        cell += press_cell(None if project.bending is None else project.bending.press_si())
        checker = RobotCollisionChecker(
            setup.model,
            setup.link_meshes,
            T_world_base=setup.T_world_base,
            tool=setup.tool_mesh,
            cell=[(b.solid, b.T_world_body) for b in cell if b.collide],
            q_reference=setup.q0,
        )
        # Swap only when everything above succeeded: a bad project never half-replaces a good one.
        self._project = project
        self._setup = setup
        self._cell = cell
        self._checker = checker
        self._q = setup.q0.copy()
        self._report: ContactReport | None = None
        self._plan: MotionPlan | None = None
        self._workflows: dict[str, Any] = {}

    def replace_project(self, project: Project) -> None:
        """Switch to another project; on any error the current one stays as it was."""
        with self._lock:
            self._load(project)

    def replace_from_json(self, text: str | bytes, *, source: str = "project") -> Project:
        """Switch to the project in JSON `text` (validated; `source` names it in errors); return
        it. On any error (ProjectError naming the field) the current project stays as it was."""
        project = parse_project_json(text, source=source)
        self.replace_project(project)
        return project

    # -- project ----------------------------------------------------------------------
    @property
    def project(self) -> Project:
        """Return the pydantic project, with the robot's current joints written into it."""
        self._project.robot.store_joints(self._q)
        return self._project

    def to_json(self) -> str:
        """Return the project as JSON text (as `save` writes it)."""
        return project_to_json(self.project)

    def save(
        self, path: PathArg | None = None, *, overwrite: bool = True, files: str = "rebase"
    ) -> Path:
        """Save atomically to `path` (default: its file), to open from there: `files` rebased or
        copied beside it (`service.project_save`); it becomes the project's file; return it."""
        return project_save.save_project_file(self, path, overwrite=overwrite, files=files).path

    to_zip = project_zip  # a .zip of the JSON and every file it names
    from_zip = classmethod(open_zip)  # the project of a .zip, unpacked in a folder

    # -- robot ------------------------------------------------------------------------
    @property
    def robot(self) -> RobotModel:
        """Return the kinematic model (`DHRobot` or `URDFRobot`)."""
        return self._setup.model

    @property
    def setup(self) -> RobotSetup:
        """Return the robot setup: link meshes, tool mesh, base and TCP frames."""
        return self._setup

    @property
    def cell(self) -> list[CellBody]:
        """Return the cell's bodies."""
        return list(self._cell)

    @property
    def joints(self) -> NDArray[np.float64]:
        """Return the robot's current joint values [rad] (a copy)."""
        return self._q.copy()

    def set_joints(self, q: ArrayLike) -> None:
        """Move the robot to joints `q` [rad]; raises JointLimitError naming the joint."""
        model = self._setup.model
        q = joint_vector(q, model.dof, "joints")
        lo, hi = model.limits[:, 0], model.limits[:, 1]
        bad = np.flatnonzero((q < lo - 1e-9) | (q > hi + 1e-9))
        if bad.size:  # told in the controller's values, as the jog panel shows them
            j, conv = int(bad[0]), model.convention
            qc, lim = conv.to_controller(q), conv.limits_to_controller(model.limits)
            raise JointLimitError(
                f"joint {j + 1}: {to_deg(qc[j]):.3f} deg is outside its limits"
                f" [{to_deg(lim[j, 0]):.3f}, {to_deg(lim[j, 1]):.3f}] deg (controller)"
            )
        with self._lock:
            self._q = np.clip(q, lo, hi)
            self._report = None

    def link_poses(self, q: ArrayLike | None = None) -> NDArray[np.float64]:
        """Return world poses (dof + 1, 4, 4) of the base and every link at `q` (default: current)."""
        qq = self._q if q is None else joint_vector(q, self.robot.dof, "q")
        return self._setup.T_world_base @ self.robot.link_transforms(qq)

    def tcp_pose(self, q: ArrayLike | None = None) -> NDArray[np.float64]:
        """Return the TCP's world pose (4, 4) [m] at `q` (default: current joints)."""
        return self.link_poses(q)[-1] @ self._setup.T_flange_tcp

    def ik_solutions(self, T_world_tcp: ArrayLike) -> list[IKSolution]:
        """Return every IK solution that puts the TCP at `T_world_tcp`, nearest first: one per
        arm configuration and turn of the wide joints, labelled 'front/elbow up/no flip, J6 +1
        turn' (the labels depend on the pose only); `move_tcp` accepts them."""
        T = check_transform(T_world_tcp, "T_world_tcp")
        setup = self._setup
        T_base_flange = (
            invert_transform(setup.T_world_base) @ T @ invert_transform(setup.T_flange_tcp)
        )
        found = labelled_solutions(self.robot, T_base_flange, self._q)
        return [IKSolution(q=q, label=label) for label, q in found]

    def move_tcp(
        self, T_world_tcp: ArrayLike, *, configuration: int | str | None = None
    ) -> NDArray[np.float64]:
        """Move the TCP to `T_world_tcp` and return the new joints [rad].

        `configuration` picks a solution by index or label; by default the one nearest the
        current joints. Unreachable poses raise UnreachableError and the robot stays.
        """
        sols = self.ik_solutions(T_world_tcp)
        self.set_joints(pick_solution([(s.label, s.q) for s in sols], configuration))
        return self.joints

    def singularities(self) -> Singularities:
        """Return the singularity report of the current joints (wrist, elbow, shoulder); DH arms
        only (the analysis reads the DH frames), other models raise WorkbenchError."""
        model = self.robot
        if not isinstance(model, DHRobot):
            raise WorkbenchError("this robot model has no singularity analysis")
        return model.singularities(self._q)

    # -- collision --------------------------------------------------------------------
    @property
    def checker(self) -> RobotCollisionChecker:
        """Return the exact (python-fcl) robot-versus-cell checker."""
        return self._checker

    @property
    def collision_policy(self) -> CollisionPolicy:
        """Return how plans check collisions: the project's `collision` section (or its defaults)."""
        return (self._project.collision or CollisionSpec()).to_si()

    def collision_status(self, q: ArrayLike | None = None) -> ContactReport:
        """Return the collision report at `q` (default: current joints, cached)."""
        if q is not None:
            return self._checker.check(joint_vector(q, self.robot.dof, "q"))
        with self._lock:
            if self._report is None:
                self._report = self._checker.check(self._q)
            return self._report

    # -- workflows --------------------------------------------------------------------
    def _workflow(self, name: str, cls: type) -> Any:
        with self._lock:
            if name not in self._workflows:
                self._workflows[name] = cls(self)
            return self._workflows[name]

    collision = WorkflowSlot(
        CollisionService, "The conservative collision engine of the project (seeds 001, 002)."
    )
    bending = WorkflowSlot(BendingService, "The press-brake bending workflow (seed 000).")
    assembly = WorkflowSlot(AssemblyService, "The virtual-assembly workflow (seed 003).")
    polishing = WorkflowSlot(PolishingService, "The polishing workflow (seed 004).")
    calibration = WorkflowSlot(CalibrationService, "TCP, work-object and base calibration.")

    touchup = WorkflowSlot(
        TouchupService, "The touch-up round trip: a program edited on the robot."
    )

    # -- motion -----------------------------------------------------------------------
    @limited("the motion plan")
    def plan_motion(self, *, dt: float = 0.01, progress: Progress | None = None) -> MotionPlan:
        """Return the plan of the project's program from its start (not the current joints; IK in
        each target's stored configuration, stored where missing), kept as `last_plan`."""
        args = (self._project, self._setup, self._checker)
        plan = plan_project(*args, policy=self.collision_policy, dt=dt, progress=progress)
        program_edit.store_configurations(self, plan)  # pose targets keep their configuration
        with self._lock:
            self._plan = plan
        return plan

    @property
    def last_plan(self) -> MotionPlan | None:
        """Return the most recent motion plan, or None before the first `plan_motion`."""
        return self._plan

    robot_programs = programs.robot_programs  # (workflow="motion", plan=None) -> list[RobotProgram]
    default_program_format = programs.default_format  # the robot's vendor's format, or None

    def export_program(
        self, fmt: str, workflow: str = "motion", *, force: bool = False, any_vendor: bool = False
    ) -> ExportedProgram:
        """Return a workflow's latest plan (planned now if none) as robot programs (rapid, krl,
        ls, urscript, nachi) or joint samples (csv, json), refused unless `force` if it collides or
        breaks a limit (PlanningError), unless `any_vendor` if not a library robot's language."""
        return programs.export(self, fmt, workflow, force=force, any_vendor=any_vendor)

    # -- your own cell (service.project_imports): the whole project checked, or nothing changes
    robot_choices = staticmethod(project_imports.robot_choices)  # () -> the robot library
    use_robot = project_imports.use_robot  # (preset): the library's robot at the same base
    add_cell_file = project_imports.add_cell_file  # (path, *, name, xyz_mm) -> its name
    import_part = project_imports.import_bending_part  # (name, data, settings) -> summary

    def import_program(self, files: dict[str, str], fmt: str | None = None) -> tuple[str, ...]:
        """Return the notes (lines not understood) of replacing the project's program by a robot
        program written elsewhere (`files`: name -> text; `service.program_import`)."""
        return program_import.import_program(self, files, fmt)
