"""Capsules mode: every body as a capsule holding its vertices, obstacles as their oriented boxes.

Seed 002, made exact. A body's capsule lies along its principal axis and holds all its
vertices (so its whole convex hull); an obstacle's oriented bounding box holds the obstacle.
A capsule against a box: the least exact `capsule_rectangle_distance` over the box's six
faces, or touching when an end point lies inside the box. Two capsules:
`segment_segment_distance` less both radii. One item (and one group) per exact pair.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.collision.bodies import Pair, RobotBodies
from workbench.geometry.distance import capsule_rectangle_distance, segment_segment_distance

FloatArray = NDArray[np.float64]


class CapsulesMode:
    """The capsule items of `bodies` (SI units); see the module docstring."""

    name = "capsules"
    exact_confirmation = True
    sdf = None

    def __init__(self, bodies: RobotBodies, *, margin: float) -> None:
        self.bodies, self.margin = bodies, margin
        seg, rad = [], []
        for m in bodies.meshes:
            v = np.asarray(m.vertices, float)
            c = v.mean(axis=0)
            _, _, vt = np.linalg.svd(v - c, full_matrices=False)
            u = vt[0]
            t = (v - c) @ u
            seg.append((c + t.min() * u, c + t.max() * u))
            rad.append(float(np.linalg.norm(v - c - np.outer(t, u), axis=1).max()) * (1 + 1e-9))
        self.segment = np.array(seg)  # (B, 2, 3) in body frames
        self.radius = np.array(rad)
        self.lever = np.stack(
            [bodies.levers_of.levers(int(bodies.frame[i]), s) for i, s in enumerate(self.segment)]
        )
        self.pairs: list[Pair] = [
            (bodies.names[b], name)
            for b in bodies.checked
            for name in bodies.obstacles
            if (bodies.names[b], name) in bodies.cell_pairs
        ] + list(bodies.self_pairs)
        self.boxes = []
        for name in bodies.obstacles:
            e = bodies.scene.static[name]
            obb = e.mesh.bounding_box_oriented
            T = e.T @ np.asarray(obb.primitive.transform, float)
            self.boxes.append((T, np.asarray(obb.primitive.extents, float) / 2))

    def groups(self) -> list[tuple[list[Pair], int]]:
        """Return (exact pairs, item count) per group, in item order: one item per pair."""
        return [([p], 1) for p in self.pairs]

    def items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return clearance lower bounds (N, I) [m] (margin subtracted) and levers (I, dof)."""
        b = self.bodies
        T = b.poses(qs)
        p = np.einsum("nbij,bkj->nbki", T[..., :3, :3], self.segment) + T[..., None, :3, 3]
        n = len(p)
        cols, levers = [], []
        for body in b.checked:
            for (Tb, half), name in zip(self.boxes, b.obstacles, strict=True):
                if (b.names[body], name) not in b.cell_pairs:
                    continue
                local = (p[:, body] - Tb[:3, 3]) @ Tb[:3, :3]  # (N, 2, 3) in the box frame
                inside = np.any(np.all(np.abs(local) <= half, axis=2), axis=1)
                best = np.full(n, np.inf)
                for k in range(3):
                    u, w = [i for i in range(3) if i != k]
                    axes = np.eye(3)[[u, w]]
                    for sgn in (-1.0, 1.0):
                        centre = np.zeros(3)
                        centre[k] = sgn * half[k]
                        d = capsule_rectangle_distance(
                            local[:, 0], local[:, 1], self.radius[body], centre, axes, half[[u, w]]
                        )
                        best = np.minimum(best, d)
                cols.append(np.where(inside, -self.radius[body], best))
                levers.append(self.lever[body])
        for sa, sb in b.self_pairs:
            ia, ib = b.index[sa], b.index[sb]
            d = segment_segment_distance(p[:, ia, 0], p[:, ia, 1], p[:, ib, 0], p[:, ib, 1])
            cols.append(d - self.radius[ia] - self.radius[ib])
            levers.append(b.lever_of_pair((sa, sb), self.lever))
        if not cols:
            return np.full((n, 1), np.inf), np.zeros((1, b.dof))
        return np.stack(cols, axis=1) - self.margin, np.stack(levers)

    def path_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return `items` for the path certifier."""
        return self.items(qs)
