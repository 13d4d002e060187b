"""`CalibrationResult`: what a calibration found, for the 3D view (SI) and the summary (mm, deg).

The summary's lines are the ones the CLI prints and the GUI shows: the fitted frame as the
project stores it (mm, deg), the errors as a pendant reports them, each point's residual by
label, the outliers dropped, and the value the project holds now.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.calibration import PointsFit, TcpFit, ThreePointFrame
from workbench.project.common import Pose
from workbench.project.units import matrix_to_pose, to_deg, to_mm

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class CalibrationResult:
    """A calibration's result (SI: m).

    `kind`: "tcp", "work_object" or "base"; `name`: the tool, work object or robot it is for.
    `T` (4, 4): what `apply` stores: T_flange_tcp, T_world_wobj or T_world_base;
    `T_previous` (4, 4): what the project holds there now (None: a new work object).
    `T_world_frame` (4, 4): the fitted frame in the world for the 3D view (the TCP at the last
    approach reading, the work object, the robot's base). `labels`, `points_world` (n, 3) and
    `residuals` (n,): the measured points in the world (a TCP's: the fitted tip at each
    reading) and each one's residual [m]; `dropped`: the labels of outliers the fit left out.
    """

    kind: str
    name: str
    T: FloatArray
    T_previous: FloatArray | None
    T_world_frame: FloatArray
    labels: tuple[str, ...]
    points_world: FloatArray
    residuals: FloatArray
    dropped: tuple[str, ...]
    lines: tuple[str, ...]

    def summary(self) -> str:
        """Return the result as text lines (mm, deg): the CLI prints them, the GUI shows them."""
        return "\n".join(self.lines)

    @property
    def residual_by_label(self) -> dict[str, float]:
        """Return {label: residual [m]} of every measured point, dropped ones too."""
        return {k: float(v) for k, v in zip(self.labels, self.residuals, strict=True)}


def _xyz(v: object) -> str:
    x, y, z = (round(float(c), 3) + 0.0 for c in np.asarray(v, float))  # + 0.0: no "-0.000"
    return f"x {x:.3f}  y {y:.3f}  z {z:.3f}"


def pose_text(T: FloatArray) -> str:
    """Return a transform [m] as the project's pose: 'x .. y .. z .. mm, rpy .. deg'."""
    return _pose_text(matrix_to_pose(T))


def _pose_text(pose: Pose) -> str:
    r = ", ".join(f"{round(v, 4) + 0.0:.4f}" for v in pose.rpy)
    return f"{_xyz(pose.xyz)} mm, rpy [{r}] deg"


def _residuals(labels: tuple[str, ...], residuals: FloatArray, dropped: tuple[str, ...]) -> str:
    parts = [
        f"{label} {float(to_mm(r)):.3f}{' (dropped)' if label in dropped else ''}"
        for label, r in zip(labels, residuals, strict=True)
    ]
    return "  residuals [mm]: " + ", ".join(parts)


def tcp_lines(
    fit: TcpFit, T: FloatArray, tool: str, labels: tuple[str, ...], stored: Pose
) -> tuple[str, ...]:
    """Return the summary of a TCP fit of `tool` from the approach readings `labels`; `T` the
    TCP in the flange as applied (the stored orientation kept when none was measured)."""
    method = "TCP and Z, X" if fit.oriented else "TCP (orientation kept from the project)"
    lines = [
        f"TCP of tool {tool!r}: {method}, {len(labels)} approach readings",
        f"  TCP in the flange: {pose_text(T)}",
        f"  fixed point in the robot base: {_xyz(to_mm(fit.point))} mm",
        f"  mean error {float(to_mm(fit.mean_error)):.3f} mm, max error"
        f" {float(to_mm(fit.max_error)):.3f} mm, min error {float(to_mm(fit.min_error)):.3f} mm",
        f"  orientations turn at least {float(to_deg(fit.turn)):.1f} deg about every axis",
        _residuals(labels, fit.residuals, ()),
    ]
    if fit.oriented and fit.skew > 0.0:
        lines.append(f"  the X reading was {float(to_deg(fit.skew)):.2f} deg off square to Z")
    lines.append(f"  the project's TCP now: {_pose_text(stored)}")
    return tuple(lines)


def three_point_lines(
    frame: ThreePointFrame,
    name: str,
    labels: tuple[str, ...],
    T_world: FloatArray,
    stored: Pose | None,
) -> tuple[str, ...]:
    """Return the summary of a three-point work object `name` (its points' place in it)."""
    vendor = "ABB user frame X1, X2, Y1" if frame.method == "abb" else "KUKA/FANUC origin, X, Y"
    local = dict(zip(frame.labels, frame.local, strict=True))
    return (
        f"work object {name!r}: 3-point method ({vendor})",
        f"  frame in the world: {pose_text(T_world)}",
        *(f"  {label} in the frame: {_xyz(to_mm(local[label.lower()]))} mm" for label in labels),
        f"  the project's value now: {'none' if stored is None else _pose_text(stored)}",
    )


def fit_lines(
    fit: PointsFit, what: str, T_world: FloatArray, stored: Pose | None
) -> tuple[str, ...]:
    """Return the summary of a points fit of `what` (a work object, the robot's base)."""
    kept = len(fit.labels) - len(fit.dropped)
    lines = [
        f"{what}: least-squares fit of {kept} of {len(fit.labels)} points",
        f"  frame in the world: {pose_text(T_world)}",
        f"  rms error {float(to_mm(fit.rms)):.3f} mm, max error {float(to_mm(fit.max_error)):.3f} mm",
        _residuals(fit.labels, fit.residuals, fit.dropped),
    ]
    if fit.dropped:
        lines.append(f"  dropped as outliers: {', '.join(fit.dropped)} (residual above tolerance)")
    lines.append(f"  the project's value now: {'none' if stored is None else _pose_text(stored)}")
    return tuple(lines)
