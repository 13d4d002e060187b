"""The cost of the carried-part check: OBB tree vs the seed's per-flange loop (seed 000, Fig. 12).

A measurement, not part of a plan: the GUI's Fig. 12 plot asks for it after a plan, and
`benchmarks/bending.py` prints it. Both methods give the same verdict; the tree needs fewer
OBB tests on free frames because one root box clears the whole part.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.geometry.obb import OBB, obb_overlap
from workbench.sheetmetal.obbtree import OBBTree


@dataclass(frozen=True, eq=False)
class CheckCost:
    """Per frame (F,): OBB tests of the tree and of the flat loop, and their check times [s]."""

    tree_tests: NDArray[np.int64]
    flat_tests: NDArray[np.int64]
    tree_seconds: NDArray[np.float64]
    flat_seconds: NDArray[np.float64]

    def ratio(self, free: NDArray[np.bool_]) -> float:
        """Return tree/flat OBB tests summed over the `free` (F,) frames (0 when none is free)."""
        if not free.any():
            return 0.0
        return float(self.tree_tests[free].sum() / max(self.flat_tests[free].sum(), 1))


def flat_loop(tree: OBBTree, obstacles: OBB, T_world_grasp: NDArray[np.float64]) -> bool:
    """Return the seed's baseline verdict of one pose (4, 4): a loop over flanges, each box vs every obstacle."""
    leaves = tree.boxes[tree.leaves].transformed(T_world_grasp)
    hit = False
    for k in range(len(tree.leaves)):
        hit |= bool(obb_overlap(leaves[k], obstacles).any())
    return hit


def time_checks(
    tree: OBBTree, obstacles: OBB, T: NDArray[np.float64], repeat: int = 3
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return per-frame check times [s] (best of `repeat`) of the tree DFS and the flat loop."""
    F = len(T)
    tree_s, flat_s = np.full(F, np.inf), np.full(F, np.inf)
    for _ in range(repeat):
        for f in range(F):
            t0 = time.perf_counter()
            tree.collide(obstacles, T[f])
            t1 = time.perf_counter()
            flat_loop(tree, obstacles, T[f])
            t2 = time.perf_counter()
            tree_s[f], flat_s[f] = min(tree_s[f], t1 - t0), min(flat_s[f], t2 - t1)
    return tree_s, flat_s


def check_cost(
    tree: OBBTree, obstacles: OBB, T_world_grasp: NDArray[np.float64], repeat: int = 3
) -> CheckCost:
    """Return the tests and times of both methods over the frames' grasp poses (F, 4, 4) [m]."""
    tree_tests = tree.collide_frames(obstacles, T_world_grasp).n_obb_tests
    flat_tests = tree.flat_collide_frames(obstacles, T_world_grasp).n_obb_tests
    tree_s, flat_s = time_checks(tree, obstacles, T_world_grasp, repeat)
    return CheckCost(tree_tests, flat_tests, tree_s, flat_s)
