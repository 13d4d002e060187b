"""Singularity detection of 6R arms: wrist, elbow and shoulder, with a margin."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Singularities:
    """Which singularities apply at one configuration, with the measures behind them.

    wrist_angle: angle [rad] between the joint-4 and joint-6 axes (0 = aligned = singular).
    elbow_angle: angle [rad] of the elbow away from stretched or folded (0 = singular).
    shoulder_distance: distance [m] of the wrist centre from the plane through the joint-1
        axis and parallel to the joint-2 axis (0 = on the axis when there is no lateral offset).
    manipulability: sqrt(det(J J^T)) of the 6 x n Jacobian [m^3/rad^6 mixed units].
    """

    wrist: bool
    elbow: bool
    shoulder: bool
    wrist_angle: float
    elbow_angle: float
    shoulder_distance: float
    manipulability: float

    @property
    def kinds(self) -> tuple[str, ...]:
        """Return the names of the singularities that apply, e.g. ("wrist",)."""
        names = ("wrist", "elbow", "shoulder")
        return tuple(
            n
            for n, flag in zip(names, (self.wrist, self.elbow, self.shoulder), strict=False)
            if flag
        )

    @property
    def any(self) -> bool:
        """Return True when at least one singularity applies."""
        return bool(self.kinds)


def _unit(v: FloatArray) -> FloatArray:
    n = float(np.linalg.norm(v))
    return v / n if n > 1e-12 else v * 0.0


def _angle_from_line(sin_abs: float, cos_val: float) -> float:
    return float(np.arctan2(sin_abs, abs(cos_val)))


def arm_singularities(
    frames: FloatArray, jacobian: FloatArray, margin: float, shoulder_margin: float
) -> Singularities:
    """Return the singularities of a 6R arm from its DH frames (7, 4, 4) and Jacobian (6, 6).

    The arm is assumed to have its joint-2 axis through frame 1's origin, joint 3 through
    frame 2's, and a wrist centre at frame 4's origin (true for the OPW family).
    margin [rad] applies to the wrist and elbow angles, shoulder_margin [m] to the distance.
    """
    z = frames[:, :3, 2]
    o = frames[:, :3, 3]
    s_w = float(np.linalg.norm(np.cross(z[3], z[5])))
    wrist_angle = _angle_from_line(s_w, float(z[3] @ z[5]))
    # Elbow: upper arm o1->o2 and forearm o2->wc projected on the plane normal to joint 2.
    n2 = _unit(z[1])
    up = o[2] - o[1]
    fo = o[4] - o[2]
    up = up - (up @ n2) * n2
    fo = fo - (fo @ n2) * n2
    s_e = float(np.linalg.norm(np.cross(_unit(up), _unit(fo))))
    elbow_angle = _angle_from_line(s_e, float(_unit(up) @ _unit(fo)))
    normal = np.cross(z[0], z[1])
    wc = o[4] - o[0]
    if np.linalg.norm(normal) > 1e-9:
        shoulder_distance = abs(float(wc @ _unit(normal)))
    else:  # joint 1 parallel to joint 2: fall back to the distance from the joint-1 axis
        shoulder_distance = float(np.linalg.norm(wc - (wc @ z[0]) * z[0]))
    # sqrt(det(J J^T)) as the product of J's singular values: forming J J^T squares the
    # condition number, so at a singularity its determinant's rounding (~1e-19) comes back
    # through the square root as ~1e-9; the singular values keep the error near 1e-16.
    if jacobian.shape[1] < jacobian.shape[0]:
        manip = 0.0  # fewer joints than task dimensions: J J^T is singular everywhere
    else:
        manip = float(np.prod(np.linalg.svd(jacobian, compute_uv=False)))
    return Singularities(
        wrist=wrist_angle < margin,
        elbow=elbow_angle < margin,
        shoulder=shoulder_distance < shoulder_margin,
        wrist_angle=wrist_angle,
        elbow_angle=elbow_angle,
        shoulder_distance=shoulder_distance,
        manipulability=manip,
    )
