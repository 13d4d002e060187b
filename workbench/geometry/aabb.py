"""Axis-aligned bounding boxes of posed point sets (what a camera fits, what a view frames)."""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


def world_aabb(points: ArrayLike, T_world_local: ArrayLike | None = None) -> FloatArray:
    """Return the box (2, 3) [lo, hi] of `points` (N, 3) placed by `T_world_local` (4, 4).

    Raises ValueError on an empty set or a wrong shape (the shape received in the message)."""
    p = np.asarray(points, float)
    if p.ndim != 2 or p.shape[1] != 3 or len(p) == 0:
        raise ValueError(f"points: expected (N, 3) with N > 0, got {p.shape}")
    if T_world_local is not None:
        T = np.asarray(T_world_local, float)
        if T.shape != (4, 4):
            raise ValueError(f"T_world_local: expected (4, 4), got {T.shape}")
        p = p @ T[:3, :3].T + T[:3, 3]
    return np.stack([p.min(axis=0), p.max(axis=0)])


def aabb_union(boxes: Iterable[ArrayLike]) -> FloatArray:
    """Return the smallest box (2, 3) holding every box (2, 3) of `boxes` (ValueError if none)."""
    b = [np.asarray(x, float) for x in boxes]
    if not b:
        raise ValueError("boxes: need at least one box")
    stacked = np.stack(b)
    return np.stack([stacked[:, 0].min(axis=0), stacked[:, 1].max(axis=0)])
