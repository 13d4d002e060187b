"""Mesh files named by a project, loaded and scaled to metres (read through the path rule).

STL, OBJ, PLY, OFF and glTF files are read by trimesh; STEP files (.step, .stp) by Open
CASCADE (`workbench.cad.step`), tessellated with the project's `cad` tolerances. A STEP file
carries its own length unit and is read in mm, so its `scale` is 0.001 (the project model
refuses any other: `workbench.project.cad.check_step_scale`).
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import trimesh

from workbench.cad.step import STEP_SUFFIXES, StepTolerance, read_step_mesh
from workbench.errors import MeshError
from workbench.project.paths import ProjectFolders, shown_path, size_limit

MESH_TYPES = ("stl", "obj", "ply", "off", "glb", "gltf")
STEP_TYPES = tuple(s.lstrip(".") for s in STEP_SUFFIXES)


def mesh_size_limit() -> int:
    """Return the largest mesh file read [bytes] (WORKBENCH_MAX_MESH_BYTES; docs/security.md)."""
    return size_limit("mesh")


def load_mesh_file(
    path: str,
    folders: ProjectFolders | Path,
    scale: float,
    field: str,
    *,
    tolerance: StepTolerance | None = None,
) -> trimesh.Trimesh:
    """Return the mesh at `path` (relative to the project's folder) scaled to metres.

    The path must stay inside the project's folder or an allowed one and name a regular file
    within the mesh size limit (`ProjectFolders.read`); `field` names it in errors. A STEP
    file is tessellated with `tolerance` (None: the defaults, `StepTolerance()`) in mm, then
    scaled by `scale`.
    """
    real, data = ProjectFolders.of(folders).read(path, field, kind="mesh")
    kind = real.suffix.lower().lstrip(".")
    path = shown_path(path)  # how the messages below name it: no server folder
    if kind in STEP_TYPES:
        step = read_step_mesh(data, path, field, tolerance or StepTolerance())
        step.apply_scale(scale)
        return step
    if kind not in MESH_TYPES:
        raise MeshError(
            f"{path!r} is not a mesh file ({', '.join(MESH_TYPES + STEP_TYPES)});"
            " export it as STL or STEP",
            field=field,
        )
    try:
        mesh = trimesh.load(io.BytesIO(data), file_type=kind, force="mesh")
    except Exception as exc:  # trimesh raises many types for broken files
        raise MeshError(f"cannot read mesh {path!r}: {type(exc).__name__}", field=field) from None
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
        raise MeshError(f"{path!r} holds no triangles; export it as STL, OBJ or PLY", field=field)
    if not np.all(np.isfinite(mesh.vertices)):
        raise MeshError(f"{path!r} has NaN or infinite vertex coordinates", field=field)
    mesh = mesh.copy()
    mesh.apply_scale(scale)
    return mesh
