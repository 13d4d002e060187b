"""Collision shapes: named solids (box, cylinder, mesh) and their python-fcl geometry."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import fcl
import numpy as np
import trimesh
from numpy.typing import ArrayLike

from workbench.errors import InputError, MeshError

SOLID_SIZE = (1e-6, 1e4)
"""Smallest and largest edge length, radius or height of a box or cylinder solid [m]."""


@dataclass(frozen=True)
class Solid:
    """A closed solid in its own frame [m]: a box (`size`), a z-axis cylinder or a mesh."""

    name: str
    kind: Literal["box", "cylinder", "mesh"]
    size: tuple[float, float, float] | None = None
    radius: float | None = None
    height: float | None = None
    mesh: trimesh.Trimesh | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if self.kind == "box" and (self.size is None or min(self.size) <= 0):
            raise InputError(
                f"{self.name}: a box needs three positive edge lengths, got {self.size}"
            )
        if self.kind == "cylinder" and not (
            self.radius and self.height and self.radius > 0 and self.height > 0
        ):
            raise InputError(f"{self.name}: a cylinder needs radius > 0 and height > 0")
        dims = self.size if self.kind == "box" else (self.radius, self.height)
        if self.kind != "mesh" and not all(
            SOLID_SIZE[0] <= float(d) <= SOLID_SIZE[1]  # type: ignore[arg-type]
            for d in dims  # type: ignore[union-attr]
        ):
            raise InputError(
                f"{self.name}: a {self.kind}'s dimensions must lie in [{SOLID_SIZE[0]:g}, "
                f"{SOLID_SIZE[1]:g}] m (smaller ones vanish in the mesh, larger ones overflow), "
                f"got {dims}"
            )
        if self.kind == "mesh":
            check_mesh(self.mesh, self.name)

    def to_trimesh(self) -> trimesh.Trimesh:
        """Return a triangle mesh of the solid in its own frame [m]."""
        if self.kind == "box":
            return trimesh.creation.box(extents=self.size)
        if self.kind == "cylinder":
            assert self.radius is not None and self.height is not None
            # A unit cylinder scaled: trimesh drops faces below an absolute area when it
            # builds one, which would leave a sub-millimetre cylinder without triangles.
            mesh = trimesh.creation.cylinder(radius=1.0, height=1.0, sections=32)
            mesh.apply_transform(np.diag([self.radius, self.radius, self.height, 1.0]))
            return mesh
        assert self.mesh is not None
        return self.mesh

    def fcl_geometry(self) -> fcl.CollisionGeometry:
        """Return the python-fcl geometry: solid primitives for box and cylinder, a BVH surface for meshes."""
        if self.kind == "box":
            return fcl.Box(*self.size)  # type: ignore[misc]
        if self.kind == "cylinder":
            return fcl.Cylinder(self.radius, self.height)
        mesh = self.to_trimesh()
        return bvh_model(mesh.vertices, mesh.faces)


def check_mesh(mesh: trimesh.Trimesh | None, name: str) -> trimesh.Trimesh:
    """Return `mesh` if usable for collision checks; raise `MeshError` naming `name` otherwise."""
    if mesh is None or not isinstance(mesh, trimesh.Trimesh):
        raise MeshError(f"{name}: expected a triangle mesh, got {type(mesh).__name__}")
    if len(mesh.faces) == 0:
        raise MeshError(f"{name}: the mesh has no triangles")
    if not np.all(np.isfinite(mesh.vertices)):
        raise MeshError(f"{name}: the mesh has NaN or infinite vertex coordinates")
    return mesh


def bvh_model(vertices: ArrayLike, faces: ArrayLike) -> fcl.BVHModel:
    """Return a python-fcl BVH (a surface, not a solid) of a triangle mesh: vertices (V, 3) [m],
    faces (F, 3) vertex indices. The project's one fcl BVH construction."""
    v = np.ascontiguousarray(vertices, float)
    f = np.ascontiguousarray(faces, np.int32)
    model = fcl.BVHModel()
    model.beginModel(len(v), len(f))
    model.addSubModel(v, f)
    model.endModel()
    return model


def fcl_transform(T: ArrayLike) -> fcl.Transform:
    """Return a python-fcl transform from a (4, 4) matrix: its rotation matrix and translation
    as they are (fcl takes a matrix; no quaternion conversion of ours)."""
    M = np.asarray(T, float)
    return fcl.Transform(np.ascontiguousarray(M[:3, :3]), np.ascontiguousarray(M[:3, 3]))
