"""A part's cell subdivision cached on disk: keyed by the mesh and the cell size, checked on load.

Entries are `.npz` files of the disk cache (geometry/npz_cache.py: written atomically, size
limit, `workbench cache clear`) in ``cells/`` under `disk_cache.cache_root()`
(``$WORKBENCH_CACHE``, else ``~/.cache/workbench``). The key is a SHA-256 of the vertices,
faces, cell size and format. On load an entry must describe the grid `subdivide` would make
for this mesh: the same origin and shape (recomputed from the mesh bounds), every boundary
cell occupied, the cell of every vertex and of every triangle's centroid a boundary cell (each
lies on the surface), and the closed flag of the mesh; an entry that fails any of these, or
cannot be read, is a miss, and the grid is subdivided again and overwritten.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.assembly.cells import CellGrid
from workbench.disk_cache import cache_root
from workbench.geometry.npz_cache import cache_path, load_entry, store_entry

__all__ = ["CELL_CACHE_ENV", "cell_cache_dir", "load_grid", "store_grid"]

CELL_CACHE_ENV = "WORKBENCH_CELL_CACHE"
"""Set to "0" to keep cell grids in memory only (no disk entries)."""
_FORMAT = 1
_ARRAYS = ("origin", "cell_size", "shape", "occupied", "boundary", "closed")


def cell_cache_dir() -> Path | None:
    """Return the folder of the cell grid entries, or None when the disk cache is off."""
    if os.environ.get(CELL_CACHE_ENV) == "0":
        return None
    return cache_root() / "cells"


def _grid_frame(mesh: trimesh.Trimesh, c: float) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Return the origin and shape `subdivide` gives the grid of `mesh` at cell size `c`."""
    lo, hi = np.asarray(mesh.bounds, dtype=float)
    n = np.ceil((hi - lo) / c).astype(int) + 2
    return 0.5 * (lo + hi) - 0.5 * n * c, n


def _path(folder: Path, mesh: trimesh.Trimesh, c: float) -> Path:
    v = np.ascontiguousarray(mesh.vertices, dtype=float)
    f = np.ascontiguousarray(mesh.faces, dtype=np.int64)
    return cache_path(folder, "cells", [v, f], {"cell_size": float(c), "format": _FORMAT})


def load_grid(
    mesh: trimesh.Trimesh, cell_size: float, folder: Path | None = None
) -> CellGrid | None:
    """Return the cached grid of `mesh` at `cell_size` [m] if one is stored and passes the
    checks of the module docstring, else None."""
    folder = folder if folder is not None else cell_cache_dir()
    if folder is None:
        return None
    d = load_entry(_path(folder, mesh, cell_size), required=_ARRAYS)
    return None if d is None else _checked(mesh, float(cell_size), d)


def store_grid(mesh: trimesh.Trimesh, grid: CellGrid, folder: Path | None = None) -> None:
    """Store `grid` (of `mesh`, at `grid.cell_size`) in the cache; a failed write is ignored
    (the cache is an optimisation: a full or read-only disk must not fail a plan)."""
    folder = folder if folder is not None else cell_cache_dir()
    if folder is None:
        return
    arrays: dict[str, NDArray] = {
        "origin": grid.origin,
        "cell_size": np.asarray(grid.cell_size, np.float64),
        "shape": np.asarray(grid.occupied.shape, np.int64),
        "occupied": np.packbits(grid.occupied, axis=None),
        "boundary": np.packbits(grid.boundary, axis=None),
        "closed": np.asarray(grid.closed, np.bool_),
    }
    try:
        store_entry(_path(folder, mesh, grid.cell_size), arrays)
    except OSError:
        pass


def _checked(mesh: trimesh.Trimesh, c: float, d: dict[str, NDArray]) -> CellGrid | None:
    origin, n = _grid_frame(mesh, c)
    shape = np.asarray(d["shape"])
    if (
        shape.shape != (3,)
        or not np.array_equal(shape, n)
        or np.asarray(d["origin"]).shape != (3,)
        or not np.array_equal(np.asarray(d["origin"], float), origin)
        or float(d["cell_size"]) != c
        or bool(d["closed"]) != bool(mesh.is_watertight)
    ):
        return None
    size = int(np.prod(n))
    bits = (size + 7) // 8
    occ_b, bnd_b = np.asarray(d["occupied"]), np.asarray(d["boundary"])
    if (
        occ_b.dtype != np.uint8
        or bnd_b.dtype != np.uint8
        or occ_b.shape != (bits,)
        or bnd_b.shape != (bits,)
    ):
        return None
    occupied = np.unpackbits(occ_b, count=size).astype(bool).reshape(tuple(n))
    boundary = np.unpackbits(bnd_b, count=size).astype(bool).reshape(tuple(n))
    if np.any(boundary & ~occupied):
        return None
    tri = np.asarray(mesh.triangles, dtype=float)
    on_surface = np.concatenate([np.asarray(mesh.vertices, float), tri.mean(axis=1)])
    idx = np.floor((on_surface - origin) / c).astype(int)
    if np.any(idx < 0) or np.any(idx >= n):
        return None
    # A point exactly on a cell face may sit in the neighbour's cell by rounding: accept either.
    tol = 1e-9 * max(1.0, float(np.max(np.ptp(mesh.vertices, axis=0))))
    ok = boundary[idx[:, 0], idx[:, 1], idx[:, 2]]
    if not np.all(ok):
        p = on_surface[~ok]
        lo_i = np.clip(np.floor((p - origin - tol) / c).astype(int), 0, n - 1)
        hi_i = np.clip(np.floor((p - origin + tol) / c).astype(int), 0, n - 1)
        for a, b in zip(lo_i, hi_i, strict=True):
            if not np.any(boundary[a[0] : b[0] + 1, a[1] : b[1] + 1, a[2] : b[2] + 1]):
                return None
    return CellGrid(
        origin=origin, cell_size=c, occupied=occupied, boundary=boundary, closed=bool(d["closed"])
    )
