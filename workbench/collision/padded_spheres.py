"""Spheres fixed in rigid bodies, padded per body so one batched matmul places them all.

The spheres mode of the collision engine places many small spheres (a few per
body) at many configurations. Gathering a (N, S, 4, 4) copy of the body frames per sphere
costs more than the placement itself; instead the centres are stored per body as a
homogeneous (B, 4, K) block (K = most spheres of one body) and placed with one
``(N, B, 3, 4) @ (B, 4, K)`` matmul (BLAS). Padding slots sit at the body origin with
radius -inf (clearance +inf: never the worst).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


class PaddedSpheres:
    """Spheres (S,) owned by bodies 0..B-1, padded per body to (B, K) slots (SI units).

    centres (S, 3) [m] in their body's frame, radii (S,) [m], owner (S,) body index.
    Attributes: `centres` (B, K, 3), `radii` (B, K) (-inf in padding), `valid` (B, K),
    `slot` (S,): the flat padded slot (b * K + k) of each input sphere.
    """

    def __init__(self, centres: ArrayLike, radii: ArrayLike, owner: ArrayLike, bodies: int) -> None:
        c = np.asarray(centres, float).reshape(-1, 3)
        r = np.asarray(radii, float).reshape(-1)
        own = np.asarray(owner, np.int64).reshape(-1)
        counts = np.bincount(own, minlength=bodies)
        k = int(counts.max()) if counts.size else 0
        self.centres: FloatArray = np.zeros((bodies, k, 3))
        self.radii: FloatArray = np.full((bodies, k), -np.inf)
        self.valid: NDArray[np.bool_] = np.zeros((bodies, k), bool)
        self.slot: NDArray[np.int64] = np.zeros(len(r), np.int64)
        for b in range(bodies):
            idx = np.flatnonzero(own == b)
            self.centres[b, : len(idx)], self.radii[b, : len(idx)] = c[idx], r[idx]
            self.valid[b, : len(idx)] = True
            self.slot[idx] = b * k + np.arange(len(idx))
        # Homogeneous centres (B, 4, K), contiguous for the batched matmul.
        h = np.concatenate([self.centres, np.ones((bodies, k, 1))], axis=2)
        self._h = np.ascontiguousarray(h.transpose(0, 2, 1))

    def place(self, T: FloatArray) -> FloatArray:
        """Return padded world centres (N, B, K, 3) [m] for body frames T (N, B, 3 or 4, 4)."""
        return np.matmul(T[..., :3, :], self._h).swapaxes(-1, -2)

    def unpad(self, c: FloatArray) -> FloatArray:
        """Return the input spheres' centres (N, S, 3) from padded ones (N, B, K, 3)."""
        return c.reshape(len(c), -1, 3)[:, self.slot]
