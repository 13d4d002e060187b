"""Exact collision and distance checks with python-fcl: moving bodies against a static cell.

python-fcl meshes are surfaces: a body wholly inside a closed mesh reports no collision
(FACTS.md). Pairs that fcl calls free but whose bounding boxes overlap get a containment
test (one vertex of each inside the other), so enclosure counts as collision.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import fcl
import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.collision.shapes import Solid, fcl_transform
from workbench.errors import InputError


@dataclass(frozen=True)
class ContactReport:
    """One configuration's exact check: the pairs in contact by name and the clearance of the rest [m]."""

    colliding: tuple[tuple[str, str], ...]
    min_distance: float  # smallest distance over checked pairs; 0 when any pair collides
    closest_pair: tuple[str, str] | None
    pairs_checked: int

    @property
    def in_collision(self) -> bool:
        """Return True when any pair collides."""
        return bool(self.colliding)

    def colliding_bodies(self) -> set[str]:
        """Return the names of all bodies in a colliding pair."""
        return {name for pair in self.colliding for name in pair}


class SceneBody:
    """A named solid of a scene: its fcl object, mesh, world pose and bounding box, as placed."""

    def __init__(self, solid: Solid) -> None:
        self.solid = solid
        self.obj = fcl.CollisionObject(solid.fcl_geometry(), fcl.Transform())
        mesh = solid.to_trimesh()
        self.mesh = mesh
        if mesh.bounds is None or len(mesh.faces) == 0 or not np.all(np.isfinite(mesh.bounds)):
            raise InputError(
                f"{solid.name}: its {solid.kind} has no usable triangles to check (too small "
                "or degenerate); give it a size of at least a few micrometres"
            )
        lo, hi = np.asarray(mesh.bounds, float)
        self.local_corners = np.array(list(itertools.product(*zip(lo, hi, strict=True))))
        # A point on the surface, for the containment test.
        self.probe = np.asarray(mesh.vertices[0], float)
        self.closed = solid.kind == "mesh" and bool(mesh.is_watertight)
        # Convex closed meshes (generated links, hulls) answer containment by half-spaces;
        # the surface itself counts as inside (1e-9 m slack), as for trimesh's ray test.
        self.halfspaces: tuple[NDArray[np.float64], NDArray[np.float64]] | None = None
        if self.closed and mesh.is_convex:
            n = np.asarray(mesh.face_normals, float)
            off = np.einsum("fi,fi->f", n, np.asarray(mesh.triangles_center, float)) + 1e-9
            self.halfspaces = (n, off)
        self.place(np.eye(4))

    def place(self, T: NDArray[np.float64]) -> None:
        self.T = np.asarray(T, float)
        self.obj.setTransform(fcl_transform(self.T))
        w = self.local_corners @ self.T[:3, :3].T + self.T[:3, 3]
        self.aabb = (w.min(0), w.max(0))

    def contains_world_point(self, p: NDArray[np.float64]) -> bool:
        if not self.closed:
            return False  # fcl primitives are solids already; open meshes have no inside
        local = (p - self.T[:3, 3]) @ self.T[:3, :3]
        if self.halfspaces is not None:
            return bool(np.all(self.halfspaces[0] @ local <= self.halfspaces[1]))
        return bool(self.mesh.contains(local[None])[0])


class CollisionScene:
    """Moving bodies and static obstacles with the pairs to check between them.

    `moving` bodies are placed on every `check`; `static` ones once. `self_pairs` are
    pairs of moving-body names to check against each other; `ignore` lists
    moving-static pairs never to check (e.g. a robot base bolted to its pedestal).
    """

    def __init__(
        self,
        moving: list[Solid],
        static: list[tuple[Solid, NDArray[np.float64]]],
        *,
        self_pairs: list[tuple[str, str]] = (),  # type: ignore[assignment]
        ignore: list[tuple[str, str]] = (),  # type: ignore[assignment]
    ) -> None:
        names = [s.name for s in moving] + [s.name for s, _ in static]
        dupes = {n for n in names if names.count(n) > 1}
        if dupes:
            raise InputError(f"body names must be unique, repeated: {sorted(dupes)}")
        self.moving = {s.name: SceneBody(s) for s in moving}
        self.static = {}
        for solid, T in static:
            entry = SceneBody(solid)
            entry.place(T)
            self.static[solid.name] = entry
        skip = {frozenset(p) for p in ignore}
        self.pairs: list[tuple[str, str]] = [
            (m, s) for m in self.moving for s in self.static if frozenset((m, s)) not in skip
        ]
        for a, b in self_pairs:
            if a not in self.moving or b not in self.moving:
                raise InputError(f"self-collision pair ({a}, {b}) names an unknown moving body")
            self.pairs.append((a, b))

    def entry(self, name: str) -> SceneBody:
        """Return the moving or static body called `name`."""
        return self.moving.get(name) or self.static[name]

    def place(self, poses: dict[str, NDArray[np.float64]]) -> None:
        """Place moving bodies at `poses` (name -> (4, 4) world pose)."""
        for name, T in poses.items():
            self.moving[name].place(T)

    def collides(self, a: str, b: str) -> bool:
        """Return whether bodies a and b (as placed) touch, or one holds the other."""
        ea, eb = self.entry(a), self.entry(b)
        if fcl.collide(ea.obj, eb.obj, fcl.CollisionRequest(), fcl.CollisionResult()) > 0:
            return True
        if not _aabbs_overlap(ea.aabb, eb.aabb):
            return False
        return eb.contains_world_point(ea.T[:3, :3] @ ea.probe + ea.T[:3, 3]) or (
            ea.contains_world_point(eb.T[:3, :3] @ eb.probe + eb.T[:3, 3])
        )

    def distance(self, a: str, b: str) -> float:
        """Return fcl's distance [m] between the surfaces of bodies a and b as placed (>= 0)."""
        ea, eb = self.entry(a), self.entry(b)
        d = fcl.distance(ea.obj, eb.obj, fcl.DistanceRequest(), fcl.DistanceResult())
        return max(float(d), 0.0)

    def aabb_gap(self, a: str, b: str) -> float:
        """Return the distance [m] between the world bounding boxes of a and b (0 when they overlap)."""
        ea, eb = self.entry(a), self.entry(b)
        gap = np.maximum(np.maximum(ea.aabb[0] - eb.aabb[1], eb.aabb[0] - ea.aabb[1]), 0.0)
        return float(np.sqrt(gap @ gap))

    def check(
        self, poses: dict[str, NDArray[np.float64]], *, distance: bool = True
    ) -> ContactReport:
        """Return the report for moving bodies placed at `poses` (name -> (4, 4) world pose)."""
        self.place(poses)
        colliding: list[tuple[str, str]] = []
        best, best_pair = np.inf, None
        for a, b in self.pairs:
            if self.collides(a, b):
                colliding.append((a, b))
                best, best_pair = 0.0, (a, b)
                continue
            if distance and best > 0:
                d = self.distance(a, b)
                if d < best:
                    best, best_pair = d, (a, b)
        return ContactReport(tuple(colliding), float(best), best_pair, len(self.pairs))


def _aabbs_overlap(
    a: tuple[NDArray[np.float64], NDArray[np.float64]],
    b: tuple[NDArray[np.float64], NDArray[np.float64]],
) -> bool:
    return bool((a[0] <= b[1]).all() and (b[0] <= a[1]).all())


def solid_from_trimesh(name: str, mesh: trimesh.Trimesh) -> Solid:
    """Return a mesh `Solid` named `name`."""
    return Solid(name=name, kind="mesh", mesh=mesh)
