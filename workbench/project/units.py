"""The project file's units (mm, deg) and SI: the one place the workbench converts them.

Sections convert themselves with `to_si()`; services use the SI specs and, for messages
that quote the project file, `to_mm` / `to_deg`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.geometry.transforms import matrix_to_rpy, xyz_rpy_to_transform
from workbench.project.common import Pose

MM = 1e-3
"""Metres per millimetre (multiply a project length to get SI)."""
DEG = np.pi / 180.0
"""Radians per degree (multiply a project angle to get SI)."""


def pose_to_matrix(pose: Pose) -> NDArray[np.float64]:
    """Return the (4, 4) transform [m] of a project pose (mm, deg)."""
    return xyz_rpy_to_transform(np.asarray(pose.xyz) * MM, np.asarray(pose.rpy) * DEG)


def matrix_to_pose(T: ArrayLike) -> Pose:
    """Return a project pose (mm, deg) of a (4, 4) transform [m]."""
    T = np.asarray(T, float)
    return Pose(
        xyz=[float(v) for v in T[:3, 3] / MM],
        rpy=[float(v) for v in matrix_to_rpy(T[:3, :3]) / DEG],
    )


def to_deg(angle: ArrayLike) -> NDArray[np.float64]:
    """Return angles [rad] in the project's degrees (for messages and the file)."""
    return np.asarray(angle, dtype=float) / DEG


def to_mm(length: ArrayLike) -> NDArray[np.float64]:
    """Return lengths [m] in the project's millimetres (for messages and the file)."""
    return np.asarray(length, dtype=float) / MM
