"""Open CASCADE shapes to triangle meshes within a stated tolerance, and their exact properties.

Shapes are in mm (OCP's unit for what `workbench.cad.step` reads); OCP is imported lazily.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.errors import MeshError

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]

REMESH_TRIES = 4
"""How often a shape is meshed at most to reach its chordal tolerance (`tessellate`)."""

MAX_TRIANGLES = 4_000_000
"""Most triangles one STEP shape may tessellate into (some 300 MB once copied into numpy,
trimesh and the collision engines): a finer mesh is refused, with the count and the fix,
before it is copied out of Open CASCADE."""


@dataclass(frozen=True)
class StepProperties:
    """Exact properties of a shape from its B-rep (not its mesh): surface `area` [mm²],
    `volume` [mm³] (0 for a surface) and axis-aligned `bbox` (2, 3) [mm] rows min, max."""

    area: float
    volume: float
    bbox: NDArray[np.float64]


def faces_of(shape: Any) -> list[Any]:
    """Return the shape's faces (`TopoDS_Face`), each oriented as it lies in the shape."""
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    out = []
    explorer = TopExp_Explorer(shape, TopAbs_FACE)
    while explorer.More():
        out.append(TopoDS.Face(explorer.Current()))
        explorer.Next()
    return out


def _matrix(location: Any) -> NDArray[np.float64]:
    trsf = location.Transformation()
    m = np.eye(4)
    for r in range(3):
        for c in range(4):
            m[r, c] = trsf.Value(r + 1, c + 1)
    return m


def tessellate(shape: Any, linear_tolerance: float, angular_tolerance: float) -> trimesh.Trimesh:
    """Return the triangle mesh [mm] of the faces of `shape` (a ``TopoDS_Shape`` in mm).

    linear_tolerance: chordal deviation [mm], the largest distance from a triangle to the
    surface; angular_tolerance [rad] between neighbouring normals (Open CASCADE's
    ``BRepMesh_IncrementalMesh``). Every vertex lies on the exact surface. BRepMesh measures
    the deviation it reached on each face (``Poly_Triangulation.Deflection``) and may exceed
    the one asked for (twice it near a sphere's poles): the shape is then meshed again with a
    proportionally smaller one, up to `REMESH_TRIES` times, so the deviation reached is within
    the tolerance (``mesh.metadata["deflection_mm"]``). Each face's triangulation is placed by
    its location and flipped where the face is reversed, and the faces' shared edge nodes are
    welded, so a closed solid gives a watertight mesh with outward normals. The exact surface
    normals at the vertices, on the side the triangles face, are in
    ``mesh.vertex_attributes["surface_normals"]`` (V, 3) (a vertex on an edge between faces
    gets one face's; the polishing fit uses them); each triangle's face (its index in
    `faces_of`) in ``mesh.face_attributes["step_face"]``. MeshError when
    a face cannot be tessellated, the tolerance cannot be reached, or the mesh would exceed
    `MAX_TRIANGLES`.
    """
    from OCP.BRepTools import BRepTools

    if not (linear_tolerance > 0 and 0 < angular_tolerance < math.pi / 2):
        raise MeshError(
            f"tessellation tolerances must be > 0 mm and in (0, 90) deg, got {linear_tolerance!r}"
            f" mm and {math.degrees(angular_tolerance)!r} deg"
        )
    asked = linear_tolerance
    for _ in range(REMESH_TRIES):
        meshed, reached = _mesh_faces(shape, asked, angular_tolerance)
        if reached <= linear_tolerance:
            break
        BRepTools.Clean_s(shape)  # drop the triangulations: the next run meshes every face
        asked *= 0.9 * linear_tolerance / reached
    else:
        raise MeshError(
            f"the tessellation deviates {reached:.3g} mm from the surface, more than the"
            f" {linear_tolerance:g} mm asked for, after {REMESH_TRIES} tries; raise the linear"
            " tolerance (the project's 'cad' section) or repair the part's surfaces"
        )
    vertices, normals, triangles, face_ids, offset = [], [], [], [], 0
    for k, (face, reversed_, matrix, tri) in enumerate(meshed):  # every face, in faces_of order
        n = tri.NbNodes()
        pts = np.array([tri.Node(i).Coord() for i in range(1, n + 1)], dtype=float)
        if matrix is not None:
            pts = pts @ matrix[:3, :3].T + matrix[:3, 3]
        idx = np.array([tri.Triangle(i).Get() for i in range(1, tri.NbTriangles() + 1)]) - 1
        if reversed_:
            idx = idx[:, ::-1]
        vertices.append(pts)
        normals.append(_surface_normals(face, tri, matrix, pts, idx))
        triangles.append(idx + offset)
        face_ids.append(np.full(len(idx), k))
        offset += n
    mesh = _welded(
        np.concatenate(vertices),
        np.concatenate(normals),
        np.concatenate(triangles),
        1e-4 * linear_tolerance,
        np.concatenate(face_ids),
    )
    mesh.metadata["deflection_mm"] = reached
    return mesh


def _mesh_faces(shape: Any, linear: float, angular: float) -> tuple[list[Any], float]:
    """Return each face's (face, reversed?, location matrix or None, triangulation) after meshing
    `shape`, and the largest deviation [mm] BRepMesh reached on any face."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepMesh import BRepMesh_IncrementalMesh
    from OCP.TopAbs import TopAbs_REVERSED
    from OCP.TopLoc import TopLoc_Location

    try:
        BRepMesh_IncrementalMesh(shape, linear, False, angular, True)
    except Exception as exc:  # OCP raises Standard_Failure subclasses
        raise MeshError(f"the tessellation failed ({type(exc).__name__}: {exc})") from None
    faces = faces_of(shape)
    meshed, failed, total, reached = [], 0, 0, 0.0
    for face in faces:
        location = TopLoc_Location()
        tri = BRep_Tool.Triangulation_s(face, location)
        if tri is None or tri.NbTriangles() == 0:
            failed += 1
            continue
        matrix = None if location.IsIdentity() else _matrix(location)
        meshed.append((face, face.Orientation() == TopAbs_REVERSED, matrix, tri))
        total += tri.NbTriangles()
        reached = max(reached, tri.Deflection())
    if failed:
        raise MeshError(
            f"{failed} of {len(faces)} faces could not be tessellated (a broken face in the"
            " file); repair the model in its CAD system (sew and check it) and export it again"
        )
    if total > MAX_TRIANGLES:
        raise MeshError(
            f"the tessellation has {total:,} triangles, more than {MAX_TRIANGLES:,}; raise the"
            " linear and angular tolerances (the project's 'cad' section) or simplify the part"
        )
    return meshed, reached


def _surface_normals(
    face: Any, tri: Any, matrix: NDArray[np.float64] | None, points: F64, triangles: I64
) -> F64:
    """Return the exact unit normals (V, 3) of the face's surface at its triangulation's
    nodes, pointing to the side its triangles (`points`, `triangles`, as placed) face."""
    from OCP.BRepLib import BRepLib_ToolTriangulatedShape

    BRepLib_ToolTriangulatedShape.ComputeNormals_s(face, tri)
    n = np.array([tri.Normal(i).Coord() for i in range(1, tri.NbNodes() + 1)], dtype=float)
    if matrix is not None:
        n = n @ matrix[:3, :3].T
    t = points[triangles]
    area_normals = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    return -n if np.einsum("ij,ij->", n[triangles[:, 0]], area_normals) < 0 else n


def _welded(vertices: F64, normals: F64, faces: I64, tol: float, face_ids: I64) -> trimesh.Trimesh:
    """Return the mesh with vertices closer than `tol` merged and collapsed triangles dropped;
    the exact surface normals in ``vertex_attributes["surface_normals"]``, each triangle's
    B-rep face (its index in `faces_of`) in ``face_attributes["step_face"]``."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    n = len(vertices)
    pairs = cKDTree(vertices).query_pairs(tol, output_type="ndarray")
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    _, first = np.unique(label, return_index=True)  # a group's first vertex stands for it
    f = label[faces]
    keep = (f[:, 0] != f[:, 1]) & (f[:, 1] != f[:, 2]) & (f[:, 2] != f[:, 0])
    return trimesh.Trimesh(
        vertices[first],
        f[keep],
        vertex_attributes={"surface_normals": normals[first]},
        face_attributes={"step_face": face_ids[keep]},
        process=False,
    )


def step_properties(shape: Any) -> StepProperties:
    """Return the exact `StepProperties` of `shape` [mm] (Open CASCADE's GProp and BRepBndLib,
    from the surfaces and curves, not from any triangulation)."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    surface, solid = GProp_GProps(), GProp_GProps()
    BRepGProp.SurfaceProperties_s(shape, surface)
    BRepGProp.VolumeProperties_s(shape, solid)
    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape, box, False, False)
    lo, hi = box.CornerMin(), box.CornerMax()
    bbox = np.array([[lo.X(), lo.Y(), lo.Z()], [hi.X(), hi.Y(), hi.Z()]])
    return StepProperties(area=surface.Mass(), volume=abs(solid.Mass()), bbox=bbox)
