"""Obstacles of a carried-part check: boxes are exact OBBs; other solids are confirmed at the leaves.

The OBB tree is the broad phase. A cylinder or mesh obstacle enters it as its bounding OBB,
and every leaf hit (flange box, obstacle) on such an obstacle is confirmed with python-fcl
(solid cylinder; BVH surface plus a winding-number containment test for closed meshes, since
an fcl mesh is only a surface), so the verdict is exact for the flange boxes.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import fcl
import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.geometry.obb import OBB
from workbench.sheetmetal.obbtree import FramesReport, OBBTree

if TYPE_CHECKING:
    from workbench.collision.shapes import Solid


@dataclass(frozen=True, eq=False)
class ExactShape:
    """A non-box obstacle for the narrow phase: fcl geometry at world pose `T_world` [m]."""

    geometry: fcl.CollisionGeometry
    T_world: NDArray[np.float64]
    mesh: trimesh.Trimesh | None = field(default=None, repr=False)  # closed mesh, world frame


@dataclass(frozen=True, eq=False)
class Obstacles:
    """Named obstacles: `boxes` (M,) OBBs in the world [m]; `exact[i]` None when box i is exact."""

    names: tuple[str, ...]
    boxes: OBB
    exact: tuple[ExactShape | None, ...]


def cell_obstacles(bodies: Iterable[tuple[str, Solid, NDArray[np.float64]]]) -> Obstacles:
    """Return the obstacles of `(name, solid, T_world_body)` triples [m].

    A box is its own exact OBB; a cylinder enters as its bounding OBB, confirmed by its fcl
    solid; a mesh as the OBB of its vertices, confirmed by its fcl surface (and containment
    when it is closed).
    """
    names, centers, rots, halves, exact = [], [], [], [], []
    for name, s, T in bodies:
        shape: ExactShape | None
        if s.kind == "box":
            assert s.size is not None
            c, R, h = T[:3, 3], T[:3, :3], np.asarray(s.size) / 2
            shape = None
        elif s.kind == "cylinder":
            assert s.radius is not None and s.height is not None
            c, R, h = T[:3, 3], T[:3, :3], np.array([s.radius, s.radius, s.height / 2])
            shape = ExactShape(s.fcl_geometry(), T)
        else:
            mesh = s.to_trimesh().copy()
            mesh.apply_transform(T)
            box = OBB.from_points(mesh.vertices)
            c, R, h = box.center, box.rotation, box.half_extents
            shape = ExactShape(s.fcl_geometry(), T, mesh if mesh.is_watertight else None)
        names.append(name)
        centers.append(c)
        rots.append(R)
        halves.append(h)
        exact.append(shape)
    if not names:
        return Obstacles((), OBB(np.zeros((0, 3)), np.zeros((0, 3, 3)), np.zeros((0, 3))), ())
    return Obstacles(
        tuple(names), OBB(np.array(centers), np.array(rots), np.array(halves)), tuple(exact)
    )


def winding_number(mesh: trimesh.Trimesh, points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return the generalized winding number (P,) of points (P, 3) w.r.t. a closed mesh (~1 inside)."""
    tri = np.asarray(mesh.triangles, float)[None] - np.asarray(points, float)[:, None, None, :]
    a, b, c = tri[:, :, 0], tri[:, :, 1], tri[:, :, 2]
    la, lb, lc = (np.linalg.norm(x, axis=-1) for x in (a, b, c))
    det = np.einsum("pti,pti->pt", a, np.cross(b, c))
    den = (
        la * lb * lc
        + np.einsum("pti,pti->pt", a, b) * lc
        + np.einsum("pti,pti->pt", b, c) * la
        + np.einsum("pti,pti->pt", c, a) * lb
    )
    return np.sum(2.0 * np.arctan2(det, den), axis=1) / (4.0 * np.pi)


def box_hits_shape(box: OBB, shape: ExactShape) -> bool:
    """Return whether one OBB (unbatched) touches `shape` exactly (python-fcl + containment)."""
    obj_box = fcl.CollisionObject(
        fcl.Box(*(2.0 * np.asarray(box.half_extents, float))),
        fcl.Transform(np.asarray(box.rotation, float), np.asarray(box.center, float)),
    )
    obj = fcl.CollisionObject(
        shape.geometry, fcl.Transform(shape.T_world[:3, :3], shape.T_world[:3, 3])
    )
    if fcl.collide(obj_box, obj, fcl.CollisionRequest()) > 0:
        return True
    if shape.mesh is None:
        return False  # fcl primitives are solids: no contact means apart
    if bool(box.contains(shape.mesh.vertices[:1]).any()):
        return True  # the mesh lies inside the box
    return bool(winding_number(shape.mesh, box.center[None])[0] > 0.5)  # box inside the mesh


def confirm_exact(
    tree: OBBTree, report: FramesReport, obstacles: Obstacles, T_world_grasp: NDArray[np.float64]
) -> FramesReport:
    """Return `report` with leaf hits on non-box obstacles kept only where the exact test agrees."""
    if all(e is None for e in obstacles.exact) or len(report.hits) == 0:
        return report
    leaves = tree.boxes[tree.leaves]
    keep = np.ones(len(report.hits), dtype=bool)
    for k, (f, flange, o) in enumerate(report.hits):
        shape = obstacles.exact[int(o)]
        if shape is not None:
            box = leaves[int(flange)].transformed(T_world_grasp[int(f)])
            keep[k] = box_hits_shape(box, shape)
    hits = report.hits[keep]
    collides = np.zeros_like(report.collides)
    collides[hits[:, 0]] = True
    return FramesReport(collides, report.n_obb_tests, hits, report.tested, report.hit_nodes)
