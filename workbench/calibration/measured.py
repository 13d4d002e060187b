"""Measured points from joint readings: the flange and the TCP by forward kinematics.

A reading taken on the pendant is the robot's joints; the point it measures is where the
project's robot model puts the TCP at those joints. Positions read off the pendant instead
are in the controller's base frame, which for some vendors lies apart from the model's
(`LibraryRobot.T_base_controller`): `in_model_base` moves them.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]


def flange_poses(model: RobotModel, q: object) -> FloatArray:
    """Return the flange poses (n, 4, 4) [m] in the model's base at joints q (n, dof) [rad]."""
    joints = np.asarray(q, dtype=float)
    if joints.ndim != 2 or joints.shape[1] != model.dof:
        raise InputError(f"joint readings: give (n, {model.dof}) joints, got {joints.shape}")
    return np.asarray(model.fk(joints)).reshape(-1, 4, 4)


def tcp_positions(model: RobotModel, q: object, T_flange_tcp: FloatArray) -> FloatArray:
    """Return the TCP positions (n, 3) [m] in the model's base at joints q (n, dof) [rad]."""
    T = flange_poses(model, q)
    return np.asarray(T[:, :3, :3] @ T_flange_tcp[:3, 3] + T[:, :3, 3])


def transformed(points: object, T: FloatArray) -> FloatArray:
    """Return points (n, 3) [m] moved by the transform T (4, 4): T p for each p."""
    p = np.asarray(points, dtype=float)
    return np.asarray(p @ T[:3, :3].T + T[:3, 3])


def in_model_base(points: object, T_base_controller: FloatArray) -> FloatArray:
    """Return points (n, 3) [m] given in the controller's base frame in the model's base."""
    return transformed(points, T_base_controller)
