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
from workbench.geometry.obb import OBB
from workbench.geometry.transforms import invert_transform
from workbench.sheetmetal.obbcheck import CollisionReport, FramesReport, NodeArrays, TreeCheck

if TYPE_CHECKING:
    from workbench.sheetmetal.folding import FoldedState

__all__ = ["CollisionReport", "FramesReport", "OBBTree", "build_obb_tree"]


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
    def _checks(self) -> tuple[TreeCheck, TreeCheck]:
        # Node arrays laid out once per tree, i.e. once per bend state and grasp flange (the
        # folded state caches its trees): the DFS from the root, and the flat leaf check.
        nodes = NodeArrays.of(self)
        dfs = TreeCheck(nodes, np.array([0]), nodes.levels)
        return dfs, TreeCheck(nodes, nodes.leaves, [])

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
