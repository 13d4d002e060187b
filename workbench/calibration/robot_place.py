"""The robot's place in the cell: its base in the world from reference points.

Reference points whose world positions are known (marks on the press, fixture pins, a
surveyed plate) are touched with the calibrated TCP; the robot gives each in its base. The
base's pose T_world_base is the rigid transform that maps the measured points onto the known
ones (least squares, outliers named: `frame_fit.fit_points` with the roles swapped), as
RoboDK's and RobotStudio's "robot base from points" calibration.
"""

from __future__ import annotations

from collections.abc import Sequence

from workbench.calibration.frame_fit import OUTLIER_TOLERANCE, PointsFit, fit_points


def fit_robot_base(
    labels: Sequence[str],
    known_world: object,
    measured_base: object,
    *,
    tolerance: float = OUTLIER_TOLERANCE,
) -> PointsFit:
    """Return the fit whose `T` is T_world_base (4, 4) [m]: measured points (n, 3) in the base
    mapped onto their known world positions (n, 3); `known`/`measured` keep those roles (the
    fit's source is `measured`)."""
    fit = fit_points(labels, measured_base, known_world, tolerance=tolerance)
    return PointsFit(fit.T, fit.labels, fit.measured, fit.known, fit.residuals, fit.dropped)
