"""Straight-line motion of a rigid part: linear position, slerped orientation, distances and samples."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.geometry.transforms import make_transform, wxyz_to_matrix


def slerp(q0: ArrayLike, q1: ArrayLike, u: ArrayLike) -> NDArray[np.float64]:
    """Return unit quaternions (n, 4) (w, x, y, z) on the short arc from q0 to q1 at fractions u (n,)."""
    q0 = np.asarray(q0, float)
    q1 = np.asarray(q1, float)
    u = np.atleast_1d(np.asarray(u, float))[:, None]
    d = float(q0 @ q1)
    if d < 0.0:
        q1, d = -q1, -d
    if d > 1.0 - 1e-12:
        q = q0 + u * (q1 - q0)
    else:
        th = np.arccos(d)
        q = (np.sin((1.0 - u) * th) * q0 + np.sin(u * th) * q1) / np.sin(th)
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def rotation_angle(T0: ArrayLike, T1: ArrayLike) -> NDArray[np.float64]:
    """Return the angle [rad] of the relative rotation between (..., 4, 4) poses."""
    R0 = np.asarray(T0, float)[..., :3, :3]
    R1 = np.asarray(T1, float)[..., :3, :3]
    c = 0.5 * (np.einsum("...ij,...ij->...", R0, R1) - 1.0)
    return np.arccos(np.clip(c, -1.0, 1.0))


def pose_distance(T0: ArrayLike, T1: ArrayLike, radius: float) -> NDArray[np.float64]:
    """Return |Δp| + radius·angle [m]: a bound on how far any point of the part moves."""
    T0 = np.asarray(T0, float)
    T1 = np.asarray(T1, float)
    dp = np.linalg.norm(T1[..., :3, 3] - T0[..., :3, 3], axis=-1)
    return dp + radius * rotation_angle(T0, T1)


def unit_quaternion(R: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return the unit quaternion (w, x, y, z), w >= 0, of one rotation (3, 3).

    `matrix_to_wxyz`'s branch choice (Shepperd) in plain floats: the planners convert two
    matrices per checked motion, where numpy's per-call cost dominated.
    """
    (a, b, c), (d, e, f), (g, h, i) = R.tolist()
    tr = a + e + i
    if tr >= a and tr >= e and tr >= i:
        s = 2.0 * math.sqrt(1.0 + tr)
        q = (0.25 * s, (h - f) / s, (c - g) / s, (d - b) / s)
    elif a >= e and a >= i:
        s = 2.0 * math.sqrt(1.0 + a - e - i)
        q = ((h - f) / s, 0.25 * s, (b + d) / s, (c + g) / s)
    elif e >= i:
        s = 2.0 * math.sqrt(1.0 + e - a - i)
        q = ((c - g) / s, (b + d) / s, 0.25 * s, (f + h) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + i - a - e)
        q = ((d - b) / s, (c + g) / s, (f + h) / s, 0.25 * s)
    n = math.sqrt(sum(x * x for x in q))
    return np.array(q) / (-n if q[0] < 0.0 else n)


def interpolate(T0: ArrayLike, T1: ArrayLike, u: ArrayLike) -> NDArray[np.float64]:
    """Return poses (n, 4, 4) at fractions u (n,) of the straight motion T0 -> T1 (lerp + slerp)."""
    T0 = np.asarray(T0, float)
    T1 = np.asarray(T1, float)
    u = np.atleast_1d(np.asarray(u, float))
    q = slerp(unit_quaternion(T0[:3, :3]), unit_quaternion(T1[:3, :3]), u)
    p = T0[:3, 3] + u[:, None] * (T1[:3, 3] - T0[:3, 3])
    return make_transform(wxyz_to_matrix(q), p)


def motion_samples(
    T0: ArrayLike, T1: ArrayLike, radius: float, resolution: float, *, include_start: bool = False
) -> NDArray[np.float64]:
    """Return poses (n, 4, 4) along T0 -> T1 (T1 last) no point of the part moves more than `resolution` [m] between."""
    d = float(pose_distance(T0, T1, radius))
    n = max(1, int(np.ceil(d / resolution)))
    u = np.arange(0 if include_start else 1, n + 1) / n
    return interpolate(T0, T1, u)


def path_samples(poses: ArrayLike, radius: float, resolution: float) -> NDArray[np.float64]:
    """Return all poses (m, 4, 4) along a piecewise straight path, spaced at most `resolution` [m]."""
    P = np.asarray(poses, float)
    out = [P[:1]] + [motion_samples(P[i], P[i + 1], radius, resolution) for i in range(len(P) - 1)]
    return np.concatenate(out)
