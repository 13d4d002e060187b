"""follow_path: inverse kinematics of a sequence of flange poses in one arm configuration.

The one rule of every workflow that makes a robot follow poses (a linear move, a carried
part, a polishing path, the bend placements and transfer of the press brake):

- analytic models (`is_analytic`): every branch of every pose at once (`ik_batch`, wide
  joints on the turn nearest `q_near`); a branch valid at every pose is kept, its wide
  joints made continuous (unwrapped, then shifted as a whole by the turn nearest `q_near`
  that fits the limits); branches whose joints jump more than `max_joint_step` between
  consecutive poses are dropped; of the rest the one nearest `q_near` wins (`cost`);
- numeric models, or `track="nearest"`: pose by pose, the `ik` solution nearest the
  previous pose (seeded there), which may change configuration where two meet.

`track="nearest"` on an analytic model is what linear moves use: the per-pose solver is
exact where the batch one leaves ~1e-16 rad of noise (a wrist joint at 0 stays 0), and the
jerk-limited timing of a move reacts to that noise (its direction changes), so the moves
keep the per-pose values.

Errors name the pose (its label and position in mm): UnreachableError when a pose has no
solution, or no single configuration reaches them all; PlanningError when every
configuration that reaches them all jumps (a flip, a singularity or a joint limit).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, PlanningError, UnreachableError
from workbench.kinematics.ik_report import branch_name
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]
NUMERIC = "nearest solution"
"""`PathIK.configuration` of a numeric model (no branches: each pose nearest the previous)."""
_TWO_PI = 2.0 * np.pi
_SLACK = 1e-9  # rad: rounding allowed at a joint limit after unwrapping


@dataclass(frozen=True, eq=False)
class PathIK:
    """Joints along a pose sequence, all in one arm configuration.

    q: (N, dof) [rad], fk(q[i]) == T_base_flange[i]; branch: the analytic branch
    b = 4 * shoulder + 2 * elbow + wrist (-1 for a numeric model); configuration: its name
    (`branch_name(model, q[0])`, or "nearest solution"); max_step: the largest joint change between
    consecutive poses [rad] (0 for one pose).
    """

    q: FloatArray
    branch: int
    configuration: str
    max_step: float


def follow_path(
    model: RobotModel,
    T_base_flange: ArrayLike,
    q_near: ArrayLike,
    *,
    labels: Sequence[str] | None = None,
    what: str = "path",
    max_joint_step: float | None = None,
    cost: Literal["start", "total"] = "start",
    track: Literal["configuration", "nearest"] = "configuration",
    points: ArrayLike | None = None,
    hint: str = "",
    branch: int | None = None,
) -> PathIK:
    """Return the `PathIK` that puts the flange on every pose (N, 4, 4) [m] in one configuration.

    q_near (dof,) [rad]: the robot's joints before the first pose; it picks the
    configuration and the joint turns. max_joint_step [rad]: largest joint change allowed
    between consecutive poses (None: any, for poses that are not a continuous path).
    cost: "start" keeps the configuration nearest q_near at the first pose (a path the
    robot enters there), "total" the one with the least summed distance to q_near over all
    poses (separate poses visited from q_near). track: "configuration" keeps one analytic
    branch over all poses (numeric models: "nearest"), "nearest" takes pose by pose the
    solution nearest the previous one (see the module docstring). Errors name the pose by `labels` (N,)
    (default "pose i of N") and its position from `points` (N, 3) [m] (default the flange
    in the base frame), prefixed by `what` and followed by `hint` (the fix to suggest).
    branch: analytic models only, keep that `ik_batch` branch (None: the one `cost` picks).
    """
    T = np.asarray(T_base_flange, dtype=float)
    if T.ndim != 3 or T.shape[1:] != (4, 4) or len(T) == 0:
        raise InputError(f"T_base_flange: expected shape (N, 4, 4) with N >= 1, got {T.shape}")
    qn = np.asarray(q_near, dtype=float).reshape(-1)
    if qn.shape != (model.dof,) or not np.all(np.isfinite(qn)):
        raise InputError(f"q_near: expected {model.dof} finite joint values [rad], got {q_near!r}")
    if labels is not None and len(labels) != len(T):
        raise InputError(f"labels: expected {len(T)} names, got {len(labels)}")
    where = T[:, :3, 3] if points is None else np.asarray(points, dtype=float).reshape(-1, 3)
    fix = f"; {hint}" if hint else ""

    def name(i: int) -> str:
        head = labels[i] if labels is not None else f"pose {i + 1} of {len(T)}"
        return f"{head} at [{', '.join(f'{v * 1000.0:.1f}' for v in where[i])}] mm"

    if model.is_analytic and track == "configuration":
        q, b = _analytic(model, T, qn, max_joint_step, cost, what, name, fix, branch)
        configuration = branch_name(model, q[0])
    else:
        q, b, configuration = _numeric(model, T, qn, what, name, fix), -1, NUMERIC
    steps = np.abs(np.diff(q, axis=0)).max(axis=1) if len(q) > 1 else np.zeros(0)
    if max_joint_step is not None and (steps > max_joint_step).any():
        i = int(np.argmax(steps > max_joint_step)) + 1
        raise PlanningError(_jump(what, name(i), steps[i - 1], configuration, max_joint_step, fix))
    return PathIK(q=q, branch=b, configuration=configuration, max_step=float(steps.max(initial=0)))


def _analytic(
    model: RobotModel,
    T: FloatArray,
    qn: FloatArray,
    max_joint_step: float | None,
    cost: str,
    what: str,
    name: Callable[[int], str],
    fix: str,
    only: int | None = None,
) -> tuple[FloatArray, int]:
    """Return (q (N, dof), branch) of the nearest branch valid and continuous along T
    (`only`: that branch alone)."""
    qb, valid = model.ik_batch(T, q_near=qn)
    if only is not None:
        keep = np.zeros(valid.shape[1], dtype=bool)
        keep[only] = True
        valid = valid & keep
    reach_any = valid.any(axis=1)
    if not reach_any.all():
        i = int(np.argmin(reach_any))
        raise UnreachableError(
            f"{what}: {name(i)} is unreachable in every arm configuration (no inverse-kinematics "
            f"solution within the joint limits){fix}"
        )
    all_ok = valid.all(axis=0)
    if not all_ok.any():
        # Name where the configuration reaching furthest along the poses gives up.
        reach = np.argmin(valid, axis=0)
        b = int(np.argmax(reach))
        furthest = branch_name(model, qb[max(int(reach[b]) - 1, 0), b])
        raise UnreachableError(
            f"{what}: no single arm configuration reaches every pose: '{furthest}', "
            f"the one reaching furthest, misses {name(int(reach[b]))}{fix}"
        )
    limits = np.asarray(model.limits, dtype=float)
    best: tuple[float, int, FloatArray] | None = None
    jumped: tuple[float, int, int, float] | None = None  # (cost, branch, pose, jump)
    for b in np.flatnonzero(all_ok).tolist():
        q = _continuous(qb[:, b], limits, qn)
        dist = np.linalg.norm(q - qn, axis=1)
        c = float(dist[0] if cost == "start" else dist.sum())
        if max_joint_step is not None and len(q) > 1:
            steps = np.abs(np.diff(q, axis=0)).max(axis=1)
            if (steps > max_joint_step).any():
                i = int(np.argmax(steps > max_joint_step))
                if jumped is None or c < jumped[0]:
                    jumped = (c, b, i + 1, float(steps[i]))
                continue
        if best is None or c < best[0]:
            best = (c, b, q)
    if best is None:
        assert jumped is not None and max_joint_step is not None
        _, b, i, jump = jumped
        raise PlanningError(
            _jump(what, name(i), jump, branch_name(model, qb[0, b]), max_joint_step, fix)
        )
    return best[2], best[1]


def _numeric(
    model: RobotModel,
    T: FloatArray,
    qn: FloatArray,
    what: str,
    name: Callable[[int], str],
    fix: str,
) -> FloatArray:
    """Return q (N, dof): per pose the IK solution nearest the previous pose's."""
    q = np.empty((len(T), model.dof))
    prev = qn
    for i in range(len(T)):
        why = "no inverse-kinematics solution within the joint limits"
        try:
            sols = np.asarray(model.ik(T[i], q_near=prev), dtype=float).reshape(-1, model.dof)
        except UnreachableError as exc:
            sols, why = np.zeros((0, model.dof)), str(exc)
        if len(sols) == 0:
            raise UnreachableError(f"{what}: {name(i)} is unreachable ({why}){fix}")
        prev = q[i] = sols[int(np.argmin(np.linalg.norm(sols - prev, axis=1)))]
    return q


def _continuous(q: FloatArray, limits: FloatArray, q_near: FloatArray) -> FloatArray:
    """Return q (N, dof) with the turn jumps of wide joints removed where the limits allow.

    A wide joint (limits beyond [-pi, pi]) is unwrapped, then shifted as a whole by the
    turn nearest q_near (dof,) at the first pose that keeps it inside its limits; a joint
    that fits no turn is left as solved (its jump then shows in the step check).
    """
    out = q.copy()
    lo, hi = limits[:, 0], limits[:, 1]
    for j in np.flatnonzero(~((lo >= -np.pi) & (hi <= np.pi))):
        u = np.unwrap(out[:, j])
        for k in sorted(range(-3, 4), key=lambda k: abs(u[0] + _TWO_PI * k - q_near[j])):
            cand = u + _TWO_PI * k if k else u
            if cand.min() >= lo[j] - _SLACK and cand.max() <= hi[j] + _SLACK:
                out[:, j] = cand
                break
    return out


def _jump(what: str, where: str, jump: float, config: str, limit: float, fix: str) -> str:
    return (
        f"{what}: {where} needs a joint jump of {jump:.3f} rad in configuration '{config}' "
        f"(more than max_joint_step {limit} rad): a configuration flip, a singularity or a "
        f"joint limit on the way{fix or '; move the path or split it with a joint move'}"
    )
