"""Exact mode: python-fcl meshes plus containment for every pair (`RobotCollisionChecker`).

The reference the fast modes are tested against. Its items are fcl's distances (0 where a
pair touches or one body holds the other); in path checks every pair goes to fcl directly
(every item flagged), so the certifier's anchors and bisection settle the intervals.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.collision.bodies import Pair, RobotBodies

FloatArray = NDArray[np.float64]


class ExactMode:
    """Exact items of `bodies`: one per exact pair (SI units)."""

    name = "exact"
    exact_confirmation = False  # it is the exact check: no containment or pair tables on top
    sdf = None

    def __init__(self, bodies: RobotBodies, *, margin: float) -> None:
        self.bodies, self.margin = bodies, margin
        self.pairs: list[Pair] = list(bodies.scene.pairs)
        self.levers = np.stack([bodies.pair_lever[p] for p in self.pairs])

    def groups(self) -> list[tuple[list[Pair], int]]:
        """Return (exact pairs, item count) per group, in item order: one item per pair."""
        return [([p], 1) for p in self.pairs]

    def items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return fcl's distances (N, P) [m] (0 touching, margin subtracted) and levers (P, dof)."""
        exact, scene = self.bodies.exact, self.bodies.scene
        out = np.zeros((len(qs), len(self.pairs)))
        for k, q in enumerate(np.atleast_2d(qs)):
            hit = set(exact.check(q, distance=False).colliding)  # places the bodies at q
            for m, (a, b) in enumerate(self.pairs):
                out[k, m] = 0.0 if (a, b) in hit else scene.distance(a, b)
        return out - self.margin, self.levers

    def path_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return items that leave every pair to fcl (all flagged)."""
        return np.full((len(qs), len(self.pairs)), -1.0), self.levers
