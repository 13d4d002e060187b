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
        self._one: tuple | None = None  # type: ignore[type-arg]  # contained_one's arrays
        self._tests: list[tuple[int, str, str]] = []  # (pair, inner, outer)
        for a, b in scene.pairs if enabled else []:
            tests = [(b, a)] if fits(b, a) else []
            if b in scene.moving and fits(a, b):
                tests.append((a, b))
            if tests:
                self._tests += [(len(self.pairs), i, o) for i, o in tests]
                self.pairs.append((a, b))

    def contained_one(self, poses: FloatArray) -> NDArray[np.bool_]:
        """Return (len(pairs),) for one configuration, the moving bodies at poses (B, 4, 4).

        The same probe-vertex tests as `contained`, all half-space tests in one padded batch
        (~15 us rather than ~15 us per test); outers without half-spaces test their mesh.
        """
        if not self._tests:
            return np.zeros(len(self.pairs), bool)
        if self._one is None:
            self._one = self._padded_tests()
        starts, inner, outer, probe, normals, offsets, world, meshes = self._one
        world[: len(poses)] = poses
        Ti, To = world.take(inner, axis=0), world.take(outer, axis=0)
        p = np.matmul(Ti[:, :3, :], probe)[:, :, 0] - To[:, :3, 3]  # world probe - outer origin
        local = np.matmul(p[:, None, :], To[:, :3, :3])  # (T, 1, 3): R_o^T (p - t_o)
        inside = np.all(np.matmul(normals, local.transpose(0, 2, 1))[:, :, 0] <= offsets, axis=1)
        for t, mesh in meshes:
            inside[t] = bool(mesh.contains(local[t])[0])
        return np.logical_or.reduceat(inside, starts)  # type: ignore[no-any-return]

    def _padded_tests(self) -> tuple:  # type: ignore[type-arg]
        b, scene = self.bodies, self.bodies.scene
        names = list(scene.static)
        row = {**b.index, **{n: len(b.names) + k for k, n in enumerate(names)}}
        static = np.stack([scene.static[n].T for n in names]) if names else np.zeros((0, 4, 4))
        faces = max(
            (len(h[0]) for _, _, o in self._tests if (h := scene.entry(o).halfspaces)), default=1
        )
        count = len(self._tests)
        normals, offsets = np.zeros((count, faces, 3)), np.full((count, faces), np.inf)
        meshes = []
        for t, (_, _, o) in enumerate(self._tests):
            h = scene.entry(o).halfspaces
            if h is None:
                meshes.append((t, scene.entry(o).mesh))
                continue
            normals[t, : len(h[0])], offsets[t, : len(h[0])] = h
        pair = np.array([k for k, _, _ in self._tests], np.int64)  # ascending, each pair
        starts = np.flatnonzero(np.r_[True, np.diff(pair) != 0])
        inner = np.array([row[i] for _, i, _ in self._tests], np.int64)
        outer = np.array([row[o] for _, _, o in self._tests], np.int64)
        probe = np.stack([np.r_[scene.entry(i).probe, 1.0] for _, i, _ in self._tests])[..., None]
        world = np.concatenate([np.zeros((len(b.names), 4, 4)), static])  # moving rows per call
        return starts, inner, outer, probe, normals, offsets, world, meshes

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
