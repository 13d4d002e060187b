"""Conversions between the project file's units (mm, deg) and SI, and project -> domain objects."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.errors import MeshError
from workbench.geometry.transforms import matrix_to_rpy, xyz_rpy_to_transform
from workbench.project.models import Pose

MM = 1e-3
DEG = np.pi / 180.0


def pose_to_matrix(pose: Pose) -> NDArray[np.float64]:
    """Return the (4, 4) transform [m] of a project pose (mm, deg)."""
    return xyz_rpy_to_transform(np.asarray(pose.xyz) * MM, np.asarray(pose.rpy) * DEG)


def matrix_to_pose(T: NDArray[np.float64]) -> Pose:
    """Return a project pose (mm, deg) of a (4, 4) transform [m]."""
    T = np.asarray(T, float)
    return Pose(
        xyz=[float(v) for v in T[:3, 3] / MM],
        rpy=[float(v) for v in matrix_to_rpy(T[:3, :3]) / DEG],
    )


def load_mesh_file(path: str, base_dir: Path, scale: float, field: str) -> trimesh.Trimesh:
    """Return the mesh at `path` (relative to `base_dir`) scaled to metres; `field` names it in errors."""
    p = Path(path)
    if not p.is_absolute():
        p = base_dir / p
    if not p.is_file():
        raise MeshError(
            f"{field}: mesh file not found: {p}; fix the path (relative to the project file)"
        )
    try:
        mesh = trimesh.load(p, force="mesh")
    except Exception as exc:  # trimesh raises many types for broken files
        raise MeshError(f"{field}: cannot read mesh {p}: {exc}") from None
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
        raise MeshError(f"{field}: {p} holds no triangles; export it as STL, OBJ or PLY")
    if not np.all(np.isfinite(mesh.vertices)):
        raise MeshError(f"{field}: {p} has NaN or infinite vertex coordinates")
    mesh = mesh.copy()
    mesh.apply_scale(scale)
    return mesh
