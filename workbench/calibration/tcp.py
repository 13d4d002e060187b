"""The tool centre point from the tool tip held on one fixed point in several orientations.

The pendant's TCP method: the operator brings the tool tip to one fixed point (a pointed pin)
in four or more orientations, and the controller finds the TCP in the flange frame, t, and the
fixed point in the robot base, P, such that every flange pose (R_i, p_i) puts the tip there:

    R_i t + p_i = P      for every reading i          (3n equations, 6 unknowns)

solved here by linear least squares. The pendant reports how far the fitted tip lies from the
fixed point at each reading: ABB's "Mean error" and "Max error" after the calculation (ABB,
"Operating manual - IRC5 with FlexPendant", 3HAC050941-001, "Defining the tool frame": the
TCP method's approach points, four at least, and the calculation result's Max/Min/Mean
error); KUKA's XYZ 4-point method is the same fit (KUKA System Software 8.x, "Operating and
Programming Instructions for System Integrators", "Tool calibration: XYZ 4-point method").

The tip's position along a direction d in the flange is only seen when the orientations turn
about axes across d: with all readings alike, or all turned about one axis, it is undetermined.
`calibrate_tcp` refuses such readings, naming the direction and how far they are turned.

ABB's "TCP and Z, X" method adds the tool's orientation (same section): holding the
orientation of an approach point, the robot is moved so that the fixed point lies on the
tool's desired +Z axis (the Z elongator point), and for X on its +X axis. In the flange frame
of that reading the fixed point lies at F_z = R^T (P - p); the tool's +Z is along F_z - t, its
+X along F_x - t made orthogonal to Z (the angle removed is reported).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.pose_check import check_transform

FloatArray = NDArray[np.float64]

MIN_READINGS = 4
"""The approach points a TCP needs (ABB's and KUKA's four)."""
MIN_TURN = np.radians(10.0)
"""The least turn [rad] of the orientations about every axis across the tool (below it, the
noise of the readings is amplified more than ten times into the TCP: refused)."""
MIN_ELONGATION = 0.005
"""The least distance [m] of an elongator point's fixed point from the TCP."""


@dataclass(frozen=True)
class TcpFit:
    """A TCP fitted from readings of one fixed point (SI: m, rad).

    `T_flange_tcp` (4, 4): the TCP in the flange; its rotation is the identity unless the
    orientation was measured (`oriented`). `point` (3,): the fixed point in the robot base.
    `residuals` (n,): each approach reading's distance from the fitted tip to the fixed point.
    `turn` [rad]: how far the orientations turn about the least-seen axis (the determinacy).
    `skew` [rad]: the X reading's angle off perpendicular to Z (0 without orientation).
    """

    T_flange_tcp: FloatArray
    point: FloatArray
    residuals: FloatArray
    turn: float
    oriented: bool = False
    skew: float = 0.0

    @property
    def mean_error(self) -> float:
        """Return the mean distance [m] of the fitted tip from the fixed point (ABB's Mean error)."""
        return float(np.mean(self.residuals))

    @property
    def min_error(self) -> float:
        """Return the smallest distance [m] of the fitted tip from the fixed point (Min error)."""
        return float(np.min(self.residuals))

    @property
    def max_error(self) -> float:
        """Return the largest distance [m] of the fitted tip from the fixed point (Max error)."""
        return float(np.max(self.residuals))

    def keeping(self, T_flange_tcp: FloatArray) -> FloatArray:
        """Return the TCP to store (4, 4) [m]: the fitted one, with the orientation of
        `T_flange_tcp` (the tool's as it was) unless the orientation was measured."""
        T = self.T_flange_tcp.copy()
        if not self.oriented:
            T[:3, :3] = np.asarray(T_flange_tcp, float)[:3, :3]
        return T

    def tips(self, T_base_flange: FloatArray) -> FloatArray:
        """Return the fitted tip (n, 3) [m] in the base at flange poses (n, 4, 4)."""
        T = np.asarray(T_base_flange, float)
        return np.asarray(T[:, :3, :3] @ self.T_flange_tcp[:3, 3] + T[:, :3, 3])


def _flanges(T_base_flange: object, what: str) -> FloatArray:
    T = np.asarray(T_base_flange, dtype=float)
    if T.ndim != 3 or T.shape[1:] != (4, 4):
        raise InputError(f"{what}: give flange poses as (n, 4, 4), got shape {T.shape}")
    for i, Ti in enumerate(T):
        check_transform(Ti, f"{what}[{i}]")
    return T


def _determinacy(R: FloatArray) -> tuple[float, FloatArray]:
    """Return (turn [rad], direction (3,) in the flange) of the least-determined TCP direction.

    The centred system (R_i - mean R) t = -(p_i - mean p) sees t through the singular values of
    the stacked R_i - mean R; a direction d is seen as far as the rotations move it. The turn
    reported is the angle whose chord 2 sin(turn / 2) is 2 s / sqrt(n): for two readings
    turned by an angle about one axis, that angle about every axis across it (and 0 along it).
    """
    stacked = (R - R.mean(axis=0)).reshape(-1, 3)
    _, s, vt = np.linalg.svd(stacked)
    half_chord = s[-1] / np.sqrt(len(R))
    return float(2.0 * np.arcsin(min(half_chord, 1.0))), vt[-1]


def _direction_name(d: FloatArray) -> str:
    axis = int(np.argmax(np.abs(d)))
    sign = "+" if d[axis] >= 0 else "-"
    return f"the flange's {sign}{'XYZ'[axis]} ({d[0]:+.2f}, {d[1]:+.2f}, {d[2]:+.2f})"


def _solve(R: FloatArray, p: FloatArray) -> tuple[FloatArray, FloatArray]:
    n = len(R)
    A = np.concatenate([R, -np.broadcast_to(np.eye(3), (n, 3, 3))], axis=2).reshape(-1, 6)
    x, *_ = np.linalg.lstsq(A, -p.reshape(-1), rcond=None)
    return x[:3], x[3:]


def _axis(T_base_flange: FloatArray, point: FloatArray, t: FloatArray, name: str) -> FloatArray:
    """Return the unit direction in the flange from the TCP to the fixed point at reading T."""
    v = T_base_flange[:3, :3].T @ (point - T_base_flange[:3, 3]) - t
    if np.linalg.norm(v) < MIN_ELONGATION:
        raise InputError(
            f"the {name} elongator reading puts the fixed point {np.linalg.norm(v) * 1e3:.1f} mm"
            f" from the TCP; move the tool at least {MIN_ELONGATION * 1e3:.0f} mm back along"
            f" its {name.upper()} axis (the fixed point on the tool's +{name.upper()} side)"
        )
    return np.asarray(v / np.linalg.norm(v))


def _orientation(z: FloatArray, x: FloatArray | None) -> tuple[FloatArray, float]:
    """Return (R_flange_tcp, skew [rad]) with +Z along `z` and +X toward `x` (or kept near the
    flange's X when only Z is measured: ABB's "TCP and Z")."""
    if x is None:
        ref = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
        skew = 0.0
    else:
        ref, skew = x, abs(float(np.arcsin(np.clip(np.dot(x, z), -1.0, 1.0))))
        if np.linalg.norm(np.cross(z, x)) < np.sin(np.radians(5.0)):
            raise InputError(
                "the X elongator direction is within 5 deg of the Z direction; measure the"
                " X point along the tool's +X axis, across the Z axis"
            )
    xo = ref - np.dot(ref, z) * z
    xo /= np.linalg.norm(xo)
    return np.column_stack([xo, np.cross(z, xo), z]), skew


def calibrate_tcp(
    T_base_flange: object,
    *,
    z_reading: object | None = None,
    x_reading: object | None = None,
    min_turn: float = MIN_TURN,
) -> TcpFit:
    """Return the TCP fitted from flange poses (n, 4, 4) [m] with the tip on one fixed point.

    `z_reading` / `x_reading` (4, 4): flange poses of ABB's Z and X elongator points (the fixed
    point on the tool's +Z, +X axis); with them the TCP's orientation is fitted too (X needs Z).
    Raises InputError for fewer than 4 readings and for orientations that turn less than
    `min_turn` [rad] about some axis across the tool, naming that axis.
    """
    T = _flanges(T_base_flange, "readings")
    if len(T) < MIN_READINGS:
        raise InputError(
            f"the TCP method needs at least {MIN_READINGS} readings of the fixed point in"
            f" different orientations, got {len(T)}"
        )
    R, p = T[:, :3, :3], T[:, :3, 3]
    turn, direction = _determinacy(R)
    if turn < min_turn:
        raise InputError(
            f"the orientations are too alike: they turn only {np.degrees(turn):.1f} deg about"
            f" an axis across {_direction_name(direction)}, so the TCP along it is undetermined;"
            f" tilt the tool at least {np.degrees(min_turn):.0f} deg more between readings,"
            " about axes across that direction"
        )
    t, point = _solve(R, p)
    residuals = np.linalg.norm(R @ t + p - point, axis=1)
    T_flange_tcp = np.eye(4)
    T_flange_tcp[:3, 3] = t
    if z_reading is None and x_reading is None:
        return TcpFit(T_flange_tcp, point, residuals, turn)
    if z_reading is None:
        raise InputError("an X elongator reading needs a Z one too (ABB's TCP and Z, X method)")
    z = _axis(_flanges([z_reading], "z reading")[0], point, t, "z")
    x = None if x_reading is None else _axis(_flanges([x_reading], "x")[0], point, t, "x")
    T_flange_tcp[:3, :3], skew = _orientation(z, x)
    return TcpFit(T_flange_tcp, point, residuals, turn, oriented=True, skew=skew)
