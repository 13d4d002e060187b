"""Mesh files named by a project, loaded and scaled to metres."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh

from workbench.errors import MeshError


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
