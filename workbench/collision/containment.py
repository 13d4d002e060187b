"""Containment: the exact pairs where one body may lie wholly inside the other, tested in batches.

Spheres and capsules hold surfaces. A body wholly inside an obstacle has its surface inside,
which the items catch; an obstacle (or another body) wholly inside a body touches none of
the body's spheres. Such (inner, outer) pairs, where the inner's largest extent is below the
outer's diagonal (which is at least its diameter) and the outer is closed, get the exact
checker's containment test (the inner's probe vertex inside the outer) at every
configuration: half-spaces for convex meshes, trimesh's ray test otherwise. fcl's collide
already finds a mesh inside a primitive (a solid).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.collision.bodies import Pair, RobotBodies
from workbench.collision.thin_matmul import thin_matmul

FloatArray = NDArray[np.float64]


class Containment:
    """The pairs needing a containment test (`pairs`) and the batched test (`contained`)."""

    def __init__(self, bodies: RobotBodies, *, enabled: bool = True) -> None:
        """enabled=False: no pairs (the exact mode's own check includes containment)."""
        self.bodies = bodies
        scene = bodies.scene

        def fits(a: str, b: str) -> bool:
            inner, outer = scene.entry(a), scene.entry(b)
            return outer.closed and bool(
                np.max(inner.mesh.extents) <= np.linalg.norm(outer.mesh.extents)
            )

        self.pairs: list[Pair] = []
        self._tests: list[tuple[int, str, str]] = []  # (pair, inner, outer)
        for a, b in scene.pairs if enabled else []:
            tests = [(b, a)] if fits(b, a) else []
            if b in scene.moving and fits(a, b):
                tests.append((a, b))
            if tests:
                self._tests += [(len(self.pairs), i, o) for i, o in tests]
                self.pairs.append((a, b))

    def contained(self, qs: FloatArray) -> NDArray[np.bool_]:
        """Return (N, len(pairs)): whether one body of the pair holds the other's probe vertex."""
        out = np.zeros((len(qs), len(self.pairs)), bool)
        if not self._tests:
            return out
        b, scene = self.bodies, self.bodies.scene
        T = b.poses(qs)

        def pose(name: str) -> FloatArray:
            if name in b.index:
                return T[:, b.index[name]]  # type: ignore[no-any-return]
            return np.broadcast_to(scene.static[name].T, (len(qs), 4, 4))

        for k, inner, outer in self._tests:
            Ti, To = pose(inner), pose(outer)
            p = np.einsum("nij,j->ni", Ti[:, :3, :3], scene.entry(inner).probe) + Ti[:, :3, 3]
            local = np.einsum("nji,nj->ni", To[:, :3, :3], p - To[:, :3, 3])
            body = scene.entry(outer)
            if body.halfspaces is not None:
                normals, offsets = body.halfspaces
                inside = np.all(thin_matmul(local, normals.T) <= offsets, axis=1)
            else:
                inside = np.asarray(body.mesh.contains(local), bool)
            out[:, k] |= inside
        return out
