"""The controller program of a planned motion: the user's program items (`motion_program.Item`:
moves and actions), the motion `Program` planned from them and its trajectory turned into a
`RobotProgram` (`robot_program`); and the planner's timing of moves a workflow's own plan does
not time (`planner_durations`, `fit_linear_speed`), for every workflow's program builder.

Two rules tie the plan and the written program:

- A move followed by an action (other than a comment) ends in an exact stop: the action
  happens at the target, as a controller runs it (a robot in a blend has not arrived).
- Each move's planned duration is the time between the trajectory's arrivals at the previous
  and at this move's target (for a blended linear move, at the end of its blend), so the
  durations add up to the trajectory's duration.

Targets carry the planned joints: a joint move's own joints, or the IK solution of the pose
nearest the joints the planner arrived with (the same solution for a pose joint move, the
one nearest the previous target); Cartesian targets (linear moves and pose joint moves) also
carry the TCP in the move's work object and the arm configuration of those joints.

SI: m, rad, s.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel
from workbench.motion.moves import JointPath, plan_program, time_program
from workbench.motion.program import (
    JOINT,
    Item,
    Move,
    Program,
    is_action,
    nearest_ik,
    program_moves,
)
from workbench.motion.programs.controller_program import (
    Gripper,
    Instruction,
    MotionLimits,
    MoveInstr,
    RobotProgram,
    Target,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
)
from workbench.motion.trajectory import Trajectory

FloatArray = NDArray[np.float64]


def arrival_indices(path: JointPath, n_moves: int) -> NDArray[np.int64]:
    """Return, per move, the index of its last waypoint in `path` (where it arrives)."""
    out = np.empty(n_moves, np.int64)
    for m in range(n_moves):
        own = np.flatnonzero(path.move_index == m)
        if own.size == 0:
            raise InputError(f"move {m} has no waypoint in the planned path")
        out[m] = own[-1]
    return out


def wait_holds(items: Sequence[Item], path: JointPath) -> list[tuple[int, float]]:
    """Return the program's waits as (waypoint index, seconds) of `path`: the wait times
    (WaitTime, a gripper's settle time) of the actions after each move, held at its target's
    last waypoint (before the first move: at the start, waypoint 0). Waits for an input have
    no known length and count 0 s (`MotionPlan.summary` says so)."""
    n = len(program_moves(items))
    arrive = arrival_indices(path, n) if n else np.zeros(0, np.int64)
    holds: dict[int, float] = {}
    done = 0
    for item in items:
        if not is_action(item):
            done += 1
            continue
        acts = item.expand() if isinstance(item, Gripper) else (item,)
        secs = sum(a.seconds for a in acts if isinstance(a, WaitTime))
        if secs > 0.0:
            wp = 0 if done == 0 else int(arrive[done - 1])
            holds[wp] = holds.get(wp, 0.0) + float(secs)
    return sorted(holds.items())


def wait_summary(items: Sequence[Item], path: JointPath) -> str:
    """Return what the plan's time holds of the program's waits ("0.40 s of waits; waits for
    inputs count 0 s"), or "" when it has none."""
    held = sum(s for _, s in wait_holds(items, path))
    inputs = any(
        isinstance(a, WaitInput)
        for it in items
        if is_action(it)
        for a in (it.expand() if isinstance(it, Gripper) else (it,))
    )
    parts = [f"{held:.2f} s of waits"] if held > 0 else []
    if inputs:
        parts.append("waits for inputs count 0 s")
    return "; ".join(parts)


def move_durations(
    path: JointPath,
    trajectory: Trajectory,
    n_moves: int,
    holds: Sequence[tuple[int, float]] = (),
) -> FloatArray:
    """Return each move's planned duration (n_moves,) [s]: the time between the arrivals at the
    previous target (the start for the first) and at its own, less the waits held between them
    (`holds`, as `Trajectory.with_holds` took them: the program states those as actions); with
    the waits they add up to the duration."""
    idx = arrival_indices(path, n_moves)
    arrive = np.asarray(trajectory.waypoint_times, float)[idx].copy()
    arrive[-1] = trajectory.duration - sum(s for w, s in holds if w >= idx[-1])
    for w, secs in holds:  # a hold at waypoint w delays every waypoint after it
        arrive[idx > w] -= secs
    return np.diff(np.concatenate([[0.0], arrive]))


def planner_durations(
    model: RobotModel, program: Program, q_start: FloatArray, T_flange_tcp: FloatArray
) -> FloatArray:
    """Return each move's duration (n_moves,) [s] as the motion planner times `program` from
    `q_start` (`plan_program` + `time_program` with the robot's limits, `move_durations`):
    how a workflow times the moves its own plan does not, so that the program planned again
    takes the same time."""
    path = plan_program(model, program, q_start, model.max_velocity, T_flange_tcp=T_flange_tcp)
    traj = time_program(
        path, model.max_acceleration, model.max_jerk, position_limits=model.limits, program=program
    )
    return move_durations(path, traj, len(program.moves))


#: `fit_linear_speed` takes the slowest speed whose planned time is at most this much
#: (relative) above the wanted one.
FIT_TOLERANCE = 1e-3


def fit_linear_speed(
    model: RobotModel,
    T_flange_tcp: FloatArray,
    q_from: FloatArray,
    T_base_tcp: FloatArray,
    duration: float,
    max_speed: float,
    *,
    rel_step: float = 1e-9,
) -> float:
    """Return the TCP speed [m/s] at which the motion planner takes `duration` [s] for a
    stop-to-stop linear move from joints `q_from` to the pose `T_base_tcp` (4, 4) [m]: the
    speed a program states for a straight move its workflow timed otherwise (e.g. in joint
    space through the line's waypoints). The time falls with the speed until the joints'
    limits take over (then it stays): the slowest speed whose time is at most `FIT_TOLERANCE`
    above `duration`, found by bisection on the log of the speed down to `rel_step` (relative);
    `max_speed` when even that is slower.

    The slowest such speed, not the first one the bisection meets inside the tolerance: where
    the joints' limits make the time flat, every speed over a range takes the time within the
    tolerance, and which one the bisection met first depended on the last bits of the planner's
    times: one retreat of the assembly cell (with the real MZ07F's frames) was written at 265
    mm/s on one install and 580 mm/s on another.
    """

    def took(v: float) -> float:
        prog = Program("fit", (Move.linear(T_base_tcp, speed=v),))
        return float(planner_durations(model, prog, q_from, T_flange_tcp)[0])

    dist = float(np.linalg.norm((model.fk(q_from) @ T_flange_tcp)[:3, 3] - T_base_tcp[:3, 3]))
    hi = float(max_speed)
    most = duration * (1.0 + FIT_TOLERANCE)
    if duration <= 0.0 or dist < 1e-9 or took(hi) > most:
        return hi
    lo = min(hi, 1e-4)
    if took(lo) <= most:
        return lo
    while hi > lo * (1.0 + rel_step):  # took(lo) > most >= took(hi)
        v = float(np.sqrt(lo * hi))
        if took(v) > most:
            lo = v
        else:
            hi = v
    return hi


def _unique_names(names: list[str]) -> list[str]:
    seen: dict[str, int] = {}
    out = []
    for k, n in enumerate(names):
        base = n or f"p{k + 1}"
        seen[base] = seen.get(base, 0) + 1
        out.append(base if seen[base] == 1 else f"{base}_{seen[base]}")
    return out


def robot_program(
    items: Sequence[Item],
    program: Program,
    path: JointPath,
    trajectory: Trajectory,
    model: RobotModel,
    *,
    tool: ToolData,
    work_objects: Sequence[WorkObject],
    T_world_base: FloatArray | None = None,
    limits: MotionLimits | None = None,
    robot: str = "robot",
) -> RobotProgram:
    """Return the `RobotProgram` of a planned motion.

    `items` are the program's items (as given to `motion_program`), `program` the motion
    program planned into `path` and `trajectory`. Every move gets its planned joints, its
    duration (`move_durations`), its speed and zone as planned, `tool` and its work object;
    pose targets also their TCP pose in that work object and arm configuration. The work
    objects (in the robot base frame) the moves use are kept, in the given order.
    """
    moves_in = program_moves(items)
    if len(moves_in) != len(program.moves):
        raise InputError(f"{len(moves_in)} program moves but {len(program.moves)} planned moves")
    n = len(program.moves)
    T_base_world = invert_transform(
        np.eye(4) if T_world_base is None else np.asarray(T_world_base, float)
    )
    wobjs = {w.name: w for w in work_objects}
    idx = arrival_indices(path, n)
    durations = move_durations(path, trajectory, n, wait_holds(items, path))
    names = _unique_names([mv.name for _, mv in moves_in])
    T_tcp_flange = invert_transform(tool.T_flange_tcp)
    planned = iter(range(n))
    instructions: list[Instruction] = []
    for item in items:
        if is_action(item):
            instructions.append(item)  # type: ignore[arg-type]
            continue
        k = next(planned)
        src, mv = moves_in[k][1], program.moves[k]
        if src.wobj not in wobjs:
            raise InputError(
                f"move {k} ({src.name}): no work object {src.wobj!r}; have {list(wobjs)}"
            )
        wobj = wobjs[src.wobj]
        q_arrive = path.positions[idx[k]]
        if mv.kind == JOINT:
            q = mv.q
        else:
            q = q_arrive
            T_flange = T_base_world @ np.asarray(src.T_world_tcp, float) @ T_tcp_flange
            if not np.allclose(model.fk(q), T_flange, atol=1e-9):  # blended: the target itself
                q = nearest_ik(model, T_flange, q_arrive, f"move {k} ({src.name})")
        if src.T_world_tcp is None:
            target = Target(names[k], np.asarray(q, float))
        else:
            T_wobj_tcp = invert_transform(wobj.T_base_wobj) @ model.fk(q) @ tool.T_flange_tcp
            target = Target.planned(names[k], np.asarray(q, float), model, T_wobj_tcp)
        instructions.append(
            MoveInstr(
                mv.kind,  # type: ignore[arg-type]
                target,
                float(mv.speed),
                float(mv.zone),
                tool.name,
                wobj.name,
                float(durations[k]),
            )
        )
    used = {src.wobj for _, src in moves_in}
    return RobotProgram(
        program.name,
        (tool,),
        tuple(w for w in work_objects if w.name in used),
        tuple(instructions),
        model.convention,
        model.dof,
        robot,
        limits or MotionLimits(),
    )
