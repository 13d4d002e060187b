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
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.obb import OBB, sat_overlap_t
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


@dataclass(frozen=True, eq=False)
class FramesReport:
    """Checks of F frames: `collides` (F,), `n_obb_tests` (F,), `hits` (K, 3) [frame, flange, obstacle]."""

    collides: NDArray[np.bool_]
    n_obb_tests: NDArray[np.int64]
    hits: NDArray[np.int64]
    tested: NDArray[np.int64]  # (J, 2) [frame, node], one row per OBB test
    hit_nodes: NDArray[np.int64]  # (J', 2) [frame, node]

    def frame(self, i: int) -> CollisionReport:
        """Return frame `i`'s result as a `CollisionReport`."""
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
        out = np.empty(int(self.leaf_flange.max()) + 1, dtype=np.int64)
        m = self.leaf_flange >= 0
        out[self.leaf_flange[m]] = np.nonzero(m)[0]
        return out

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
        return _traverse(self, obstacles, T_world_grasp, np.array([0]), descend=True)

    def flat_collide(self, obstacles: OBB, T_world_grasp: ArrayLike) -> CollisionReport:
        """Return the flat check (every flange box against every obstacle) of one pose (4, 4)."""
        T = np.asarray(T_world_grasp, dtype=float)
        if T.shape != (4, 4):
            raise InputError(f"T_world_grasp: expected shape (4, 4), got {T.shape}")
        return self.flat_collide_frames(obstacles, T[None]).frame(0)

    def flat_collide_frames(self, obstacles: OBB, T_world_grasp: ArrayLike) -> FramesReport:
        """Return the flat per-flange check of F poses (F, 4, 4), batched."""
        return _traverse(self, obstacles, T_world_grasp, self.leaves, descend=False)


def _traverse(
    tree: OBBTree, obstacles: OBB, T_world_grasp: ArrayLike, start: NDArray[np.int64], descend: bool
) -> FramesReport:
    if not isinstance(obstacles, OBB):
        raise InputError(f"obstacles: expected an OBB (batch (M,)), got {type(obstacles).__name__}")
    T = np.asarray(T_world_grasp, dtype=float)
    if T.ndim != 3 or T.shape[1:] != (4, 4) or not np.all(np.isfinite(T)):
        raise InputError(f"T_world_grasp: expected finite shape (F, 4, 4), got {T.shape}")
    F = len(T)
    o_c, o_r, o_e = (
        obstacles.center.reshape(-1, 3),
        obstacles.rotation.reshape(-1, 3, 3),
        obstacles.half_extents.reshape(-1, 3),
    )
    M = len(o_c)
    # Obstacles into each frame's grasp frame once (the node boxes never move), all arrays
    # components-first and contiguous so that gathers and SAT steps run over contiguous rows.
    first = np.ascontiguousarray
    W = first(np.moveaxis(T[:, :3, :3], (1, 2), (0, 1)))  # W[k, i, f] = R_world_grasp[f][k, i]
    diff = o_c.T[:, None, :] - T[:, :3, 3].T[:, :, None]  # (3, F, M)
    Oc = first(np.moveaxis(o_r, (1, 2), (0, 1)))  # (3, 3, M)
    oc = sum(W[k][:, :, None] * diff[k][None] for k in range(3)).reshape(3, F * M)
    orot = sum(W[k][:, None, :, None] * Oc[k][None, :, None, :] for k in range(3)).reshape(
        3, 3, F * M
    )
    oe = first(o_e.T)
    nc = first(tree.boxes.center.T)
    nr = first(np.moveaxis(tree.boxes.rotation, (1, 2), (0, 1)))
    ne = first(tree.boxes.half_extents.T)
    f_idx, n_idx, o_idx = (
        a.ravel() for a in np.meshgrid(np.arange(F), start, np.arange(M), indexing="ij")
    )
    tested_f, tested_n, hit_f, hit_n, hits = [], [], [], [], []
    # Bounding-sphere radii: boxes whose spheres are apart cannot overlap, so only the
    # pairs whose spheres meet pay for the 15-axis separating-axis test.
    n_rad = np.sqrt((ne * ne).sum(axis=0))
    o_rad = np.sqrt((oe * oe).sum(axis=0))
    while len(f_idx):
        fo = f_idx * M + o_idx
        d = oc[:, fo] - nc[:, n_idx]
        reach = n_rad[n_idx] + o_rad[o_idx]
        near = np.flatnonzero((d * d).sum(axis=0) <= reach * reach)
        ok = np.zeros(len(f_idx), dtype=bool)
        if len(near):
            fn, nn = fo[near], n_idx[near]
            ok[near] = sat_overlap_t(
                d[:, near], nr[:, :, nn], ne[:, nn], orot[:, :, fn], oe[:, o_idx[near]]
            )
        tested_f.append(f_idx)
        tested_n.append(n_idx)
        f_idx, n_idx, o_idx = f_idx[ok], n_idx[ok], o_idx[ok]
        hit_f.append(f_idx)
        hit_n.append(n_idx)
        flange = tree.leaf_flange[n_idx]
        leaf = flange >= 0
        hits.append(np.stack([f_idx[leaf], flange[leaf], o_idx[leaf]], axis=1))
        if not descend:
            break
        inner = ~leaf
        f_idx, n_idx, o_idx = f_idx[inner], n_idx[inner], o_idx[inner]
        cnt = tree.child_count[n_idx]
        offs = np.repeat(tree.child_start[n_idx] - (np.cumsum(cnt) - cnt), cnt)
        n_idx = tree.child_index[offs + np.arange(int(cnt.sum()))]
        f_idx, o_idx = np.repeat(f_idx, cnt), np.repeat(o_idx, cnt)
    h = np.concatenate(hits) if hits else np.zeros((0, 3), np.int64)
    collides = np.zeros(F, dtype=bool)
    collides[h[:, 0]] = True
    tf = np.concatenate(tested_f) if tested_f else np.zeros(0, np.int64)

    def pairs(a: list, b: list) -> NDArray[np.int64]:
        return (
            np.stack([np.concatenate(a), np.concatenate(b)], axis=1)
            if a
            else np.zeros((0, 2), np.int64)
        )

    return FramesReport(
        collides,
        np.bincount(tf, minlength=F),
        h.astype(np.int64),
        pairs(tested_f, tested_n),
        pairs(hit_f, hit_n),
    )


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
