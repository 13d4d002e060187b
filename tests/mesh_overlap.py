"""The twin of a mesh-pair collision verdict: python-fcl surface collision plus containment
(fcl meshes are surfaces: a mesh wholly inside another reports no contact)."""

from __future__ import annotations

import fcl
import trimesh


def fcl_overlap(a: trimesh.Trimesh, b: trimesh.Trimesh) -> bool:
    """Return whether meshes `a` and `b` (closed, same frame) touch or one holds the other."""

    def obj(m: trimesh.Trimesh) -> fcl.CollisionObject:
        bvh = fcl.BVHModel()
        bvh.beginModel(len(m.vertices), len(m.faces))
        bvh.addSubModel(m.vertices, m.faces)
        bvh.endModel()
        return fcl.CollisionObject(bvh, fcl.Transform())

    hit = fcl.collide(obj(a), obj(b), fcl.CollisionRequest(), fcl.CollisionResult()) > 0
    return bool(hit or a.contains(b.vertices[:1]).any() or b.contains(a.vertices[:1]).any())
