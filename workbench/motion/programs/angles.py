"""Orientation conventions of robot controllers, from rotation matrices.

Each is canonical where the convention leaves a choice, so the same rotation prints the same
on every machine (rounding noise of 1e-16 must not flip a sign the program then states):
an angle that would print as -180 prints as +180 (`PRINTED_ZERO_DEG`), and a quaternion whose
w prints as 0 has its first component that does not print as 0 positive (`PRINTED_ZERO`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.geometry.transforms import matrix_to_rpy, matrix_to_wxyz

#: Below this a quaternion component prints as 0 (the posts print 9 decimals).
PRINTED_ZERO = 5e-10
#: Within this of -180 deg an angle prints as -180 (the posts print 6 decimals).
PRINTED_ZERO_DEG = 5e-7


def quaternion_wxyz(R: ArrayLike) -> NDArray[np.float64]:
    """Return the unit quaternion (w, x, y, z), w >= 0, of a (3, 3) rotation (ABB q1..q4);
    when w prints as 0, the first of x, y, z that does not is positive."""
    q = matrix_to_wxyz(np.asarray(R, float))
    if abs(q[0]) < PRINTED_ZERO:
        lead = next((c for c in q[1:] if abs(c) >= PRINTED_ZERO), 1.0)
        if lead < 0:
            q = -q
    return q


def _half_open(deg: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return angles [deg] in (-180, 180] as printed: one that prints as -180 is +180."""
    return np.where(deg <= -180.0 + PRINTED_ZERO_DEG, deg + 360.0, deg)


def abc_deg(R: ArrayLike) -> NDArray[np.float64]:
    """Return KUKA (A, B, C) [deg]: R = Rz(A) Ry(B) Rx(C)."""
    roll, pitch, yaw = matrix_to_rpy(np.asarray(R, float))
    return _half_open(np.degrees([yaw, pitch, roll]))


def wpr_deg(R: ArrayLike) -> NDArray[np.float64]:
    """Return FANUC (W, P, R) [deg]: fixed-axis rotations about x, then y, then z."""
    return _half_open(np.degrees(matrix_to_rpy(np.asarray(R, float))))


def rotation_vector(R: ArrayLike) -> NDArray[np.float64]:
    """Return the rotation vector (3,) [rad] (axis times angle, angle in [0, pi]) of R (UR)."""
    w, x, y, z = quaternion_wxyz(R)
    s = np.sqrt(x * x + y * y + z * z)
    if s < 1e-15:
        return np.zeros(3)
    angle = 2.0 * np.arctan2(s, w)
    return np.array([x, y, z]) / s * angle
