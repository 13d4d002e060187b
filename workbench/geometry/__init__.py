"""Pure-numpy geometry: transforms, OBBs, distances, LBVH, sparse SDF, enveloping spheres."""

from __future__ import annotations

from workbench.geometry.distance import capsule_rectangle_distance, segment_segment_distance
from workbench.geometry.lbvh import LBVH
from workbench.geometry.obb import OBB, obb_overlap
from workbench.geometry.pose_check import check_rotation, check_transform
from workbench.geometry.sdf import SparseSDF
from workbench.geometry.spheres import SphereSet, fit_spheres
from workbench.geometry.transforms import (
    invert_transform,
    make_transform,
    matrix_to_rpy,
    matrix_to_wxyz,
    rot_x,
    rot_y,
    rot_z,
    rpy_to_matrix,
    transform_to_xyz_rpy,
    wxyz_to_matrix,
    xyz_rpy_to_transform,
)

__all__ = [
    "LBVH",
    "OBB",
    "SparseSDF",
    "SphereSet",
    "capsule_rectangle_distance",
    "check_rotation",
    "check_transform",
    "fit_spheres",
    "invert_transform",
    "make_transform",
    "matrix_to_rpy",
    "matrix_to_wxyz",
    "obb_overlap",
    "rot_x",
    "rot_y",
    "rot_z",
    "rpy_to_matrix",
    "segment_segment_distance",
    "transform_to_xyz_rpy",
    "wxyz_to_matrix",
    "xyz_rpy_to_transform",
]
