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

Every case runs (no skips): a missing post, reader or workflow builder fails. The workflows'
plans are made once per session (tests/example_plans.py) and shared by the formats; each read-back
program is planned (IK along its moves) once and only re-timed while the stated joint-move
times are fitted, so the whole matrix stays fast enough for the unit suite.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from pathlib import Path

import numpy as np
import pytest
from example_plans import PROJECTS, planned, slow_marks
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
from workbench.motion.programs.controller_program import ReadMove, ReadProgram
from workbench.motion.programs.first_move import FIRST_MOVE_SPEED, safe_start
from workbench.motion.programs.readback import in_robot_base
from workbench.motion.programs.urscript import blend_radii
from workbench.project import load_project

ROOT = Path(__file__).resolve().parents[1]
SIGNALS_BY = {"rapid": "name"}  # RAPID names its signals; the others number them
# FANUC's CR has 1 mm steps (CR1 is the least blend); a blended joint move is CNT100, a speed
# percentage with no radius: the replan gives those moves the plan's zones
CHECK_ARGS = {"ls": {"zone_tol": 1e-3, "joint_zones": False}}


CASES = [
    pytest.param(
        path.name,
        wf,
        fmt,
        id=f"{path.stem}-{wf}-{fmt}",
        marks=slow_marks(path, wf),
    )
    for path in PROJECTS
    for wf in load_project(path).workflows()
    for fmt in PROGRAM_FORMATS
]


@functools.cache
def _planned(project: str, workflow: str) -> tuple[Workbench, tuple[RobotProgram, ...], dict]:
    wb, programs = planned(project, workflow)  # once per session, shared (tests/example_plans.py)
    return wb, programs, _start_joints(wb, workflow, programs)


def _start_joints(wb: Workbench, workflow: str, programs: tuple[RobotProgram, ...]) -> dict:
    """Return each program's start joints [rad]: where its workflow's builder timed its first
    move from (the motion plan's start; each assembly robot's own start; the robot's current
    joints for bending and polishing, as their services pass them)."""
    from workbench.service.programs import latest_plan

    plan = latest_plan(wb, workflow)
    if workflow == "assembly":
        by_robot = {name: m.joints[0] for name, m in plan.motions.items()}
        return {p.name: by_robot[p.robot] for p in programs}
    q0 = plan.positions[0] if workflow == "motion" else wb.joints
    return {p.name: np.asarray(q0, float) for p in programs}


def _waits(actions: tuple) -> float:
    return float(sum(a.seconds for a in actions if isinstance(a, WaitTime)))


def _motion_program(
    read: ReadProgram, model, fractions: dict[int, float], zones: dict[int, float]
) -> tuple[Program, np.ndarray]:  # noqa: ANN001
    """Return the read program as the planner's moves (joint: re-solved joints, linear: the
    pose in the base frame) and its tool's TCP; `zones` replaces the read zones of moves whose
    program states none (FANUC's CNT100 on a joint move)."""
    rp = to_robot_program(read, model)
    tools = {t.name for t in (rp.tool(m.tool) for m in rp.moves)}
    assert len(tools) == 1, f"one tool per program, got {tools}"
    moves = []
    for k, (mv, rm) in enumerate(zip(rp.moves, read.moves, strict=True)):
        if mv.kind == "joint":
            speed = rm.speed if rm.speed is not None else fractions[k]
            zone = zones.get(k, mv.zone)
            moves.append(Move.joint(mv.target.q, speed=speed, zone=zone, name=mv.name))
        else:
            assert mv.kind == "linear", f"{mv.kind} moves are not planned by this test"
            T = rp.work_object(mv.wobj).T_base_wobj @ mv.target.T_wobj_tcp
            moves.append(Move.linear(T, speed=mv.speed, zone=mv.zone, name=mv.name))
    return Program(rp.name, tuple(moves)), rp.tool(rp.moves[0].tool).T_flange_tcp


def _replan(
    read: ReadProgram,
    model,  # noqa: ANN001
    q_start: np.ndarray,
    zones: dict[int, float] | None = None,
) -> float:
    """Return the duration [s] of the read program planned again. A joint move stated only by
    a time (RAPID's \\T, URScript's t) runs, as the controller runs it, at the slowest speed
    fraction at which the planner takes that time (a short move limited by acceleration takes
    it at any fraction above that): bisection per timed move on the log of the fraction. The
    path (IK along the moves) does not depend on the fractions: it is planned once, and only
    the timed moves' speed limits change between the timings."""
    timed = {k: m.duration for k, m in enumerate(read.moves) if m.speed is None and m.duration}
    program, T_flange_tcp = _motion_program(
        read, model, dict.fromkeys(range(len(read.moves)), 1.0), zones or {}
    )
    path = plan_program(model, program, q_start, model.max_velocity, T_flange_tcp=T_flange_tcp)
    vmax = np.asarray(model.max_velocity, float)
    seg_move = path.move_index[1:]  # the move each segment (waypoint k -> k + 1) belongs to
    ends = [np.flatnonzero(path.move_index == m)[-1] for m in range(len(program.moves))]

    def timing(fractions: dict[int, float]):  # noqa: ANN202
        limits = path.speed_limits.copy()
        for k, f in fractions.items():
            limits[seg_move == k] = f * vmax
        return time_program(
            dataclasses.replace(path, speed_limits=limits),
            model.max_acceleration,
            model.max_jerk,
            position_limits=model.limits,
        )

    lo, hi = dict.fromkeys(timed, 1e-3), dict.fromkeys(timed, 1.0)
    for _ in range(14 if timed else 0):
        traj = timing({k: float(np.sqrt(lo[k] * hi[k])) for k in timed})
        took = np.diff(np.concatenate([[0.0], traj.waypoint_times[ends]]))
        for k, d in timed.items():
            f = float(np.sqrt(lo[k] * hi[k]))
            if took[k] > d * (1.0 + 1e-3):
                lo[k] = f
            else:
                hi[k] = f
    return float(timing(hi).duration)


def _without_first_move(read: ReadProgram) -> ReadProgram:
    """Return the read program without its first move (the safe move to the first target)."""
    k = next(i for i, x in enumerate(read.instructions) if isinstance(x, ReadMove))
    return dataclasses.replace(
        read, instructions=read.instructions[:k] + read.instructions[k + 1 :]
    )


@pytest.mark.parametrize(("project", "workflow", "fmt"), CASES)
def test_exported_program_reads_back_and_replans(project: str, workflow: str, fmt: str) -> None:
    write, read_fn = post(fmt), reader(fmt)
    assert write is not None, f"no post write_{fmt}"
    assert read_fn is not None, f"no reader read_{fmt}"
    wb, programs, starts = _planned(project, workflow)
    assert programs, f"{project}: the {workflow} workflow gave no robot program"
    model = wb.robot
    for program in programs:
        exported = write(program)
        # a MultiMove task's work objects are in the shared world: re-solved in the robot's base
        read = read_fn(exported.files)
        if fmt == "rapid":
            read = in_robot_base(read, program.T_world_base)
        check_read_back(
            program,
            read,
            model,
            signals_by=SIGNALS_BY.get(fmt, "number"),
            zones=blend_radii(safe_start(program)) if fmt == "urscript" else None,
            **CHECK_ARGS.get(fmt, {}),
        )
        # the first move is reached from wherever the robot stands, at a bounded speed: the
        # cycle replanned is the rest, from the first target
        planned = program.cycle_time - program.moves[0].duration
        rest = _without_first_move(read)
        unstated = (
            {k - 1: m.zone for k, m in enumerate(program.moves) if m.kind == "joint" and k > 0}
            if fmt == "ls"
            else {}
        )
        q_first = program.moves[0].target.q
        replanned = _replan(rest, model, q_first, unstated) + _waits(read.actions())
        assert abs(replanned - planned) <= 0.01 * planned, (program.name, replanned, planned)
        pulses = [a for a in program.actions() if isinstance(a, PulseOutput)]
        assert len(pulses) == len([a for a in read.actions() if isinstance(a, PulseOutput)])


def test_motion_durations_add_up_to_the_planned_cycle_time() -> None:
    wb, programs, _ = _planned("mz07_cell.json", "motion")
    plan = wb.last_plan
    assert plan is not None
    (program,) = programs
    # the plan holds the program's waits at their stops: moves + waits = the plan's time
    waits = _waits(program.actions())
    assert waits > 0.0  # the example's gripper settles
    assert sum(m.duration for m in program.moves) == pytest.approx(
        plan.cycle_time - waits, abs=1e-9
    )
    assert program.cycle_time == pytest.approx(plan.cycle_time, abs=1e-9)


@pytest.mark.parametrize(("project", "workflow", "fmt"), CASES)
def test_first_move_is_untimed_and_speed_bounded(project: str, workflow: str, fmt: str) -> None:
    """Issue 27 part 2: the first motion of every exported program is reached from wherever
    the robot stands: a joint move with no stated time (no RAPID \\T, no URScript t=), at a
    bounded speed (at most FIRST_MOVE_SPEED of the joints' maximum; RAPID: at most 250 mm/s
    and 45 deg/s), ending in an exact stop; read back through the format's reader."""
    wb, programs, _ = _planned(project, workflow)
    for program in programs:
        files = post(fmt)(program).files
        read = reader(fmt)(files)
        first = read.moves[0]
        assert first.kind == "joint" and first.duration is None and first.zone == 0.0
        if fmt == "rapid":
            (text,) = files.values()
            line = text.splitlines()[first.line - 1]
            assert "\\T" not in line and first.speed is None, line
            v_tcp, v_ori = (float(x) for x in re.search(r",\s*\[([\d.]+),([\d.]+),", line).groups())  # type: ignore[union-attr]
            assert v_tcp <= 250.0 and v_ori <= 45.0, line
        else:
            assert first.speed is not None and 0.0 < first.speed <= FIRST_MOVE_SPEED + 1e-9
            if fmt == "urscript":
                (text,) = files.values()
                movej = next(ln for ln in text.splitlines() if ln.strip().startswith("movej("))
                assert "t=" not in movej, movej
        # the rest of the program is as planned: the second move keeps its planned timing
        if len(program.moves) > 1 and fmt in ("rapid", "urscript"):
            second = read.moves[1]
            if second.kind == "joint" and program.moves[1].duration > 0:
                assert second.duration == pytest.approx(program.moves[1].duration, abs=1e-3)


def test_multimove_robot_b_is_written_in_its_base_in_the_world() -> None:
    """RAPID MultiMove: robot B's targets are in its own base, which lies 600 mm / 90 deg off
    in the shared world (wobj0): they are written in a declared wobjdata whose uframe is B's
    base in the world, and read back and re-solved through it they give the planned joints;
    robot A (its base is the world) keeps wobj0."""
    wb, programs, _ = _planned("assembly_cell.json", "assembly")
    model = wb.robot
    by_robot = {p.robot: p for p in programs}
    b = next(p for p in programs if not np.allclose(p.T_world_base, np.eye(4)))
    assert np.linalg.norm(b.T_world_base[:3, 3]) > 0.1  # the example's B stands apart
    text = post("rapid")(b).text
    wname = f"{b.robot}_base"
    decl = next(ln for ln in text.splitlines() if f"wobjdata {wname}:=" in ln)
    assert decl.strip().startswith("TASK PERS wobjdata")
    read = reader("rapid")({f"{b.name}.mod": text})
    moves = read.moves
    assert moves and all(m.wobj == wname for m in moves) and "\\WObj:=wobj0" not in text
    (w,) = [w for w in read.work_objects if w.name == wname]
    np.testing.assert_allclose(w.T_base_wobj, b.T_world_base, atol=1e-6)
    # re-solved through that work object (in B's base), the targets are the planned joints
    rp = to_robot_program(in_robot_base(read, b.T_world_base), model)
    for mv, planned_mv in zip(rp.moves, b.moves, strict=True):
        assert np.max(np.abs(mv.target.q - planned_mv.target.q)) < 1e-6, mv.name
        if mv.target.cartesian:  # the world pose of the written target is B's TCP in the world
            tool = b.tool(planned_mv.tool).T_flange_tcp
            T_world = b.T_world_base @ model.fk(planned_mv.target.q) @ tool
            T_read = w.T_base_wobj @ mv.target.T_wobj_tcp
            np.testing.assert_allclose(T_read[:3, 3], T_world[:3, 3], atol=1e-5)
    # robot A's base is MultiMove's world: its targets stay in wobj0
    a = next(p for p in by_robot.values() if p is not b)
    np.testing.assert_allclose(a.T_world_base, np.eye(4), atol=1e-12)
    assert "\\WObj:=wobj0" in post("rapid")(a).text
