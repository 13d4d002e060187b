"""wb.touchup: a program edited on the controller compared with the project's (which targets
moved, by how much, one correction of each work object where they agree), and applied on
request; the project stays as it was until `apply`, which returns the previous one for undo
and plans the motion again (`motion.programs.touchup`, `project.touchup`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from workbench.errors import InputError, WorkbenchError
from workbench.kinematics.robot_library import library_robot
from workbench.motion.programs.controller_base import in_model_base
from workbench.motion.programs.formats import format_of, reader
from workbench.motion.programs.touchup import (
    TouchupReport,
    TouchupSettings,
    compare,
    read_notes,
    taught_targets,
)
from workbench.project.io import project_from_dict
from workbench.project.paths import size_limit
from workbench.project.touchup import (
    TOUCHUP_MODES,
    base_and_tool,
    planned_targets,
    touched_up_project,
    work_object_frames,
)

if TYPE_CHECKING:
    from workbench.project.models import Project
    from workbench.service.motion_plan import MotionPlan, Progress
    from workbench.service.workbench import Workbench

__all__ = [
    "TOUCHUP_MODES",
    "TouchupApplied",
    "TouchupReport",
    "TouchupService",
    "TouchupSettings",
]  # the GUI takes the report and settings types from here (it imports only the service)


@dataclass(frozen=True)
class TouchupApplied:
    """What `apply` did: the `mode`, the `notes` (each change, what was not applied), the
    motion `plan` made after it (None when planning failed: `plan_error` says why)."""

    mode: str
    notes: tuple[str, ...]
    plan: MotionPlan | None
    plan_error: str = ""

    def summary(self) -> str:
        """Return what was applied and the plan's verdict as text lines."""
        lines = [f"applied ({self.mode}):"] + [f"  {n}" for n in self.notes]
        if self.plan is not None:
            lines.append(f"plan: {self.plan.summary()}")
        else:
            lines.append(f"plan: failed: {self.plan_error}")
        return "\n".join(lines)


class TouchupService:
    """The touch-up round trip of the open project (`Workbench.touchup`)."""

    def __init__(self, wb: Workbench) -> None:
        self._wb = wb
        self.settings = TouchupSettings()
        self.last_report: TouchupReport | None = None
        self.last_applied: TouchupApplied | None = None
        self._basis: tuple[TouchupReport, str] | None = None

    def set_settings(self, settings: TouchupSettings) -> None:
        """Use other tolerances (`TouchupSettings`, m and rad) from the next `compare` on."""
        if not isinstance(settings, TouchupSettings):
            raise InputError("settings: give a TouchupSettings", field="settings")
        self.settings = settings

    def compare(self, files: dict[str, str], fmt: str | None = None) -> TouchupReport:
        """Return the comparison of the program in `files` (name -> text: a KRL .src with its
        .dat) with the project's program: a row per move, a correction per work object. `fmt`
        defaults to the one the file names tell. The project does not change."""
        wb = self._wb
        if not files:
            raise InputError(
                "touch-up: no program file given; give the program read from the robot"
            )
        project = wb.project
        planned = planned_targets(project, wb.robot)
        if not planned:
            raise InputError(
                "touch-up: the project has no program moves to compare with; plan or import a"
                " program first",
                field="program",
            )
        limit = size_limit("program")
        for name, text in files.items():
            if len(text) > limit:
                raise InputError(
                    f"{len(text)} characters, over the {limit}-byte limit of a robot program"
                    " (WORKBENCH_MAX_PROGRAM_BYTES)",
                    field=name,
                )
        fmt = fmt or format_of(list(files))
        source = ", ".join(files)
        try:
            read = reader(fmt)(files)
            if project.robot.preset is not None:  # work objects as the controller states them
                read = in_model_base(read, library_robot(project.robot.preset).T_base_controller)
            T_world_base, T_flange_tcp = base_and_tool(project)
            taught = taught_targets(read, wb.robot, T_world_base, T_flange_tcp)
        except WorkbenchError as exc:
            raise InputError(
                f"{exc}; check that it is a {fmt} program of this project's robot (or give the"
                " format)",
                field=source,
            ) from None
        if not taught:
            raise InputError(
                f"the program has no moves the reader understood; is it a {fmt} program?",
                field=source,
            )
        frames = work_object_frames(project)
        notes = read_notes(read, frames, T_world_base, T_flange_tcp)
        report = compare(
            planned,
            taught,
            frames,
            source=source,
            fmt=fmt,
            settings=self.settings,
            notes=notes,
        )
        self.last_report = report
        self._basis = (report, self._program_of(project))
        return report

    @staticmethod
    def _program_of(project: Project) -> str:
        program = project.program.model_dump_json() if project.program else ""
        return program + str([w.model_dump_json() for w in project.work_objects or ()])

    def apply(
        self,
        report: TouchupReport,
        *,
        mode: str = "work_object",
        plan: bool = True,
        progress: Progress | None = None,
    ) -> Project:
        """Apply `report` to the project in `mode` ("work_object": fold each shared correction
        into its work object, targets that do not fit kept as taught; "targets": every moved
        target as taught; "both") and return the previous project (undo:
        `wb.replace_project(previous)`). Then plan the motion again and check it (`plan`;
        `progress` as `wb.plan_motion`'s), kept with the notes as `last_applied`; a failed plan
        is reported there, not raised."""
        wb = self._wb
        previous = wb.project.model_copy(deep=True)
        basis = self._basis
        if basis is None or basis[0] is not report or basis[1] != self._program_of(previous):
            raise InputError(
                "touch-up: the project's program or work objects changed since this comparison"
                " (or it was made on another project); compare the program again, then apply",
                field="report",
            )
        data, notes = touched_up_project(previous, report, mode, wb.robot.convention)
        with wb._lock:  # the applied project keeps this touch-up (settings, report, result)
            wb.replace_project(project_from_dict(data, source=f"touch-up of {report.source}"))
            wb._workflows["touchup"] = self
        result: MotionPlan | None = None
        error = ""
        if plan:
            try:
                result = wb.plan_motion(progress=progress)
            except WorkbenchError as exc:
                error = str(exc)
        self.last_applied = TouchupApplied(mode, notes, result, error)
        return previous
