"""A robot carrying a part: inverse kinematics along a TCP path in one consistent configuration."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import UnreachableError
from workbench.geometry.transforms import invert_transform

#: Largest joint change [rad] allowed between consecutive TCP samples of a carried path; a
#: larger one means the configuration flipped (a wrist or shoulder singularity was crossed).
MAX_JOINT_STEP = 0.5


@dataclass(frozen=True)
class CarryIK:
    """Joints (M, dof) [rad] along a TCP path, all in one arm configuration (`branch`, -1 if numeric)."""

    q: NDArray[np.float64]
    branch: int
    max_step: float


def _unwrap_into_limits(q: NDArray[np.float64], limits: NDArray[np.float64]) -> NDArray | None:
    """Return q (M, dof) with each joint's turns made continuous and inside limits, or None."""
    out = np.unwrap(q, axis=0)
    for j in range(q.shape[1]):
        lo, hi = limits[j]
        col = out[:, j]
        for shift in (0.0, 2 * np.pi, -2 * np.pi, 4 * np.pi, -4 * np.pi):
            c = col + shift
            if c.min() >= lo - 1e-9 and c.max() <= hi + 1e-9:
                out[:, j] = c
                break
        else:
            return None
    return out


def carry_ik(
    model: Any,
    T_world_base: ArrayLike,
    T_flange_tcp: ArrayLike,
    T_world_tcp: ArrayLike,
    q_near: ArrayLike,
    *,
    what: str = "path",
) -> CarryIK:
    """Return the joints that put the TCP on every pose of `T_world_tcp` (M, 4, 4) [m], one configuration.

    The arm configuration (branch) is the one valid at every pose, continuous (no joint
    moves more than MAX_JOINT_STEP between poses) and nearest `q_near` (dof,) [rad] at the
    first pose. Raises UnreachableError naming the first pose (index and position in mm)
    that no single configuration reaches within the joint limits.
    """
    Tw = np.asarray(T_world_tcp, float).reshape(-1, 4, 4)
    Tb = invert_transform(np.asarray(T_world_base, float))
    Tf = invert_transform(np.asarray(T_flange_tcp, float))
    T_bf = Tb @ Tw @ Tf
    q_ref = np.asarray(q_near, float)
    limits = np.asarray(model.limits, float)
    if getattr(model, "is_analytic", False) and hasattr(model, "ik_batch"):
        qb, valid = model.ik_batch(T_bf, q_near=q_ref)
        best: tuple[float, int, NDArray[np.float64], float] | None = None
        for b in range(qb.shape[1]):
            if not valid[:, b].all():
                continue
            q = _unwrap_into_limits(qb[:, b], limits)
            if q is None:
                continue
            step = float(np.abs(np.diff(q, axis=0)).max(initial=0.0))
            if step > MAX_JOINT_STEP:
                continue
            cost = float(np.linalg.norm(q[0] - q_ref))
            if best is None or cost < best[0]:
                best = (cost, b, q, step)
        if best is not None:
            return CarryIK(q=best[2], branch=best[1], max_step=best[3])
        # Name the pose where the configuration reaching furthest gives up.
        reach = [
            int(np.argmin(valid[:, b])) if not valid[:, b].all() else len(Tw)
            for b in range(qb.shape[1])
        ]
        i = int(max(reach))
        if i >= len(Tw):
            raise UnreachableError(
                f"{what}: every arm configuration that reaches all {len(Tw)} poses flips on the way "
                f"(a joint would jump more than {np.degrees(MAX_JOINT_STEP):.0f} deg between "
                "samples, or leave its limits); move the start or goal, or change the grasp"
            )
        raise UnreachableError(_unreachable(what, i, len(Tw), Tw[i]))
    rows = []
    prev = q_ref
    for i, T in enumerate(T_bf):
        try:
            sols = np.asarray(model.ik(T, q_near=prev), float).reshape(-1, model.dof)
        except UnreachableError:
            sols = np.zeros((0, model.dof))
        if len(sols) == 0:
            raise UnreachableError(_unreachable(what, i, len(Tw), Tw[i]))
        prev = sols[np.argmin(np.linalg.norm(sols - prev, axis=1))]
        rows.append(prev)
    q = np.asarray(rows)
    step = float(np.abs(np.diff(q, axis=0)).max(initial=0.0))
    return CarryIK(q=q, branch=-1, max_step=step)


def _unreachable(what: str, i: int, n: int, T: NDArray[np.float64]) -> str:
    p = ", ".join(f"{v * 1000:.1f}" for v in T[:3, 3])
    return (
        f"{what}: pose {i + 1} of {n} (TCP at [{p}] mm) is out of reach of the robot in one arm "
        "configuration (no inverse-kinematics solution within the joint limits); move the "
        "start or goal closer to the robot, or change the grasp"
    )
