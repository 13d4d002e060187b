"""Polishing picked faces of a STEP solid: the faces' triangles are the surface the path
covers; the whole solid is an obstacle for the robot, and for the tool all of it but the
picked faces and a contact band beside them.

The tool presses into the polished faces (the contact's offset D = F/k) and, at their edges,
into the neighbouring faces by as much: triangles of the other faces within `contact_band`
of the picked faces are a contact zone the tool may touch (they are split first to edges no
longer than the band, so the zone reaches at most twice the band from the picked faces).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.cad.step import StepTolerance, is_step
from workbench.cad.step_faces import StepFace, faces_submesh, read_step_faces
from workbench.collision.shapes import Solid
from workbench.errors import InputError, MeshError
from workbench.polishing.workpiece import WorkpieceReport, check_file, scaled_workpiece

F64 = NDArray[np.float64]
MM = 1e-3

#: Names of the obstacle bodies a solid workpiece adds to the cell.
SOLID_BODY = "workpiece"
AWAY_BODY = "workpiece away from the polished faces"

#: Added to the contact offset F/k to make the contact band beside the polished faces [m]
#: (the tessellation's deviation, 0.05 mm by default, and the tool's seating).
CONTACT_MARGIN = 1e-3

#: Most triangles the contact zone's split may make (a band far smaller than the part).
MAX_SPLIT_TRIANGLES = 400_000


@dataclass(frozen=True)
class SolidWorkpiece:
    """A STEP solid with picked faces: every face of the file (`faces`), the `picked` indices,
    and the whole solid's mesh in the world frame [m] (`mesh`, its triangles' face indices in
    ``face_attributes["step_face"]``)."""

    faces: tuple[StepFace, ...]
    picked: tuple[int, ...]
    mesh: trimesh.Trimesh


def check_picked(picked: Sequence[int], faces: Sequence[StepFace], shown: str) -> None:
    """InputError naming `faces` for an index outside the file's faces."""
    n = len(faces)
    bad = [i for i in picked if not 0 <= i < n]
    if bad:
        raise InputError(
            f"face {bad[0]} is not a face of {shown!r}: it has {n} faces, indices 0 to {n - 1};"
            " pick from the list of its faces (`workbench polishing-faces`, the Polishing tab)",
            field="faces",
        )


def load_solid_workpiece(
    path: str | Path,
    picked: Sequence[int],
    T_world_workpiece: F64,
    tolerance: StepTolerance | None = None,
    name: str | None = None,
) -> tuple[trimesh.Trimesh, WorkpieceReport, SolidWorkpiece]:
    """Return the picked faces' mesh in metres (as `load_workpiece` returns a surface, not yet
    placed), its report, and the `SolidWorkpiece` placed at `T_world_workpiece` (4, 4) [m].

    MeshError naming `faces` for a file that is not STEP; `check_picked`'s InputError."""
    p = Path(path)
    shown = str(p) if name is None else name
    if not is_step(p):
        raise MeshError(
            f"faces picks faces of a STEP solid, but the workpiece {shown!r} is a mesh file;"
            " remove polishing.faces (the whole mesh is polished) or give a STEP file",
            field="faces",
        )
    check_file(p, shown)
    read = read_step_faces(p.read_bytes(), shown, "workpiece", tolerance or StepTolerance())
    check_picked(picked, read.faces, shown)
    mesh, report = scaled_workpiece(faces_submesh(read.mesh, picked), "mm", str(p), shown)
    whole = read.mesh.copy()
    whole.vertices = np.asarray(read.mesh.vertices) * MM
    whole.apply_transform(np.asarray(T_world_workpiece, float))
    return mesh, report, SolidWorkpiece(read.faces, tuple(picked), whole)


def contact_zone(solid: SolidWorkpiece, band: float) -> tuple[trimesh.Trimesh, trimesh.Trimesh]:
    """Return (the other faces' triangles within `band` [m] of the picked faces, those beyond),
    world frame [m]. Triangles touching the band are first split to edges <= `band`."""
    ids = np.asarray(solid.mesh.face_attributes["step_face"])
    picked_mask = np.isin(ids, solid.picked)
    verts = np.asarray(solid.mesh.vertices)
    tris = np.asarray(solid.mesh.faces)
    polished = trimesh.Trimesh(verts, tris[picked_mask], process=False)
    other = tris[~picked_mask]

    def near(points: F64) -> NDArray[np.bool_]:
        _, dist, _ = trimesh.proximity.closest_point(polished, points)
        return np.asarray(dist) <= band

    reach = np.linalg.norm(verts[other] - verts[other][:, [1, 2, 0]], axis=2).max(axis=1)
    centre = verts[other].mean(axis=1)
    # A triangle can come within `band` only if its centre is within band + its longest edge.
    _, d_centre, _ = trimesh.proximity.closest_point(polished, centre)
    maybe = np.asarray(d_centre) <= band + reach
    try:
        v, f = trimesh.remesh.subdivide_to_size(verts, other[maybe], max_edge=band, max_iter=12)
    except ValueError:  # more than max_iter halvings: the band is far below the part's size
        f = np.zeros((MAX_SPLIT_TRIANGLES + 1, 3), int)
    if len(f) > MAX_SPLIT_TRIANGLES:
        raise InputError(
            f"the contact band of {band / MM:g} mm splits the faces beside the polished ones into"
            f" {len(f):,} triangles (more than {MAX_SPLIT_TRIANGLES:,}); raise the force or lower"
            " the contact stiffness (a deeper offset), or pick fewer faces",
            field="faces",
        )
    in_zone = near(v).reshape(-1)[f].any(axis=1) if len(f) else np.zeros(0, bool)
    zone = trimesh.Trimesh(v, f[in_zone], process=False)
    away: trimesh.Trimesh = trimesh.util.concatenate(  # type: ignore[assignment]
        [
            trimesh.Trimesh(verts, other[~maybe], process=False),
            trimesh.Trimesh(v, f[~in_zone], process=False),
        ]
    )
    return zone, away


def obstacle_bodies(
    solid: SolidWorkpiece, band: float
) -> tuple[list[tuple[Solid, F64]], list[tuple[str, str]]]:
    """Return the bodies a solid workpiece adds to the cell (world poses) and the pairs the
    robot checker ignores: the whole solid (`SOLID_BODY`) for every link, not the tool; the
    solid beyond the picked faces' contact band (`AWAY_BODY`) for the tool only."""
    _, away = contact_zone(solid, band)
    bodies = [(Solid(SOLID_BODY, "mesh", mesh=solid.mesh), np.eye(4))]
    ignore = [("tool", SOLID_BODY)]
    if len(away.faces):
        bodies.append((Solid(AWAY_BODY, "mesh", mesh=away), np.eye(4)))
    return bodies, ignore
