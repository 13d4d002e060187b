"""Robot programs of every workflow and their export: the plan (planned now if none, refused
when it breaks a check unless forced), each workflow's `robot_programs(plan)`, the registry.

A library robot (`robot.preset`) runs its vendor's language only: `default_format` is it, and
a robot program in another vendor's language is refused (InputError naming the robot, its
vendor and the format to use) unless `any_vendor`. Robots given by DH rows or a URDF have
no vendor and export any format. Joint samples (csv, json) are never refused."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from workbench.errors import InputError, PlanningError
from workbench.kinematics.joint_convention import JointConvention
from workbench.kinematics.robot_library import LibraryRobot, library_robot
from workbench.motion.programs.controller_base import in_controller_base
from workbench.motion.programs.controller_program import ContactForce, RobotProgram
from workbench.motion.programs.exported import ExportedProgram
from workbench.motion.programs.formats import (
    PROGRAM_FORMATS,
    SAMPLE_FORMATS,
    check_format,
    write_programs,
    write_samples,
)
from workbench.motion.programs.names import controller_model
from workbench.project.program_io import motion_limits, tool_data, work_objects
from workbench.service import program_edit
from workbench.service.motion_plan import MotionPlan, robot_program

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

#: The workflows that export robot programs.
WORKFLOWS = ("motion", "bending", "assembly", "polishing")
#: The formats whose programs press with force control (RAPID: ABB's FC Pressure, rapid.py).
FORCE_CONTROL_FORMATS = ("rapid",)


def _check_workflow(workflow: str) -> str:
    if workflow not in WORKFLOWS:
        raise InputError(f"workflow: {workflow!r} is not one of {', '.join(WORKFLOWS)}")
    return workflow


def latest_plan(wb: Workbench, workflow: str) -> Any:
    """Return the workflow's latest plan, planned now when there is none, or when it was
    checked against another clearance margin or fewer exemptions than the project's now."""
    if _check_workflow(workflow) == "motion":  # planned again after an edit of the program
        last = wb.last_plan
        stale = last is not None and program_edit.editor(wb).plan_is_stale(last)
        return wb.plan_motion() if last is None or stale or margin_changed(wb, last) else last
    plan: Any
    if workflow == "bending":
        plan = wb.bending.last_plan
    elif workflow == "assembly":
        plan = wb.assembly.last_plan
    else:
        plan = wb.polishing.last_motion
    return plan_workflow(wb, workflow) if plan is None or margin_changed(wb, plan) else plan


def margin_changed(wb: Workbench, plan: Any) -> bool:
    """Return True when a robot report of `plan` measured another margin than the project's,
    or left out fewer exempt pairs (the plan is then checked again before an export)."""
    policy = wb.collision_policy
    reports = [getattr(plan, "collision_report", None), getattr(plan, "robot_report", None)]
    reports += list(getattr(plan, "robot_reports", {}).values())
    return any(
        r is not None
        and r.nearest is not None
        and (r.nearest.margin != policy.margin or not set(policy.exempt) <= set(r.nearest.exempt))
        for r in reports
    )


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


def robot_programs(wb: Workbench, workflow: str = "motion", plan: Any = None) -> list[RobotProgram]:
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


def convention_of(wb: Workbench, robot: str) -> JointConvention:
    """Return the joint convention of the robot named `robot` (an assembly cell's further arm
    by its preset; any other name: the project's robot), for samples in the controller's
    values."""
    assembly = wb.project.assembly
    for r in assembly.robots if assembly is not None else ():
        if r.name == robot and r.name != wb.project.robot.name:
            return library_robot(r.preset).convention
    return wb.robot.convention


def library_entry(wb: Workbench) -> LibraryRobot | None:
    """Return the robot library's record of the project's robot (None: a DH or URDF robot)."""
    preset = wb.project.robot.preset
    return None if preset is None else library_robot(preset)


def default_format(wb: Workbench) -> str | None:
    """Return the robot's vendor's program format ("rapid", "krl", "ls", "urscript",
    "nachi"), or None for a robot without a vendor (DH rows, URDF: any format)."""
    entry = library_entry(wb)
    return None if entry is None else entry.program_format


def check_vendor(wb: Workbench, fmt: str, *, any_vendor: bool = False) -> None:
    """Raise InputError when `fmt` is a robot-program format the robot's controller does not
    run (a library robot of another vendor), unless `any_vendor`."""
    entry = library_entry(wb)
    if any_vendor or entry is None or fmt not in PROGRAM_FORMATS:
        return
    if fmt != entry.program_format:
        raise InputError(
            f"format: the robot {entry.title!r} (preset {entry.name!r}) is a {entry.vendor}"
            f" robot; its controller runs {entry.program_format!r} programs, not {fmt!r}:"
            f" export as {entry.program_format!r}, or pass any_vendor=True (--any-vendor)"
            f" to write {fmt!r} anyway"
        )


def export(
    wb: Workbench,
    fmt: str,
    workflow: str = "motion",
    *,
    force: bool = False,
    any_vendor: bool = False,
) -> ExportedProgram:
    """Return the workflow's latest plan exported as `fmt` (robot programs, or csv/json joint
    samples). A plan that collides or breaks a limit is refused (PlanningError with its
    summary) unless `force`; a program in another vendor's language than the library robot's
    is refused (InputError, `check_vendor`) unless `any_vendor`."""
    check_format(fmt)
    check_vendor(wb, fmt, any_vendor=any_vendor)
    plan = latest_plan(wb, workflow)
    if not plan.ok and not force:
        raise PlanningError(
            f"{workflow}: the plan has problems: {plan.summary()}; fix them, or export with"
            " force=True (--force) to write it anyway"
        )
    if fmt in SAMPLE_FORMATS:
        samples = _samples(workflow, plan)
        out = write_samples(fmt, samples, [convention_of(wb, name) for name, _, _ in samples])
        note = contact_note(wb, workflow, fmt)  # the joints of the offset targets
        return ExportedProgram(out.files, out.notes + ((note,) if note else ()))
    written = controller_programs(wb, workflow, robot_programs(wb, workflow, plan))
    return write_programs(fmt, written, models=robot_models(wb, written))


def robot_models(wb: Workbench, programs: list[RobotProgram]) -> list[str]:
    """Return each program's robot model as its controller names it (`controller_model` of the
    library title, e.g. 'MZ07'; a DH or URDF robot: its name): the assembly's further arms by
    their preset, every other program by the project robot's."""
    project = wb.project
    presets = {project.robot.name: project.robot.preset}
    if project.assembly is not None:
        presets.update({r.name: r.preset for r in project.assembly.robots})
    out = []
    for p in programs:
        preset = presets.get(p.robot, project.robot.preset)
        out.append(controller_model(library_robot(preset).title if preset else p.robot))
    return out


def contact_note(wb: Workbench, workflow: str, fmt: str) -> str | None:
    """Return what an export of a pressing workflow (polishing) in a format without force
    control assumes: a compliant tool with D = F/k, with the numbers (None: nothing to say).
    Every post without force control writes it in its header; the GUI shows it on export."""
    if _check_workflow(workflow) != "polishing" or fmt in FORCE_CONTROL_FORMATS:
        return None
    si = wb.polishing.si
    return ContactForce(si.force, si.control.stiffness).compliance_note()


def controller_programs(
    wb: Workbench, workflow: str, programs: list[RobotProgram]
) -> list[RobotProgram]:
    """Return the programs with the project robot's work objects in its controller's base frame
    (`LibraryRobot.T_base_controller`; the same frame but for FANUC's world at J2 height)."""
    entry = library_entry(wb)
    if entry is None:
        return programs
    main = wb.project.robot.name
    return [
        in_controller_base(p, entry.T_base_controller)
        if workflow != "assembly" or p.robot == main
        else p
        for p in programs
    ]
