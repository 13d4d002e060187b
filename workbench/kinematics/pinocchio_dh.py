"""Pinocchio models built from DH rows: the independent twin of the numpy DH chain."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
from numpy.typing import NDArray

from workbench.kinematics.dh_chain import dh_fixed_part


def _se3(T: NDArray[np.float64]) -> pin.SE3:
    return pin.SE3(np.ascontiguousarray(T[:3, :3]), np.ascontiguousarray(T[:3, 3]))


def build_dh_model(
    dh: NDArray[np.float64], limits: NDArray[np.float64], max_velocity: NDArray[np.float64]
) -> pin.Model:
    """Return a pin.Model of revolute-z joints placed by the DH rows, with frames "link_i", "flange".

    With A_i = Rz(q_i) B_i, joint i sits at B_(i-1) on joint i-1 (B_0 = identity) and
    frame "link_i" (DH frame i) at B_i on joint i; "flange" is "link_n".
    """
    B = dh_fixed_part(dh)
    model = pin.Model()
    parent = 0
    for i in range(dh.shape[0]):
        placement = pin.SE3.Identity() if i == 0 else _se3(B[i - 1])
        parent = model.addJoint(
            parent,
            pin.JointModelRZ(),
            placement,
            f"joint_{i + 1}",
            np.array([1e3]),
            np.array([max_velocity[i]]),
            np.array([limits[i, 0]]),
            np.array([limits[i, 1]]),
        )
        model.appendBodyToJoint(parent, pin.Inertia.Random(), pin.SE3.Identity())
        model.addFrame(pin.Frame(f"link_{i + 1}", parent, _se3(B[i]), pin.FrameType.OP_FRAME))
    model.addFrame(pin.Frame("flange", parent, _se3(B[-1]), pin.FrameType.OP_FRAME))
    return model
