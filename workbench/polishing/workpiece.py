"""Workpiece import: load a mesh or STEP file, settle its units, and report its defects.

A STEP file (.step, .stp) is tessellated by `workbench.cad.step` with the given tolerances;
it carries its own length unit and is read in mm, so its units are "mm" ("auto" reads it so,
"m" is refused).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from workbench.cad.step import StepTolerance, is_step, read_step_mesh
from workbench.errors import InputError, MeshError
from workbench.polishing.choices import MESH_UNITS, MeshUnits

#: A part whose bounding-box diagonal, read in metres, lies outside this range is taken to be
#: in the wrong units (1000x too large or too small).
MIN_DIAGONAL_M = 2e-3
MAX_DIAGONAL_M = 20.0
#: The mesh files read as a workpiece (besides STEP): trimesh would read more (a DXF as a 2D
#: path, in this process and unbounded), so any other ending is refused by name.
MESH_SUFFIXES = (".stl", ".obj", ".ply", ".off", ".glb", ".gltf")


@dataclass(frozen=True)
class WorkpieceReport:
    """What `load_workpiece` found in a file. Lengths in m, after the unit scale."""

    path: str
    units: str  # the units the file was read in: "mm" or "m"
    scale: float  # factor applied to the file's coordinates to get metres
    n_vertices: int
    n_faces: int
    bbox_diagonal: float  # [m]
    n_degenerate_faces: int  # faces with (near) zero area, removed from the returned mesh
    n_nonmanifold_edges: int  # edges shared by more than two faces
    n_boundary_edges: int  # edges used by one face only
    n_boundary_loops: int  # connected chains of boundary edges
    n_holes: int  # boundary loops besides the outer rim of an open surface
    is_watertight: bool
    warnings: tuple[str, ...]


def check_file(path: Path, name: str) -> None:
    """MeshError when the workpiece file `path` (named `name`) is missing or empty."""
    if not path.is_file():
        raise MeshError(
            f"workpiece file {name!r} does not exist; give the path of an STL, OBJ or PLY file"
        )
    if path.stat().st_size == 0:
        raise MeshError(
            f"workpiece file {name!r} is empty; give an STL, OBJ or PLY file with triangles"
        )


def _read(path: Path, tolerance: StepTolerance, name: str) -> trimesh.Trimesh:
    check_file(path, name)
    if is_step(path):
        return read_step_mesh(path.read_bytes(), name, None, tolerance)  # the caller's field
    suffix = path.suffix.lower()
    if suffix not in MESH_SUFFIXES:
        raise MeshError(
            f"workpiece file {name!r} is not a mesh file ({', '.join(MESH_SUFFIXES)}, .step,"
            " .stp); give an STL, OBJ or PLY file, or a STEP file"
        )
    try:
        loaded = trimesh.load(str(path), file_type=suffix[1:], force="mesh", process=True)
    except Exception as exc:  # trimesh raises many types for unreadable files
        said = str(exc)  # trimesh's words may give the path it read: name it as `name` does
        if name != str(path):
            said = said.replace(repr(str(path)), repr(name)).replace(str(path), repr(name))
        raise MeshError(
            f"workpiece file {name!r} is not a readable mesh ({type(exc).__name__}: {said}); "
            "give an STL, OBJ or PLY file with triangles"
        ) from exc
    if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0:
        raise MeshError(
            f"workpiece file {name!r} contains no triangles; give an STL, OBJ or PLY file with triangles"
        )
    return loaded


def _diagonal(vertices: np.ndarray) -> float:
    return float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))


def _choose_scale(raw_diag: float, units: str, path: str) -> tuple[str, float, list[str]]:
    warnings: list[str] = []
    if units not in MESH_UNITS:
        raise InputError(f"units must be 'auto', 'mm' or 'm', got {units!r}")
    if units == "auto":
        # Read in metres unless that makes the part larger than MAX_DIAGONAL_M: then it is in mm.
        chosen = "mm" if raw_diag > MAX_DIAGONAL_M else "m"
        if chosen == "m" and raw_diag > 2.0:
            warnings.append(
                f"bounding-box diagonal {raw_diag:g} is ambiguous (a {raw_diag:g} m part or a "
                f"{raw_diag:g} mm part); read as metres, pass units='mm' if the file is in mm"
            )
    else:
        chosen = units
    scale = 1e-3 if chosen == "mm" else 1.0
    diag = raw_diag * scale
    if not MIN_DIAGONAL_M <= diag <= MAX_DIAGONAL_M:
        other = "m" if chosen == "mm" else "mm"
        raise MeshError(
            f"workpiece {path!r} read with units={chosen!r} has a bounding-box diagonal of {diag:g} m, "
            f"outside the plausible range [{MIN_DIAGONAL_M:g}, {MAX_DIAGONAL_M:g}] m: the units look "
            f"1000x off; pass units={other!r} (or fix the file)",
            field="units",
        )
    return chosen, scale, warnings


def _edge_topology(faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return unique sorted edges (E,2) and the number of faces using each (E,)."""
    edges = faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    n = int(faces.max()) + 1
    keys, counts = np.unique(edges.min(axis=1) * n + edges.max(axis=1), return_counts=True)
    return np.stack([keys // n, keys % n], axis=1), counts


def _count_loops(boundary_edges: np.ndarray, n_vertices: int) -> tuple[int, np.ndarray]:
    """Return the number of connected boundary chains and each chain's edge count."""
    if len(boundary_edges) == 0:
        return 0, np.zeros(0, dtype=int)
    a, b = boundary_edges[:, 0], boundary_edges[:, 1]
    graph = coo_matrix((np.ones(len(a)), (a, b)), shape=(n_vertices, n_vertices))
    _, labels = connected_components(graph, directed=False)
    edge_label = labels[a]
    used, per_loop = np.unique(edge_label, return_counts=True)
    return len(used), per_loop


def inspect_mesh(
    mesh: trimesh.Trimesh,
    *,
    path: str = "<mesh>",
    units: str = "m",
    scale: float = 1.0,
    warnings: tuple[str, ...] = (),
) -> tuple[trimesh.Trimesh, WorkpieceReport]:
    """Return a cleaned copy of `mesh` (lengths in m, degenerate faces removed) and its report."""
    vertices = np.asarray(mesh.vertices, dtype=float)
    faces = np.asarray(mesh.faces, dtype=np.int64)
    diag = _diagonal(vertices)
    tri = vertices[faces]
    area2 = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    # Degenerate: doubled area below (1e-6 of the diagonal)^2, or a repeated vertex index.
    repeated = (
        (faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) | (faces[:, 0] == faces[:, 2])
    )
    degenerate = repeated | (area2 <= (1e-6 * diag) ** 2)
    good = faces[~degenerate]
    if len(good) == 0:
        raise MeshError(f"workpiece {path!r} has only degenerate (zero-area) faces")
    uniq, counts = _edge_topology(good)
    boundary = uniq[counts == 1]
    n_loops, per_loop = _count_loops(boundary, len(vertices))
    n_holes = max(n_loops - 1, 0)
    found = list(warnings)
    if degenerate.any():
        found.append(f"{int(degenerate.sum())} degenerate faces removed")
    if (counts > 2).any():
        found.append(
            f"{int((counts > 2).sum())} non-manifold edges (shared by more than two faces)"
        )
    if n_holes:
        found.append(f"{n_holes} holes (boundary loops besides the outer rim)")
    # vertex_attributes: a STEP file's exact surface normals, masked with the vertices
    attributes = dict(mesh.vertex_attributes)
    cleaned = trimesh.Trimesh(
        vertices=vertices, faces=good, vertex_attributes=attributes, process=False
    )
    cleaned.remove_unreferenced_vertices()
    report = WorkpieceReport(
        path=path,
        units=units,
        scale=scale,
        n_vertices=len(cleaned.vertices),
        n_faces=len(cleaned.faces),
        bbox_diagonal=diag,
        n_degenerate_faces=int(degenerate.sum()),
        n_nonmanifold_edges=int((counts > 2).sum()),
        n_boundary_edges=int(len(boundary)),
        n_boundary_loops=n_loops,
        n_holes=n_holes,
        is_watertight=bool(len(boundary) == 0 and not (counts > 2).any()),
        warnings=tuple(found),
    )
    return cleaned, report


def load_workpiece(
    path: str | Path,
    *,
    units: MeshUnits = "auto",
    tolerance: StepTolerance | None = None,
    name: str | None = None,
) -> tuple[trimesh.Trimesh, WorkpieceReport]:
    """Return the workpiece mesh in metres (degenerate faces removed) and a `WorkpieceReport`.

    path: an STL, OBJ or PLY file, or a STEP file tessellated with `tolerance` (None: the
    defaults). units: "mm", "m", or "auto" (metres unless the part would then be larger than
    20 m, in which case millimetres; a STEP file: mm). Raises `MeshError` for a missing,
    empty or non-mesh file, a STEP file read in "m", and a part whose size in the chosen
    units is implausible (bounding-box diagonal outside [2 mm, 20 m]); `InputError` for an
    unknown `units`. Vertex normals of the result (``mesh.vertex_normals``) follow the face
    winding. Messages name the file `name` (default: `path`); errors about the units name
    the field ``units``.
    """
    p = Path(path)
    shown = str(p) if name is None else name
    if units not in MESH_UNITS:
        raise InputError(f"units must be 'auto', 'mm' or 'm', got {units!r}")
    if is_step(p):
        if units == "m":
            raise MeshError(
                f"workpiece {shown!r} is a STEP file: it carries its own length unit and is read"
                " in mm, so units='m' would make it 1000x too large; pass units='mm' or 'auto'",
                field="units",
            )
        units = "mm"
    return scaled_workpiece(_read(p, tolerance or StepTolerance(), shown), units, str(p), shown)


def scaled_workpiece(
    raw: trimesh.Trimesh, units: MeshUnits, path: str, shown: str
) -> tuple[trimesh.Trimesh, WorkpieceReport]:
    """Return `raw` (in the file's `units`) in metres, cleaned and reported (`load_workpiece`'s
    second half; `shown` names the file in errors)."""
    raw_diag = _diagonal(np.asarray(raw.vertices))
    chosen, scale, warnings = _choose_scale(raw_diag, units, shown)
    scaled = trimesh.Trimesh(
        vertices=np.asarray(raw.vertices) * scale,
        faces=raw.faces,
        vertex_attributes=dict(raw.vertex_attributes),
        process=False,
    )
    return inspect_mesh(scaled, path=path, units=chosen, scale=scale, warnings=tuple(warnings))
