"""Robot motion along a polishing path: TCP frames with z into the surface, IK in one configuration.

The tool is round, so its rotation about its own axis is free; the frames keep their x
axis as close as possible to a fixed reference direction (the workpiece's x), so the wrist
does not turn a full circle per spiral lap. Every point is solved in the same arm
configuration (shoulder, elbow, wrist branch), and wide joints are kept continuous
(`workbench.kinematics.follow_path`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.kinematics import RobotModel, follow_path

F64 = NDArray[np.float64]

#: Largest joint change [rad] allowed between consecutive path points (a larger one is a
#: configuration flip or a pass near a singularity).
MAX_JOINT_STEP = 0.2
#: The fix the errors suggest.
HINT = "move or turn the workpiece (polishing.pose)"


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


def solve_path_ik(
    robot: RobotModel,
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
    jump by more than `max_joint_step` [rad] (`workbench.kinematics.follow_path`).
    """
    ik = follow_path(
        robot,
        T_base_flange,
        q_near,
        labels=labels,
        what="polishing path",
        max_joint_step=max_joint_step,
        hint=HINT,
    )
    return ik.q, ik.configuration
