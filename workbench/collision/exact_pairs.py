"""The exact pairs as the path certifier asks for them: placed lazily, collided, measured.

The certifier works on many configurations at once but asks python-fcl only about the few
pairs its fast items flag. `ExactPairs` keeps the world poses of the configuration in
question and places a moving body in the exact checker's scene only when a pair needs it.
It also gives the pairs' bounding-box gaps (a cheap lower bound of their distance), the
distances at table nodes and the penetration depth reported for a collision.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.collision.bodies import Pair, RobotBodies
from workbench.geometry.lbvh import LBVH

FloatArray = NDArray[np.float64]


class ExactPairs:
    """fcl verdicts and distances of the exact pairs of `bodies`, less `margin` [m]."""

    def __init__(self, bodies: RobotBodies, margin: float) -> None:
        self.bodies, self.margin = bodies, margin
        scene = bodies.scene
        self._pending = np.zeros((0, 4, 4))
        self._placed: set[str] = set()
        self._corners = np.stack([scene.moving[n].local_corners for n in bodies.names])
        self._rows = [(bodies.index.get(a, -1), bodies.index.get(b, -1), b) for a, b in scene.pairs]

    def place(self, poses: FloatArray) -> None:
        """Set the world poses (B, 4, 4) of the moving bodies; each is placed when first used."""
        self._pending = poses
        self._placed = set()

    def _ready(self, pair: Pair) -> None:
        moving = self.bodies.scene.moving
        for name in pair:
            if name in moving and name not in self._placed:
                moving[name].place(self._pending[self.bodies.index[name]])
                self._placed.add(name)

    def collides(self, pair: Pair) -> bool:
        """Return the exact verdict (fcl collide, then containment) of a pair as placed."""
        self._ready(pair)
        return self.bodies.scene.collides(*pair)

    def distance(self, pair: Pair) -> float:
        """Return the pair's surface distance [m] as placed, less the margin."""
        self._ready(pair)
        return self.bodies.scene.distance(*pair) - self.margin

    def aabb_gaps(self, poses: FloatArray) -> FloatArray:
        """Return (N, P): gaps [m] between the world bounding boxes of every exact pair, less the margin.

        poses (N, B, 4, 4) of the moving bodies; pairs in `scene.pairs` order. A gap is a lower
        bound of the pair's distance (0 where the boxes overlap).
        """
        static = self.bodies.scene.static
        w = (
            np.einsum("nbij,bkj->nbki", poses[..., :3, :3], self._corners)
            + poses[:, :, None, :3, 3]
        )
        lo, hi = w.min(axis=2), w.max(axis=2)  # (N, B, 3)
        out = np.empty((len(poses), len(self._rows)))
        for k, (ia, ib, b) in enumerate(self._rows):
            alo, ahi = lo[:, ia], hi[:, ia]
            blo, bhi = (lo[:, ib], hi[:, ib]) if ib >= 0 else static[b].aabb
            gap = np.maximum(np.maximum(alo - bhi, blo - ahi), 0.0)
            out[:, k] = np.sqrt(np.einsum("ni,ni->n", gap, gap))
        return out - self.margin

    def node_distances(self, pair: Pair, qs: FloatArray) -> FloatArray:
        """Return the pair's exact distance [m] at qs (M, dof): 0 when touching or held (no margin)."""
        b, scene = self.bodies, self.bodies.scene
        T = b.poses(qs)
        ia, ib = b.index[pair[0]], b.index.get(pair[1])
        out = np.empty(len(qs))
        for k in range(len(qs)):
            scene.moving[pair[0]].place(T[k, ia])
            if ib is not None:
                scene.moving[pair[1]].place(T[k, ib])
            out[k] = 0.0 if scene.collides(*pair) else scene.distance(*pair)
        self._placed = set()  # the path's pending poses must be placed again
        return out

    def penetration(self, q: FloatArray, a: str, b: str) -> float:
        """Return the depth [m] of the deepest vertex of body a inside b or of b inside a."""
        scene = self.bodies.scene
        self.bodies.exact.check(q, distance=False)  # places the moving bodies at q
        self._placed = set()
        ea, eb = scene.entry(a), scene.entry(b)
        depth = 0.0
        for inner, outer in ((ea, eb), (eb, ea)):
            v = np.asarray(inner.mesh.vertices, float) @ inner.T[:3, :3].T + inner.T[:3, 3]
            local = (v - outer.T[:3, 3]) @ outer.T[:3, :3]
            bvh = LBVH(outer.mesh.vertices, outer.mesh.faces)
            inside = bvh.ray_crossings(local, np.array([0.5773, 0.5774, 0.5775])) % 2 == 1
            if np.any(inside):
                depth = max(depth, float(bvh.closest_points(local[inside])[1].max()))
        return depth
