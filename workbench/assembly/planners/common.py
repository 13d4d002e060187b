"""What both part planners share: motion validation, scene bounds and the retreat from a tight pose.

Motions are checked with the AABB stage and then the exact check (`cells=False`): the
verdict is the same as with the cell stage in between, and faster (see interference.py).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import motion_samples
from workbench.errors import InputError


def check_options(planner: str, fn: Callable[..., Any], options: Mapping[str, object]) -> None:
    """Raise InputError naming the options `fn` (a planner) does not take, and those it does."""
    sig = inspect.signature(fn).parameters.values()
    allowed = [p.name for p in sig if p.kind is inspect.Parameter.KEYWORD_ONLY]
    unknown = sorted(set(options) - set(allowed))
    if unknown:
        raise InputError(
            f"planner {planner!r} has no option {', '.join(unknown)}; it takes {', '.join(allowed)}"
        )


def motion_free(checker: InterferenceChecker, T0: NDArray, T1: NDArray, resolution: float) -> bool:
    """Return True if the part moved straight from T0 to T1 (T0 excluded) never interferes."""
    S = motion_samples(T0, T1, checker.radius, resolution)
    return checker.first_interference(S, cells=False) < 0


def last_free(
    checker: InterferenceChecker, T0: NDArray, T1: NDArray, resolution: float
) -> NDArray | None:
    """Return the last free pose (4, 4) along T0 -> T1 before the first interference, or None if none."""
    S = motion_samples(T0, T1, checker.radius, resolution)
    hit = checker.first_interference(S, cells=False)
    if hit < 0:
        return S[-1]
    return S[hit - 1] if hit > 0 else None


def scene_bounds(
    checker: InterferenceChecker, *poses: NDArray, margin: float | None = None
) -> NDArray:
    """Return (2, 3) bounds [m] for the part's position: obstacles and given poses, grown by the part's radius."""
    pts = [T[:3, 3] for T in poses] + [b.bounds[i] for b in checker.obstacles for i in (0, 1)]
    P = np.asarray(pts, dtype=float)
    m = 2.0 * checker.radius if margin is None else margin
    return np.stack([P.min(axis=0) - m, P.max(axis=0) + m])


def retreat(
    checker: InterferenceChecker, T: NDArray, toward: NDArray, resolution: float
) -> NDArray | None:
    """Return a pose (4, 4) the part reaches from T by a straight retreat that frees it, or None.

    A part seated in a hole cannot leave it sideways. When the short straight motion from
    T toward `toward` [m] collides, the part is withdrawn along the world and part axes
    (most aligned with `toward` first) by its own extent plus a margin; the first axis
    whose whole withdrawal is free is used (assembly by disassembly). None means the
    direct move is free, or no axis frees the part.
    """
    p0 = T[:3, 3]
    d_goal = np.asarray(toward, float) - p0
    dist = float(np.linalg.norm(d_goal))
    if dist < 1e-12:
        return None
    probe = min(dist, 4.0 * checker.radius)
    T_probe = T.copy()
    T_probe[:3, 3] = p0 + d_goal / dist * probe
    if motion_free(checker, T, T_probe, resolution):
        return None
    axes = np.concatenate([np.eye(3), T[:3, :3].T])
    dirs = np.concatenate([axes, -axes])
    dirs = dirs[np.argsort(-(dirs @ d_goal))]
    lo, hi = checker.moving.bounds
    for d in dirs:
        local = T[:3, :3].T @ d
        length = float(np.abs(local) @ (hi - lo)) + 4.0 * resolution
        T1 = T.copy()
        T1[:3, 3] = p0 + d * length
        if motion_free(checker, T, T1, resolution):
            return T1
    return None
