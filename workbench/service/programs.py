"""Robot programs of every workflow and their export: the plan (planned now if none, refused
when it breaks a check unless forced), each workflow's `robot_programs(plan)`, the registry."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from workbench.errors import InputError, PlanningError
from workbench.motion.programs.exported import ExportedProgram
from workbench.motion.programs.formats import (
    SAMPLE_FORMATS,
    check_format,
    write_programs,
    write_samples,
)
from workbench.motion.programs.model import RobotProgram
from workbench.project.program_io import motion_limits, tool_data, work_objects
from workbench.service import program_edit
from workbench.service.motion_plan import MotionPlan, robot_program

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

#: The workflows that export robot programs.
WORKFLOWS = ("motion", "bending", "assembly", "polishing")


def _check_workflow(workflow: str) -> str:
    if workflow not in WORKFLOWS:
        raise InputError(f"workflow: {workflow!r} is not one of {', '.join(WORKFLOWS)}")
    return workflow


def latest_plan(wb: Workbench, workflow: str) -> Any:
    """Return the workflow's latest plan, planned now when there is none."""
    if _check_workflow(workflow) == "motion":  # planned again after an edit of the program
        plan = wb.last_plan
        stale = plan is not None and program_edit.editor(wb).plan_is_stale(plan)
        return wb.plan_motion() if plan is None or stale else plan
    if workflow == "bending":
        return wb.bending.last_plan or wb.bending.plan()
    if workflow == "assembly":
        return wb.assembly.last_plan or wb.assembly.plan_sequence()
    return wb.polishing.last_motion or wb.polishing.plan_motion()


def plan_workflow(wb: Workbench, workflow: str, *, progress: Any = None) -> Any:
    """Plan the workflow now (motion: the program; bending; assembly: the sequence; polishing:
    the motion along its path) and return the plan, kept as the workflow's latest."""
    if _check_workflow(workflow) == "motion":
        return wb.plan_motion(progress=progress)
    if workflow == "bending":
        return wb.bending.plan(progress=progress)
    if workflow == "assembly":
        return wb.assembly.plan_sequence(progress=progress)
    return wb.polishing.plan_motion(progress=progress)


def motion_programs(wb: Workbench, plan: MotionPlan | None = None) -> list[RobotProgram]:
    """Return the Motion workflow's program (one robot) of `plan` (default: the latest)."""
    plan = plan or latest_plan(wb, "motion")
    project = wb.project
    program = robot_program(
        plan,
        wb.setup,
        tool=tool_data(project.tool),
        work_objects=work_objects(project),
        limits=motion_limits(project.robot),
        robot=project.robot.name,
    )
    return [program]


def robot_programs(wb: Workbench, workflow: str, plan: Any = None) -> list[RobotProgram]:
    """Return the robot programs (one per robot) of a workflow's plan (default: the latest)."""
    if _check_workflow(workflow) == "motion":
        return motion_programs(wb, plan)
    service = getattr(wb, workflow)
    if not hasattr(service, "robot_programs"):
        raise InputError(
            f"workflow {workflow!r}: its robot programs are not in this build yet; export the"
            " motion workflow, or csv/json samples"
        )
    return list(service.robot_programs(plan or latest_plan(wb, workflow)))


def _samples(workflow: str, plan: Any) -> list[tuple[str, Any, Any]]:
    if hasattr(plan, "motions"):  # one motion per robot (assembly)
        return [(name, m.times, m.joints) for name, m in plan.motions.items()]
    if isinstance(plan, MotionPlan):
        return [(plan.program.name, plan.times, plan.positions)]
    return [(workflow, plan.times, plan.joints)]


def export(
    wb: Workbench, fmt: str, workflow: str = "motion", *, force: bool = False
) -> ExportedProgram:
    """Return the workflow's latest plan exported as `fmt` (robot programs, or csv/json joint
    samples). A plan that collides or breaks a limit is refused (PlanningError with its
    summary) unless `force`."""
    check_format(fmt)
    plan = latest_plan(wb, workflow)
    if not plan.ok and not force:
        raise PlanningError(
            f"{workflow}: the plan has problems: {plan.summary()}; fix them, or export with"
            " force=True (--force) to write it anyway"
        )
    if fmt in SAMPLE_FORMATS:
        return write_samples(fmt, _samples(workflow, plan))
    return write_programs(fmt, robot_programs(wb, workflow, plan))
