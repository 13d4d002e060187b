"""Robot motion along a polishing path: TCP frames with z into the surface, IK in one configuration.

The tool is round, so its rotation about its own axis is free; the frames keep their x
axis as close as possible to a fixed reference direction (the workpiece's x), so the wrist
does not turn a full circle per spiral lap. Every point is solved in the same arm
configuration (shoulder, elbow, wrist branch), and wide joints are kept continuous.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, PlanningError, UnreachableError
from workbench.kinematics import branch_name

F64 = NDArray[np.float64]

#: Largest joint change [rad] allowed between consecutive path points (a larger one is a
#: configuration flip or a pass near a singularity).
MAX_JOINT_STEP = 0.2


def tool_frames(points: ArrayLike, tool_z: ArrayLike, x_ref: ArrayLike) -> F64:
    """Return frames (N, 4, 4) [m] at `points` (N, 3) with z along unit `tool_z` (N, 3).

    x is `x_ref` (3,) projected onto the plane normal to z (another axis where x_ref is
    nearly parallel to z); y = z × x. Raises `InputError` for bad shapes or zero vectors.
    """
    p = np.asarray(points, dtype=float)
    z = np.asarray(tool_z, dtype=float)
    xr = np.asarray(x_ref, dtype=float)
    if p.ndim != 2 or p.shape[1] != 3 or z.shape != p.shape:
        raise InputError(f"points and tool_z must both be (N, 3), got {p.shape} and {z.shape}")
    if xr.shape != (3,) or not np.linalg.norm(xr) > 0:
        raise InputError(f"x_ref must be a nonzero 3-vector, got {xr!r}")
    zn = np.linalg.norm(z, axis=1, keepdims=True)
    if not (zn > 1e-12).all():
        raise InputError("tool_z contains zero-length vectors")
    z = z / zn
    x = xr[None, :] - (z @ xr)[:, None] * z
    xn = np.linalg.norm(x, axis=1)
    weak = xn < 1e-6 * np.linalg.norm(xr)
    if weak.any():
        alt = np.array([0.0, 1.0, 0.0]) if abs(xr[1]) < 0.9 * np.linalg.norm(xr) else np.eye(3)[2]
        x[weak] = alt - (z[weak] @ alt)[:, None] * z[weak]
        xn = np.linalg.norm(x, axis=1)
    x /= xn[:, None]
    y = np.cross(z, x)
    T = np.zeros((len(p), 4, 4))
    T[:, :3, 0], T[:, :3, 1], T[:, :3, 2], T[:, :3, 3] = x, y, z, p
    T[:, 3, 3] = 1.0
    return T


def _continuous(q: F64, limits: F64, q_near: F64) -> F64:
    """Return q (N, n) with 2π jumps of wide joints removed where the limits allow it, each
    wide joint on the turn that starts nearest q_near (n,)."""
    out = q.copy()
    wide = (limits[:, 1] - limits[:, 0]) > 2 * np.pi
    for j in np.flatnonzero(wide):
        u = np.unwrap(out[:, j])
        # Shift the whole unwrapped run by whole turns into the limits, nearest turn first.
        turns = sorted(range(-3, 4), key=lambda k: abs(u[0] + 2 * np.pi * k - q_near[j]))
        for k in turns:
            cand = u + 2 * np.pi * k
            if cand.min() >= limits[j, 0] - 1e-9 and cand.max() <= limits[j, 1] + 1e-9:
                out[:, j] = cand
                break
    return out


def _name(i: int, labels: list[str] | None, T: F64) -> str:
    where = labels[i] if labels else f"point {i}"
    return f"{where} at {np.round(T[i, :3, 3] * 1000.0, 1).tolist()} mm"


def solve_path_ik(
    robot: Any,
    T_base_flange: ArrayLike,
    q_near: ArrayLike,
    *,
    labels: list[str] | None = None,
    max_joint_step: float = MAX_JOINT_STEP,
) -> tuple[F64, str]:
    """Return (joints (N, n) [rad], configuration label): IK of every pose in one configuration.

    T_base_flange (N, 4, 4) [m]; q_near (n,) [rad] picks the configuration (the one whose
    solution at the first pose is nearest) and the joint turns. labels (N,) name the points
    in errors. Raises `UnreachableError` naming the first point that no configuration, or
    not the chosen one, reaches, and `PlanningError` naming a point where a joint would
    jump by more than `max_joint_step` [rad].
    """
    T = np.asarray(T_base_flange, dtype=float)
    qn = np.asarray(q_near, dtype=float)
    if T.ndim != 3 or T.shape[1:] != (4, 4) or len(T) == 0:
        raise InputError(f"T_base_flange must be (N, 4, 4) with N >= 1, got {T.shape}")
    if getattr(robot, "is_analytic", False):
        qb, valid = robot.ik_batch(T, q_near=qn)
        reach_any = valid.any(axis=1)
        if not reach_any.all():
            i = int(np.argmin(reach_any))
            raise UnreachableError(
                f"{_name(i, labels, T)} is unreachable in every arm configuration; move the "
                "workpiece closer to the robot (polishing.pose) or turn it"
            )
        all_ok = valid.all(axis=0)
        d0 = np.where(valid[0], np.linalg.norm(np.nan_to_num(qb[0] - qn, nan=1e9), axis=1), np.inf)
        if not all_ok.any():
            b = int(np.argmin(d0))
            i = int(np.argmin(valid[:, b]))
            raise UnreachableError(
                f"no single arm configuration reaches the whole path: in '{branch_name(b)}' "
                f"{_name(i, labels, T)} is unreachable; move or turn the workpiece"
            )
        b = int(np.argmin(np.where(all_ok, d0, np.inf)))
        q = _continuous(qb[:, b], np.asarray(robot.limits, float), qn)
        label = branch_name(b)
    else:
        q = np.empty((len(T), len(qn)))
        prev = qn
        for i in range(len(T)):
            sols = np.asarray(robot.ik(T[i], q_near=prev), float).reshape(-1, len(qn))
            if len(sols) == 0:
                raise UnreachableError(f"{_name(i, labels, T)} is unreachable; move the workpiece")
            prev = q[i] = sols[int(np.argmin(np.linalg.norm(sols - prev, axis=1)))]
        label = "nearest solution"
    jump = np.max(np.abs(np.diff(q, axis=0)), axis=1) if len(q) > 1 else np.zeros(0)
    if (jump > max_joint_step).any():
        i = int(np.argmax(jump > max_joint_step)) + 1
        raise PlanningError(
            f"{_name(i, labels, T)} needs a joint jump of {jump[i - 1]:.3f} rad in configuration "
            f"'{label}' (more than {max_joint_step} rad): a singularity or joint limit on the way; "
            "move or turn the workpiece"
        )
    return q, label
