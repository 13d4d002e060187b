"""Sparse two-level signed distance field of a triangle mesh (seed 001, step 2).

Level 1: a coarse grid (cell size h, by default 1/64 of the model's largest extent). A cell
is marked when a triangle grown by the band width r can touch it: the cell box grown by r
(a cube, which contains the ball-grown box) overlaps the triangle by the separating-axis
test (only the cells whose centre lies in the triangle's plane slab are tested; the
others fail its normal axis anyway). Level 2: each marked cell is split into s^3 fine cells; exact distances at their
corners come from the LBVH, and the sign from ray parity along x and y (both must agree
and neither may be untrusted, i.e. lie between the ends of a triangle the row grazes;
otherwise three skewed rays vote). Hits and corners of a row are compared exactly.

Values are truncated at W = r + sqrt(3)/2 * h/s (the band plus half a fine diagonal):
exact corner distances are only needed up to W, and they come from a triangle-driven pass
(each triangle visits the corners within W of its plane and of its side planes,
`triangle_raster.band_points`) when that costs less than LBVH queries; else the pass
goes to 2 fine cells and the rest come from the LBVH.

Query: inside a marked cell the value is trilinear in the fine corners. The truncated field
is 1-Lipschitz, so the value is within ``max_error = sqrt(3)/2 * h/s`` (half the fine-cell
diagonal) of clamp(d, -W, W): where |d| <= r it is within max_error of the exact signed
distance d, and elsewhere |value| <= |d| + max_error with the sign of d. Outside the band
the value is a guaranteed lower bound of |d| with the right sign: every point within r of
the surface lies in a marked cell, so a point in an unmarked cell is at least
``r + h * max(edt - sqrt(3), 0)`` away, with `edt` the distance (in cells, centre to centre)
from its cell to the nearest marked cell. Outside the grid the value is the distance to the
mesh AABB (also a lower bound). Negative inside. A conservative sphere test is therefore
``query(c) < radius + margin + max_error`` for spheres with radius + margin <= r.

A mesh that is not watertight (some edge not shared by exactly two triangles) gets a
warning and an unsigned field (all values >= 0).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import ndimage

from workbench.errors import InputError
from workbench.geometry.distance import point_triangle_distance2_rows
from workbench.geometry.lbvh import LBVH, check_mesh
from workbench.geometry.npz_cache import cache_path, load_entry, store_entry
from workbench.geometry.triangle_raster import (
    band_points,
    plane_slabs,
    slab_point_counts,
    slab_points,
    triangle_box_overlap,
)

__all__ = ["SparseSDF", "is_watertight", "triangle_box_overlap"]

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
Progress = Callable[[float, str], None]
_FORMAT = 1
_ARRAYS = (
    "band",
    "block_index",
    "cell_size",
    "far",
    "mesh_bounds",
    "origin",
    "signed",
    "subdivisions",
    "values",
)  # what a field is made of
_SKEWED = np.array([[1.0, 0.0123, 0.0071], [0.0093, 1.0, 0.0137], [0.0111, 0.0059, 1.0]])


def is_watertight(vertices: FloatArray, faces: IntArray) -> bool:
    """Return True when every edge (vertices merged by position) is shared by exactly two faces."""
    order = np.lexsort((vertices[:, 2], vertices[:, 1], vertices[:, 0]))
    sv = vertices[order]
    new = np.ones(len(sv), dtype=bool)
    new[1:] = np.any(sv[1:] != sv[:-1], axis=1)
    inv = np.empty(len(sv), dtype=np.int64)
    inv[order] = np.cumsum(new) - 1  # the same id for vertices at the same position
    f = inv[faces]
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    e = e[e[:, 0] != e[:, 1]]
    _, counts = np.unique(e[:, 0] * (len(vertices) + 1) + e[:, 1], return_counts=True)
    return bool(np.all(counts == 2))


_SIDE, _SIDE0, _ONES8 = np.array([-1.0, 1.0]), np.array([1.0, 0.0]), np.ones(8)


def _max_error(values: NDArray[np.float32], fine_cell: float) -> float:
    """Return the bound [m] on |query - exact signed distance| where |d| <= band: half a fine
    cell's diagonal (trilinear interpolation of a 1-Lipschitz field) plus float32 rounding."""
    rounding = 4.0 * float(np.finfo(np.float32).eps) * float(np.abs(values).max(initial=0.0))
    return float(np.sqrt(3.0) / 2.0 * fine_cell + rounding)


class SparseSDF:
    """Two-level sparse signed distance field; build with `SparseSDF.from_mesh`."""

    def __init__(self, arrays: dict[str, Any]) -> None:
        self.origin: FloatArray = np.asarray(arrays["origin"], dtype=float)
        self.cell_size = float(arrays["cell_size"])
        self.subdivisions = int(arrays["subdivisions"])
        self.band = float(arrays["band"])
        self.signed = bool(arrays["signed"])
        self.mesh_bounds: FloatArray = np.asarray(arrays["mesh_bounds"], dtype=float)
        self.block_index: NDArray[np.int32] = np.asarray(arrays["block_index"], dtype=np.int32)
        self.values: NDArray[np.float32] = np.asarray(arrays["values"], dtype=np.float32)
        self.far: NDArray[np.float32] = np.asarray(arrays["far"], dtype=np.float32)
        self.dims = np.array(self.block_index.shape)
        # Flat views for the query's gathers (np.take on 1-D beats fancy indexing in 3-4-D).
        self._block_flat = self.block_index.reshape(-1)
        self._far_flat = self.far.reshape(-1)
        self._values_flat = self.values.reshape(-1)
        # The field is immutable once built or loaded, so its error bound is computed here,
        # once (it rescans every value: 0.3-0.4 ms for the MZ07 cell's 675k, which every
        # single-configuration check read twice when it was a property).
        self.values.flags.writeable = False
        self.max_error: float = _max_error(self.values, self.fine_cell_size)
        # `query_fast`'s constants: grid strides, the 8 corner offsets of a fine cell.
        e = self.subdivisions + 1
        d1, d2 = int(self.dims[1]), int(self.dims[2])
        self._strides = np.array([d1 * d2, d2, 1], np.int64)
        self._fine_strides = np.array([e * e, e, 1], np.int64)
        self._corners = np.array(
            [(dx * e + dy) * e + dz for dx in (0, 1) for dy in (0, 1) for dz in (0, 1)], np.int64
        )
        self._dims_l: list[int] = [int(x) for x in self.dims]

    @property
    def fine_cell_size(self) -> float:
        """Return the fine cell edge h/s [m]."""
        return self.cell_size / self.subdivisions

    @property
    def memory_bytes(self) -> int:
        """Return the bytes held by the field's arrays."""
        return int(self.values.nbytes + self.block_index.nbytes + self.far.nbytes)

    @property
    def equivalent_resolution(self) -> int:
        """Return the dense grid resolution (cells along the largest axis) of the fine level."""
        return int(self.dims.max() * self.subdivisions)

    @property
    def block_count(self) -> int:
        """Return the number of marked (subdivided) coarse cells."""
        return int(len(self.values))

    # ------------------------------------------------------------------ build
    @classmethod
    def from_mesh(
        cls,
        mesh: Any,
        *,
        resolution: int = 64,
        cell_size: float | None = None,
        subdivisions: int = 4,
        band: float | None = None,
        cache_dir: str | Path | None = None,
        progress: Progress | None = None,
    ) -> SparseSDF:
        """Return the field of `mesh` (trimesh.Trimesh or (vertices, faces)); lengths in m.

        resolution: coarse cells along the largest extent (seed 001: 64 to 100), used when
        `cell_size` [m] is None. subdivisions: fine cells per coarse cell edge. band: r [m],
        the distance from the surface within which values are interpolated (default one
        coarse cell). cache_dir: reuse/store the field there, keyed by a hash of the mesh and
        the parameters. progress: called as progress(fraction, message).
        """
        if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
            v_in, f_in = mesh.vertices, mesh.faces
        elif isinstance(mesh, tuple) and len(mesh) == 2:
            v_in, f_in = mesh
        else:
            raise InputError(
                f"mesh must be a trimesh.Trimesh or a (vertices, faces) tuple, got {type(mesh).__name__}"
            )
        v, f = check_mesh(v_in, f_in)
        if int(subdivisions) < 1:
            raise InputError(f"subdivisions must be >= 1, got {subdivisions}")
        extent = float(np.ptp(v, axis=0).max())
        if cell_size is None:
            if int(resolution) < 2:
                raise InputError(f"resolution must be >= 2 coarse cells, got {resolution}")
            h = (extent or 1.0) / int(resolution)
        else:
            h = float(cell_size)
            if not np.isfinite(h) or h <= 0:
                raise InputError(f"cell_size must be a positive length in m, got {cell_size}")
        r = h if band is None else float(band)
        if not np.isfinite(r) or r < 0:
            raise InputError(f"band must be a length >= 0 m, got {band}")
        params = {"h": h, "s": int(subdivisions), "r": r, "format": _FORMAT}
        path = None
        if cache_dir is not None:
            path = cache_path(cache_dir, "sdf", [v, f], params)
            cached = load_entry(path, required=_ARRAYS)
            if cached is not None:
                if progress:
                    progress(1.0, f"loaded distance field from cache {path.name}")
                return cls(cached)
        arrays = _build(v, f, h, int(subdivisions), r, progress or (lambda _f, _m: None))
        if path is not None:
            store_entry(path, arrays)
        return cls(arrays)

    # ------------------------------------------------------------------ query
    def query(self, points: ArrayLike) -> FloatArray:
        """Return signed distances (M,) [m] at points (M,3); negative inside.

        Within ``max_error`` of exact in the band; outside it a lower bound of |d| (sign right).
        """
        p = np.asarray(points, dtype=float)
        if p.ndim != 2 or p.shape[1] != 3:
            raise InputError(f"points must have shape (M, 3), got {p.shape}")
        if not np.all(np.isfinite(p)):
            raise InputError("points contain NaN or inf; give finite coordinates in metres")
        g = (p - self.origin) / self.cell_size
        ci = np.floor(g).astype(np.int64)
        # In the grid: one unsigned compare per axis (negative indices wrap to huge values),
        # on 1-D columns rather than an all(axis=1) reduction over (M, 3).
        cu = ci.view(np.uint64)
        d0, d1, d2 = (int(x) for x in self.dims)
        in_grid = cu[:, 0] < d0
        in_grid &= cu[:, 1] < d1
        in_grid &= cu[:, 2] < d2
        idx = np.flatnonzero(in_grid)
        out = np.empty(len(p))
        if idx.size < len(p):  # outside the grid: distance to the mesh AABB (a lower bound)
            o = np.flatnonzero(~in_grid)
            po = p[o]
            d_box = np.maximum(np.maximum(self.mesh_bounds[0] - po, po - self.mesh_bounds[1]), 0.0)
            out[o] = np.linalg.norm(d_box, axis=1)
        flat = ((ci[:, 0] * d1 + ci[:, 1]) * d2 + ci[:, 2]).take(idx)
        blk = self._block_flat.take(flat)
        far = blk < 0
        out[idx[far]] = self._far_flat.take(flat[far])
        near_sel = ~far
        near = idx[near_sel]
        if near.size:
            s = self.subdivisions
            e = s + 1
            local = np.take(g - ci, near, axis=0) * s
            fi = np.clip(np.floor(local).astype(np.int64), 0, s - 1)
            t = local - fi
            base = ((blk[near_sel].astype(np.int64) * e + fi[:, 0]) * e + fi[:, 1]) * e + fi[:, 2]
            vals = self._values_flat
            acc = np.zeros(len(near))
            tx, ty, tz = t[:, 0], t[:, 1], t[:, 2]
            for dx in (0, 1):
                wx = tx if dx else 1.0 - tx
                for dy in (0, 1):
                    wy = ty if dy else 1.0 - ty
                    for dz in (0, 1):
                        wz = tz if dz else 1.0 - tz
                        val = vals.take(base + ((dx * e + dy) * e + dz))
                        acc += wx * wy * wz * val
            out[near] = acc
        return out

    def query_fast(self, points: FloatArray) -> FloatArray:
        """Return `query` at points (M, 3) [m] that the caller guarantees finite float64.

        The same trilinear interpolation in ~20 numpy calls on preallocated constants (the
        8 corners gathered at once), for the few points of one configuration; points outside
        the grid go to `query`.
        """
        g = (points - self.origin) / self.cell_size
        cf = np.floor(g)
        ci = cf.astype(np.int64)
        # In the grid: negative indices wrap to huge unsigned ones; one reduction for all.
        hi = ci.view(np.uint64).max(axis=0).tolist()
        if not (hi[0] < self._dims_l[0] and hi[1] < self._dims_l[1] and hi[2] < self._dims_l[2]):
            return self.query(points)
        flat = ci @ self._strides
        blk = self._block_flat.take(flat).astype(np.int64)
        s = self.subdivisions
        local = (g - cf) * s
        fi = np.floor(local)
        np.minimum(fi, s - 1.0, out=fi)  # local >= 0; == s only by rounding
        t = local - fi
        e3 = (s + 1) ** 3
        base = np.maximum(blk, 0) * e3 + fi.astype(np.int64) @ self._fine_strides
        v = self._values_flat.take(base[:, None] + self._corners)  # (M, 8)
        tt = t[:, :, None] * _SIDE + _SIDE0  # (M, 3, 2): weights 1 - t and t per axis
        w = tt[:, 0, :, None, None] * tt[:, 1, None, :, None] * tt[:, 2, None, None, :]
        w = w.reshape(-1, 8)
        w *= v
        acc = w @ _ONES8
        if blk.min() < 0:
            return np.where(blk < 0, self._far_flat.take(flat), acc)  # type: ignore[no-any-return]
        return acc  # type: ignore[no-any-return]


def _unique_keys(key: IntArray, size: int | None) -> tuple[IntArray, IntArray]:
    """Return (sorted unique keys, index of each key among them) for keys in [0, size).

    A mark-and-count pass over [0, size) when that range is small (size None: the
    largest key + 1), else np.unique; the same result either way.
    """
    top = int(key.max()) + 1 if size is None else size
    if top > max(1 << 22, 8 * len(key)):
        u, inv = np.unique(key, return_inverse=True)
        return u, inv.reshape(-1)
    mark = np.zeros(top, dtype=bool)
    mark[key] = True
    rank = np.cumsum(mark) - 1
    return np.flatnonzero(mark), rank[key]


def _grid_scale(origin: FloatArray, dims: IntArray, step: float) -> float:
    """Return the largest coordinate magnitude [m] on a grid (for rounding margins)."""
    return float(np.abs(np.stack([origin, origin + dims * step])).max()) + step


def _mark_cells(
    tri: FloatArray, origin: FloatArray, dims: IntArray, h: float, r: float
) -> NDArray[np.bool_]:
    """Return the coarse cells (bool dims) that triangles (T,3,3) grown by r [m] can touch.

    A cell is marked when its box grown by r (a cube of half-size h/2 + r) overlaps the
    triangle. Triangles whose grown box covers at most 8 cells mark them all (tight
    enough); the others test, by the separating-axis test, only the cells of that box whose
    centre lies in the triangle's plane slab (the normal axis of the same test, widened for
    rounding), so the set equals testing every cell of the box.
    """
    marked = np.zeros(dims, dtype=bool)
    imin = np.clip(np.floor((tri.min(axis=1) - r - origin) / h).astype(np.int64), 0, dims - 1)
    imax = np.clip(np.floor((tri.max(axis=1) + r - origin) / h).astype(np.int64), 0, dims - 1)
    span = imax - imin + 1
    count = span.prod(axis=1)
    small = np.flatnonzero(count <= 8)
    if small.size:
        cnt = count[small]
        tid = np.repeat(small, cnt)
        k = np.arange(len(tid)) - np.repeat(np.cumsum(cnt) - cnt, cnt)
        sp = span[tid]
        cell = imin[tid] + np.stack(
            [k // (sp[:, 1] * sp[:, 2]), (k // sp[:, 2]) % sp[:, 1], k % sp[:, 2]], axis=1
        )
        marked[cell[:, 0], cell[:, 1], cell[:, 2]] = True
    big = np.flatnonzero(count > 8)
    if big.size:
        half = h / 2 + r
        tb = tri[big]
        normal, offset, slab = plane_slabs(tb, half, cube=True, scale=_grid_scale(origin, dims, h))
        centre0 = origin + 0.5 * h
        for t, i0, i1, i2 in slab_points(imin[big], imax[big], normal, offset, slab, centre0, h):
            centre = centre0 + np.stack([i0, i1, i2], axis=1) * h
            v = tb[t]
            ok = triangle_box_overlap(v[:, 0], v[:, 1], v[:, 2], centre, half)
            marked[i0[ok], i1[ok], i2[ok]] = True
    return marked


def _skewed_inside(lbvh: LBVH, points: FloatArray) -> NDArray[np.bool_]:
    """Return inside flags by a majority of three skewed-ray parities (robust fallback)."""
    votes = np.zeros(len(points), dtype=np.int64)
    for d in _SKEWED:
        votes += lbvh.ray_crossings(points, d) % 2
    return votes >= 2


def _row_parity(
    lbvh: LBVH, ij: IntArray, axis: int, origin: FloatArray, hf: float
) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """Return (inside by ray parity along `axis`, trusted) for fine corners ij (P,3).

    One full-line ray per grid row. Hits are compared with the corners of their own row
    exactly (sorted by (row, t), not by one float key mixing row and position, which
    loses ~row * 1e-16 of resolution and misplaced corners within ~1e-12 of a face).
    A degenerate hit (near an edge, or the row lying in a triangle's plane) makes parity
    untrustworthy only on its own side: a corner past every degenerate triangle's extent
    along the row counts the regular hits after it, a corner before all of them counts
    those before it; only corners between are untrusted.
    """
    other = [k for k in range(3) if k != axis]
    width = int(ij[:, other[1]].max()) + 1
    rows, row_of = _unique_keys(ij[:, other[0]] * width + ij[:, other[1]], None)
    starts = np.empty((len(rows), 3))
    starts[:, axis] = origin[axis]
    starts[:, other[0]] = origin[other[0]] + (rows // width) * hf
    starts[:, other[1]] = origin[other[1]] + (rows % width) * hf
    direction = np.zeros(3)
    direction[axis] = 1.0
    hq, ht, hdeg, hleaf = lbvh.ray_hit_leaves(starts, direction, full_line=True)
    # Untrusted stretch of each row: the extents along `axis` of its degenerate triangles.
    margin = 1e-9 * lbvh.scale
    dl = hleaf[hdeg]
    ta, tb, tc = lbvh.a[dl, axis], lbvh.b[dl, axis], lbvh.c[dl, axis]
    bad_lo = np.full(len(rows), np.inf)
    bad_hi = np.full(len(rows), -np.inf)
    np.minimum.at(bad_lo, hq[hdeg], np.minimum(np.minimum(ta, tb), tc) - origin[axis] - margin)
    np.maximum.at(bad_hi, hq[hdeg], np.maximum(np.maximum(ta, tb), tc) - origin[axis] + margin)
    rq, rt = hq[~hdeg], ht[~hdeg]
    xc = ij[:, axis] * hf  # corner position along the row, in the rays' t
    # Merge hits and corners by (row, t); at equal t a hit sorts before the corner.
    n_hit = len(rq)
    order = np.lexsort(
        (
            np.concatenate([np.zeros(n_hit, np.int8), np.ones(len(xc), np.int8)]),
            np.concatenate([rt, xc]),
            np.concatenate([rq, row_of]),
        )
    )
    hits_upto = np.cumsum(order < n_hit)
    pos = np.empty(len(order), dtype=np.int64)
    pos[order] = np.arange(len(order))
    total = np.bincount(rq, minlength=len(rows))
    before = hits_upto[pos[n_hit:]] - (np.cumsum(total) - total)[row_of]
    after = total[row_of] - before
    trust_after = xc > bad_hi[row_of]
    trust_before = xc < bad_lo[row_of]
    odd = np.where(trust_after, after, before) % 2 == 1
    return odd, trust_after | trust_before


def _corner_box(
    tri: FloatArray, n_fine: IntArray, origin: FloatArray, hf: float, w: float
) -> tuple[IntArray, IntArray]:
    """Return the index boxes (lo, hi) (T,3) of the fine corners in triangles' AABBs grown by w."""
    top = n_fine - 1
    lo = np.clip(np.ceil((tri.min(axis=1) - w - origin) / hf).astype(np.int64), 0, top)
    hi = np.clip(np.floor((tri.max(axis=1) + w - origin) / hf).astype(np.int64), 0, top)
    return lo, hi


def _scatter_d2(
    tri: FloatArray,
    ukey: IntArray,
    n_fine: IntArray,
    origin: FloatArray,
    hf: float,
    w: float,
) -> FloatArray:
    """Return squared distances (P,) at corners `ukey` (sorted), exact where <= w**2, else inf.

    Each triangle (T,3,3) visits the existing corners of its AABB grown by w [m] that
    `band_points` keeps (within w of its plane and of its side planes); every corner within
    w is among them, so the minimum over triangles is exact there. Corners that project
    into the triangle take the plane distance, the rest the point-triangle distance.
    """
    best = np.full(len(ukey), np.inf)
    lo, hi = _corner_box(tri, n_fine, origin, hf, w)
    ta, tb, tc = (np.ascontiguousarray(tri[:, k].T) for k in range(3))
    # Corner key -> row of ukey: a dense table when the fine grid is small enough (one
    # gather per pair), else a binary search. -1: not a corner of a marked block.
    dense = int(np.prod(n_fine)) <= max(1 << 23, 8 * len(ukey)) and len(ukey) < 2**31
    if dense:
        table = np.full(int(np.prod(n_fine)), -1, dtype=np.int32)
        table[ukey] = np.arange(len(ukey), dtype=np.int32)
    scale = _grid_scale(origin, n_fine - 1, hf)
    for tid, g0, g1, g2, d2 in band_points(tri, lo, hi, origin, hf, w, scale):
        key = (g0 * n_fine[1] + g1) * n_fine[2] + g2
        if dense:
            pos = table.take(key)
        else:
            pos = np.minimum(np.searchsorted(ukey, key), len(ukey) - 1)
            pos[ukey.take(pos) != key] = -1
        hit = np.nonzero(pos >= 0)[0]
        pos, d2 = pos.take(hit), d2.take(hit)
        todo = np.nonzero(np.isnan(d2))[0]
        if todo.size:
            sel = hit.take(todo)
            t = tid.take(sel)
            p = np.stack(
                [
                    origin[0] + g0.take(sel) * hf,
                    origin[1] + g1.take(sel) * hf,
                    origin[2] + g2.take(sel) * hf,
                ]
            )
            d2[todo] = point_triangle_distance2_rows(
                p, np.take(ta, t, axis=1), np.take(tb, t, axis=1), np.take(tc, t, axis=1)
            )
        np.minimum.at(best, pos, d2)
    best[best > w * w] = np.inf
    return best


def _toward_zero_f32(x: FloatArray) -> NDArray[np.float32]:
    """Return x as float32 rounded toward zero, so a lower bound of |d| stays one."""
    y = x.astype(np.float32)
    too_big = np.abs(y.astype(np.float64)) > np.abs(x)
    y[too_big] = np.nextafter(y[too_big], np.float32(0.0))
    return y


def _build(
    v: FloatArray, f: IntArray, h: float, s: int, r: float, progress: Progress
) -> dict[str, Any]:
    progress(0.0, "building LBVH")
    lbvh = LBVH(v, f)
    watertight = is_watertight(v, f)
    if not watertight:
        warnings.warn(
            "mesh is not watertight (some edges are not shared by exactly two triangles): "
            "the distance field is unsigned (no inside); repair the mesh for signed distances",
            stacklevel=3,
        )
    lo, hi = lbvh.bounds
    pad = r + h
    origin = lo - pad
    dims = np.maximum(np.ceil((hi + pad - origin) / h).astype(np.int64), 1)
    progress(0.05, f"marking coarse cells ({dims[0]}x{dims[1]}x{dims[2]})")
    marked = _mark_cells(np.stack([lbvh.a, lbvh.b, lbvh.c], axis=1), origin, dims, h, r)
    blocks = np.argwhere(marked)
    block_index = np.full(dims, -1, dtype=np.int32)
    block_index[blocks[:, 0], blocks[:, 1], blocks[:, 2]] = np.arange(len(blocks), dtype=np.int32)
    # Fine corners, shared between neighbouring blocks: compute each once.
    e = np.arange(s + 1)
    offs = np.stack(np.meshgrid(e, e, e, indexing="ij"), axis=-1).reshape(-1, 3)
    n_fine = dims * s + 1
    gij = (blocks[:, None, :] * s + offs[None]).reshape(-1, 3)
    key = (gij[:, 0] * n_fine[1] + gij[:, 1]) * n_fine[2] + gij[:, 2]
    ukey, inv = _unique_keys(key, int(np.prod(n_fine)))
    uij = np.stack(
        [ukey // (n_fine[1] * n_fine[2]), (ukey // n_fine[2]) % n_fine[1], ukey % n_fine[2]], axis=1
    )
    hf = h / s
    pts = origin + uij * hf
    # Values are truncated at W = r + sqrt(3)/2 hf: exact distances are only needed up to W.
    trunc = r + np.sqrt(3.0) / 2.0 * hf
    # Triangle-driven pass up to W when that enumerates fewer than ~20 (triangle, corner)
    # pairs per corner (about the cost of one LBVH query: ~0.1 us a pair, ~3 us a query);
    # else to 2 fine cells + LBVH. Counted on the plane slabs the pass enumerates.
    tri = np.stack([lbvh.a, lbvh.b, lbvh.c], axis=1)
    lo_c, hi_c = _corner_box(tri, n_fine, origin, hf, trunc)
    n_c, _, half_c = plane_slabs(tri, trunc, cube=False, scale=_grid_scale(origin, dims, h))
    pairs_full = float(slab_point_counts(lo_c, hi_c, n_c, half_c, hf).sum())
    w_s = trunc if pairs_full <= 20.0 * len(pts) else min(trunc, 2.0 * hf)
    progress(0.1, f"distances at {len(pts)} fine corners ({len(blocks)} blocks), near triangles")
    dist = np.sqrt(_scatter_d2(tri, ukey, n_fine, origin, hf, w_s))
    far_c = np.nonzero(dist > w_s)[0]
    if trunc > w_s and far_c.size:
        step = 65536
        for i in range(0, far_c.size, step):
            progress(
                0.4 + 0.4 * i / far_c.size,
                f"distances at {far_c.size} corners farther than {w_s:.4g} m",
            )
            sel = far_c[i : i + step]
            dist[sel] = lbvh.closest_points(pts[sel])[1]
    dist = np.minimum(dist, trunc)
    sign_far = np.ones(dims, dtype=np.float64)
    if watertight:
        progress(0.8, "signs by ray parity along x and y")
        in_x, ok_x = _row_parity(lbvh, uij, 0, origin, hf)
        in_y, ok_y = _row_parity(lbvh, uij, 1, origin, hf)
        inside = in_x
        # Corners exactly on the surface need no sign (often rows lying in a face plane).
        redo = np.nonzero((~ok_x | ~ok_y | (in_x != in_y)) & (dist > 0))[0]
        if redo.size:
            inside[redo] = _skewed_inside(lbvh, pts[redo])
        dist = np.where(inside, -dist, dist)
        labels, n_lab = ndimage.label(~marked)
        if n_lab:
            first = ndimage.minimum_position(labels, labels, np.arange(1, n_lab + 1))
            centres = origin + (np.array(first, dtype=float).reshape(-1, 3) + 0.5) * h
            comp_inside = _skewed_inside(lbvh, centres)
            sign_far = np.where(np.concatenate([[False], comp_inside])[labels], -1.0, 1.0)
    progress(0.95, "far-field bounds")
    edt = ndimage.distance_transform_edt(~marked)
    far = sign_far * (r + h * np.maximum(edt - np.sqrt(3.0), 0.0))
    values = dist[inv.reshape(-1)].reshape(len(blocks), s + 1, s + 1, s + 1)
    progress(1.0, f"done: {len(blocks)} blocks, {values.nbytes / 1e6:.1f} MB")
    return {
        "origin": origin,
        "cell_size": np.float64(h),
        "subdivisions": np.int64(s),
        "band": np.float64(r),
        "signed": np.bool_(watertight),
        "mesh_bounds": lbvh.bounds,
        "block_index": block_index,
        "values": values.astype(np.float32),
        "far": _toward_zero_f32(far),
    }
