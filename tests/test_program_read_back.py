"""Every example project x every robot-program format: exported, read back, re-planned (issue 12 part 5).

For each example project and each workflow it has, the workflow's robot programs are written
by each format's post and read back by that format's reader; then

- `check_read_back` (tests/program_round_trip.py) holds: every Cartesian target re-solved
  through its tool, work object and configuration data gives the planned joints (1e-6 rad),
  FK of the planned joints is the written pose (0.01 mm, 0.01 deg), the actions are the
  plan's in order, and the speeds or stated durations are the planned ones;
- the read-back program planned again (joint fractions and linear speeds as read; a joint
  move stated only by its time, RAPID's and URScript's, planned at the fraction that takes
  that time, as the controller does) takes the planned time: sum of the moves' planned
  durations plus the waits, within 1 %.

A format without a reader, or a workflow whose service has no `robot_programs` yet, is
skipped with the missing name in the reason (the end state of issue 12 skips nothing).
"""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np
import pytest
from program_round_trip import check_read_back

from workbench import Workbench
from workbench.motion import Move, Program, plan_program, time_program
from workbench.motion.programs import (
    PROGRAM_FORMATS,
    PulseOutput,
    RobotProgram,
    WaitTime,
    post,
    reader,
    to_robot_program,
)
from workbench.motion.programs.exported import ReadProgram
from workbench.project import load_project

ROOT = Path(__file__).resolve().parents[1]
PROJECTS = sorted((ROOT / "projects").glob("*.json"))
SIGNALS_BY = {"rapid": "name"}  # RAPID names its signals; the others number them


def _workflows(path: Path) -> list[str]:
    p = load_project(path)
    found = []
    if p.program is not None and p.program.moves:
        found.append("motion")
    if p.bending is not None:
        found.append("bending")
    if p.assembly is not None and p.assembly.parts:
        found.append("assembly")
    if p.polishing is not None:
        found.append("polishing")
    return found


CASES = [
    pytest.param(
        path.name,
        wf,
        fmt,
        id=f"{path.stem}-{wf}-{fmt}",
        marks=() if wf == "motion" else (pytest.mark.slow,),
    )
    for path in PROJECTS
    for wf in _workflows(path)
    for fmt in PROGRAM_FORMATS
]


@functools.cache
def _planned(project: str, workflow: str) -> tuple[Workbench, tuple[RobotProgram, ...], dict]:
    wb = Workbench.open(ROOT / "projects" / project)
    service = None if workflow == "motion" else getattr(wb, workflow)
    if service is not None and not hasattr(service, "robot_programs"):
        pytest.skip(f"wb.{workflow}.robot_programs is not in this build yet")
    programs = tuple(wb.robot_programs(workflow))
    return wb, programs, _start_joints(wb, workflow, programs)


def _start_joints(wb: Workbench, workflow: str, programs: tuple[RobotProgram, ...]) -> dict:
    """Return each program's start joints [rad] (where its plan starts)."""
    from workbench.service.programs import latest_plan

    plan = latest_plan(wb, workflow)
    if hasattr(plan, "motions"):
        motions = list(plan.motions.values())
        by_robot = {name: m.joints[0] for name, m in plan.motions.items()}
        return {p.name: by_robot.get(p.robot, motions[0].joints[0]) for p in programs}
    q0 = plan.positions[0] if hasattr(plan, "positions") else plan.joints[0]
    return {p.name: q0 for p in programs}


def _waits(actions: tuple) -> float:
    return float(sum(a.seconds for a in actions if isinstance(a, WaitTime)))


def _motion_program(
    read: ReadProgram, model, fractions: dict[int, float]
) -> tuple[Program, np.ndarray]:  # noqa: ANN001
    """Return the read program as the planner's moves (joint: re-solved joints, linear: the
    pose in the base frame) and its tool's TCP."""
    rp = to_robot_program(read, model)
    tools = {t.name for t in (rp.tool(m.tool) for m in rp.moves)}
    assert len(tools) == 1, f"one tool per program, got {tools}"
    moves = []
    for k, (mv, rm) in enumerate(zip(rp.moves, read.moves, strict=True)):
        if mv.kind == "joint":
            speed = rm.speed if rm.speed is not None else fractions[k]
            moves.append(Move.joint(mv.target.q, speed=speed, zone=mv.zone, name=mv.name))
        else:
            assert mv.kind == "linear", f"{mv.kind} moves are not planned by this test"
            T = rp.work_object(mv.wobj).T_base_wobj @ mv.target.T_wobj_tcp
            moves.append(Move.linear(T, speed=mv.speed, zone=mv.zone, name=mv.name))
    return Program(rp.name, tuple(moves)), rp.tool(rp.moves[0].tool).T_flange_tcp


def _replan(read: ReadProgram, model, q_start: np.ndarray) -> float:  # noqa: ANN001
    """Return the duration [s] of the read program planned again; joint moves stated only by
    a time get the speed fraction at which the planner takes that time (fixed point)."""
    timed = {k: m.duration for k, m in enumerate(read.moves) if m.speed is None}
    fractions = dict.fromkeys(timed, 1.0)
    first = _motion_program(read, model, fractions)[0].moves[0]
    if first.kind == "joint" and np.max(np.abs(first.q - q_start)) < 1e-6:
        # the program starts where the robot stands: the read-back joints (within the
        # written digits) are that start, not a micro-move to plan (ruckig refuses those)
        q_start = first.q
    for _ in range(12):
        program, T_flange_tcp = _motion_program(read, model, fractions)
        path = plan_program(model, program, q_start, model.max_velocity, T_flange_tcp=T_flange_tcp)
        traj = time_program(
            path, model.max_acceleration, model.max_jerk, position_limits=model.limits
        )
        if not timed:
            return float(traj.duration)
        arrive = [
            traj.waypoint_times[np.flatnonzero(path.move_index == m)[-1]]
            for m in range(len(program.moves))
        ]
        took = np.diff(np.concatenate([[0.0], arrive]))
        worst = max(abs(took[k] - d) / d for k, d in timed.items())
        if worst < 1e-3:
            break
        for k, d in timed.items():
            fractions[k] = float(np.clip(fractions[k] * took[k] / d, 1e-3, 1.0))
    return float(traj.duration)


@pytest.mark.parametrize(("project", "workflow", "fmt"), CASES)
def test_exported_program_reads_back_and_replans(project: str, workflow: str, fmt: str) -> None:
    write, read_fn = post(fmt), reader(fmt)
    if write is None:
        pytest.skip(f"no post write_{fmt} in this build")
    if read_fn is None:
        pytest.skip(f"no reader read_{fmt} in this build")
    wb, programs, starts = _planned(project, workflow)
    assert programs, f"{project}: the {workflow} workflow gave no robot program"
    model = wb.robot
    for program in programs:
        exported = write(program)
        read = read_fn(exported.files)
        check_read_back(program, read, model, signals_by=SIGNALS_BY.get(fmt, "number"))
        planned = program.cycle_time
        replanned = _replan(read, model, starts[program.name]) + _waits(read.actions())
        assert abs(replanned - planned) <= 0.01 * planned, (program.name, replanned, planned)
        pulses = [a for a in program.actions() if isinstance(a, PulseOutput)]
        assert len(pulses) == len([a for a in read.actions() if isinstance(a, PulseOutput)])


def test_motion_durations_add_up_to_the_planned_cycle_time() -> None:
    wb, programs, _ = _planned("mz07_cell.json", "motion")
    plan = wb.last_plan
    assert plan is not None
    (program,) = programs
    assert sum(m.duration for m in program.moves) == pytest.approx(plan.cycle_time, abs=1e-9)
    assert program.cycle_time == pytest.approx(
        plan.cycle_time + _waits(program.actions()), abs=1e-9
    )
