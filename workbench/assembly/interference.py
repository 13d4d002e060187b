"""Interference of a moving part with static obstacles: seed 003's two stages plus an exact check.

Stage 1 (AABB): the moving part's world AABB against each obstacle's AABB discards pairs.
Stage 2 (cells): the part's boundary cells, as boxes rotating with the part, against the
obstacle's occupied cells (boxes fixed in the world); plus an obstacle vertex looked up in
the part's occupied cells, for an obstacle wholly inside the part. Both stages are
conservative: they never call a pair free that touches.
Stage 3 (exact, the last word): python-fcl BVH mesh collision, plus a winding-number
containment test in both directions because fcl meshes are surfaces.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass

import fcl
import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.assembly.boxes import obb_aabb_overlap
from workbench.assembly.cells import (
    CellGrid,
    check_cell_size,
    check_mesh,
    subdivide_cached,
    winding_number,
)
from workbench.errors import InputError

# An obstacle grid never has more than this many cells along an axis; its cells may be
# coarser than the moving part's (still conservative, just less selective).
MAX_OBSTACLE_CELLS_PER_AXIS = 128


@dataclass
class CheckStats:
    """Counters of work done: poses checked and pairs reaching each stage."""

    poses: int = 0
    aabb_pairs: int = 0
    cell_pairs: int = 0
    exact_pairs: int = 0


class _Body:
    def __init__(self, mesh: trimesh.Trimesh, grid: CellGrid) -> None:
        self.mesh = mesh
        self.grid = grid
        self.bounds = np.asarray(mesh.bounds, dtype=float)
        self.fcl_obj = fcl.CollisionObject(_bvh(mesh), fcl.Transform())
        # One vertex per connected component, for the containment test.
        labels = trimesh.graph.connected_component_labels(mesh.face_adjacency, len(mesh.faces))
        # Up to 32 vertices per connected component, for the containment test: with the
        # surfaces apart, each component lies wholly inside or wholly outside the other body.
        rng = np.random.default_rng(0)
        sets = []
        for c in np.unique(labels):
            v = np.unique(mesh.faces[labels == c])
            sets.append(mesh.vertices[rng.choice(v, 32, replace=len(v) < 32)])
        self.probes = np.asarray(sets, dtype=float)  # (components, 32, 3)
        self.triangles = np.ascontiguousarray(mesh.triangles, dtype=float)


def _bvh(mesh: trimesh.Trimesh) -> fcl.BVHModel:
    m = fcl.BVHModel()
    m.beginModel(len(mesh.vertices), len(mesh.faces))
    m.addSubModel(np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int32))
    m.endModel()
    return m


def _fcl_tf(T: NDArray[np.float64]) -> fcl.Transform:
    return fcl.Transform(np.ascontiguousarray(T[:3, :3]), np.ascontiguousarray(T[:3, 3]))


def exact_interference(
    mesh_a: trimesh.Trimesh, T_world_a: ArrayLike, mesh_b: trimesh.Trimesh, T_world_b: ArrayLike
) -> bool:
    """Return True if two closed meshes placed at (4, 4) poses [m] intersect or one encloses the other."""
    Ta, Tb = np.asarray(T_world_a, float), np.asarray(T_world_b, float)
    oa = fcl.CollisionObject(_bvh(mesh_a), _fcl_tf(Ta))
    ob = fcl.CollisionObject(_bvh(mesh_b), _fcl_tf(Tb))
    if fcl.collide(oa, ob, fcl.CollisionRequest(), fcl.CollisionResult()) > 0:
        return True
    T_b_a = np.linalg.solve(Tb, Ta)
    pa = mesh_a.vertices[:1] @ T_b_a[:3, :3].T + T_b_a[:3, 3]
    T_a_b = np.linalg.inv(T_b_a)
    pb = mesh_b.vertices[:1] @ T_a_b[:3, :3].T + T_a_b[:3, 3]
    return bool(winding_number(pa, mesh_b)[0] > 0.5 or winding_number(pb, mesh_a)[0] > 0.5)


def _grid_lookup(grid: CellGrid, points: NDArray[np.float64]) -> NDArray[np.bool_]:
    idx = np.floor((points - grid.origin) / grid.cell_size).astype(int)
    ok = np.all((idx >= 0) & (idx < grid.occupied.shape), axis=-1)
    out = np.zeros(points.shape[:-1], dtype=bool)
    i = idx[ok]
    out[ok] = grid.occupied[i[:, 0], i[:, 1], i[:, 2]]
    return out


class InterferenceChecker:
    """Interference verdicts for one moving part (in its own frame) among static world obstacles."""

    def __init__(
        self,
        moving: trimesh.Trimesh,
        obstacles: Sequence[trimesh.Trimesh],
        cell_size: float | None = None,
        *,
        obstacle_cell_size: float | None = None,
    ) -> None:
        """Subdivide the part and obstacles into cells of side `cell_size` [m] (default 1/20 of the part).

        obstacle_cell_size [m]: obstacles' cell side (default: cell_size, coarsened so an
        obstacle has at most MAX_OBSTACLE_CELLS_PER_AXIS cells along any axis).
        """
        check_mesh(moving, "moving", require_closed=True)
        if isinstance(obstacles, trimesh.Trimesh) or not isinstance(obstacles, Sequence):
            raise InputError("obstacles must be a list of trimesh.Trimesh in the world frame")
        for i, ob in enumerate(obstacles):
            check_mesh(ob, f"obstacles[{i}]", require_closed=False)
        if cell_size is None:
            cell_size = float(np.max(moving.extents)) / 20.0
        self.cell_size = check_cell_size(cell_size, moving)
        self.moving = _Body(moving, subdivide_cached(moving, self.cell_size))
        self.obstacles = []
        for ob in obstacles:
            c = max(self.cell_size, float(np.max(ob.extents)) / (MAX_OBSTACLE_CELLS_PER_AXIS - 2))
            if obstacle_cell_size is not None:
                c = check_cell_size(obstacle_cell_size, ob, "obstacle_cell_size")
            self.obstacles.append(_Body(ob, subdivide_cached(ob, c)))
        self._cells = self.moving.grid.centers("boundary")
        lo, hi = self.moving.bounds
        self._box_c, self._box_h = 0.5 * (lo + hi), 0.5 * (hi - lo)
        self.radius = float(np.max(np.linalg.norm(moving.vertices, axis=1)))
        self.stats = CheckStats()

    # -- stages, each (P, 4, 4) poses -> (P, n_obstacles) bool --------------------------
    def aabb_stage(self, T: ArrayLike) -> NDArray[np.bool_]:
        """Return (P, n_obstacles): True where the part's world AABB meets an obstacle's AABB."""
        T = _poses(T)
        c = T[:, :3, :3] @ self._box_c + T[:, :3, 3]
        h = np.abs(T[:, :3, :3]) @ self._box_h
        if not self.obstacles:
            return np.zeros((len(T), 0), dtype=bool)
        ob = np.stack([b.bounds for b in self.obstacles])  # (n, 2, 3)
        return np.all(
            (c[:, None] - h[:, None] <= ob[None, :, 1])
            & (c[:, None] + h[:, None] >= ob[None, :, 0]),
            axis=-1,
        )

    def cell_stage_pair(self, T: ArrayLike, k: int) -> NDArray[np.bool_]:
        """Return (P,): True where the part's cells meet obstacle `k`'s cells (conservative)."""
        T = _poses(T)
        g = self.obstacles[k].grid
        R, t = T[:, :3, :3], T[:, :3, 3]
        cw = self._cells @ np.swapaxes(R, 1, 2) + t[:, None]  # (P, N, 3)
        hm = self.moving.grid.half
        hw = hm * np.abs(R).sum(axis=2)  # (P, 3) world AABB half of one moving cell
        shape = np.asarray(g.occupied.shape)
        lo = np.floor((cw - hw[:, None] - g.origin) / g.cell_size).astype(np.int64)
        hi = np.floor((cw + hw[:, None] - g.origin) / g.cell_size).astype(np.int64)
        inside = np.all((hi >= 0) & (lo < shape), axis=-1)
        p, n = np.nonzero(inside)
        lo = np.maximum(lo[p, n], 0)
        ext = np.minimum(hi[p, n], shape - 1) - lo  # cells spanned per axis, minus one
        strides = np.array([shape[1] * shape[2], shape[2], 1])
        base = lo @ strides
        occ = g.occupied.ravel()
        span = int(ext.max(initial=-1)) + 1
        hit = np.zeros(len(T), dtype=bool)
        sel_i, sel_lin = [], []
        for off in itertools.product(range(span), repeat=3):
            ok = np.all(ext >= off, axis=1) if any(off) else np.ones(len(base), dtype=bool)
            lin = base[ok] + int(np.dot(off, strides))
            o = occ[lin]
            sel_i.append(np.nonzero(ok)[0][o])
            sel_lin.append(lin[o])
        if span > 0:
            i = np.concatenate(sel_i)
            lin = np.concatenate(sel_lin)
            if len(i):
                jj = np.stack(np.unravel_index(lin, g.occupied.shape), axis=1)
                cb = g.origin + (jj + 0.5) * g.cell_size
                over = obb_aabb_overlap(cw[p[i], n[i]], R[p[i]], hm, cb, g.half)
                hit[p[i][over]] = True
        # An obstacle wholly inside the part: its probe vertices fall in the part's cells.
        probes = self.obstacles[k].probes
        local = (probes.reshape(1, -1, 3) - t[:, None]) @ R  # (P, m, 3): R^T (p - t)
        inside = _grid_lookup(self.moving.grid, local).reshape(len(T), *probes.shape[:2])
        hit |= np.any(np.all(inside, axis=2), axis=1)
        return hit

    def exact_pair(self, T: NDArray[np.float64], k: int) -> bool:
        """Return True if the part at pose T (4, 4) truly interferes with obstacle `k` (fcl + containment)."""
        ob = self.obstacles[k]
        self.moving.fcl_obj.setTransform(_fcl_tf(T))
        if fcl.collide(
            self.moving.fcl_obj, ob.fcl_obj, fcl.CollisionRequest(), fcl.CollisionResult()
        ):
            return True
        # Surfaces apart: interference only if one body encloses the other.
        if ob.grid.closed:
            p = self.moving.probes @ T[:3, :3].T + T[:3, 3]
            if _inside(p, ob):
                return True
        q = (ob.probes - T[:3, 3]) @ T[:3, :3]
        return _inside(q, self.moving)

    # -- verdicts ------------------------------------------------------------------------
    def first_interference(self, T: ArrayLike, *, chunk: int = 16) -> int:
        """Return the index of the first of poses (P, 4, 4) at which the part interferes, or -1.

        Poses are checked in order, `chunk` at a time, and checking stops at the first hit.
        """
        T = _poses(T)
        for s in range(0, len(T), chunk):
            hit = self._first_in(T[s : s + chunk])
            if hit >= 0:
                return s + hit
        return -1

    def _first_in(self, T: NDArray[np.float64]) -> int:
        self.stats.poses += len(T)
        cand = self.aabb_stage(T)
        self.stats.aabb_pairs += int(cand.sum())
        for k in range(len(self.obstacles)):
            rows = np.nonzero(cand[:, k])[0]
            if len(rows):
                self.stats.cell_pairs += len(rows)
                cand[rows, k] = self.cell_stage_pair(T[rows], k)
        for p in np.nonzero(cand.any(axis=1))[0]:
            for kk in np.nonzero(cand[p])[0]:
                self.stats.exact_pairs += 1
                if self.exact_pair(T[p], int(kk)):
                    return int(p)
        return -1

    def interferes(self, T: ArrayLike) -> bool:
        """Return True if the part at pose T (4, 4) in the world interferes with any obstacle."""
        return self.first_interference(np.asarray(T, float)[None]) >= 0

    def colliding_obstacles(self, T: ArrayLike) -> list[int]:
        """Return the indices of obstacles the part at pose T (4, 4) interferes with (exact)."""
        T = _poses(T)[:1]
        cand = self.aabb_stage(T)[0]
        return [int(k) for k in np.nonzero(cand)[0] if self.exact_pair(T[0], int(k))]


def _inside(points: NDArray[np.float64], body: _Body) -> bool:
    """Return True if any probe set (C, m, 3) [m] lies inside the body's closed mesh.

    A probe in an empty cell proves its set outside, one in an interior cell proves it
    inside; only sets wholly in boundary cells need the winding number.
    """
    g = body.grid
    idx = np.floor((points - g.origin) / g.cell_size).astype(np.int64)
    ok = np.all((idx >= 0) & (idx < g.occupied.shape), axis=-1)
    i = np.where(ok[..., None], idx, 0)
    occ = ok & g.occupied[i[..., 0], i[..., 1], i[..., 2]]
    bnd = ok & g.boundary[i[..., 0], i[..., 1], i[..., 2]]
    if np.any(occ & ~bnd):
        return True
    undecided = np.all(bnd, axis=-1)
    if not np.any(undecided):
        return False
    w = winding_number(points[undecided, 0], body.mesh, triangles=body.triangles)
    return bool(np.any(w > 0.5))


def _poses(T: ArrayLike) -> NDArray[np.float64]:
    T = np.asarray(T, dtype=float)
    if T.shape == (4, 4):
        T = T[None]
    if T.ndim != 3 or T.shape[1:] != (4, 4):
        raise InputError(f"poses must have shape (4, 4) or (P, 4, 4), got {T.shape}")
    return T
