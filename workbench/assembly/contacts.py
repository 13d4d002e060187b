"""Contacts between many independently moving solids (robot links, tools, parts), over many samples.

Broad phase: each body's local bounding box, placed at its pose, gives a world AABB; only
pairs whose AABBs overlap go on. Narrow phase: python-fcl collision, then (fcl meshes are
surfaces) a containment test: a vertex of one body inside the other closed mesh (its
oriented box first, the winding number only where that cannot decide). Touching counts.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass

import fcl
import numpy as np
from numpy.typing import NDArray

from workbench.assembly.cells import winding_number
from workbench.collision.shapes import Solid, fcl_transform
from workbench.errors import InputError


@dataclass(frozen=True)
class Contact:
    """Two bodies touching at sample `index` (time `time` [s] where the samples are timed)."""

    index: int
    time: float
    body_a: str
    body_b: str

    def describe(self) -> str:
        """Return the contact as a sentence (time in s)."""
        return f"{self.body_a} hits {self.body_b} at t = {self.time:.3f} s (sample {self.index})"


class Bodies:
    """Named solids, each placed anew at every sample, and the pairs of them to check."""

    def __init__(self, solids: Sequence[Solid], pairs: Sequence[tuple[str, str]]) -> None:
        """solids: closed solids in their own frames [m]; pairs: names of the pairs to check."""
        self.names = [s.name for s in solids]
        dupes = sorted({n for n in self.names if self.names.count(n) > 1})
        if dupes:
            raise InputError(f"body names must be unique, repeated: {dupes}")
        index = {n: i for i, n in enumerate(self.names)}
        for a, b in pairs:
            if a not in index or b not in index or a == b:
                raise InputError(f"pair ({a}, {b}) must name two different bodies of {self.names}")
        self.pa = np.array([index[a] for a, _ in pairs], dtype=np.int64)
        self.pb = np.array([index[b] for _, b in pairs], dtype=np.int64)
        self.objs = [fcl.CollisionObject(s.fcl_geometry(), fcl.Transform()) for s in solids]
        self.meshes = [s.to_trimesh() for s in solids]
        bounds = np.array([m.bounds for m in self.meshes], dtype=float)  # (B, 2, 3)
        self.lo, self.hi = bounds[:, 0], bounds[:, 1]
        self.corners = np.array(
            [list(itertools.product(*zip(lo, hi, strict=True))) for lo, hi in bounds]
        )  # (B, 8, 3)
        # Primitives are solid in fcl already; only closed meshes need the containment test.
        self.solid_mesh = [
            s.kind == "mesh" and m.is_watertight for s, m in zip(solids, self.meshes, strict=True)
        ]
        self.probe = np.array([m.vertices[0] for m in self.meshes], dtype=float)
        self.triangles = [np.ascontiguousarray(m.triangles, dtype=float) for m in self.meshes]

    @property
    def pairs(self) -> list[tuple[str, str]]:
        """Return the checked pairs by name."""
        return [(self.names[a], self.names[b]) for a, b in zip(self.pa, self.pb, strict=True)]

    def aabb_overlaps(self, poses: NDArray[np.float64]) -> NDArray[np.bool_]:
        """Return (N, P): True where the world AABBs of a pair's bodies overlap, for poses (N, B, 4, 4)."""
        w = np.einsum("nbij,bkj->nbki", poses[..., :3, :3], self.corners) + poses[:, :, None, :3, 3]
        lo, hi = w.min(axis=2), w.max(axis=2)  # (N, B, 3)
        return np.all(
            (lo[:, self.pa] <= hi[:, self.pb]) & (lo[:, self.pb] <= hi[:, self.pa]), axis=-1
        )

    def touching(self, k: int, Ta: NDArray[np.float64], Tb: NDArray[np.float64]) -> bool:
        """Return True if the bodies of pair `k` at world poses Ta, Tb (4, 4) touch or one holds the other."""
        a, b = int(self.pa[k]), int(self.pb[k])
        oa, ob = self.objs[a], self.objs[b]
        oa.setTransform(fcl_transform(Ta))
        ob.setTransform(fcl_transform(Tb))
        if fcl.collide(oa, ob, fcl.CollisionRequest(), fcl.CollisionResult()) > 0:
            return True
        return self._inside(a, Ta, b, Tb) or self._inside(b, Tb, a, Ta)

    def _inside(self, i: int, Ti: NDArray, j: int, Tj: NDArray) -> bool:
        """Return True if body i's probe vertex lies inside closed body j."""
        if not self.solid_mesh[j]:
            return False
        p = Ti[:3, :3] @ self.probe[i] + Ti[:3, 3]
        local = (p - Tj[:3, 3]) @ Tj[:3, :3]
        if np.any(local < self.lo[j]) or np.any(local > self.hi[j]):
            return False
        return bool(
            winding_number(local[None], self.meshes[j], triangles=self.triangles[j])[0] > 0.5
        )

    def contacts(
        self,
        poses: NDArray[np.float64],
        *,
        active: NDArray[np.bool_] | None = None,
        first: bool = False,
    ) -> list[tuple[int, int]]:
        """Return (sample, pair) of every touching pair at poses (N, B, 4, 4), in sample order.

        active (N, P): pairs to check per sample (default all). first: stop at the first
        sample with a contact (its touching pairs are all returned).
        """
        poses = np.asarray(poses, dtype=float)
        if poses.ndim != 4 or poses.shape[1:] != (len(self.names), 4, 4):
            raise InputError(
                f"poses must have shape (N, {len(self.names)}, 4, 4), got {poses.shape}"
            )
        cand = self.aabb_overlaps(poses)
        if active is not None:
            cand &= active
        out: list[tuple[int, int]] = []
        for n in np.flatnonzero(cand.any(axis=1)):
            for k in np.flatnonzero(cand[n]):
                if self.touching(int(k), poses[n, self.pa[k]], poses[n, self.pb[k]]):
                    out.append((int(n), int(k)))
            if first and out:
                break
        return out
