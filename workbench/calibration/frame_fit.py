"""A frame from N points measured at known positions on the part (least squares, outliers named).

The part's drawing gives points in the part's (work object's) frame; the robot measures the
same points in its base. The frame is the rigid transform that maps the known points onto the
measured ones best (`geometry.rigid_fit`, Kabsch): RoboDK's and RobotStudio's "points" frame
calibration. A point whose residual exceeds the tolerance (a mis-touched or mislabelled point)
is dropped while enough points remain, and named.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.rigid_fit import fit_rigid_robust

FloatArray = NDArray[np.float64]

OUTLIER_TOLERANCE = 0.001
"""The residual [m] above which a point is dropped as an outlier (default; 1 mm)."""


@dataclass(frozen=True)
class PointsFit:
    """A rigid transform fitted to labelled point pairs.

    `T` (4, 4) maps the known points onto the measured ones [m]; `residuals` (n,) [m] each
    point's distance after the fit (dropped ones too); `dropped` the labels of outliers, worst
    first. `known` and `measured` (n, 3) [m] as given.
    """

    T: FloatArray
    labels: tuple[str, ...]
    known: FloatArray
    measured: FloatArray
    residuals: FloatArray
    dropped: tuple[str, ...]

    @property
    def kept_residuals(self) -> FloatArray:
        """Return the residuals [m] of the points the fit used."""
        keep = [i for i, label in enumerate(self.labels) if label not in self.dropped]
        return np.asarray(self.residuals[keep])

    @property
    def rms(self) -> float:
        """Return the root-mean-square residual [m] of the points the fit used."""
        return float(np.sqrt(np.mean(self.kept_residuals**2)))

    @property
    def max_error(self) -> float:
        """Return the largest residual [m] of the points the fit used."""
        return float(np.max(self.kept_residuals))


def fit_points(
    labels: Sequence[str],
    known: object,
    measured: object,
    *,
    tolerance: float = OUTLIER_TOLERANCE,
) -> PointsFit:
    """Return the rigid transform mapping `known` (n, 3) onto `measured` (n, 3) [m], least
    squares, outliers above `tolerance` [m] dropped and named. InputError for fewer than 3
    points, collinear ones, NaN or lengths that differ from `labels`."""
    k, m = np.asarray(known, dtype=float), np.asarray(measured, dtype=float)
    if len(labels) != len(k) or len(k) != len(m):
        raise InputError(f"{len(labels)} labels, {len(k)} known and {len(m)} measured points")
    try:
        fit = fit_rigid_robust(k, m, tolerance)
    except InputError as exc:
        raise InputError(f"points {', '.join(labels)}: {exc.detail}") from exc
    dropped = tuple(labels[i] for i in fit.dropped)
    return PointsFit(fit.T, tuple(labels), k, m, fit.residuals, dropped)
