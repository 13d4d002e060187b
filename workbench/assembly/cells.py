"""Finite subdivision of a part into cubic cells (seed 003, Sec. 5.1, Fig. 9).

The part's bounding box is cut by planes every `cell_size` along x, y and z; a cell is
kept when it holds part of the solid. Boundary cells are those a surface triangle
touches (cube-triangle separating-axis test); interior cells are the untouched cells
that the outside cannot reach by face-adjacent steps (a flood fill from a padding layer
that cannot cross the surface). Cells therefore cover the solid: any point of the solid
lies in a kept cell, which makes the cell stage of the interference check conservative.
"""

from __future__ import annotations

import hashlib
import warnings
from dataclasses import dataclass

import numpy as np
import trimesh
from numpy.typing import NDArray
from scipy import ndimage

from workbench.assembly.boxes import box_triangle_overlap
from workbench.bounded_cache import BoundedCache
from workbench.errors import InputError, MeshError

_CHUNK = 200_000
MAX_CELLS = 4_000_000
"""Most cubic cells a part's bounding box may be cut into (extent / cell_size per axis,
multiplied): a finer subdivision is refused before it starts, with its estimate."""


@dataclass(frozen=True, eq=False)
class CellGrid:
    """Cells of one part in the part's frame: grid origin [m], cell side [m], masks (nx, ny, nz)."""

    origin: NDArray[np.float64]
    cell_size: float
    occupied: NDArray[np.bool_]
    boundary: NDArray[np.bool_]
    closed: bool

    @property
    def half(self) -> float:
        """Return the half side of a cell [m]."""
        return 0.5 * self.cell_size

    def centers(self, which: str = "occupied") -> NDArray[np.float64]:
        """Return (N, 3) centres [m] of the `which` ("occupied" or "boundary") cells."""
        mask = self.occupied if which == "occupied" else self.boundary
        return self.origin + (np.argwhere(mask) + 0.5) * self.cell_size


def check_cell_size(
    cell_size: float, mesh: trimesh.Trimesh, name: str = "cell_size", *, part: str | None = None
) -> float:
    """Return `cell_size` [m] as float after checking it is finite, > 0 and <= the part's extent.

    InputError names `name`, and `part` (the part's name) when given."""
    of = "" if part is None else f" (part {part!r})"
    try:
        c = float(cell_size)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a number in metres, got {cell_size!r}{of}") from None
    extent = float(np.max(mesh.extents))
    if not np.isfinite(c) or c <= 0.0:
        raise InputError(f"{name} must be a finite length > 0 m, got {cell_size!r}{of}")
    if c > extent:
        raise InputError(
            f"{name}={c:g} m is larger than the part (largest extent {extent:g} m); "
            f"use a cell size <= {extent:g} m, typically 1/10 to 1/50 of it{of}"
        )
    cells = float(np.prod(np.ceil(np.asarray(mesh.extents, float) / c) + 1))
    if cells > MAX_CELLS:
        finest = float(np.cbrt(np.prod(np.asarray(mesh.extents, float)) / MAX_CELLS))
        raise InputError(
            f"{name}={c:g} m cuts the part ({' x '.join(f'{e:g}' for e in mesh.extents)} m) into"
            f" about {cells:.3g} cells, above the budget of {MAX_CELLS:,} "
            f"(workbench.assembly.cells.MAX_CELLS); use a cell size of at least ~{finest:.2g} m{of}"
        )
    return c


def check_mesh(
    mesh: object, name: str, *, require_closed: bool, part: str | None = None
) -> trimesh.Trimesh:
    """Return `mesh` after checking it is a non-empty Trimesh; MeshError (or a warning) if not closed.

    A MeshError names `name`, and `part` (the part's name) when given."""
    of = "" if part is None else f" (part {part!r})"
    if not isinstance(mesh, trimesh.Trimesh):
        raise InputError(f"{name} must be a trimesh.Trimesh, got {type(mesh).__name__}")
    if len(mesh.faces) == 0 or not np.all(np.isfinite(mesh.vertices)):
        raise MeshError(
            f"{name} is empty or has non-finite vertices; give a closed triangle mesh{of}"
        )
    if not mesh.is_watertight:
        msg = (
            f"{name} is not closed (not watertight: {len(mesh.faces)} faces with open edges); "
            "interior cells and containment cannot be decided — repair it (e.g. fill holes)"
        )
        if require_closed:
            raise MeshError(msg + of)
        warnings.warn(msg + "; treating it as a surface only", RuntimeWarning, stacklevel=3)
    return mesh


def subdivide(mesh: trimesh.Trimesh, cell_size: float) -> CellGrid:
    """Return the cells (in the mesh frame) of side `cell_size` [m] that hold part of `mesh`."""
    c = check_cell_size(cell_size, mesh)
    lo, hi = np.asarray(mesh.bounds, dtype=float)
    # One padding layer on every side so the flood fill starts outside the part.
    n = np.ceil((hi - lo) / c).astype(int) + 2
    origin = 0.5 * (lo + hi) - 0.5 * n * c
    tri = np.asarray(mesh.triangles, dtype=float)
    tol = 1e-9 * max(1.0, float(np.max(np.abs(hi - lo))))
    t_lo = np.floor((tri.min(axis=1) - origin - tol) / c).astype(int)
    t_hi = np.floor((tri.max(axis=1) - origin + tol) / c).astype(int)
    t_lo = np.clip(t_lo, 0, n - 1)
    t_hi = np.clip(t_hi, 0, n - 1)
    dims = t_hi - t_lo + 1
    counts = dims.prod(axis=1)
    boundary = np.zeros(n, dtype=bool)
    starts = np.concatenate([[0], np.cumsum(counts)])
    # Enumerate (triangle, cell) candidate pairs in chunks of triangles.
    f0 = 0
    while f0 < len(tri):
        f1 = int(np.searchsorted(starts, starts[f0] + _CHUNK, side="right")) - 1
        f1 = max(f1, f0 + 1)
        ids = np.repeat(np.arange(f0, f1), counts[f0:f1])
        local = np.arange(len(ids)) - np.repeat(starts[f0:f1] - starts[f0], counts[f0:f1])
        d = dims[ids]
        k = local % d[:, 2]
        j = (local // d[:, 2]) % d[:, 1]
        i = local // (d[:, 2] * d[:, 1])
        idx = t_lo[ids] + np.stack([i, j, k], axis=1)
        centers = origin + (idx + 0.5) * c
        hit = box_triangle_overlap(centers, 0.5 * c, tri[ids], tol=tol)
        h = idx[hit]
        boundary[h[:, 0], h[:, 1], h[:, 2]] = True
        f0 = f1
    closed = bool(mesh.is_watertight)
    occupied = boundary.copy()
    if closed:
        labels, _ = ndimage.label(~boundary)
        outside = labels[0, 0, 0]
        occupied |= (labels != outside) & ~boundary
    return CellGrid(origin=origin, cell_size=c, occupied=occupied, boundary=boundary, closed=closed)


def winding_number(
    points: NDArray[np.float64],
    mesh: trimesh.Trimesh,
    *,
    triangles: NDArray[np.float64] | None = None,
) -> NDArray[np.float64]:
    """Return the generalised winding number (K,) of points (K, 3) [m] w.r.t. a closed mesh.

    About 1 inside, 0 outside (Van Oosterom–Strackee solid angles summed over triangles).
    """
    p = np.atleast_2d(np.asarray(points, dtype=float))
    tri = np.asarray(mesh.triangles if triangles is None else triangles, dtype=float)
    out = np.empty(len(p))
    step = max(1, _CHUNK // max(1, len(tri)))
    for s in range(0, len(p), step):
        v = tri[None, :, :, :] - p[s : s + step, None, None, :]
        a, b, cc = v[..., 0, :], v[..., 1, :], v[..., 2, :]
        la, lb, lc = (np.linalg.norm(x, axis=-1) for x in (a, b, cc))
        bxc = np.stack(
            [
                b[..., 1] * cc[..., 2] - b[..., 2] * cc[..., 1],
                b[..., 2] * cc[..., 0] - b[..., 0] * cc[..., 2],
                b[..., 0] * cc[..., 1] - b[..., 1] * cc[..., 0],
            ],
            axis=-1,
        )
        num = np.einsum("...i,...i->...", a, bxc)
        den = (
            la * lb * lc
            + np.einsum("...i,...i->...", a, b) * lc
            + np.einsum("...i,...i->...", b, cc) * la
            + np.einsum("...i,...i->...", cc, a) * lb
        )
        out[s : s + step] = np.arctan2(num, den).sum(axis=1) / (2.0 * np.pi)
    return out


# The grids of meshes seen before, least recently used evicted first (a server sees many parts).
CELL_GRID_CACHE_ITEMS = 64
CELL_GRID_CACHE_BYTES = 256 << 20
_CACHE: BoundedCache[CellGrid] = BoundedCache(
    CELL_GRID_CACHE_ITEMS,
    CELL_GRID_CACHE_BYTES,
    lambda g: g.occupied.nbytes + g.boundary.nbytes + g.origin.nbytes,
)


def subdivide_cached(mesh: trimesh.Trimesh, cell_size: float) -> CellGrid:
    """Return `subdivide(mesh, cell_size)`, reusing the grid of an identical mesh seen before:
    in memory, else on disk (`cell_cache`: keyed by mesh and cell size, checked on load)."""
    from workbench.assembly.cell_cache import load_grid, store_grid

    h = hashlib.blake2b(np.ascontiguousarray(mesh.vertices, dtype=float).tobytes(), digest_size=16)
    h.update(np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes())
    key = (h.hexdigest(), float(cell_size))
    grid = _CACHE.get(key)
    if grid is None:
        c = check_cell_size(cell_size, mesh)
        grid = load_grid(mesh, c)
        if grid is None:
            grid = subdivide(mesh, c)
            store_grid(mesh, grid)
        _CACHE.put(key, grid)
    return grid
