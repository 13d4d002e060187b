"""Midpoint subdivision of long triangles: the same surface in pieces with short edges."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


def split_long_triangles(
    tri: FloatArray, max_edge: float, *, limit: int | None = None, rounds: int = 30
) -> FloatArray:
    """Return the same surface as triangles (T', 3, 3) with every edge <= max_edge [m].

    Only the long triangles are split, 1 -> 4 at the edge midpoints, so the union of the
    pieces is the original surface (containing each piece contains the triangle). Stops
    early when a round would take the count past `limit`, or after `rounds` rounds.
    """
    for _ in range(rounds):
        edge = np.linalg.norm(tri - np.roll(tri, 1, axis=1), axis=2).max(axis=1)
        long = edge > max_edge
        if not np.any(long) or (limit is not None and len(tri) + 3 * int(long.sum()) > limit):
            break
        t = tri[long]
        a, b, c = t[:, 0], t[:, 1], t[:, 2]
        ab, bc, ca = (a + b) / 2, (b + c) / 2, (c + a) / 2
        pieces = np.stack(
            [np.stack(x, axis=1) for x in ((a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca))]
        )
        tri = np.concatenate([tri[~long], pieces.reshape(-1, 3, 3)])
    return tri
