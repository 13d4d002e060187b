"""Calibration of the cell as built: the TCP, work objects and the robot's base from readings.

SI inside (m, rad); the readings come as flange poses or points in the robot's base.
"""

from __future__ import annotations

from workbench.calibration.frame_fit import PointsFit, fit_points
from workbench.calibration.frame_three_point import (
    THREE_POINT_METHODS,
    ThreePointFrame,
    three_point_frame,
)
from workbench.calibration.robot_place import fit_robot_base
from workbench.calibration.tcp import TcpFit, calibrate_tcp

__all__ = [
    "THREE_POINT_METHODS",
    "PointsFit",
    "TcpFit",
    "ThreePointFrame",
    "calibrate_tcp",
    "fit_points",
    "fit_robot_base",
    "three_point_frame",
]
