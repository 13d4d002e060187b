"""The faces of a STEP solid as a list a user picks from: index, surface type, exact area,
centroid and (planar faces) normal, with the solid's mesh telling each triangle's face.

Indices are the faces' order in `faces_of` (Open CASCADE's ``TopExp_Explorer`` over the
shape read from the file): the same file gives the same indices on every load. Lengths in mm.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.cad.brep_mesh import faces_of
from workbench.cad.isolation import run_isolated
from workbench.cad.step import (
    MM_PER_M,
    StepTolerance,
    checked_shape,
    mesh_from_arrays,
    shape_arrays,
)

F64 = NDArray[np.float64]

#: Open CASCADE's surface types (``GeomAbs_SurfaceType``) by the names the list shows.
SURFACE_TYPES = {
    "GeomAbs_Plane": "plane",
    "GeomAbs_Cylinder": "cylinder",
    "GeomAbs_Cone": "cone",
    "GeomAbs_Sphere": "sphere",
    "GeomAbs_Torus": "torus",
    "GeomAbs_BezierSurface": "bezier",
    "GeomAbs_BSplineSurface": "bspline",
    "GeomAbs_SurfaceOfRevolution": "revolution",
    "GeomAbs_SurfaceOfExtrusion": "extrusion",
    "GeomAbs_OffsetSurface": "offset",
    "GeomAbs_OtherSurface": "other",
}


@dataclass(frozen=True)
class StepFace:
    """One face of a STEP shape: its `index` (stable for the file), surface `kind` ("plane",
    "cylinder", "bspline", ...), exact `area` [mm²] and `centroid` (3,) [mm] (Open CASCADE's
    GProp), and the outward unit `normal` (3,) of a planar face (None on a curved one)."""

    index: int
    kind: str
    area: float
    centroid: tuple[float, float, float]
    normal: tuple[float, float, float] | None

    def label(self) -> str:
        """Return the face as the list shows it: "3: plane, 1200 mm² at (…)"."""
        c = ", ".join(f"{round(x, 1) + 0.0:.1f}" for x in self.centroid)  # no "-0.0"
        return f"{self.index}: {self.kind}, {self.area:.1f} mm² at ({c}) mm"


@dataclass(frozen=True)
class StepFaces:
    """A STEP file's faces (`faces`, by index) and its mesh [mm] whose triangles carry their
    face's index in ``mesh.face_attributes["step_face"]``."""

    faces: tuple[StepFace, ...]
    mesh: trimesh.Trimesh


def face_table(shape: Any) -> tuple[StepFace, ...]:
    """Return the `StepFace` of every face of `shape` [mm], in `faces_of` order."""
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.BRepGProp import BRepGProp
    from OCP.GeomAbs import GeomAbs_Plane
    from OCP.GProp import GProp_GProps
    from OCP.TopAbs import TopAbs_REVERSED

    out = []
    for i, face in enumerate(faces_of(shape)):
        props = GProp_GProps()
        BRepGProp.SurfaceProperties_s(face, props)
        c = props.CentreOfMass()
        surface = BRepAdaptor_Surface(face)
        kind = surface.GetType()
        normal = None
        if kind == GeomAbs_Plane:
            d = surface.Plane().Axis().Direction()
            sign = -1.0 if face.Orientation() == TopAbs_REVERSED else 1.0
            normal = (sign * d.X() + 0.0, sign * d.Y() + 0.0, sign * d.Z() + 0.0)  # no -0.0
        out.append(
            StepFace(
                index=i,
                kind=SURFACE_TYPES.get(kind.name, kind.name),
                area=float(props.Mass()),
                centroid=(c.X(), c.Y(), c.Z()),
                normal=normal,
            )
        )
    return tuple(out)


def read_step_faces(data: bytes, name: str, field: str, tolerance: StepTolerance) -> StepFaces:
    """Return the `StepFaces` of the STEP file `data` (named `name`; MeshError naming `field`
    as `read_step_mesh` raises it), tessellated with `tolerance`, read in a CAD worker
    (`workbench.cad.isolation`) as `read_step_mesh` is."""
    linear = tolerance.linear * MM_PER_M
    table, arrays = run_isolated(
        "workbench.cad.step_faces:faces_arrays",
        (data, name, field, linear, tolerance.angular),
        name=name,
        field=field,
        fix=f", raise the tolerances ({linear:g} mm, the project's 'cad' section)",
    )
    return StepFaces(tuple(table), mesh_from_arrays(arrays))


def faces_arrays(
    data: bytes, name: str, field: str, linear: float, angular: float
) -> tuple[tuple[StepFace, ...], dict[str, Any]]:
    """In the CAD worker: the face table and the mesh arrays (`step.mesh_arrays`) of `data`."""
    shape = checked_shape(data, name, field)
    return face_table(shape), shape_arrays(shape, data, name, field, linear, angular)


def faces_submesh(mesh: trimesh.Trimesh, picked: Sequence[int]) -> trimesh.Trimesh:
    """Return the triangles of `mesh` whose ``step_face`` is in `picked`, with their vertices
    (and ``surface_normals``) only."""
    keep = np.isin(np.asarray(mesh.face_attributes["step_face"]), np.asarray(picked, int))
    faces = np.asarray(mesh.faces)[keep]
    used, inverse = np.unique(faces, return_inverse=True)
    attrs = {k: np.asarray(v)[used] for k, v in mesh.vertex_attributes.items()}
    return trimesh.Trimesh(
        np.asarray(mesh.vertices)[used],
        inverse.reshape(-1, 3),
        vertex_attributes=attrs,
        face_attributes={"step_face": np.asarray(mesh.face_attributes["step_face"])[keep]},
        process=False,
    )


__all__ = ["StepFace", "StepFaces", "face_table", "faces_submesh", "read_step_faces"]
