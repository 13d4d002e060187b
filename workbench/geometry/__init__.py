"""Pure-numpy geometry: transforms, OBBs, distances, LBVH, sparse SDF, enveloping spheres."""

from __future__ import annotations

from workbench.geometry.distance import capsule_rectangle_distance, segment_segment_distance
from workbench.geometry.lbvh import LBVH
from workbench.geometry.obb import OBB, obb_overlap
from workbench.geometry.pose_check import check_rotation, check_transform
from workbench.geometry.sdf import SparseSDF
from workbench.geometry.spheres import SphereSet, fit_spheres

__all__ = [
    "LBVH",
    "OBB",
    "SparseSDF",
    "SphereSet",
    "capsule_rectangle_distance",
    "check_rotation",
    "check_transform",
    "fit_spheres",
    "obb_overlap",
    "segment_segment_distance",
]
