"""IK solutions of one pose labelled by arm configuration, as a jog panel lists them."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, UnreachableError
from workbench.kinematics.ik_report import branch_names
from workbench.kinematics.joint_turns import all_turns
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]


def branch_solutions(
    model: RobotModel, T_base_flange: ArrayLike, q_near: ArrayLike | None = None
) -> tuple[FloatArray, NDArray[np.int64]]:
    """Return (q (k, dof) [rad], branch (k,)): the IK solutions of one pose (4, 4) in limits.

    Analytic models: one row per valid arm configuration, `branch` its index (0..7), wide
    joints on the turn nearest q_near. Numeric models: the solver's rows, branch -1. An
    unreachable pose gives k = 0 (no error).
    """
    T = np.asarray(T_base_flange, dtype=float)
    if model.is_analytic:
        qb, valid = model.ik_batch(T[None], q_near=q_near)
        b = np.flatnonzero(valid[0])
        return np.asarray(qb[0, b], float).reshape(-1, model.dof), b.astype(np.int64)
    try:
        rows = np.asarray(model.ik(T, q_near=q_near), float).reshape(-1, model.dof)
    except UnreachableError:
        rows = np.zeros((0, model.dof))
    return rows, np.full(len(rows), -1, dtype=np.int64)


def labelled_solutions(
    model: RobotModel, T_base_flange: ArrayLike, q_near: ArrayLike
) -> list[tuple[str, FloatArray]]:
    """Return (label, q (dof,) [rad]) of every IK solution of one pose (4, 4), nearest q_near first.

    Analytic models: every arm configuration at every turn of the wide joints the limits
    allow, labelled by `ik_report.branch_names` ('front/elbow up/no flip, J6 +1 turn'): the
    labels and the set of solutions depend on the pose only, not on q_near, so a list of them
    stays the same when the arm moves from one solution to another. Numeric models: the
    solver's rows, 'solution k'. Raises UnreachableError when there is none.
    """
    qn = np.asarray(q_near, dtype=float)
    rows, branches = branch_solutions(model, T_base_flange, qn)
    if len(rows) and branches[0] >= 0:
        limits = np.asarray(model.limits, float)
        rows = np.concatenate([all_turns(r, limits) for r in rows], axis=0)
        names = branch_names(model, rows)
    else:
        names = [f"solution {k + 1}" for k in range(len(rows))]
    seen: dict[str, int] = {}
    found = []
    for name, q in zip(names, rows, strict=True):
        seen[name] = seen.get(name, 0) + 1  # a tie on a configuration boundary stays apart
        found.append((name if seen[name] == 1 else f"{name} ({seen[name]})", np.array(q)))
    if not found:
        raise UnreachableError(
            "the TCP pose is unreachable: no inverse-kinematics solution within the joint limits"
        )
    found.sort(key=lambda s: float(np.linalg.norm(s[1] - qn)))
    return found


def pick_solution(
    solutions: list[tuple[str, FloatArray]], configuration: int | str | None
) -> FloatArray:
    """Return the q of `solutions` (as `labelled_solutions` gives them) that `configuration` names.

    None: the first (nearest); an int: that index; a str: that label. A bad index raises
    InputError, a label that cannot reach the pose UnreachableError; both list what exists.
    """
    if configuration is None:
        return solutions[0][1]
    if isinstance(configuration, int):
        if not 0 <= configuration < len(solutions):
            raise InputError(
                f"configuration: index {configuration} out of range; {len(solutions)} solution(s) exist"
            )
        return solutions[configuration][1]
    for label, q in solutions:
        if label == configuration:
            return q
    raise UnreachableError(
        f"configuration {configuration!r} cannot reach this pose; available:"
        f" {[label for label, _ in solutions]}"
    )
