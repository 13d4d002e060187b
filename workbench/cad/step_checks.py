"""Bounds and checks on a STEP file before and after Open CASCADE reads it.

Before the reader: the file's entity count and how deeply its lists nest (OCP's parser
recurses per level and crashes on a deep one). After it: the load failures OCP reports
(unresolved references, entities of the wrong type), named by their entity number; the
shape's extent against the cell's; the triangles a tessellation would make, estimated from
the tolerance and the surfaces before meshing; and whether the mesh of a solid is closed and
points outwards. Each refusal is a MeshError naming the file, the field and the setting.
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any

import numpy as np

from workbench.errors import MeshError

if TYPE_CHECKING:
    import trimesh

MAX_STEP_ENTITIES = 2_000_000
"""Most entities (``#n = ...``) a STEP file may hold (a 200 MiB file holds some 3 million):
counted in the text before the reader starts."""
MAX_STEP_NESTING = 64
"""Deepest nesting of parenthesised lists in a STEP file (CAD systems write 3 or 4; Open
CASCADE's parser recurses per level and crashes between 50,000 and 70,000 on an 8 MiB stack): measured in the text before the reader starts."""
MAX_COORDINATE_MM = 100_000.0
"""Largest absolute x, y or z of a CAD file's geometry [mm]: the cell's half extent
(`workbench.project.bounds.CELL_HALF_EXTENT_MM`, a 200 m cube)."""
MAX_LOAD_FAILURES_NAMED = 5
"""How many of a file's load failures a message names (it counts them all)."""

_ENTITY = re.compile(rb"#\d+\s*=")
_ENTITY_KIND = re.compile(rb"(?m)^\s*#(\d+)\s*=\s*\(?\s*([A-Za-z_0-9]*)")
_COMMENT = re.compile(rb"/\*.*?\*/", re.S)
_SOLID = re.compile(rb"MANIFOLD_SOLID_BREP|BREP_WITH_VOIDS|CLOSED_SHELL")


def declares_solid(data: bytes) -> bool:
    """Return whether STEP text `data` declares a solid (a closed shell): its mesh must close."""
    return _SOLID.search(data) is not None


def nesting_depth(data: bytes) -> int:
    """Return the deepest nesting of ``( )`` in STEP text `data`, outside strings and comments.

    A STEP string is ``'...'`` with ``''`` for a quote inside it, so the parity of the quotes
    seen so far says whether a character lies in a string."""
    marks = np.frombuffer(
        _COMMENT.sub(b"", data).translate(None, bytes(set(range(256)) - set(b"()'"))),
        dtype=np.uint8,
    )
    if len(marks) == 0:
        return 0
    outside = (np.cumsum(marks == ord("'"), dtype=np.int64) & 1) == 0
    step = ((marks == ord("(")) & outside).astype(np.int32) - ((marks == ord(")")) & outside)
    return int(np.cumsum(step, dtype=np.int64).max(initial=0))


def check_text(data: bytes, name: str, field: str | None) -> None:
    """Refuse a STEP file with more entities than `MAX_STEP_ENTITIES` or lists nested deeper
    than `MAX_STEP_NESTING`, before any reader sees it."""
    count = sum(1 for _ in _ENTITY.finditer(data))
    if count > MAX_STEP_ENTITIES:
        raise MeshError(
            f"STEP file {name!r} holds {count:,} entities, more than {MAX_STEP_ENTITIES:,}"
            " (workbench.cad.step_checks.MAX_STEP_ENTITIES); export the part alone, or simplify it",
            field=field,
        )
    depth = nesting_depth(data)
    if depth > MAX_STEP_NESTING:
        raise MeshError(
            f"STEP file {name!r} nests lists {depth:,} deep, more than {MAX_STEP_NESTING}"
            " (workbench.cad.step_checks.MAX_STEP_NESTING): it is damaged or made to break"
            " readers; export it again from its CAD system",
            field=field,
        )


def load_failures(reader: Any, data: bytes) -> list[tuple[str, str, list[str]]]:
    """Return the load failures the STEP `reader` reports after ``ReadFile``: per failing
    entity its label (``#21``, from the file's text), its kind (EDGE_CURVE) and the messages."""
    model = reader.Model()
    checks = reader.WS().ModelCheckList(False)
    found: list[tuple[int, list[str]]] = []
    checks.Start()
    while checks.More():
        check, number = checks.Value(), checks.Number()
        fails = [str(check.CFail(i)) for i in range(1, check.NbFails() + 1)]
        if fails:
            found.append((number, fails))
        checks.Next()
    glob = model.GlobalCheck()
    if not found and glob.NbFails():
        found.append((0, [str(glob.CFail(i)) for i in range(1, glob.NbFails() + 1)]))
    if not found:
        return []
    # OCP numbers entities in the order of the file's DATA section: the n-th ``#id =``
    start = max(data.find(b"DATA;"), 0)
    labels = [(m.group(1), m.group(2)) for m in _ENTITY_KIND.finditer(data, start)]
    out = []
    for number, fails in found:
        if 0 < number <= len(labels):
            ident, kind = labels[number - 1]
            out.append((f"#{ident.decode()}", kind.decode() or "complex entity", fails))
        else:
            out.append(("the file", "header or structure", fails))
    return out


def check_load(reader: Any, data: bytes, name: str, field: str | None) -> None:
    """Refuse a STEP file whose reader reports load failures, naming the first entities."""
    failures = load_failures(reader, data)
    if not failures:
        return
    shown = "; ".join(
        f"{label} {kind}: {', '.join(dict.fromkeys(fails))}"
        for label, kind, fails in failures[:MAX_LOAD_FAILURES_NAMED]
    )
    more = len(failures) - MAX_LOAD_FAILURES_NAMED
    raise MeshError(
        f"STEP file {name!r} does not load whole: {len(failures)} entities fail ({shown}"
        f"{f'; and {more} more' if more > 0 else ''}); the file is damaged or incomplete (its"
        " references do not resolve): export it again from its CAD system",
        field=field,
    )


def check_extent(bbox: Any, name: str, field: str | None) -> None:
    """Refuse a shape whose bounding box (2, 3) [mm] reaches past `MAX_COORDINATE_MM`."""
    box = np.asarray(bbox, dtype=float)
    far = float(np.max(np.abs(box))) if np.all(np.isfinite(box)) else math.inf
    if far > MAX_COORDINATE_MM:
        raise MeshError(
            f"{name!r} reaches {far:.4g} mm from its origin, beyond the cell's"
            f" {MAX_COORDINATE_MM:,.0f} mm (workbench.cad.step_checks.MAX_COORDINATE_MM): check"
            " the file's length unit, or move the part near its origin",
            field=field,
        )


def _segments(sweep: float, radius: float, linear: float, angular: float) -> float:
    """Return the chords a tessellation needs along an arc of `sweep` [rad] and `radius` [mm]."""
    if radius <= 0 or not math.isfinite(radius):
        return 1.0
    chord = 2.0 * math.acos(max(1.0 - linear / radius, -1.0))
    return max(1.0, math.ceil(abs(sweep) / max(min(chord, angular), 1e-12)))


def estimate_triangles(shape: Any, linear: float, angular: float) -> int:
    """Return an estimate of the triangles that meshing `shape` [mm] within `linear` [mm] and
    `angular` [rad] makes, from its surfaces alone (nothing is meshed).

    Per face: a cylinder or cone needs chords around its sweep (one row along its length); a
    sphere or torus chords both ways; another curved surface its area over the area of a
    triangle whose sagitta on a sphere of half the face's size is `linear`; a plane ~0 (its
    edges are counted with the curved faces around them). Two triangles per cell."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.BRepBndLib import BRepBndLib
    from OCP.BRepGProp import BRepGProp
    from OCP.GeomAbs import GeomAbs_SurfaceType as S
    from OCP.GProp import GProp_GProps

    from workbench.cad.brep_mesh import faces_of

    total = 0.0
    for face in faces_of(shape):
        surf = BRepAdaptor_Surface(face, True)
        kind = surf.GetType()
        du = surf.LastUParameter() - surf.FirstUParameter()
        dv = surf.LastVParameter() - surf.FirstVParameter()
        if kind == S.GeomAbs_Plane:
            continue
        if kind == S.GeomAbs_Cylinder:
            total += 2 * _segments(du, surf.Cylinder().Radius(), linear, angular)
        elif kind == S.GeomAbs_Sphere:
            r = surf.Sphere().Radius()
            total += 2 * _segments(du, r, linear, angular) * _segments(dv, r, linear, angular)
        elif kind == S.GeomAbs_Torus:
            t = surf.Torus()
            big, small = t.MajorRadius() + t.MinorRadius(), t.MinorRadius()
            total += 2 * _segments(du, big, linear, angular) * _segments(dv, small, linear, angular)
        else:
            props, box = GProp_GProps(), Bnd_Box()
            BRepGProp.SurfaceProperties_s(face, props)
            BRepBndLib.Add_s(face, box, False)
            if box.IsVoid():
                continue
            size = box.CornerMin().Distance(box.CornerMax())
            rho = max(size / 2.0, linear)
            side = min(math.sqrt(8.0 * rho * linear), rho * angular)
            total += 2 + abs(props.Mass()) / (0.433 * max(side, 1e-9) ** 2)
        if total > 1e15:
            break
    return int(min(total, 1e15))


def check_closed(meshes: list[trimesh.Trimesh], name: str, field: str | None) -> None:
    """Refuse the meshes of a file's solids [mm] when one is open (an edge on one triangle
    only) or inside out (negative volume): the solid in the file is broken."""
    for i, mesh in enumerate(meshes):
        which = f"solid {i + 1} of {len(meshes)}" if len(meshes) > 1 else "its solid"
        edges = mesh.edges_sorted
        _, counts = np.unique(edges, axis=0, return_counts=True)
        open_edges = int((counts == 1).sum())
        if open_edges:
            raise MeshError(
                f"STEP file {name!r}: {which} meshes open ({open_edges} triangle edges have"
                " no neighbour): the solid has gaps or missing faces; sew it and check it in"
                " its CAD system and export it again",
                field=field,
            )
        volume = float(mesh.volume)
        if volume <= 0:
            raise MeshError(
                f"STEP file {name!r}: {which} is inside out (its faces point inwards, volume"
                f" {volume:.4g} mm³); reverse or repair it in its CAD system and export it again",
                field=field,
            )
