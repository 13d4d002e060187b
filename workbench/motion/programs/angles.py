"""Orientation conventions of robot controllers, from rotation matrices."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.geometry.transforms import matrix_to_rpy, matrix_to_wxyz


def quaternion_wxyz(R: ArrayLike) -> NDArray[np.float64]:
    """Return the unit quaternion (w, x, y, z), w >= 0, of a (3, 3) rotation (ABB q1..q4)."""
    return matrix_to_wxyz(np.asarray(R, float))


def abc_deg(R: ArrayLike) -> NDArray[np.float64]:
    """Return KUKA (A, B, C) [deg]: R = Rz(A) Ry(B) Rx(C)."""
    roll, pitch, yaw = matrix_to_rpy(np.asarray(R, float))
    return np.degrees([yaw, pitch, roll])


def wpr_deg(R: ArrayLike) -> NDArray[np.float64]:
    """Return FANUC (W, P, R) [deg]: fixed-axis rotations about x, then y, then z."""
    return np.degrees(matrix_to_rpy(np.asarray(R, float)))


def rotation_vector(R: ArrayLike) -> NDArray[np.float64]:
    """Return the rotation vector (3,) [rad] (axis times angle, angle in [0, pi]) of R (UR)."""
    w, x, y, z = quaternion_wxyz(R)
    s = np.sqrt(x * x + y * y + z * z)
    if s < 1e-15:
        return np.zeros(3)
    angle = 2.0 * np.arctan2(s, w)
    return np.array([x, y, z]) / s * angle
