"""A robot carrying a part: its joints along a TCP path in one arm configuration (`follow_path`)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from workbench.geometry.transforms import invert_transform
from workbench.kinematics import PathIK, RobotModel, follow_path

#: Largest joint change [rad] allowed between consecutive TCP samples of a carried path; a
#: larger one means the configuration flipped (a wrist or shoulder singularity was crossed).
MAX_JOINT_STEP = 0.5
HINT = "the part is out of reach of the robot there: move the start or goal closer, or change the grasp"


def carry_ik(
    model: RobotModel,
    T_world_base: ArrayLike,
    T_flange_tcp: ArrayLike,
    T_world_tcp: ArrayLike,
    q_near: ArrayLike,
    *,
    what: str = "path",
) -> PathIK:
    """Return the joints that put the TCP on every pose of `T_world_tcp` (M, 4, 4) [m], one configuration.

    `follow_path` on the flange poses: the arm configuration valid at every pose, with no
    joint moving more than MAX_JOINT_STEP between poses, nearest `q_near` (dof,) [rad] at
    the first pose. UnreachableError names the first pose (index, TCP position in mm) that
    no configuration reaches; PlanningError where every configuration reaching all flips.
    """
    Tw = np.asarray(T_world_tcp, float).reshape(-1, 4, 4)
    Tb = invert_transform(np.asarray(T_world_base, float))
    Tf = invert_transform(np.asarray(T_flange_tcp, float))
    return follow_path(
        model,
        Tb @ Tw @ Tf,
        q_near,
        what=what,
        max_joint_step=MAX_JOINT_STEP,
        points=Tw[:, :3, 3],
        hint=HINT,
    )
