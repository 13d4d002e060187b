"""Reading STEP files (ISO 10303-21, AP203/AP214/AP242) into Open CASCADE shapes through OCP.

Open CASCADE converts the file's length unit to millimetres on reading (``xstep.cascade.unit``
is MM), so every shape returned here is in mm; callers scale to metres. OCP is imported lazily:
a project without STEP files never loads it.

The entry points, `read_step_mesh` (every mesh route: cell objects, tools, links, assembly
parts, the polishing workpiece) and `read_step_sheet` (a sheet-metal part's faces), read the
file in a CAD worker process with a time and memory limit (`workbench.cad.isolation`) and
bound it before and after the reader (`workbench.cad.step_checks`); `read_step_shape` is the
reader itself, for the worker and for files this program wrote.
"""

from __future__ import annotations

import math
import os
import tempfile
from dataclasses import dataclass
from typing import Any

import numpy as np
import trimesh

from workbench.cad import brep_mesh, step_checks
from workbench.cad.brep_mesh import StepProperties, faces_of, step_properties, tessellate
from workbench.cad.isolation import run_isolated
from workbench.cad.sheet_brep import SheetBrep, read_sheet_brep
from workbench.errors import MeshError

__all__ = [
    "STEP_SUFFIXES",
    "StepProperties",
    "StepTolerance",
    "faces_of",
    "is_step",
    "read_step_mesh",
    "read_step_shape",
    "read_step_sheet",
    "step_properties",
    "tessellate",
    "write_step",
]

STEP_SUFFIXES = (".step", ".stp")
"""File name endings read as STEP."""


def is_step(path: str | os.PathLike[str] | None) -> bool:
    """Return whether `path` names a STEP file (.step or .stp, any case)."""
    return path is not None and os.fspath(path).lower().endswith(STEP_SUFFIXES)


MM_PER_M = 1000.0  # OCP's shapes are in mm; tolerances arrive in m
DEFAULT_LINEAR_MM = 0.05
"""The default chordal deviation of a tessellation [mm] (the project's `cad.linear_tolerance`)."""
DEFAULT_ANGULAR_DEG = 5.0
"""The default angle between neighbouring normals [deg] (the project's `cad.angular_tolerance`)."""


def _quiet() -> None:
    """Silence OCP's transfer statistics (printed on stdout through the default printer)."""
    from OCP.Message import Message, Message_Gravity

    for printer in Message.DefaultMessenger_s().Printers():
        printer.SetTraceLevel(Message_Gravity.Message_Fail)


def read_step_shape(data: bytes, name: str, field: str | None) -> Any:
    """Return the OCP ``TopoDS_Shape`` [mm] of the STEP file `data` (named `name` in errors),
    in this process: for the CAD worker and for files this program wrote.

    MeshError names `field` when the bytes are not a STEP file, are too large or too deeply
    nested (`step_checks.check_text`), load with failures (`step_checks.check_load`: broken
    references), hold no shape, or OCP fails.
    """
    if not data.lstrip()[:32].upper().startswith(b"ISO-10303-21"):
        raise MeshError(
            f"{name!r} is not a STEP file (it does not start with 'ISO-10303-21;');"
            " export the part as STEP AP214 or AP242",
            field=field,
        )
    step_checks.check_text(data, name, field)
    try:  # OCP's libraries link libGL and libX11 (Debian: libgl1), even without a display
        from OCP.IFSelect import IFSelect_RetDone
        from OCP.Interface import Interface_Static
        from OCP.STEPControl import STEPControl_Reader
    except (ImportError, OSError) as exc:
        raise MeshError(
            f"cannot read STEP file {name!r}: Open CASCADE (OCP) does not load here"
            f" ({exc}); install the package 'cadquery-ocp-novtk' and the system library"
            " libGL (Debian: apt-get install libgl1)",
            field=field,
        ) from None

    _quiet()
    Interface_Static.SetCVal_s("xstep.cascade.unit", "MM")
    fd, tmp = tempfile.mkstemp(suffix=".step")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        reader = STEPControl_Reader()
        status = reader.ReadFile(tmp)
        if status != IFSelect_RetDone:
            raise MeshError(
                f"cannot read STEP file {name!r} ({status.name}); check that it is a"
                " complete STEP export",
                field=field,
            )
        step_checks.check_load(reader, data, name, field)
        if reader.TransferRoots() == 0:
            raise MeshError(f"STEP file {name!r} holds no shape to transfer", field=field)
        shape = reader.OneShape()
    except MeshError:
        raise
    except Exception as exc:  # OCP raises Standard_Failure subclasses on broken files
        raise MeshError(
            f"cannot read STEP file {name!r}: {type(exc).__name__}", field=field
        ) from None
    finally:
        os.unlink(tmp)
    if shape.IsNull():
        raise MeshError(f"STEP file {name!r} holds no shape", field=field)
    return shape


@dataclass(frozen=True)
class StepTolerance:
    """How finely a STEP shape is tessellated: chordal deviation `linear` [m] (the largest
    distance between a triangle and the exact surface) and `angular` [rad] (the largest angle
    between the normals of neighbouring triangles on one face)."""

    linear: float = DEFAULT_LINEAR_MM / MM_PER_M
    angular: float = math.radians(DEFAULT_ANGULAR_DEG)


def read_step_mesh(
    data: bytes, name: str, field: str | None, tolerance: StepTolerance
) -> trimesh.Trimesh:
    """Return the tessellated STEP file `data` [mm] (its own length unit converted to mm),
    read in a CAD worker (`workbench.cad.isolation`).

    MeshError naming `field` for a file that is not STEP, unreadable, too large or nested too
    deep, loads with failures, reaches beyond the cell, holds no face (only curves or points),
    would mesh into too many triangles, does not tessellate (`tessellate`), holds a solid whose
    mesh is open or inside out, or crashes, hangs or swells its reader.
    """
    linear = tolerance.linear * MM_PER_M
    arrays = run_isolated(
        "workbench.cad.step:mesh_arrays",
        (data, name, field, linear, tolerance.angular),
        name=name,
        field=field,
        fix=f", raise the tolerances ({linear:g} mm, the project's 'cad' section)",
    )
    return mesh_from_arrays(arrays)


def mesh_from_arrays(arrays: dict[str, Any]) -> trimesh.Trimesh:
    """Return the mesh `mesh_arrays` sent back from the worker (each triangle's B-rep face index
    in ``face_attributes["step_face"]``)."""
    mesh = trimesh.Trimesh(
        arrays["vertices"],
        arrays["faces"],
        vertex_attributes={"surface_normals": arrays["surface_normals"]},
        face_attributes={"step_face": arrays["step_face"]},
        process=False,
    )
    mesh.metadata["deflection_mm"] = arrays["deflection_mm"]
    return mesh


def read_step_sheet(data: bytes, name: str, field: str) -> SheetBrep:
    """Return the faces of the STEP file `data` as a `SheetBrep` [m] (`read_sheet_brep`), read
    in a CAD worker; MeshError naming `field` as `read_step_mesh` says (but for meshing)."""
    brep: SheetBrep = run_isolated(
        "workbench.cad.step:sheet_brep", (data, name, field), name=name, field=field
    )
    return brep


def checked_shape(data: bytes, name: str, field: str | None) -> Any:
    """In the CAD worker: the shape of STEP file `data`, refused when it holds no face or
    reaches beyond the cell (MeshError naming `field`)."""
    shape = read_step_shape(data, name, field)
    if not faces_of(shape):
        raise MeshError(
            f"STEP file {name!r} holds no surfaces or solids (only curves or points);"
            " export the part's solid body (or its faces) as STEP",
            field=field,
        )
    step_checks.check_extent(_bbox(shape), name, field)
    return shape


def _bbox(shape: Any) -> Any:
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    box = Bnd_Box()
    BRepBndLib.Add_s(shape, box, False)
    if box.IsVoid():
        return [[0.0] * 3] * 2
    lo, hi = box.CornerMin(), box.CornerMax()
    return [[lo.X(), lo.Y(), lo.Z()], [hi.X(), hi.Y(), hi.Z()]]


def mesh_arrays(
    data: bytes, name: str, field: str, linear: float, angular: float
) -> dict[str, Any]:
    """In the CAD worker: the mesh of STEP file `data` within `linear` [mm] and `angular`
    [rad] as plain arrays (vertices, faces, surface_normals, deflection_mm) [mm].

    The triangles are estimated before meshing (`step_checks.estimate_triangles`) and a file
    whose estimate exceeds `brep_mesh.MAX_TRIANGLES` is refused; each solid's mesh must be
    closed and point outwards (`step_checks.check_closed`), and so must the whole mesh of a file
    that declares a solid but gives none (its shell does not close)."""
    return shape_arrays(checked_shape(data, name, field), data, name, field, linear, angular)


def shape_arrays(
    shape: Any, data: bytes, name: str, field: str, linear: float, angular: float
) -> dict[str, Any]:
    """In the CAD worker: `mesh_arrays` of the shape already read from STEP file `data`."""
    from OCP.TopAbs import TopAbs_SOLID
    from OCP.TopExp import TopExp_Explorer

    estimate = step_checks.estimate_triangles(shape, linear, angular)
    max_triangles = brep_mesh.MAX_TRIANGLES
    if estimate > max_triangles:
        raise MeshError(
            f"STEP file {name!r} would mesh into some {estimate:,} triangles at {linear:g} mm,"
            f" more than {max_triangles:,} (workbench.cad.brep_mesh.MAX_TRIANGLES); raise the"
            " linear and angular tolerances (the project's 'cad' section) or simplify the part",
            field=field,
        )
    try:
        mesh = tessellate(shape, linear, angular)
    except MeshError as exc:
        raise MeshError(f"STEP file {name!r}: {exc}", field=field) from None
    solids = []
    explorer = TopExp_Explorer(shape, TopAbs_SOLID)
    while explorer.More():
        solids.append(explorer.Current())
        explorer.Next()
    if len(solids) == 1 and len(faces_of(solids[0])) == len(faces_of(shape)):
        step_checks.check_closed([mesh], name, field)
    elif not solids and step_checks.declares_solid(data):
        step_checks.check_closed([mesh], name, field)  # the file's solid did not come out
    elif solids:
        meshes = [tessellate(s, linear, angular) for s in solids]
        step_checks.check_closed(meshes, name, field)
    return {
        "vertices": np.asarray(mesh.vertices, dtype=float),
        "faces": np.asarray(mesh.faces, dtype=np.int64),
        "surface_normals": np.asarray(mesh.vertex_attributes["surface_normals"], dtype=float),
        "deflection_mm": float(mesh.metadata["deflection_mm"]),
        "step_face": np.asarray(mesh.face_attributes["step_face"], dtype=np.int64),
    }


def sheet_brep(data: bytes, name: str, field: str) -> SheetBrep:
    """In the CAD worker: the `SheetBrep` [m] of STEP file `data`."""
    return read_sheet_brep(checked_shape(data, name, field), field)


def write_step(shape: Any, name: str) -> bytes:
    """Return `shape` [mm] as the bytes of an AP214 STEP file in mm, with `name` and a fixed
    time stamp in its header: the same shape gives the same bytes (the example generators)."""
    from OCP.APIHeaderSection import APIHeaderSection_MakeHeader
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.Interface import Interface_Static
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer
    from OCP.TCollection import TCollection_HAsciiString

    _quiet()
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    writer = STEPControl_Writer()
    writer.Transfer(shape, STEPControl_AsIs)
    header = APIHeaderSection_MakeHeader(writer.Model())
    header.SetName(TCollection_HAsciiString(name))
    header.SetTimeStamp(TCollection_HAsciiString("2026-01-01T00:00:00"))
    fd, tmp = tempfile.mkstemp(suffix=".step")
    os.close(fd)
    try:
        if writer.Write(tmp) != IFSelect_RetDone:
            raise MeshError(f"cannot write STEP file {name!r}")
        with open(tmp, "rb") as fh:
            return fh.read()
    finally:
        os.unlink(tmp)
