"""The arm configuration of a joint vector (front/back, elbow up/down, wrist flip) and the IK
solution of a pose that a stored configuration selects.

Controllers store a Cartesian target with the configuration it was taught in (ABB confdata,
KUKA Status/Turn, FANUC CONFIG, NACHI's configuration word), so that the controller's IK picks
the same joints as the planner did. The branch part is geometric and the same for every
vendor; each post encodes it (and the turns of the wide joints, from the controller's joint
values) in its own words, and each reader decodes it back into an `ArmConfiguration` plus
controller joint ranges, which `select_solution` turns back into the joints.

Definitions (model frames of a 6R arm with a spherical wrist; frame i of `link_transforms`):

- front: the wrist centre (origin of frame 5) lies in front of axis 1, i.e. along +x of
  frame 1 (the direction the shoulder reaches out at q1), not behind it.
- elbow up: the forearm bends upward from the upper arm: with u = axis 2 -> axis 3 (frame
  1 -> frame 2 origins) and w = axis 3 -> wrist centre, (u x w) . y_arm > 0, where
  y_arm = z_base x x_1 is the arm plane's normal. A function of q3 only (the stretched arm is
  the boundary), as ABB's "wrist centre relative to the lower arm" and KUKA's bit 1 are.
- wrist flip: the controller's J5 has the sign its vendor calls flipped,
  `JointConvention.flip_sign`: negative for ABB ("axis 5 negative"), KUKA (bit 2 set) and
  NACHI; positive for FANUC, whose J5 turns the other way (its usual tool-down posture,
  J5 = -90 deg, is "N", no flip, as ABB's J5 = +90 deg is cfx 0).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import UnreachableError
from workbench.kinematics.joint_turns import all_turns
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]

RANGE_TOL = 1e-6
"""How far [rad] a joint may lie outside a stored range and still be taken, when no solution
lies inside one (rounding of a joint written on a range's boundary: programs hold about
1e-7 rad)."""


@dataclass(frozen=True)
class ArmConfiguration:
    """The geometric branch of one arm pose (see the module docstring)."""

    front: bool
    elbow_up: bool
    wrist_flip: bool

    def label(self) -> str:
        """Return 'front/elbow up/no flip' and the like."""
        return "/".join(
            (
                "front" if self.front else "back",
                "elbow up" if self.elbow_up else "elbow down",
                "flip" if self.wrist_flip else "no flip",
            )
        )


def arm_configurations(model: RobotModel, q_model: ArrayLike) -> list[ArmConfiguration]:
    """Return the `ArmConfiguration` of each joint vector q (..., dof) [rad, model convention]."""
    q = np.asarray(q_model, float).reshape(-1, model.dof)
    F = np.asarray(model.link_transforms(q), float)  # (N, dof+1, 4, 4)
    x1 = F[:, 1, :3, 0]
    o1, o2, pc = F[:, 1, :3, 3], F[:, 2, :3, 3], F[:, 5, :3, 3]
    base_z = F[:, 0, :3, 2]
    o0 = F[:, 0, :3, 3]
    front = np.einsum("ij,ij->i", pc - o0, x1) >= 0.0
    y_arm = np.cross(base_z, x1)
    elbow = np.einsum("ij,ij->i", np.cross(o2 - o1, pc - o2), y_arm) > 0.0
    conv = model.convention
    j5 = conv.to_controller(q)[:, 4] * -conv.flip_sign  # < 0: flipped
    return [
        ArmConfiguration(bool(f), bool(e), bool(w < 0.0))
        for f, e, w in zip(front, elbow, j5, strict=True)
    ]


def arm_configuration(model: RobotModel, q_model: ArrayLike) -> ArmConfiguration:
    """Return the `ArmConfiguration` of one joint vector q (dof,) [rad, model convention]."""
    return arm_configurations(model, q_model)[0]


def every_solution(model: RobotModel, T_base_flange: ArrayLike) -> FloatArray:
    """Return every IK solution (k, dof) [rad] of one pose: each branch at each turn the limits allow."""
    try:
        rows = np.asarray(model.ik(np.asarray(T_base_flange, float)), float).reshape(-1, model.dof)
    except UnreachableError:
        return np.zeros((0, model.dof))
    if len(rows) == 0:
        return rows
    return np.concatenate([all_turns(r, model.limits) for r in rows], axis=0)


def select_solution(
    model: RobotModel,
    T_base_flange: ArrayLike,
    configuration: ArmConfiguration,
    controller_ranges: ArrayLike | None = None,
    *,
    q_near: ArrayLike | None = None,
    where: str = "target",
) -> FloatArray:
    """Return the joints (dof,) [rad, model] that a stored configuration selects for a pose.

    `controller_ranges` (dof, 2) [rad, controller convention] are the half-open intervals
    [lo, hi) the vendor's turn data put each joint in (ABB's quadrants, KUKA's Turn signs,
    FANUC's turn numbers); None or +-inf rows leave a joint free. Solutions inside the ranges
    win; where none is, those within `RANGE_TOL` of them count (a joint written on a boundary).
    `q_near` (the previous target's joints) is for linear and circular moves, which controllers
    run continuously from where the arm is (KUKA ignores Status/Turn there, ABB checks
    confdata only): the solutions within `RANGE_TOL` of the ranges count, the nearest wins. Raises UnreachableError
    naming `where` when no solution has that configuration, or when several remain (the
    configuration data does not pin the joints down).
    """
    sols = every_solution(model, T_base_flange)
    if len(sols) == 0:
        raise UnreachableError(f"{where}: the pose has no IK solution within the joint limits")
    confs = arm_configurations(model, sols)
    keep = np.array([c == configuration for c in confs])
    if controller_ranges is not None:
        rng = np.asarray(controller_ranges, float).reshape(model.dof, 2)
        qc = model.convention.to_controller(sols)
        # half-open [lo, hi): the solutions inside win, a joint within RANGE_TOL of a bound
        # taken where the bound puts it (on lo inside, on hi outside: an IK's rounding moves
        # a joint written as 0 to -1e-7 and its turn to 360 - 1e-7); only where none is (a
        # joint written on a boundary) do those within RANGE_TOL of a range count
        inside = keep & np.all((qc >= rng[:, 0] - RANGE_TOL) & (qc < rng[:, 1] - RANGE_TOL), axis=1)
        near = keep & np.all((qc >= rng[:, 0] - RANGE_TOL) & (qc <= rng[:, 1] + RANGE_TOL), axis=1)
        keep = near if q_near is not None or not inside.any() else inside
    found = sols[keep]
    if q_near is not None and len(found) > 1:
        # a linear move: the controller follows the path from the previous joints
        d = np.linalg.norm(found - np.asarray(q_near, float), axis=1)
        return np.asarray(found[int(np.argmin(d))], float)
    if len(found) == 0:
        have = sorted({c.label() for c in confs})
        raise UnreachableError(
            f"{where}: no IK solution in the stored configuration {configuration.label()}"
            f" within the stored joint ranges; the pose has {', '.join(have)}"
        )
    if len(found) > 1:
        spread = float(np.max(np.ptp(found, axis=0)))
        if spread > 1e-6:
            raise UnreachableError(
                f"{where}: {len(found)} IK solutions share the configuration"
                f" {configuration.label()}; the configuration data does not select one"
            )
    return np.asarray(found[0], float)
