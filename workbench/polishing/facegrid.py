"""A uniform grid of face centroids in a planar chart: the candidate faces of a point.

A triangle lies inside the disc of radius r around its centroid, r its largest
centroid-to-vertex distance; with square cells of side h >= reach (the largest r over the
mesh), the centroid of every face containing a point p lies in p's cell or one of its eight
neighbours; more precisely in a cell that the square [p - reach, p + reach] meets (on
average (1 + 2 reach / h)^2 of the nine). So the faces listed in those cells are a complete
candidate set, and an exact containment test over them locates p.

Built in O(F) without a comparison sort: cell ids fit in 16 bits (at most 65,536 cells;
cells grow when the chart would need more), where numpy's stable argsort is a radix sort.
On a mesh whose face sizes vary widely (one cell holding many small faces) the candidate
sets grow; `FaceGrid.build` then returns None and the caller uses a KD-tree instead.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]

MAX_CELLS = 1 << 16  # cell ids fit in uint16: radix argsort
MAX_PER_CELL = 32  # beyond this the mesh is too uneven for one grid level
_OFFSETS = np.array([(dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)], dtype=np.int64)


@dataclass(frozen=True)
class FaceGrid:
    """Faces by the grid cell of their chart centroid.

    lo (2,) [m] the grid's lower corner; h [m] the cell side (>= the mesh's reach); nx, ny
    cells along u and v; ptr (nx*ny + 1,) and order (F,): the faces of cell c (= ix*ny + iy)
    are order[ptr[c]:ptr[c+1]].
    """

    lo: F64
    h: float
    reach: float
    nx: int
    ny: int
    ptr: I64
    order: I64

    @staticmethod
    def build(
        cu: F64, cv: F64, reach: float, *, max_per_cell: int = MAX_PER_CELL
    ) -> FaceGrid | None:
        """Return the grid of centroids (cu, cv) (F,) [m] with cells >= `reach` [m], or None if
        some cell would hold more than `max_per_cell` faces."""
        lo = np.array([cu.min(), cv.min()])
        # The margin keeps rounding in the cell index from pushing a centroid at exactly
        # `reach` two cells away.
        h = max(reach * (1.0 + 1e-6), 1e-300)
        while True:
            inv = 1.0 / h
            # The same arithmetic as the per-face index below, so the largest index is nx - 1.
            nx = int((cu.max() - lo[0]) * inv) + 1
            ny = int((cv.max() - lo[1]) * inv) + 1
            if nx * ny <= MAX_CELLS:
                break
            h *= 1.05
        cell = ((cu - lo[0]) * inv).astype(np.int64) * ny + ((cv - lo[1]) * inv).astype(np.int64)
        counts = np.bincount(cell, minlength=nx * ny)
        if counts.max() > max_per_cell:
            return None
        order = np.argsort(cell.astype(np.uint16), kind="stable").astype(np.int64)
        ptr = np.zeros(nx * ny + 1, dtype=np.int64)
        np.cumsum(counts, out=ptr[1:])
        return FaceGrid(lo=lo, h=h, reach=reach, nx=nx, ny=ny, ptr=ptr, order=order)

    def candidates(self, p: F64) -> tuple[I64, I64]:
        """Return (owner (K,), face (K,)): for each point p[owner] (Q, 2) [m] the faces of the
        cells that the square [p - reach, p + reach] meets (at most the 3 x 3 block of cells
        around p's, as h >= reach), grouped by owner in increasing order."""
        inv = 1.0 / self.h
        r = self.reach * (1.0 + 1e-7)  # < h: the square stays within the 3 x 3 block
        pu, pv = p[:, 0] - self.lo[0], p[:, 1] - self.lo[1]
        ix = np.floor(pu * inv).astype(np.int64)
        iy = np.floor(pv * inv).astype(np.int64)
        # Only the cells the square meets: (1 + 2 reach / h)^2 of the 9 on average.
        ax = np.maximum(np.floor((pu - r) * inv).astype(np.int64), 0)[:, None]
        bx = np.minimum(np.floor((pu + r) * inv).astype(np.int64), self.nx - 1)[:, None]
        ay = np.maximum(np.floor((pv - r) * inv).astype(np.int64), 0)[:, None]
        by = np.minimum(np.floor((pv + r) * inv).astype(np.int64), self.ny - 1)[:, None]
        jx = ix[:, None] + _OFFSETS[:, 0]
        jy = iy[:, None] + _OFFSETS[:, 1]
        valid = (jx >= ax) & (jx <= bx) & (jy >= ay) & (jy <= by)
        cell = np.where(valid, jx * self.ny + jy, 0).ravel()
        start = self.ptr[cell]
        cnt = np.where(valid.ravel(), self.ptr[cell + 1] - start, 0)
        total = int(cnt.sum())
        first = np.cumsum(cnt) - cnt
        pos = np.repeat(start - first, cnt) + np.arange(total)
        owner = np.repeat(np.arange(len(p)), cnt.reshape(len(p), 9).sum(axis=1))
        return owner, self.order[pos]
