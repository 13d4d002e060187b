"""What the assembly exports: each robot's program of the sequence, and a part plan's key points.

Programs: one joint move per waypoint the motion module timed (approach pose, approach,
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

from workbench.assembly.part_moves import PartPlan
from workbench.assembly.tasks import TaskPlan
from workbench.errors import InputError
from workbench.geometry.transforms import matrix_to_rpy
from workbench.motion import Move, Program

KEY_POINT_FORMATS = ("csv", "json")
_MM = 1e-3  # m per mm
_DEG = np.pi / 180.0  # rad per deg
BLEND = 0.005  # zone [m] of the moves between exact stops


def robot_program(robot: str, tasks: Sequence[TaskPlan], speed: float) -> Program:
    """Return robot `robot`'s part of the sequence `tasks` as a `Program`; speed: fraction of its limits.

    Moves are named t<task>_<waypoint> (task numbers count every task of the sequence).
    InputError when the robot carries no part in `tasks`.
    """
    moves = []
    for k, task in enumerate(tasks):
        if task.robot != robot:
            continue
        wp = task.trajectory.waypoints
        stops = {1, len(wp) - 2, len(wp) - 1} | {
            int(np.argmin(np.abs(task.trajectory.waypoint_times - (t - task.t0))))
            for t in (task.t_pick, task.t_place)
        }
        for i in range(1, len(wp)):
            moves.append(
                Move.joint(
                    wp[i], speed=speed, zone=0.0 if i in stops else BLEND, name=f"t{k + 1}_{i}"
                )
            )
    if not moves:
        raise InputError(f"robot {robot!r} carries no part in the planned sequence")
    name = "".join(c if c.isalnum() else "_" for c in f"assembly_{robot}")[:24]
    return Program(name, tuple(moves))


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
