"""Checks that turn joint waypoints and joint limits into float arrays or raise InputError."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError


def check_waypoints(waypoints: ArrayLike, *, name: str = "waypoints") -> NDArray[np.float64]:
    """Return waypoints as a finite (N, dof) float array with N >= 2 [rad]."""
    try:
        q = np.array(waypoints, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name} must be an (N, dof) array of numbers, got {waypoints!r}") from exc
    if q.ndim != 2 or q.shape[1] < 1:
        raise InputError(f"{name} must have shape (N, dof), got shape {q.shape}")
    if q.shape[0] < 2:
        raise InputError(
            f"{name}: got a single waypoint (shape {q.shape}); a path needs at least two"
        )
    bad = np.argwhere(~np.isfinite(q))
    if bad.size:
        i, j = bad[0]
        raise InputError(f"{name}[{i}] joint {j + 1} is {q[i, j]}; every value must be finite")
    return q


def check_limits(
    name: str, limits: ArrayLike, dof: int, *, n_segments: int | None = None
) -> NDArray[np.float64]:
    """Return positive finite limits (dof,) (or (n_segments, dof) where allowed)."""
    try:
        arr = np.array(limits, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name} must be {dof} positive numbers, got {limits!r}") from exc
    if arr.ndim == 0:
        arr = np.full(dof, float(arr))
    shapes = [(dof,)] + ([(n_segments, dof)] if n_segments is not None else [])
    if arr.shape not in shapes:
        allowed = " or ".join(str(s) for s in shapes)
        raise InputError(f"{name} must have shape {allowed} (one per joint), got shape {arr.shape}")
    bad = ~np.isfinite(arr) | (arr <= 0.0)
    if np.any(bad):
        idx = tuple(int(i) for i in np.argwhere(bad)[0])
        j = idx[-1]
        raise InputError(f"{name} for joint {j + 1} is {arr[idx]}; limits must be finite and > 0")
    return arr


def check_position_limits(limits: ArrayLike, waypoints: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return position limits (dof, 2) [rad] after checking every waypoint lies within them."""
    dof = waypoints.shape[1]
    lim = np.array(limits, dtype=float)
    if lim.shape != (dof, 2):
        raise InputError(
            f"position_limits must have shape ({dof}, 2) [lower, upper], got {lim.shape}"
        )
    if np.any(np.isnan(lim)) or np.any(lim[:, 0] >= lim[:, 1]):
        j = int(np.flatnonzero(np.isnan(lim).any(axis=1) | (lim[:, 0] >= lim[:, 1]))[0])
        raise InputError(
            f"position_limits for joint {j + 1} are {lim[j].tolist()}; need lower < upper"
        )
    out = (waypoints < lim[:, 0]) | (waypoints > lim[:, 1])
    if np.any(out):
        i, j = (int(x) for x in np.argwhere(out)[0])
        raise InputError(
            f"waypoints[{i}] joint {j + 1} = {waypoints[i, j]:.6g} rad is outside its position "
            f"limits [{lim[j, 0]:.6g}, {lim[j, 1]:.6g}] rad; move the waypoint inside them"
        )
    return lim
