"""Reading STEP files (ISO 10303-21, AP203/AP214/AP242) into Open CASCADE shapes through OCP.

Open CASCADE converts the file's length unit to millimetres on reading (``xstep.cascade.unit``
is MM), so every shape returned here is in mm; callers scale to metres. OCP is imported lazily:
a project without STEP files never loads it.
"""

from __future__ import annotations

import math
import os
import tempfile
from dataclasses import dataclass
from typing import Any

import trimesh

from workbench.cad.brep_mesh import StepProperties, faces_of, step_properties, tessellate
from workbench.errors import MeshError

__all__ = [
    "STEP_SUFFIXES",
    "StepProperties",
    "StepTolerance",
    "faces_of",
    "is_step",
    "mesh_step_shape",
    "read_step_mesh",
    "read_step_shape",
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


def read_step_shape(data: bytes, name: str, field: str) -> Any:
    """Return the OCP ``TopoDS_Shape`` [mm] of the STEP file `data` (named `name` in errors).

    MeshError names `field` when the bytes are not a STEP file, hold no shape, or OCP fails.
    """
    if not data.lstrip()[:32].upper().startswith(b"ISO-10303-21"):
        raise MeshError(
            f"{field}: {name!r} is not a STEP file (it does not start with 'ISO-10303-21;');"
            " export the part as STEP AP214 or AP242"
        )
    try:  # OCP's libraries link libGL and libX11 (Debian: libgl1), even without a display
        from OCP.IFSelect import IFSelect_RetDone
        from OCP.Interface import Interface_Static
        from OCP.STEPControl import STEPControl_Reader
    except (ImportError, OSError) as exc:
        raise MeshError(
            f"{field}: cannot read STEP file {name!r}: Open CASCADE (OCP) does not load here"
            f" ({exc}); install the package 'cadquery-ocp-novtk' and the system library"
            " libGL (Debian: apt-get install libgl1)"
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
                f"{field}: cannot read STEP file {name!r} ({status.name}); check that it is a"
                " complete STEP export"
            )
        if reader.TransferRoots() == 0:
            raise MeshError(f"{field}: STEP file {name!r} holds no shape to transfer")
        shape = reader.OneShape()
    except MeshError:
        raise
    except Exception as exc:  # OCP raises Standard_Failure subclasses on broken files
        raise MeshError(f"{field}: cannot read STEP file {name!r}: {type(exc).__name__}") from None
    finally:
        os.unlink(tmp)
    if shape.IsNull():
        raise MeshError(f"{field}: STEP file {name!r} holds no shape")
    return shape


@dataclass(frozen=True)
class StepTolerance:
    """How finely a STEP shape is tessellated: chordal deviation `linear` [m] (the largest
    distance between a triangle and the exact surface) and `angular` [rad] (the largest angle
    between the normals of neighbouring triangles on one face)."""

    linear: float = DEFAULT_LINEAR_MM / MM_PER_M
    angular: float = math.radians(DEFAULT_ANGULAR_DEG)


def read_step_mesh(data: bytes, name: str, field: str, tolerance: StepTolerance) -> trimesh.Trimesh:
    """Return the tessellated STEP file `data` [mm] (its own length unit converted to mm).

    MeshError naming `field` for a file that is not STEP, unreadable, holds no face (only
    curves or points), or does not tessellate (`tessellate`).
    """
    return mesh_step_shape(read_step_shape(data, name, field), name, field, tolerance)


def mesh_step_shape(shape: Any, name: str, field: str, tolerance: StepTolerance) -> trimesh.Trimesh:
    """Return the tessellated shape [mm] read from the STEP file `name` (`read_step_mesh`'s
    second half: MeshError naming `field` when it holds no face or does not tessellate)."""
    if not faces_of(shape):
        raise MeshError(
            f"{field}: STEP file {name!r} holds no surfaces or solids (only curves or points);"
            " export the part's solid body (or its faces) as STEP"
        )
    try:
        return tessellate(shape, tolerance.linear * MM_PER_M, tolerance.angular)
    except MeshError as exc:
        raise MeshError(f"{field}: STEP file {name!r}: {exc}") from None


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
