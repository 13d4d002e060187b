"""What the assembly exports: each robot's program of the sequence, and a part plan's key points.

Robot programs (`assembly_programs`, issue 12): one `RobotProgram` per robot. Per task of the
robot: a joint move to the approach pose, a linear approach to the pick, the gripper closes, the
carried path as joint moves through the planned waypoints (5 mm blends), an exact stop at the
place, the gripper opens, a linear retreat, a joint move home. Every target carries the planned
joints (the task trajectory's waypoints, never re-solved), Cartesian ones also the TCP in the
robot's base work object and their arm configuration; every move its planned duration (the time
between the waypoints; a linear approach or retreat spans the waypoints of its straight line,
which the task timed in joint space: its TCP speed is the one at which the motion planner takes
that time, `fit_linear_speed`).
The tasks run one after the other: where a task's robot is not the previous task's, the two
robots meet at a sync point (the same name, in the same order, in both programs): the previous
one after its task, the next one before it; RAPID writes WaitSyncTask, the other posts an I/O
handshake with each robot's `sync` signals. Run that way, each task starts when the plan starts
it and the programs end at the plan's duration.

Legacy programs (`robot_program`, the first posts): one joint move per waypoint the motion module timed (approach pose, approach,
the carried path every 20 mm, retreat, home) at the sequence's speed; exact stops at the
approach pose, the pick and the place, 5 mm blends elsewhere. Key points: CSV or JSON in
the units of the project file and the controllers (mm, deg).
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Sequence
from typing import Any

import numpy as np

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.part_moves import PartPlan
from workbench.assembly.tasks import TaskPlan
from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform, matrix_to_rpy
from workbench.motion.programs.controller_program import (
    Comment,
    Instruction,
    MoveInstr,
    ProgramSettings,
    RobotProgram,
    SyncPoint,
    Target,
    ToolData,
    WorkObject,
)
from workbench.motion.programs.from_plan import fit_linear_speed

KEY_POINT_FORMATS = ("csv", "json")
_MM = 1e-3  # m per mm
_DEG = np.pi / 180.0  # rad per deg
BLEND = 0.005  # zone [m] of the moves between exact stops


def program_name(robot: str) -> str:
    """Return the program (and RAPID task) name of robot `robot`'s assembly program."""
    return "".join(c if c.isalnum() else "_" for c in f"assembly_{robot}")[:24]


def _task_moves(
    k: int, task: TaskPlan, arm: AssemblyArm, tool: ToolData, settings: ProgramSettings
) -> list[Instruction]:
    """Return the instructions of task number `k` (see the module docstring)."""
    model, T_flange_tcp = arm.setup.model, arm.setup.T_flange_tcp
    wp, wt = task.trajectory.waypoints, np.asarray(task.trajectory.waypoint_times, float)
    n = len(wp)
    pick = int(np.argmin(np.abs(wt - (task.t_pick - task.t0))))
    place = int(np.argmin(np.abs(wt - (task.t_place - task.t0))))
    tcp = model.fk(wp) @ T_flange_tcp  # the robot base is the work object

    def move(
        kind: str,
        i: int,
        a: int,
        label: str,
        cartesian: bool = True,
        zone: float = 0.0,
        speed: float = 1.0,
    ) -> MoveInstr:
        dt = float(wt[i] - wt[a])
        if kind == "linear":  # the speed at which the motion planner takes the planned time
            top = settings.limits.max_tcp_speed
            speed = fit_linear_speed(model, T_flange_tcp, wp[a], tcp[i], dt, top)
        tgt = Target.planned(f"t{k + 1}_{label}", wp[i], model, tcp[i] if cartesian else None)
        return MoveInstr(kind, tgt, speed, zone, tool.name, "base", dt)  # type: ignore[arg-type]

    def grip(close: bool) -> Instruction:
        g = settings.close if close else settings.open
        what = "close" if close else "open"
        return (
            g
            if g is not None
            else Comment(f"gripper {what}: the project has no io.gripper; add one")
        )

    out: list[Instruction] = [Comment(f"task {k + 1}: {task.part}")]
    out.append(move("joint", 1, 0, "approach"))
    if pick > 1:
        out.append(move("linear", pick, 1, "pick"))
    out.append(grip(True))
    for i in range(pick + 1, place + 1):
        label = "place" if i == place else f"c{i - pick}"
        out.append(move("joint", i, i - 1, label, zone=0.0 if i == place else BLEND))
    out.append(grip(False))
    if n - 2 > place:
        out.append(move("linear", n - 2, place, "retreat"))
    out.append(move("joint", n - 1, n - 2, "home", cartesian=False))
    return out


def assembly_programs(
    tasks: Sequence[TaskPlan],
    arms: dict[str, AssemblyArm],
    settings: ProgramSettings,
    tools: dict[str, ToolData] | None = None,
) -> list[RobotProgram]:
    """Return one `RobotProgram` per robot that has a task, in the order of `arms` (see the
    module docstring).

    `settings`: the main arm's tool (`settings.tool`), the gripper actions (None: a comment
    says so), the sync signals per robot, the motion limits. `tools`: the further arms' tools by
    robot name (TCP, mass, centre of gravity; a further arm not in it gets its setup's TCP as
    "<robot>_tool", without mass). Joint moves run at speed 1 in their planned times.
    """
    used = [name for name in arms if any(t.robot == name for t in tasks)]
    if not used:
        raise InputError("the planned sequence has no task; plan the sequence first")
    given = tools or {}
    tools = {
        n: settings.tool
        if arms[n].main
        else given.get(n) or ToolData(f"{n}_tool", arms[n].setup.T_flange_tcp)
        for n in used
    }
    world = next((a.setup.T_world_base for a in arms.values() if a.main), np.eye(4))
    ins: dict[str, list[Instruction]] = {n: [] for n in used}
    n_sync = 0
    for k, task in enumerate(tasks):
        if k > 0 and tasks[k - 1].robot != task.robot:
            n_sync += 1
            pair = (tasks[k - 1].robot, task.robot)
            names = tuple(program_name(r) for r in pair)
            for r in pair:
                out, inp = settings.sync.get(r, (None, None))
                ins[r].append(SyncPoint(f"sync{n_sync}", names, out, inp))  # type: ignore[arg-type]
        ins[task.robot] += _task_moves(k, task, arms[task.robot], tools[task.robot], settings)
    return [
        RobotProgram(
            program_name(n),
            (tools[n],),
            (WorkObject("base", np.eye(4)),),
            tuple(ins[n]),
            arms[n].setup.model.convention,
            arms[n].setup.model.dof,
            n,
            settings.limits,
            # MultiMove's shared world is the main arm's base (its wobj0)
            T_world_base=invert_transform(np.asarray(world, float))
            @ np.asarray(arms[n].setup.T_world_base, float),
        )
        for n in used
    ]


def key_points_text(plan: PartPlan, fmt: str) -> str:
    """Return the key points of a part plan as CSV or JSON text (mm, deg).

    Columns: index, x, y, z [mm], roll, pitch, yaw [deg] (R = Rz·Ry·Rx), and for a carried
    part the carrying robot's joints [deg] at that key point (the nearest dense sample).
    """
    if fmt not in KEY_POINT_FORMATS:
        raise InputError(f"fmt must be one of {KEY_POINT_FORMATS}, got {fmt!r}")
    rows = []
    for i, T in enumerate(plan.key_points):
        xyz = T[:3, 3] / _MM
        rpy = matrix_to_rpy(T[:3, :3]) / _DEG
        row: dict[str, Any] = {"index": i}
        row.update({k: float(v) for k, v in zip(("x", "y", "z"), xyz, strict=True)})
        row.update({k: float(v) for k, v in zip(("roll", "pitch", "yaw"), rpy, strict=True)})
        if plan.joints is not None:
            j = int(np.argmin(np.linalg.norm(plan.samples[:, :3, 3] - T[:3, 3], axis=1)))
            row.update({f"j{k + 1}": float(v / _DEG) for k, v in enumerate(plan.joints[j])})
        rows.append(row)
    if fmt == "json":
        return json.dumps(
            {
                "part": plan.part,
                "planner": plan.path.planner,
                "robot": plan.robot,
                "units": {
                    "position": "mm",
                    "orientation": "deg (R = Rz(yaw) Ry(pitch) Rx(roll))",
                },
                "key_points": rows,
            },
            indent=2,
        )
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    for r in rows:
        writer.writerow({k: (f"{v:.4f}" if isinstance(v, float) else v) for k, v in r.items()})
    return buf.getvalue()
