"""Joint and linear moves turned into joint waypoints through IK, with blends, then timed.

A linear move is sampled along its straight line (position) and slerp (orientation); each
sample's IK solution is the one nearest the previous sample (`kinematics.follow_path`,
``track="nearest"``), the first one nearest the joints the move starts from; a jump larger
than `max_joint_step` (from the start, or between samples) or an unreachable sample is an
error naming the move and the sample. A zone > 0 between two linear moves replaces the corner by
a quadratic Bezier curve that leaves the first line `zone` metres before the corner and
joins the second line `zone` metres after it (shortened to half of either line).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial.transform import Rotation, Slerp

from workbench.errors import InputError, PlanningError, UnreachableError
from workbench.geometry.transforms import invert_transform, make_transform
from workbench.kinematics.model import RobotModel
from workbench.kinematics.path_ik import follow_path
from workbench.motion.program import JOINT, LINEAR, Program
from workbench.motion.trajectory import Trajectory, smooth_joint_path

# A line of a whole number of steps (85 mm at 5 mm) gets that many samples even when its
# length carries rounding noise (a target read back from a program): the count, and so the
# planned time, does not jump with the rounding of a re-read pose (RAPID/KRL/LS write 4 decimals
# of a mm: 5e-8 m, 1e-5 of a 5 mm step): a line up to 1e-3 of a step longer is not split again.
_COUNT_SLACK = 1e-3
#: How `plan_program` samples a linear move by default: every LINE_STEP [m] of TCP travel and
#: LINE_ANGLE_STEP [rad] of tool rotation (a workflow that times a straight line itself samples
#: it the same way, so the line planned again as a linear move takes the same time).
LINE_STEP = 0.005
LINE_ANGLE_STEP = float(np.radians(2.0))


@dataclass(frozen=True, eq=False)
class JointPath:
    """Joint waypoints (M, 6) [rad] of a program; `move_index[k]` is the move waypoint k belongs to.

    `stop_indices` are exact stops; `speed_limits` (M-1, 6) [rad/s] are per-segment joint
    speed limits that realise each move's speed.
    """

    positions: NDArray[np.float64]
    move_index: NDArray[np.int64]
    stop_indices: tuple[int, ...]
    speed_limits: NDArray[np.float64]


def line_poses(T_a: NDArray, T_b: NDArray, step: float, angle_step: float) -> NDArray[np.float64]:
    """Return poses (k, 4, 4) along the straight line a -> b, excluding a, including b."""
    dist = float(np.linalg.norm(T_b[:3, 3] - T_a[:3, 3]))
    rots = Rotation.from_matrix(np.stack([T_a[:3, :3], T_b[:3, :3]]))
    angle = float((rots[0].inv() * rots[1]).magnitude())
    n = max(1, int(np.ceil(max(dist / step, angle / angle_step) - _COUNT_SLACK)))
    s = np.arange(1, n + 1) / n
    R = Slerp([0.0, 1.0], rots)(s).as_matrix()
    return make_transform(R, T_a[:3, 3] + s[:, None] * (T_b[:3, 3] - T_a[:3, 3]))


def corner_poses(
    T_in: NDArray, T_corner: NDArray, T_out: NDArray, step: float, angle_step: float
) -> NDArray[np.float64]:
    """Return poses (k, 4, 4) of the quadratic Bezier blend from T_in via T_corner to T_out."""
    p0, p1, p2 = T_in[:3, 3], T_corner[:3, 3], T_out[:3, 3]
    length = float(np.linalg.norm(p1 - p0) + np.linalg.norm(p2 - p1))
    rots = Rotation.from_matrix(np.stack([T_in[:3, :3], T_out[:3, :3]]))
    angle = float((rots[0].inv() * rots[1]).magnitude())
    n = max(2, int(np.ceil(max(length / step, angle / angle_step) - _COUNT_SLACK)))
    s = np.arange(1, n + 1) / n
    pos = ((1 - s) ** 2)[:, None] * p0 + (2 * s * (1 - s))[:, None] * p1 + (s**2)[:, None] * p2
    return make_transform(Slerp([0.0, 1.0], rots)(s).as_matrix(), pos)


def follow_poses(
    robot: RobotModel,
    T_base_flange: NDArray,
    q_prev: NDArray,
    *,
    max_joint_step: float,
    label: str,
) -> NDArray[np.float64]:
    """Return joints (k, 6) [rad] for poses (k, 4, 4), each the IK solution nearest the last
    (the first nearest q_prev, the joints the move starts from).

    Raises PlanningError naming the move and the point that is unreachable or needs a joint
    jump over `max_joint_step` [rad], from q_prev to the first point too.
    """
    names = [f"point {k}" for k in range(len(T_base_flange))]
    try:
        path = follow_path(
            robot,
            T_base_flange,
            q_prev,
            labels=names,
            what=label,
            max_joint_step=max_joint_step,
            track="nearest",
        )
    except UnreachableError as exc:
        raise PlanningError(exc.detail, field=exc.field) from exc
    # follow_path bounds the steps between the poses; the step onto the first is the move's.
    jump = float(np.abs(path.q[0] - q_prev).max())
    if jump > max_joint_step:
        raise PlanningError(
            f"{label}: point 0 at {T_base_flange[0, :3, 3].round(4).tolist()} m needs a joint"
            f" jump of {jump:.3f} rad from the move's start (more than max_joint_step"
            f" {max_joint_step} rad): a configuration flip or singularity; move the path or"
            " split it with a joint move"
        )
    return path.q


def plan_program(
    robot: RobotModel,
    program: Program,
    q_start: ArrayLike,
    max_velocity: ArrayLike,
    *,
    T_flange_tcp: ArrayLike | None = None,
    step: float = LINE_STEP,
    angle_step: float = LINE_ANGLE_STEP,
    max_joint_step: float = 0.2,
) -> JointPath:
    """Return the `JointPath` of `program` from joints `q_start` (6,) [rad].

    Linear moves are sampled every `step` [m] / `angle_step` [rad]; `max_velocity` (6,)
    [rad/s] is scaled by joint-move speed fractions, and capped for linear moves so the TCP
    speed stays at most the move's speed.
    """
    T_ft = np.eye(4) if T_flange_tcp is None else np.asarray(T_flange_tcp, float)
    T_tf = invert_transform(T_ft)
    vmax = np.asarray(max_velocity, float)
    q = np.asarray(q_start, float).reshape(-1)
    if q.shape != (6,) or not np.all(np.isfinite(q)):
        raise InputError(f"q_start must be 6 finite joint angles [rad], got {q_start!r}")
    pts, owner, stops, seg_v = [q], [-1], [0], []
    moves = program.moves
    for m, mv in enumerate(moves):
        label = f"move {m} ({mv.name or mv.kind})"
        if mv.kind == JOINT:
            new, v = mv.q[None], [mv.speed * vmax]
        else:
            # after a blend, the last waypoint is where the blend curve ended
            T_from = np.asarray(robot.fk(pts[-1]), float) @ T_ft
            T_to = mv.T
            nxt = moves[m + 1] if m + 1 < len(moves) else None
            if mv.zone > 0 and nxt is not None and nxt.kind == LINEAR:
                len_in = max(float(np.linalg.norm(T_to[:3, 3] - T_from[:3, 3])), 1e-12)
                len_out = max(float(np.linalg.norm(nxt.T[:3, 3] - T_to[:3, 3])), 1e-12)
                r = min(mv.zone, 0.5 * len_in, 0.5 * len_out)
                f_in, f_out = 1.0 - r / len_in, r / len_out
                T_in = _interp(T_from, T_to, f_in)
                T_out = _interp(T_to, nxt.T, f_out)
                poses = np.concatenate(
                    [
                        line_poses(T_from, T_in, step, angle_step),
                        corner_poses(T_in, T_to, T_out, step, angle_step),
                    ]
                )
            else:
                poses = line_poses(T_from, T_to, step, angle_step)
            new = follow_poses(
                robot, poses @ T_tf, pts[-1], max_joint_step=max_joint_step, label=label
            )
            pos = np.concatenate([T_from[None, :3, 3], poses[:, :3, 3]])
            ds = np.maximum(np.linalg.norm(np.diff(pos, axis=0), axis=1), 1e-9)
            dq = np.abs(np.diff(np.concatenate([pts[-1][None], new]), axis=0))
            v = list(np.clip(dq * (mv.speed / ds)[:, None], 1e-3 * vmax, vmax))
        for row in new:
            pts.append(row)
            owner.append(m)
        seg_v.extend(v)
        if mv.zone == 0.0:
            stops.append(len(pts) - 1)
    return JointPath(np.array(pts), np.array(owner), tuple(stops), np.array(seg_v))


def _interp(T_a: NDArray, T_b: NDArray, f: float) -> NDArray[np.float64]:
    rots = Rotation.from_matrix(np.stack([T_a[:3, :3], T_b[:3, :3]]))
    R = Slerp([0.0, 1.0], rots)([f]).as_matrix()[0]
    return make_transform(R, T_a[:3, 3] + f * (T_b[:3, 3] - T_a[:3, 3]))


def time_program(
    path: JointPath,
    max_acceleration: ArrayLike,
    max_jerk: ArrayLike,
    *,
    position_limits: ArrayLike | None = None,
    dt: float = 0.004,
    program: Program | None = None,
) -> Trajectory:
    """Return the jerk-limited `Trajectory` [s, rad] through a `JointPath`.

    A segment that cannot be timed is named by its move ("move 3 (pick)" with the
    `program` the path came from, else "move 3") in the PlanningError."""
    moves = program.moves if program is not None else ()
    labels = [
        "the start"
        if m < 0
        else f"move {m} ({moves[m].name or moves[m].kind})"
        if m < len(moves)
        else f"move {m}"
        for m in path.move_index.tolist()
    ]
    return smooth_joint_path(
        path.positions,
        path.speed_limits,
        max_acceleration,
        max_jerk,
        position_limits=position_limits,
        exact_stop=path.stop_indices,
        dt=dt,
        labels=labels,
    )
