"""Why a pose has no IK solution: out of reach (by how much) or outside which joint limit."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.kinematics.arm_configuration import arm_configurations
from workbench.kinematics.joint_turns import LIMIT_SLACK, wrap_to_pi
from workbench.kinematics.opw_single import solve_single

if TYPE_CHECKING:
    from workbench.kinematics.dh_robot import DHRobot
    from workbench.kinematics.model import RobotModel

_HALF_TURN = math.pi * (1.0 + 1e-12)  # rad; a joint at exactly +-180 deg is on turn 0


def joint_turn_numbers(model: RobotModel, q_model: ArrayLike) -> NDArray[np.int64]:
    """Return the turn k (..., dof) of each joint: q_ctrl - 360 k deg lies in (-180, 180].

    Counted in the controller's convention (the one the sliders and programs show), so
    "J6 +1 turn" means the controller's J6 is between 180 and 540 deg.
    """
    qc = np.asarray(model.convention.to_controller(np.asarray(q_model, float)), float)
    return np.ceil((qc - _HALF_TURN) / (2.0 * math.pi)).astype(np.int64)


def wide_joints(model: RobotModel) -> NDArray[np.int64]:
    """Return the indices of the joints whose controller limits span more than +-180 deg."""
    lim = np.asarray(model.convention.limits_to_controller(model.limits), float)
    return np.flatnonzero((lim[:, 0] < -_HALF_TURN) | (lim[:, 1] > _HALF_TURN))


def branch_names(model: RobotModel, q_model: ArrayLike) -> list[str]:
    """Return the configuration label of each joint vector q (..., dof) [rad, model convention].

    THE LABELLING RULE of IK configurations: the arm configuration
    (`ArmConfiguration.label()`: 'front/elbow up/no flip') and, for each joint whose limits
    span more than one turn, its turn when not 0 ('J6 +1 turn'): the label tells apart every
    IK solution of one pose and does not depend on where the arm was before.
    """
    q = np.asarray(q_model, float).reshape(-1, model.dof)
    if len(q) == 0:
        return []
    wide = wide_joints(model)
    turns = joint_turn_numbers(model, q)
    names = []
    for conf, k in zip(arm_configurations(model, q), turns, strict=True):
        extra = [
            f"J{j + 1} {int(k[j]):+d} turn{'s' if abs(int(k[j])) > 1 else ''}"
            for j in wide
            if k[j] != 0
        ]
        names.append(", ".join([conf.label(), *extra]))
    return names


def branch_name(model: RobotModel, q_model: ArrayLike) -> str:
    """Return the configuration label of one joint vector q (dof,) [rad] (see `branch_names`)."""
    return branch_names(model, q_model)[0]


def unreachable_reason(robot: DHRobot, T: NDArray[np.float64]) -> str:
    """Return a message saying why pose T (4, 4) [m] has no IK solution for `robot`."""
    pos = T[:3, 3] * 1000.0
    head = f"pose at xyz = [{pos[0]:.1f}, {pos[1]:.1f}, {pos[2]:.1f}] mm is unreachable: "
    g = robot.opw
    if g is None:
        dist = float(np.linalg.norm(T[:3, 3]))
        return head + (
            f"numeric IK (pinocchio CLIK from 15 seeds) found no solution within the joint "
            f"limits; the flange target is {dist * 1000:.1f} mm from the base origin"
        )
    pc = T[:3, 3] - T[:3, 1] * g.w6[1] - T[:3, 2] * g.w6[2]
    rho = math.hypot(pc[0], pc[1])
    if rho < abs(g.b) - 1e-12:
        return head + (
            f"the wrist centre is {rho * 1000:.1f} mm from the joint-1 axis, inside the "
            f"lateral offset of {abs(g.b) * 1000:.1f} mm"
        )
    beta = math.asin(max(-1.0, min(1.0, -g.sig1 * g.b / rho))) if rho > 0 else 0.0
    r_max, r_min = abs(g.a2) + g.K, abs(abs(g.a2) - g.K)
    dists = []
    for sgn in (1.0, -1.0):
        px1 = sgn * rho * math.cos(beta) - g.a1
        py1 = g.sig1 * (pc[2] - g.d1)
        dists.append(math.hypot(px1, py1))
    if min(dists) > r_max:
        return head + (
            f"out of reach by {(min(dists) - r_max) * 1000:.1f} mm (the wrist centre is "
            f"{min(dists) * 1000:.1f} mm from the joint-2 axis; the arm reaches {r_max * 1000:.1f} mm)"
        )
    if max(dists) < r_min:
        return head + (
            f"too close by {(r_min - max(dists)) * 1000:.1f} mm (the wrist centre is "
            f"{max(dists) * 1000:.1f} mm from the joint-2 axis; the arm folds to {r_min * 1000:.1f} mm)"
        )
    problems = []
    lo, hi = robot.limits[:, 0], robot.limits[:, 1]
    for *theta, err in solve_single(g, T):
        if not err < 1e-9:
            continue
        q = wrap_to_pi(np.asarray(theta) - robot.dh[:, 0])
        k_lo = np.ceil((lo - LIMIT_SLACK - q) / (2 * math.pi))
        k_hi = np.floor((hi + LIMIT_SLACK - q) / (2 * math.pi))
        bad = np.nonzero(k_lo > k_hi)[0]
        if bad.size:
            j = int(bad[0])
            problems.append(
                f"{branch_name(robot, q)}: joint {j + 1} = {math.degrees(q[j]):.1f} deg outside "
                f"[{math.degrees(lo[j]):.1f}, {math.degrees(hi[j]):.1f}] deg"
            )
        elif robot.controller_limits is not None and not robot.within_limits(q):
            # a coupled convention (FANUC's J3 from the horizontal): the controller's values
            qc, lim = robot.convention.to_controller(q), robot.controller_limits
            j = int(np.flatnonzero((qc < lim[:, 0]) | (qc > lim[:, 1]))[0])
            problems.append(
                f"{branch_name(robot, q)}: the controller's J{j + 1} = {math.degrees(qc[j]):.1f}"
                f" deg outside [{math.degrees(lim[j, 0]):.1f}, {math.degrees(lim[j, 1]):.1f}] deg"
            )
    if problems:
        return (
            head + "every configuration is outside the joint limits (" + "; ".join(problems) + ")"
        )
    return head + "no configuration reproduces the pose to 1e-9 (numerically degenerate pose)"
