"""IK solutions of one pose labelled by arm configuration, as a jog panel lists them."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, UnreachableError
from workbench.kinematics.ik_report import branch_name
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]


def labelled_solutions(
    model: RobotModel, T_base_flange: ArrayLike, q_near: ArrayLike
) -> list[tuple[str, FloatArray]]:
    """Return (label, q (dof,) [rad]) of every IK solution of one pose (4, 4), nearest q_near first.

    Analytic models: one solution per arm configuration, labelled by its branch
    ('front/elbow A/no flip'), wide joints on the turn nearest q_near, so labels stay
    stable as the arm moves. Numeric models: 'solution k'. Raises UnreachableError when
    there is none.
    """
    T = np.asarray(T_base_flange, dtype=float)
    qn = np.asarray(q_near, dtype=float)
    if model.is_analytic:
        qb, valid = model.ik_batch(T[None], q_near=qn)
        found = [(branch_name(b), np.array(qb[0, b])) for b in range(qb.shape[1]) if valid[0, b]]
    else:
        rows = np.asarray(model.ik(T, q_near=qn), float).reshape(-1, model.dof)
        found = [(f"solution {k + 1}", row) for k, row in enumerate(rows)]
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
