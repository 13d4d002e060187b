"""Interference of a moving part with static obstacles: seed 003's two stages plus an exact check.

Stage 1 (AABB): the moving part's world AABB against each obstacle's AABB discards pairs.
Stage 2 (cells): the part's boundary cells, as boxes rotating with the part, against the
obstacle's occupied cells (boxes fixed in the world); plus an obstacle vertex looked up in
the part's occupied cells, for an obstacle wholly inside the part. Both stages are
conservative: they never call a pair free that touches.
Stage 3 (exact, the last word): python-fcl BVH mesh collision, plus a winding-number
containment test in both directions because fcl meshes are surfaces. The containment
test runs only where it can succeed: a component of one body can lie inside the other
only if its bounding box lies inside the other's.

The cell stage is a filter, not part of the verdict: with or without it the answer is
the exact one. The planners check motions with `cells=False` (AABB, then exact), as in
numpy the cell stage costs more per pose than one python-fcl collide on every scene of
`benchmarks/assembly.py`; direct verdict calls keep the seed's two stages by default
(`cell_filter`).
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
from workbench.collision.shapes import bvh_model, fcl_transform
from workbench.errors import InputError

# An obstacle grid never has more than this many cells along an axis; its cells may be
# coarser than the moving part's (still conservative, just less selective).
MAX_OBSTACLE_CELLS_PER_AXIS = 128


@dataclass
class CheckStats:
    """Counters of work done: poses through the AABB stage and pairs reaching each later stage."""

    poses: int = 0
    aabb_pairs: int = 0
    cell_pairs: int = 0
    exact_pairs: int = 0


class _Body:
    def __init__(self, mesh: trimesh.Trimesh, grid: CellGrid) -> None:
        self.mesh = mesh
        self.grid = grid
        self.bounds = np.asarray(mesh.bounds, dtype=float)
        self.fcl_obj = fcl.CollisionObject(bvh_model(mesh.vertices, mesh.faces), fcl.Transform())
        labels = trimesh.graph.connected_component_labels(mesh.face_adjacency, len(mesh.faces))
        # Up to 32 vertices per connected component, for the containment test: with the
        # surfaces apart, each component lies wholly inside or wholly outside the other body.
        rng = np.random.default_rng(0)
        sets, boxes = [], []
        for c in np.unique(labels):
            v = np.unique(mesh.faces[labels == c])
            sets.append(mesh.vertices[rng.choice(v, 32, replace=len(v) < 32)])
            boxes.append([mesh.vertices[v].min(axis=0), mesh.vertices[v].max(axis=0)])
        self.probes = np.asarray(sets, dtype=float)  # (components, 32, 3)
        # Each component's box (components, 2, 3) [m]: it can be enclosed only if this is.
        self.component_boxes = np.asarray(boxes, dtype=float)
        self.triangles = np.ascontiguousarray(mesh.triangles, dtype=float)


def exact_interference(
    mesh_a: trimesh.Trimesh, T_world_a: ArrayLike, mesh_b: trimesh.Trimesh, T_world_b: ArrayLike
) -> bool:
    """Return True if two closed meshes placed at (4, 4) poses [m] intersect or one encloses the other."""
    Ta, Tb = np.asarray(T_world_a, float), np.asarray(T_world_b, float)
    oa = fcl.CollisionObject(bvh_model(mesh_a.vertices, mesh_a.faces), fcl_transform(Ta))
    ob = fcl.CollisionObject(bvh_model(mesh_b.vertices, mesh_b.faces), fcl_transform(Tb))
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
        cell_filter: bool = True,
    ) -> None:
        """Subdivide the part and obstacles into cells of side `cell_size` [m] (default 1/20 of the part).

        obstacle_cell_size [m]: obstacles' cell side (default: cell_size, coarsened so an
        obstacle has at most MAX_OBSTACLE_CELLS_PER_AXIS cells along any axis).
        cell_filter: whether verdict calls run the cell stage between AABB and exact by
        default (the seed's two stages); it changes speed only, never the verdict.
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
        self.cell_filter = bool(cell_filter)
        self.stats = CheckStats()
        # Cached once: obstacle bounds for the AABB stage, the part's probes for the
        # containment pre-test, and the fcl request object.
        self._ob_bounds = np.asarray([b.bounds for b in self.obstacles], float).reshape(-1, 2, 3)
        self._probes_flat = self.moving.probes.reshape(-1, 3)
        # Static halves of the enclosure pre-test, rotation-free: a part component fits in
        # an obstacle's box only if its probes' diameter is at most the box's diagonal; an
        # obstacle component fits in the part's world AABB only if no side of its box
        # exceeds 2 |half extents| (the largest that AABB gets along an axis).
        P = self.moving.probes
        diam = np.max(np.linalg.norm(P[:, :, None] - P[:, None], axis=-1), axis=(1, 2))
        diag = np.linalg.norm(self._ob_bounds[:, 1] - self._ob_bounds[:, 0], axis=1)
        self._may_hold_part = np.array(
            [
                b.grid.closed and bool(np.any(diam <= d))
                for b, d in zip(self.obstacles, diag, strict=True)
            ],
            dtype=bool,
        )
        reach = 2.0 * float(np.linalg.norm(self._box_h))
        self._fitting_boxes = [
            b.component_boxes[
                np.all(b.component_boxes[:, 1] - b.component_boxes[:, 0] <= reach, axis=1)
            ]
            for b in self.obstacles
        ]
        self._may_fit_in_part = np.array([len(f) > 0 for f in self._fitting_boxes], dtype=bool)
        self._request = fcl.CollisionRequest()

    # -- stages, each (P, 4, 4) poses -> (P, n_obstacles) bool --------------------------
    def aabb_stage(self, T: ArrayLike) -> NDArray[np.bool_]:
        """Return (P, n_obstacles): True where the part's world AABB meets an obstacle's AABB."""
        T = _poses(T)
        R = T[:, :3, :3]
        c = R.dot(self._box_c) + T[:, :3, 3]
        h = np.abs(R).dot(self._box_h)
        lo, hi = c - h, c + h
        ob = self._ob_bounds  # (n, 2, 3)
        # Axis by axis on (P, n): numpy is slow on a trailing axis of 3.
        m = (lo[:, :1] <= ob[:, 1, 0]) & (hi[:, :1] >= ob[:, 0, 0])
        for a in (1, 2):
            m &= (lo[:, a : a + 1] <= ob[:, 1, a]) & (hi[:, a : a + 1] >= ob[:, 0, a])
        return m

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
        T = np.asarray(T, dtype=float)
        self.moving.fcl_obj.setTransform(fcl_transform(T))
        ob = self.obstacles[k]
        if fcl.collide(self.moving.fcl_obj, ob.fcl_obj, self._request, fcl.CollisionResult()):
            return True
        pairs = np.zeros((1, len(self.obstacles)), dtype=bool)
        pairs[0, k] = True
        return self._first_enclosed(T[None], pairs) == 0

    def _enclosable(
        self, T: NDArray[np.float64], pairs: NDArray[np.bool_]
    ) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
        """Return (P, n) masks within `pairs` (P, n): a part component may lie inside obstacle k /
        one of k's components inside the part.

        Necessary conditions for enclosure: the box of a part component's probe vertices
        lies in the obstacle's box; an obstacle component's box lies in the part's world
        AABB (which holds the whole part at any rotation). Obstacles that can never pass
        (see __init__) are skipped.
        """
        part_in = np.zeros_like(pairs)
        ob_in = np.zeros_like(pairs)
        used = pairs.any(axis=0)
        R, t = T[:, :3, :3], T[:, :3, 3]
        ks = np.nonzero(used & self._may_hold_part)[0]
        if len(ks):
            C = len(self.moving.probes)
            pw = (self._probes_flat @ np.swapaxes(R, 1, 2) + t[:, None]).reshape(len(T), C, -1, 3)
            plo, phi = pw.min(axis=2), pw.max(axis=2)  # (P, C, 3)
            ob = self._ob_bounds[ks]
            m = np.ones((len(T), C, len(ks)), dtype=bool)
            for a in range(3):
                m &= (plo[:, :, a, None] >= ob[:, 0, a]) & (phi[:, :, a, None] <= ob[:, 1, a])
            part_in[:, ks] = m.any(axis=1) & pairs[:, ks]
        ks = np.nonzero(used & self._may_fit_in_part)[0]
        if len(ks):
            c = R.dot(self._box_c) + t
            h = np.abs(R).dot(self._box_h)
            lo, hi = c - h, c + h
            for k in ks.tolist():
                cb = self._fitting_boxes[k]  # (Ck, 2, 3)
                q = np.ones((len(T), len(cb)), dtype=bool)
                for a in range(3):
                    q &= (cb[:, 0, a] >= lo[:, a : a + 1]) & (cb[:, 1, a] <= hi[:, a : a + 1])
                ob_in[:, k] = q.any(axis=1) & pairs[:, k]
        return part_in, ob_in

    def _first_enclosed(self, T: NDArray[np.float64], pairs: NDArray[np.bool_]) -> int:
        """Return the first of poses T (m, 4, 4) where the part and an obstacle of `pairs` (m, n)
        enclose one another (their surfaces known apart), or -1."""
        part_in, ob_in = self._enclosable(T, pairs)
        for i in np.nonzero((part_in | ob_in).any(axis=1))[0].tolist():
            R, t = T[i, :3, :3], T[i, :3, 3]
            for k in np.nonzero(part_in[i])[0].tolist():
                if _inside(self.moving.probes @ R.T + t, self.obstacles[k]):
                    return i
            for k in np.nonzero(ob_in[i])[0].tolist():
                if _inside((self.obstacles[k].probes - t) @ R, self.moving):
                    return i
        return -1

    # -- verdicts ------------------------------------------------------------------------
    def first_interference(
        self, T: ArrayLike, *, chunk: int = 16, cells: bool | None = None
    ) -> int:
        """Return the index of the first of poses (P, 4, 4) at which the part interferes, or -1.

        The AABB stage runs on all poses at once; the poses it does not clear go on in
        order, `chunk` at a time, through the cell stage (if `cells`, default
        `cell_filter`) and the exact check, and checking stops at the first hit.
        """
        T = _poses(T)
        use_cells = self.cell_filter if cells is None else bool(cells)
        cand = self.aabb_stage(T)
        self.stats.poses += len(T)
        return self._first_hot(T, cand, np.nonzero(cand.any(axis=1))[0], use_cells, chunk)

    def first_free_group(
        self, T: ArrayLike, sizes: ArrayLike, *, chunk: int = 16, cells: bool | None = None
    ) -> int:
        """Return the index of the first group of poses at none of which the part interferes, or -1.

        T (P, 4, 4) holds the groups one after another (say the samples of candidate
        motions, best first) and sizes (G,) their lengths. The AABB stage runs on all
        poses at once; then groups are decided in order, each stopping at its first hit,
        so a group the AABB stage clears costs nothing more.
        """
        T = _poses(T)
        n = np.asarray(sizes, dtype=np.int64).reshape(-1)
        if np.any(n < 0) or int(n.sum()) != len(T):
            raise InputError(f"sizes must be >= 0 and sum to the {len(T)} poses, got {n.sum()}")
        use_cells = self.cell_filter if cells is None else bool(cells)
        cand = self.aabb_stage(T)
        self.stats.poses += len(T)
        hot: NDArray[np.bool_] = np.any(cand, axis=1)
        ends = np.cumsum(n)
        csum = np.concatenate([[0], np.cumsum(hot)])
        n_hot = csum[ends] - csum[ends - n]
        for g in range(len(n)):
            if n_hot[g] == 0:
                return g
            a, b = int(ends[g] - n[g]), int(ends[g])
            rows = a + np.nonzero(hot[a:b])[0]
            if self._first_hot(T, cand, rows, use_cells, chunk) < 0:
                return g
        return -1

    def _first_hot(
        self,
        T: NDArray[np.float64],
        cand: NDArray[np.bool_],
        hot: NDArray[np.intp],
        use_cells: bool,
        chunk: int,
    ) -> int:
        """Return the first of the poses T[hot] (in order) that interferes, or -1; cand: AABB pairs (P, n)."""
        for s in range(0, len(hot), chunk):
            rows = hot[s : s + chunk]
            c = cand[rows]
            self.stats.aabb_pairs += int(c.sum())
            if use_cells:
                for k in np.nonzero(c.any(axis=0))[0].tolist():
                    r = np.nonzero(c[:, k])[0]
                    self.stats.cell_pairs += len(r)
                    c[r, k] = self.cell_stage_pair(T[rows[r]], k)
            # Surfaces first, in order, up to the first contact; then enclosure, which
            # needs surfaces apart, on the poses before it in one vectorised pass.
            hit, apart = -1, []
            for i in np.nonzero(c.any(axis=1))[0].tolist():
                self.moving.fcl_obj.setTransform(fcl_transform(T[rows[i]]))
                for k in np.nonzero(c[i])[0].tolist():
                    self.stats.exact_pairs += 1
                    if fcl.collide(
                        self.moving.fcl_obj,
                        self.obstacles[k].fcl_obj,
                        self._request,
                        fcl.CollisionResult(),
                    ):
                        hit = i
                        break
                if hit >= 0:
                    break
                apart.append(i)
            if apart:
                e = self._first_enclosed(T[rows[apart]], c[apart])
                if e >= 0:
                    return int(rows[apart[e]])
            if hit >= 0:
                return int(rows[hit])
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
