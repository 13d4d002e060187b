"""Batched check of an OBB tree (seed 000 Fig. 9) over many frames, and its reports.

Fig. 9's DFS level by level for all frames at once: the start nodes against every obstacle,
then the children of every node-obstacle pair that hit. One matrix product puts every node
box in the world for every frame; each test compares the two world AABBs first and runs the
exact 15-axis test (`sat_overlap_rt`) only where they meet. Reports keep the hit mask and
derive their rows from it on first use.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.obb import OBB, SAT_EPS, sat_overlap_rt

if TYPE_CHECKING:
    from workbench.sheetmetal.obbtree import OBBTree

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class CollisionReport:
    """Result of one carried-part check: verdict, hits, and the work done (for the GUI)."""

    collides: bool
    hit_flanges: tuple[int, ...]
    hit_obstacles: tuple[int, ...]
    hit_pairs: tuple[tuple[int, int], ...]  # (flange, obstacle)
    n_obb_tests: int
    nodes_tested: tuple[int, ...]
    nodes_hit: tuple[int, ...]


class FramesReport:
    """Checks of F frames: `collides` (F,), `n_obb_tests` (F,), `hits` (K, 3) [frame, flange, obstacle].

    `tested` (J, 2) [frame, node] has one row per OBB test and `hit_nodes` (J', 2) [frame, node]
    one row per node-obstacle pair that hit. A report from the traversal keeps `hit_mask`
    (F, N, M): which node-obstacle pairs hit; `hits`, `tested` and `hit_nodes` are derived
    from it on first use (the batched check does not pay for rows nobody reads). Read-only.
    """

    __slots__ = ("collides", "n_obb_tests", "hit_mask", "_hits", "_tested", "_hit_nodes", "_dfs")

    def __init__(
        self,
        collides: NDArray[np.bool_],
        n_obb_tests: NDArray[np.int64],
        hits: NDArray[np.int64] | None = None,
        tested: NDArray[np.int64] | None = None,
        hit_nodes: NDArray[np.int64] | None = None,
        *,
        hit_mask: NDArray[np.bool_] | None = None,
        dfs: TreeCheck | None = None,
    ) -> None:
        if hit_mask is None and (hits is None or tested is None or hit_nodes is None):
            raise InputError("FramesReport: give hits, tested and hit_nodes, or hit_mask and dfs")
        self.collides = collides
        self.n_obb_tests = n_obb_tests
        self.hit_mask = hit_mask
        self._hits, self._tested, self._hit_nodes, self._dfs = hits, tested, hit_nodes, dfs

    @property
    def hits(self) -> NDArray[np.int64]:
        """Return the leaf hits (K, 3) [frame, flange, obstacle], sorted."""
        if self._hits is None:
            assert self.hit_mask is not None and self._dfs is not None
            self._hits = np.argwhere(self.hit_mask[:, self._dfs.nodes.leaves]).astype(np.int64)
        return self._hits

    @property
    def tested(self) -> NDArray[np.int64]:
        """Return one row [frame, node] per OBB test (J, 2), sorted."""
        if self._tested is None:
            assert self.hit_mask is not None and self._dfs is not None
            cnt = self._dfs.tested_counts(self.hit_mask)
            flat = np.repeat(np.arange(cnt.size), cnt.ravel())
            self._tested = np.stack(np.divmod(flat, cnt.shape[1]), axis=1).astype(np.int64)
        return self._tested

    @property
    def hit_nodes(self) -> NDArray[np.int64]:
        """Return one row [frame, node] per node-obstacle pair that hit (J', 2), sorted."""
        if self._hit_nodes is None:
            assert self.hit_mask is not None
            self._hit_nodes = np.argwhere(self.hit_mask)[:, :2].astype(np.int64)
        return self._hit_nodes

    def frame(self, i: int) -> CollisionReport:
        """Return frame `i`'s result as a `CollisionReport`."""
        if self.hit_mask is not None and self._dfs is not None:
            return self._dfs.frame_report(self.hit_mask[i], int(self.n_obb_tests[i]))
        h = self.hits[self.hits[:, 0] == i]
        return CollisionReport(
            collides=bool(self.collides[i]),
            hit_flanges=tuple(int(x) for x in np.unique(h[:, 1])),
            hit_obstacles=tuple(int(x) for x in np.unique(h[:, 2])),
            hit_pairs=tuple(sorted({(int(a), int(b)) for a, b in h[:, 1:]})),
            n_obb_tests=int(self.n_obb_tests[i]),
            nodes_tested=tuple(int(x) for x in np.unique(self.tested[self.tested[:, 0] == i, 1])),
            nodes_hit=tuple(
                int(x) for x in np.unique(self.hit_nodes[self.hit_nodes[:, 0] == i, 1])
            ),
        )


# Pairs whose world-axis bounding boxes (AABBs of the OBBs) are apart skip the 15-axis test:
# an OBB lies inside its AABB, so this only drops pairs that cannot overlap. For a thin part
# in a cell of upright fixtures it is far tighter than bounding spheres (the seed transfer's
# root tests: 1 of 352 pairs left, against 119 for spheres). The filter is worth its own numpy
# calls only on larger batches; a few pairs go straight to the exact test.
# The filter must never be tighter than the exact test, which widens every projected radius
# by using |R_ij| + SAT_EPS in place of |R_ij|. The AABB half extents take the same form,
# sum_j (|B_kj| + SAT_EPS) b_j (`_aabb_half`): for boxes on the world axes (where the AABB
# is the box and the filter is as tight as it gets) the filter's test along world axis k is
# then the exact test's face-axis test k with the same slack, and the relative 1e-9 on top
# covers the different rounding of the two sums. (A relative slack alone dropped touching
# thin plates: half thickness 1e-5 m gives 1e-14 m, the exact test keeps gaps to ~1e-12 m.)
AABB_FILTER_MIN = 24
_AABB_SLACK = 1.0 + 1e-9


def _aabb_half(axes: NDArray[np.float64], slack_half: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return world AABB half extents (3, ...) [m] of boxes with axes[k, j, ...] = B_kj and
    `slack_half` (3, ...) = half extents * _AABB_SLACK: sum_j (|B_kj| + SAT_EPS) b_j."""
    box = np.abs(axes)
    box += SAT_EPS
    box *= slack_half[None]
    return box.sum(axis=1)


# Axis order x, y, z, x, y: with axes (and half extents) extended so, the rolled indices
# i + 1, i + 2 (mod 3) of the edge axes are slices (see `sat_overlap_rt`).
_CYC = np.array([0, 1, 2, 0, 1])


@dataclass(frozen=True, eq=False)
class NodeArrays:
    """A tree's node arrays in the shapes the batched traversal reads."""

    count: int
    leaves: NDArray[np.int64]  # (flanges,) node of each flange's leaf
    parent: NDArray[np.int64]  # (N,) -1 for the root
    child_count: NDArray[np.int64]  # (N,)
    levels: list[tuple[NDArray[np.int64], NDArray[np.int64]]]  # depth >= 1: (nodes, parents)
    axes_center: NDArray[np.float64]  # (3, 6N): per node axes x y z x y, then the centre [m]
    half: NDArray[np.float64]  # (5, N) half extents [m], cyclic like the axes
    slack_half: NDArray[np.float64]  # (3, N) half extents * _AABB_SLACK [m], for the AABBs

    @classmethod
    def of(cls, tree: OBBTree) -> NodeArrays:
        n = len(tree.level)
        parent = np.full(n, -1, dtype=np.int64)
        for p in range(n):
            lo = tree.child_start[p]
            parent[tree.child_index[lo : lo + tree.child_count[p]]] = p
        leaf = tree.leaf_flange >= 0
        leaves = np.empty(int(tree.leaf_flange.max()) + 1, dtype=np.int64)
        leaves[tree.leaf_flange[leaf]] = np.nonzero(leaf)[0]
        rot, center = tree.boxes.rotation, tree.boxes.center
        ac = np.concatenate([rot[:, :, _CYC], center[:, :, None]], axis=2)  # (N, 3, 6)
        half = tree.boxes.half_extents
        return cls(
            count=n,
            leaves=leaves,
            parent=parent,
            child_count=tree.child_count,
            levels=[
                (np.flatnonzero(tree.level == k), parent[tree.level == k])
                for k in range(1, int(tree.level.max()) + 1)
            ],
            axes_center=np.ascontiguousarray(ac.transpose(1, 0, 2).reshape(3, 6 * n)),
            half=np.ascontiguousarray(half[:, _CYC].T),
            slack_half=np.ascontiguousarray(half.T * _AABB_SLACK),
        )


@dataclass(frozen=True, eq=False)
class TreeCheck:
    """One way of checking a tree: start nodes against every obstacle, then levels to descend."""

    nodes: NodeArrays
    start: NDArray[np.int64]
    levels: list[tuple[NDArray[np.int64], NDArray[np.int64]]]  # empty: no descent
    _cache: dict[str, Any] = field(default_factory=dict, repr=False)  # the last obstacles

    def _obstacles(self, obstacles: OBB) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Return obstacles components-first (obs (3, 6, M), oe (5, M), world AABB half (3, M)).

        obs[k, j, m] is the k-th coordinate of axis j (x y z x y, cyclic) for j < 5, of the
        centre for j = 5; oe the half extents, cyclic too. Kept for the last obstacles object
        (OBBs are immutable; a cell's obstacles are checked over and over).
        """
        last = self._cache.get("obstacles")
        if last is not None and last[0] is obstacles:
            return last[1]  # type: ignore[no-any-return]
        o_c = obstacles.center.reshape(-1, 3)
        M = len(o_c)
        obs = np.empty((3, 6, M))
        obs[:, :5] = obstacles.rotation.reshape(-1, 3, 3)[:, :, _CYC].transpose(1, 2, 0)
        obs[:, 5] = o_c.T
        oe = np.ascontiguousarray(obstacles.half_extents.reshape(-1, 3)[:, _CYC].T)
        # World AABB half extents: sum_j |B_kj| b_j, widened (see _AABB_SLACK).
        o_box = _aabb_half(obs[:, :3], oe[:3] * _AABB_SLACK)  # (3, M)
        out = (obs, oe, o_box)
        self._cache["obstacles"] = (obstacles, out)
        return out

    def run(self, obstacles: OBB, T_world_grasp: ArrayLike) -> FramesReport:
        """Return the check of F poses: start nodes x obstacles, then descend level by level.

        A fixed few dozen numpy calls per call whatever F is: obstacles laid out once per
        obstacles object, one product puts every node box in the world for every frame,
        the start nodes' AABBs against every obstacle by broadcasting, then per level one
        gather of the candidate pairs and one 15-axis test (`sat_overlap_rt`) of them all.
        """
        if not isinstance(obstacles, OBB):
            raise InputError(
                f"obstacles: expected an OBB (batch (M,)), got {type(obstacles).__name__}"
            )
        T = np.asarray(T_world_grasp, dtype=float)
        if T.ndim != 3 or T.shape[1:] != (4, 4) or not np.isfinite(T).all():
            raise InputError(f"T_world_grasp: expected finite shape (F, 4, 4), got {T.shape}")
        nodes = self.nodes
        F, N = len(T), nodes.count
        obs, oe, o_box = self._obstacles(obstacles)
        M = obs.shape[2]
        # Every node box in the world for every frame in one product: W[k, j, f * N + n] as
        # obs, for node n in frame f.
        prod = (T[:, :3, :3].reshape(3 * F, 3) @ nodes.axes_center).reshape(F, 3, N, 6)
        W4 = np.ascontiguousarray(prod.transpose(1, 3, 0, 2))  # (3, 6, F, N)
        W4[:, 5] += T[:, :3, 3].T[:, :, None]
        W = W4.reshape(3, 6, F * N)
        hit = np.zeros((F, N, M), dtype=bool)
        flat_hit = hit.reshape(-1)
        # Start nodes against every obstacle: the AABB filter by broadcasting (the start
        # nodes' world AABBs only), then the exact test on the pairs whose AABBs meet.
        S = len(self.start)
        tests = np.full(F, S * M, dtype=np.int64)
        if self.levels and S == 1:  # the DFS from one root: its AABB by slicing
            r = int(self.start[0])
            n_box = _aabb_half(W4[:, :3, :, r], nodes.slack_half[:, r, None])  # (3, F)
            d = obs[:, 5, None, :] - W4[:, 5, :, r, None]  # (3, F, M)
            np.abs(d, out=d)
            lim = n_box[:, :, None] + o_box[:, None, :]  # the same sums as the exact test's
            near = np.flatnonzero(np.logical_and.reduce(d <= lim, axis=0))
            if not near.size:  # the common case on a free path: no root pair's AABBs meet
                return FramesReport(np.zeros(F, bool), tests, hit_mask=hit, dfs=self)
            f, m = np.divmod(near, M)
            return self._descend(W, obs, oe, o_box, hit, tests, f, m)
        fn0 = np.arange(F)[:, None] * N + self.start  # (F, S)
        start_axes = W4[:, :3].take(self.start, axis=-1)  # (3, 3, F, S)
        n_box = _aabb_half(start_axes, nodes.slack_half[:, None].take(self.start, axis=-1))
        d = obs[:, 5, None, None, :] - W[:, 5].take(fn0, axis=-1)[..., None]  # (3, F, S, M)
        lim = n_box[..., None] + o_box[:, None, None, :]
        near = np.flatnonzero(np.logical_and.reduce(np.abs(d) <= lim, axis=0))
        if not near.size:  # no start pair's AABBs meet
            return FramesReport(np.zeros(F, bool), tests, hit_mask=hit, dfs=self)
        fs, m = np.divmod(near, M)
        fn = fn0.reshape(-1)[fs]
        n: NDArray[np.int64] | slice = slice(self.start[0], self.start[0] + 1) if S == 1 else fn % N
        found = _test(
            W, obs, oe, nodes.half, d.reshape(3, -1).take(near, axis=-1), fn, n, m, flat_hit, M
        )
        for lvl_nodes, parents in self.levels:  # (several start nodes with levels: not built)
            if not found:
                break
            # Children of every node-obstacle pair that hit (DFS: only those are tested).
            idx = np.flatnonzero(hit[:, parents, :])
            if not len(idx):
                break
            f, km = np.divmod(idx, len(lvl_nodes) * M)
            tests += np.bincount(f, minlength=F)
            k, m = np.divmod(km, M)
            n = lvl_nodes[k]
            fn = f * N + n
            d = obs[:, 5].take(m, axis=-1) - W[:, 5].take(fn, axis=-1)
            if len(idx) >= AABB_FILTER_MIN:
                axes = W[:, :3].take(fn, axis=-1)
                lim = _aabb_half(axes, nodes.slack_half.take(n, axis=-1)) + o_box.take(m, axis=-1)
                near = np.flatnonzero(np.logical_and.reduce(np.abs(d) <= lim, axis=0))
                d, fn, n, m = d.take(near, axis=-1), fn[near], n[near], m[near]
            found = _test(W, obs, oe, nodes.half, d, fn, n, m, flat_hit, M)
        collides = np.logical_or.reduce(hit[:, nodes.leaves].reshape(F, -1), axis=1)
        return FramesReport(collides, tests, hit_mask=hit, dfs=self)

    def _descend(
        self,
        W: FloatArray,
        obs: FloatArray,
        oe: FloatArray,
        o_box: FloatArray,
        hit: NDArray[np.bool_],
        tests: NDArray[np.int64],
        f: NDArray[np.int64],
        m: NDArray[np.int64],
    ) -> FramesReport:
        """Return the report of the DFS below the root pairs (frame f, obstacle m) whose AABBs meet.

        The same verdicts, hits and test counts as descending level by level, in one 15-axis
        test: every node of the tree against the obstacle of each such root pair (the
        root's own exact test among them), the AABB filter first where there are enough
        pairs; then level by level a node hits only if its own test and its parent's did
        (which is what the DFS tests), and each hit pair's children count as tests.
        """
        nodes = self.nodes
        F, N, M = hit.shape
        H = len(f)
        if H == 1 and N < AABB_FILTER_MIN:
            return self._descend_one(W, obs, oe, hit, tests, int(f[0]), int(m[0]))
        every = self._cache.get("every")
        if every is None or len(every) != N:
            every = self._cache["every"] = np.arange(N)
        fn = (f[:, None] * N + every).reshape(-1)  # (H * N,): every node per pair
        n: NDArray[np.int64] | slice = slice(None) if H == 1 else np.tile(every, H)
        mm = np.repeat(m, N)
        d = obs[:, 5].take(mm, axis=-1) - W[:, 5].take(fn, axis=-1)
        if H * N >= AABB_FILTER_MIN:
            n = np.tile(every, H)
            axes = W[:, :3].take(fn, axis=-1)
            lim = _aabb_half(axes, nodes.slack_half.take(n, axis=-1)) + o_box.take(mm, axis=-1)
            keep = np.flatnonzero(np.logical_and.reduce(np.abs(d) <= lim, axis=0))
            d, fn, n, mm = d.take(keep, axis=-1), fn[keep], n[keep], mm[keep]
            sat = np.zeros(H * N, dtype=bool)
            sat[keep] = _sat(W, obs, oe, nodes.half, d, fn, n, mm)
            sat = sat.reshape(H, N)
        else:
            sat = _sat(W, obs, oe, nodes.half, d, fn, n, mm).reshape(H, N)
        for lvl_nodes, parents in self.levels:  # DFS: tested only below a hit
            sat[:, lvl_nodes] &= sat[:, parents]
        hit[f[:, None], every, m[:, None]] = sat
        np.add.at(tests, f, sat @ nodes.child_count)  # each hit pair's children were tested
        collides = np.logical_or.reduce(hit[:, nodes.leaves].reshape(F, -1), axis=1)
        return FramesReport(collides, tests, hit_mask=hit, dfs=self)

    def _descend_one(
        self,
        W: FloatArray,
        obs: FloatArray,
        oe: FloatArray,
        hit: NDArray[np.bool_],
        tests: NDArray[np.int64],
        f: int,
        m: int,
    ) -> FramesReport:
        """Return `_descend` for one root pair (frame f, obstacle m): slices, no gathers."""
        nodes = self.nodes
        F, N, M = hit.shape
        Wf = W[:, :, f * N : (f + 1) * N]  # (3, 6, N): every node in frame f
        Bd = np.empty((3, 6, N))
        Bd[:, :5] = obs[:, :5, m, None]
        np.subtract(obs[:, 5, m, None], Wf[:, 5], out=Bd[:, 5])  # [B | cb - ca]
        Rt = np.einsum("ki...,kj...->ij...", Wf[:, :5], Bd)  # A^T [B | d], as in _sat
        sat = sat_overlap_rt(Rt, nodes.half, oe[:, m, None])
        for lvl_nodes, parents in self.levels:  # DFS: tested only below a hit
            sat[lvl_nodes] &= sat[parents]
        hit[f, :, m] = sat
        tests[f] += int(sat @ nodes.child_count)  # each hit pair's children were tested
        collides = np.zeros(F, dtype=bool)
        collides[f] = sat[nodes.leaves].any()
        return FramesReport(collides, tests, hit_mask=hit, dfs=self)

    def tested_counts(self, hit: NDArray[np.bool_]) -> NDArray[np.int64]:
        """Return the OBB tests per frame and node (F, N) behind `hit` (F, N, M)."""
        F, N, M = hit.shape
        cnt = np.zeros((F, N), dtype=np.int64)
        cnt[:, self.start] = M
        if self.levels:
            inner = self.nodes.parent >= 0
            cnt[:, inner] = hit.sum(axis=2)[:, self.nodes.parent[inner]]
        return cnt

    def frame_report(self, hit: NDArray[np.bool_], n_tests: int) -> CollisionReport:
        """Return one frame's `CollisionReport` from its hit mask (N, M)."""
        start = sorted(self.start.tolist()) if hit.shape[1] else []  # no obstacle: no test
        if not hit.any():  # the common case on a path: nothing but the start nodes tested
            return CollisionReport(False, (), (), (), n_tests, tuple(start), ())
        pairs = np.argwhere(hit[self.nodes.leaves]).tolist()  # sorted (flange, obstacle)
        node_hit = np.logical_or.reduce(hit, axis=1)
        tested = set(start)
        if self.levels:
            parent = self.nodes.parent
            tested.update(np.flatnonzero((parent >= 0) & node_hit[parent]).tolist())
        return CollisionReport(
            collides=bool(pairs),
            hit_flanges=tuple(sorted({p[0] for p in pairs})),
            hit_obstacles=tuple(sorted({p[1] for p in pairs})),
            hit_pairs=tuple((p[0], p[1]) for p in pairs),
            n_obb_tests=n_tests,
            nodes_tested=tuple(sorted(tested)),
            nodes_hit=tuple(np.flatnonzero(node_hit).tolist()),
        )


def _test(
    W: NDArray[np.float64],
    obs: NDArray[np.float64],
    oe: NDArray[np.float64],
    half: NDArray[np.float64],
    d: NDArray[np.float64],
    fn: NDArray[np.int64],
    n: NDArray[np.int64] | slice,
    m: NDArray[np.int64],
    flat_hit: NDArray[np.bool_],
    M: int,
) -> bool:
    """Mark the pairs (frame * N + node fn, obstacle m; offsets d (3, P)) that overlap; any?"""
    if not len(m):
        return False
    ok = _sat(W, obs, oe, half, d, fn, n, m)
    flat_hit[(fn * M + m)[ok]] = True
    return bool(ok.any())


def _sat(
    W: NDArray[np.float64],
    obs: NDArray[np.float64],
    oe: NDArray[np.float64],
    half: NDArray[np.float64],
    d: NDArray[np.float64],
    fn: NDArray[np.int64],
    n: NDArray[np.int64] | slice,
    m: NDArray[np.int64],
) -> NDArray[np.bool_]:
    """Return the exact 15-axis verdicts (P,) of pairs (frame * N + node fn, obstacle m)."""
    if not len(m):
        return np.zeros(0, dtype=bool)
    # Gathers with `take`: it returns components-first contiguous arrays (fancy indexing of
    # the last axis lays the result out pair-major, which makes every later step strided).
    Bd = obs.take(m, axis=-1)
    Bd[:, 5] = d  # [B | cb - ca]
    # A^T [B | d] per pair: one stacked matmul (P, 5, 3) @ (P, 3, 6), read as (5, 6, P).
    A = W.take(fn, axis=-1)[:, :5]
    Rt = np.einsum("ki...,kj...->ij...", A, Bd)
    a = half[:, n] if isinstance(n, slice) else half.take(n, axis=-1)
    return sat_overlap_rt(Rt, a, oe.take(m, axis=-1))
