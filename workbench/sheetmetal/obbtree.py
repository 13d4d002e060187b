"""Hierarchical OBB tree of a folded part (seed 000 §2.1) and its coarse-to-fine check (Fig. 9).

Split rule: the root holds every flange and uses the gripped flange as reference; a node's
children are its reference flange (a leaf) and, for each bend of the reference inside the
node, the group of flanges connected through that bend, whose reference is the flange on
the other side of the bend. Node boxes are stored in the grasp (gripped flange) frame, so
carrying the part only moves the root transform. Internal boxes contain their leaves' boxes,
so the traversal's verdict equals testing every flange box against every obstacle.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.obb import OBB, sat_overlap_rt
from workbench.geometry.transforms import invert_transform

if TYPE_CHECKING:
    from workbench.sheetmetal.folding import FoldedState


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
        dfs: _Traversal | None = None,
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


@dataclass(frozen=True, eq=False)
class OBBTree:
    """Node boxes in the grasp frame (node 0 = root) with children in CSR form and levels."""

    grasp_flange: int
    boxes: OBB  # (N,)
    flanges: tuple[tuple[int, ...], ...]  # flanges under each node
    leaf_flange: NDArray[np.int64]  # (N,) flange of a leaf, -1 for internal nodes
    level: NDArray[np.int64]  # (N,) depth, root = 0
    child_start: NDArray[np.int64]
    child_count: NDArray[np.int64]
    child_index: NDArray[np.int64]

    @property
    def leaves(self) -> NDArray[np.int64]:
        """Return the node index of each flange's leaf (F,)."""
        return self._checks[0].nodes.leaves.copy()

    @cached_property
    def _checks(self) -> tuple[_Traversal, _Traversal]:
        # Node arrays laid out once per tree, i.e. once per bend state and grasp flange (the
        # folded state caches its trees): the DFS from the root, and the flat leaf check.
        nodes = _Nodes.of(self)
        dfs = _Traversal(nodes, np.array([0]), nodes.levels)
        return dfs, _Traversal(nodes, nodes.leaves, [])

    def collide(self, obstacles: OBB, T_world_grasp: ArrayLike) -> CollisionReport:
        """Return the DFS (coarse root first, descend into hit nodes) check of one pose (4, 4)."""
        T = np.asarray(T_world_grasp, dtype=float)
        if T.shape != (4, 4):
            raise InputError(
                f"T_world_grasp: expected shape (4, 4), got {T.shape}; use collide_frames for (F, 4, 4)"
            )
        return self.collide_frames(obstacles, T[None]).frame(0)

    def collide_frames(self, obstacles: OBB, T_world_grasp: ArrayLike) -> FramesReport:
        """Return the tree check of F poses (F, 4, 4), batched over frames and obstacles."""
        return self._checks[0].run(obstacles, T_world_grasp)

    def flat_collide(self, obstacles: OBB, T_world_grasp: ArrayLike) -> CollisionReport:
        """Return the flat check (every flange box against every obstacle) of one pose (4, 4)."""
        T = np.asarray(T_world_grasp, dtype=float)
        if T.shape != (4, 4):
            raise InputError(f"T_world_grasp: expected shape (4, 4), got {T.shape}")
        return self.flat_collide_frames(obstacles, T[None]).frame(0)

    def flat_collide_frames(self, obstacles: OBB, T_world_grasp: ArrayLike) -> FramesReport:
        """Return the flat per-flange check of F poses (F, 4, 4), batched."""
        return self._checks[1].run(obstacles, T_world_grasp)


# Pairs whose world-axis bounding boxes (AABBs of the OBBs) are apart skip the 15-axis test:
# an OBB lies inside its AABB, so this only drops pairs that cannot overlap. For a thin part
# in a cell of upright fixtures it is far tighter than bounding spheres (the seed transfer's
# root tests: 1 of 352 pairs left, against 119 for spheres). The filter is worth its own numpy
# calls only on larger batches; a few pairs go straight to the exact test. AABB half extents
# are inflated by a relative 1e-9 so rounding never drops a pair the exact test calls touching.
AABB_FILTER_MIN = 24
_AABB_SLACK = 1.0 + 1e-9
# Axis order x, y, z, x, y: with axes (and half extents) extended so, the rolled indices
# i + 1, i + 2 (mod 3) of the edge axes are slices (see `sat_overlap_rt`).
_CYC = np.array([0, 1, 2, 0, 1])


@dataclass(frozen=True, eq=False)
class _Nodes:
    """A tree's node arrays in the shapes the batched traversal reads."""

    count: int
    leaves: NDArray[np.int64]  # (flanges,) node of each flange's leaf
    parent: NDArray[np.int64]  # (N,) -1 for the root
    child_count: NDArray[np.int64]  # (N,)
    levels: list[tuple[NDArray[np.int64], NDArray[np.int64]]]  # depth >= 1: (nodes, parents)
    axes_center: NDArray[np.float64]  # (3, 6N): per node axes x y z x y, then the centre [m]
    half: NDArray[np.float64]  # (5, N) half extents [m], cyclic like the axes

    @classmethod
    def of(cls, tree: OBBTree) -> _Nodes:
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
        )


@dataclass(frozen=True, eq=False)
class _Traversal:
    """One way of checking a tree: start nodes against every obstacle, then levels to descend."""

    nodes: _Nodes
    start: NDArray[np.int64]
    levels: list[tuple[NDArray[np.int64], NDArray[np.int64]]]  # empty: no descent

    def run(self, obstacles: OBB, T_world_grasp: ArrayLike) -> FramesReport:
        """Return the check of F poses: start nodes x obstacles, then descend level by level."""
        if not isinstance(obstacles, OBB):
            raise InputError(
                f"obstacles: expected an OBB (batch (M,)), got {type(obstacles).__name__}"
            )
        T = np.asarray(T_world_grasp, dtype=float)
        if T.ndim != 3 or T.shape[1:] != (4, 4) or not np.isfinite(T).all():
            raise InputError(f"T_world_grasp: expected finite shape (F, 4, 4), got {T.shape}")
        nodes = self.nodes
        F, N = len(T), nodes.count
        o_c = obstacles.center.reshape(-1, 3)
        M = len(o_c)
        # Obstacles components-first: obs[k, j, m] is the k-th coordinate of axis j (x y z x y,
        # cyclic) for j < 5, of the centre for j = 5; oe (5, M) half extents, cyclic too.
        obs = np.empty((3, 6, M))
        obs[:, :5] = obstacles.rotation.reshape(-1, 3, 3)[:, :, _CYC].transpose(1, 2, 0)
        obs[:, 5] = o_c.T
        oe = np.ascontiguousarray(obstacles.half_extents.reshape(-1, 3)[:, _CYC].T)
        # World AABB half extents: sum_j |B_kj| b_j, inflated (see _AABB_SLACK).
        o_box = (np.abs(obs[:, :3]) * (oe[:3] * _AABB_SLACK)).sum(axis=1)  # (3, M)
        # Every node box in the world for every frame in one product: W[k, j, f * N + n] as
        # obs, for node n in frame f.
        prod = (T[:, :3, :3].reshape(3 * F, 3) @ nodes.axes_center).reshape(F, 3, N, 6)
        W4 = np.ascontiguousarray(prod.transpose(1, 3, 0, 2))  # (3, 6, F, N)
        W4[:, 5] += T[:, :3, 3].T[:, :, None]
        W = W4.reshape(3, 6, F * N)
        n_box = (np.abs(W4[:, :3]) * (nodes.half[:3, None] * _AABB_SLACK)).sum(axis=1)
        n_box = n_box.reshape(3, F * N)
        hit = np.zeros((F, N, M), dtype=bool)
        flat_hit = hit.reshape(-1)
        # Start nodes against every obstacle: the AABB filter by broadcasting, then the exact
        # test on the pairs whose AABBs meet.
        S = len(self.start)
        fn0 = np.arange(F)[:, None] * N + self.start  # (F, S)
        d = obs[:, 5, None, None, :] - W[:, 5].take(fn0, axis=-1)[..., None]  # (3, F, S, M)
        lim = n_box.take(fn0, axis=-1)[..., None] + o_box[:, None, None, :]
        near = np.flatnonzero(np.logical_and.reduce(np.abs(d) <= lim, axis=0))
        fs, m = np.divmod(near, M)
        fn = fn0.reshape(-1)[fs]
        n: NDArray[np.int64] | slice = slice(self.start[0], self.start[0] + 1) if S == 1 else fn % N
        found = _test(
            W, obs, oe, nodes.half, d.reshape(3, -1).take(near, axis=-1), fn, n, m, flat_hit, M
        )
        tests = np.full(F, S * M, dtype=np.int64)
        for lvl_nodes, parents in self.levels:
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
                lim = n_box.take(fn, axis=-1) + o_box.take(m, axis=-1)
                near = np.flatnonzero(np.logical_and.reduce(np.abs(d) <= lim, axis=0))
                d, fn, n, m = d.take(near, axis=-1), fn[near], n[near], m[near]
            found = _test(W, obs, oe, nodes.half, d, fn, n, m, flat_hit, M)
        collides = np.logical_or.reduce(hit[:, nodes.leaves].reshape(F, -1), axis=1)
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
        if not hit.any():  # the common case on a path: nothing but the start nodes tested
            start = tuple(sorted(self.start.tolist()))
            return CollisionReport(False, (), (), (), n_tests, start, ())
        pairs = np.argwhere(hit[self.nodes.leaves]).tolist()  # sorted (flange, obstacle)
        node_hit = np.logical_or.reduce(hit, axis=1)
        tested = set(self.start.tolist())
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
    # Gathers with `take`: it returns components-first contiguous arrays (fancy indexing of
    # the last axis lays the result out pair-major, which makes every later step strided).
    Bd = obs.take(m, axis=-1)
    Bd[:, 5] = d  # [B | cb - ca]
    Rt = np.einsum("ki...,kj...->ij...", W.take(fn, axis=-1)[:, :5], Bd)  # A^T [B | d]
    a = half[:, n] if isinstance(n, slice) else half.take(n, axis=-1)
    ok = sat_overlap_rt(Rt, a, oe.take(m, axis=-1))
    flat_hit[(fn * M + m)[ok]] = True
    return bool(ok.any())


def build_obb_tree(state: FoldedState, grasp_flange: int) -> OBBTree:
    """Return the §2.1 OBB tree of `state` rooted at flange `grasp_flange`, boxes in its frame."""
    part = state.part
    g = part.flange_index(grasp_flange)
    nf = len(part.flanges)
    leaves = state.flange_obbs().transformed(invert_transform(state.T_part_flange[g]))
    nbrs: list[list[int]] = [[] for _ in range(nf)]
    for b in part.bends:
        nbrs[b.parent].append(b.child)
        nbrs[b.child].append(b.parent)

    def group(seed: int, members: set[int], blocked: int) -> list[int]:
        out, stack = {seed}, [seed]
        while stack:
            for m in nbrs[stack.pop()]:
                if m in members and m != blocked and m not in out:
                    out.add(m)
                    stack.append(m)
        return sorted(out)

    sets: list[tuple[int, ...]] = []
    refs: list[int] = []
    levels: list[int] = []
    children: list[list[int]] = []

    def add(members: list[int], ref: int, level: int) -> int:
        idx = len(sets)
        sets.append(tuple(members))
        refs.append(ref)
        levels.append(level)
        children.append([])
        if len(members) > 1:
            children[idx].append(add([ref], ref, level + 1))
            for nb in nbrs[ref]:
                if nb in members:
                    children[idx].append(add(group(nb, set(members), ref), nb, level + 1))
        return idx

    add(list(range(nf)), g, 0)
    centers, rots, halves = [], [], []
    for s in sets:
        if len(s) == 1:
            centers.append(leaves.center[s[0]])
            rots.append(leaves.rotation[s[0]])
            halves.append(leaves.half_extents[s[0]])
        else:
            idx = list(s)
            box = OBB.from_points(
                leaves.corners()[idx].reshape(-1, 3), rotations=leaves.rotation[idx]
            )
            centers.append(box.center)
            rots.append(box.rotation)
            halves.append(box.half_extents)
    counts = np.array([len(c) for c in children], dtype=np.int64)
    return OBBTree(
        grasp_flange=g,
        boxes=OBB(np.array(centers), np.array(rots), np.array(halves)),
        flanges=tuple(sets),
        leaf_flange=np.array([s[0] if len(s) == 1 else -1 for s in sets], dtype=np.int64),
        level=np.array(levels, dtype=np.int64),
        child_start=np.concatenate([[0], np.cumsum(counts)[:-1]]).astype(np.int64),
        child_count=counts,
        child_index=np.array([c for cs in children for c in cs], dtype=np.int64),
    )
