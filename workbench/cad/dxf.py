"""Reading DXF flat patterns (ezdxf): the blank's outline and its bend lines.

What is read (R12 to R2018, ASCII or binary, model space, blocks inserted there included):

- Units: ``$INSUNITS`` (in, ft, mm, cm, m, ...); unset (0, or R12, which has none) or a
  unit that is not a length is taken as millimetres and said in `FlatPattern.notes`.
- Outline: the closed contours off the bend layers: closed LWPOLYLINE/POLYLINE (bulges
  included), CIRCLE, closed SPLINE/ELLIPSE, and LINE/ARC/open polyline chains joined end to end
  within `JOIN_TOL`; curves are flattened within `CHORD_TOL`. The largest contour is the
  outline; contours inside it are holes (`FlatPattern.holes`; each becomes a hole of the
  flange it falls in, `workbench.sheetmetal.flat_split`); a contour outside it is refused
  (one part per file).
- Bend lines: LINE entities on layer `bend_layer`, ``<bend_layer>_UP`` or ``<bend_layer>_DOWN``
  (case-insensitive; "-" or " " for "_"). The angle (and the direction, and optionally the
  inner radius) come from the bend note nearest the line (`workbench.cad.bend_notes`); the
  layers ``_UP``/``_DOWN`` give the direction too (a note that disagrees is refused).

`read_flat_pattern`, the one entry point, reads the file in a CAD worker process with a time
and memory limit (`workbench.cad.isolation`), bounded before parsing, expanding and flattening
(`workbench.cad.dxf_checks`).
"""

from __future__ import annotations

import io
import os
import re
import tempfile
from typing import Any

import numpy as np
import shapely

from workbench.cad import dxf_checks
from workbench.cad.bend_notes import assign_notes, read_notes
from workbench.cad.dxf_contours import CURVE_TYPES, chain_curves, flatten
from workbench.cad.flat_pattern import (
    BendLine,
    FlatPattern,
    FlatPatternError,
    check_flat_pattern,
)
from workbench.cad.isolation import run_isolated
from workbench.geometry.polygon import clean_ring

#: $INSUNITS code -> (name, metres per drawing unit); anything else is read as mm.
UNITS = {
    1: ("in", 0.0254),
    2: ("ft", 0.3048),
    4: ("mm", 1e-3),
    5: ("cm", 1e-2),
    6: ("m", 1.0),
    8: ("microinch", 2.54e-8),
    9: ("mil", 2.54e-5),
    10: ("yd", 0.9144),
    14: ("dm", 0.1),
}
DXF_SUFFIXES = (".dxf",)
"""File name endings read as DXF."""


def _read_binary(data: bytes) -> Any:
    # ezdxf's recover mode reads ASCII only; readfile detects and reads binary DXF
    import ezdxf

    fd, tmp = tempfile.mkstemp(suffix=".dxf")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        return ezdxf.readfile(tmp)
    finally:
        os.unlink(tmp)


def _load(data: bytes, name: str, field: str) -> Any:
    from ezdxf import recover

    fix = "export the flat pattern as DXF (R12 to R2018)"
    if not (data.startswith(b"AutoCAD Binary DXF") or b"SECTION" in data[:65536].upper()):
        raise FlatPatternError(f"{name!r} is not a DXF file (no SECTION); {fix}", field=field)
    dxf_checks.check_text(data, name, field)
    try:
        if data.startswith(b"AutoCAD Binary DXF"):
            doc = _read_binary(data)
        else:
            doc, _auditor = recover.read(io.BytesIO(data))
    except Exception as exc:  # ezdxf raises DXFStructureError and others on broken files
        raise FlatPatternError(
            f"{name!r} is not a readable DXF file ({type(exc).__name__}: {exc}); {fix}", field=field
        ) from None
    return doc


def _units(doc: Any) -> tuple[float, str, list[str]]:
    code = int(doc.header.get("$INSUNITS", 0) or 0)
    if code in UNITS:
        unit, scale = UNITS[code]
        return scale, unit, []
    why = "not set" if code == 0 else f"{code}, not a length unit read here"
    return 1e-3, "mm", [f"drawing units taken as mm ($INSUNITS {why})"]


def _entities(space: Any, layer: str | None = None, depth: int = 0) -> list[tuple[Any, str]]:
    out = []
    for e in space:
        own = str(e.dxf.get("layer", "0"))
        here = layer if (layer is not None and own == "0") else own
        if e.dxftype() == "INSERT" and depth < dxf_checks.MAX_INSERT_DEPTH:
            out += _entities(e.virtual_entities(), here, depth + 1)
        else:
            out.append((e, here))
    return out


def _bend_kind(layer: str, bend_layer: str) -> int | None:
    """Return 0 (bend layer), +1 (its _UP), -1 (its _DOWN), or None (not a bend layer)."""
    norm = re.sub(r"[\s\-]+", "_", layer.strip().upper())
    base = re.sub(r"[\s\-]+", "_", bend_layer.strip().upper())
    return {base: 0, f"{base}_UP": 1, f"{base}_DOWN": -1, f"{base}_DN": -1}.get(norm)


def _outline(curves: list, name: str, field: str, unit: str, scale: float) -> tuple:
    closed, chains = chain_curves(curves)
    u = 1.0 / scale
    if not closed:
        if chains:
            a, b = chains[0][0] * u, chains[0][-1] * u
            raise FlatPatternError(
                f"{name!r} has no closed outline: its curves off the bend layers form "
                f"{len(chains)} open chain(s); one runs from ({a[0]:.6g}, {a[1]:.6g}) to "
                f"({b[0]:.6g}, {b[1]:.6g}) {unit}, a gap of {np.linalg.norm(a - b):.4g} {unit}; "
                "join its ends or draw the blank as a closed polyline",
                field=field,
            )
        raise FlatPatternError(
            f"{name!r} has no closed outline (closed polyline, or lines and arcs joined end to "
            "end) off the bend layers; draw the blank's outline",
            field=field,
        )
    polys = []
    for pts in closed:
        ring = clean_ring(pts)
        if len(ring) < 3:
            continue
        poly = shapely.Polygon(ring)
        if not poly.is_valid:
            c = np.asarray(poly.centroid.coords[0]) * u
            raise FlatPatternError(
                f"{name!r}: the closed contour around ({c[0]:.6g}, {c[1]:.6g}) {unit} crosses "
                "itself; redraw it as a simple closed contour",
                field=field,
            )
        polys.append((abs(poly.area), ring, poly))
    if not polys:
        raise FlatPatternError(
            f"{name!r}: its closed contours are degenerate; draw the blank's outline", field=field
        )
    polys.sort(key=lambda p: -p[0])
    outer = polys[0][2]
    holes = [ring for _, ring, p in polys[1:] if outer.contains(p)]
    apart = [p for _, _, p in polys[1:] if not outer.contains(p)]
    if apart:
        c = np.asarray(apart[0].centroid.coords[0]) * u
        raise FlatPatternError(
            f"{name!r} holds {len(apart) + 1} separate outlines (one around ({c[0]:.6g}, "
            f"{c[1]:.6g}) {unit}); save one flat pattern per file",
            field=field,
        )
    notes = []
    if chains:
        notes.append(f"{len(chains)} open curve chain(s) off the bend layers ignored")
    return polys[0][1], tuple(holes), notes


def read_flat_pattern(
    data: bytes, name: str, field: str, *, bend_layer: str = "BEND"
) -> FlatPattern:
    """Return the flat pattern [m, rad] of the DXF file `data` (named `name` in messages),
    read in a CAD worker process (`workbench.cad.isolation`).

    FlatPatternError (an InputError) names `field` and the fix: not a DXF file, too many
    objects, blocks that expand too far, geometry beyond the cell or a spline of too high a
    degree (`workbench.cad.dxf_checks`), no closed outline, several outlines, no bend line on
    the bend layers (the message lists the layers present), too many bend lines, a bend line
    without an angle or direction (named by its number and ends), a bend line that does not
    cross the outline from edge to edge, two bend lines that cross. MeshError for a reader
    that fails otherwise, crashes, or runs past its time or memory limit.
    """
    pattern: FlatPattern = run_isolated(
        "workbench.cad.dxf:flat_pattern_here",
        (data, name, field, bend_layer),
        name=name,
        field=field,
    )
    return pattern


def flat_pattern_here(data: bytes, name: str, field: str, bend_layer: str) -> FlatPattern:
    """In the CAD worker: `read_flat_pattern`'s work."""
    doc = _load(data, name, field)
    scale, unit, notes = _units(doc)
    dxf_checks.check_expansion(doc, name, field)
    items = _entities(doc.modelspace())
    curves, lines, skipped = [], [], 0
    for e, layer in items:
        dxf_checks.check_entity(e, scale, name, field, layer)
        kind, dxftype = _bend_kind(layer, bend_layer), e.dxftype()
        if kind is not None:
            if dxftype == "LINE":
                lines.append((e, layer, kind))
            else:
                skipped += dxftype in CURVE_TYPES
        elif dxftype in CURVE_TYPES:
            curve = flatten(e, scale, layer)
            if curve is not None:
                curves.append(curve)
    if not lines:
        layers = sorted({layer for _, layer in items} | {str(t.dxf.name) for t in doc.layers})
        raise FlatPatternError(
            f"{name!r} has no bend lines: no LINE on layer {bend_layer!r} (nor {bend_layer}_UP, "
            f"{bend_layer}_DOWN); its layers are {layers}: put the bend lines on layer "
            f"{bend_layer!r} or name the layer that holds them as the bend layer",
            field=field,
        )
    dxf_checks.check_bend_count(len(lines), name, field)
    outline, holes, more = _outline(curves, name, field, unit, scale)
    if skipped:
        more.append(f"{skipped} curve(s) on the bend layers that are not LINEs ignored")
    segs = [
        (np.array(e.dxf.start.vec2, float) * scale, np.array(e.dxf.end.vec2, float) * scale)
        for e, _, _ in lines
    ]
    assigned = assign_notes(read_notes([e for e, _ in items], scale), segs)
    bend_lines = []
    for i, ((_e, layer, kind), (a, b), note) in enumerate(zip(lines, segs, assigned, strict=True)):
        pa, pb = a / scale, b / scale
        label = (
            f"bend line {i + 1} (LINE on layer {layer!r} from ({pa[0]:.6g}, {pa[1]:.6g}) to "
            f"({pb[0]:.6g}, {pb[1]:.6g}) {unit})"
        )
        if note is None:
            raise FlatPatternError(
                f"{label} has no bend angle: no bend note near it; put a TEXT note such as "
                "'UP 90° R1.5' (direction, bend angle in degrees, optional inner radius) at "
                "its midpoint",
                field=field,
            )
        direction = note.direction if note.direction is not None else (kind or None)
        if direction is None:
            raise FlatPatternError(
                f"{label} has no direction: write UP or DOWN in its note {note.text!r} or put "
                f"it on layer {bend_layer}_UP or {bend_layer}_DOWN",
                field=field,
            )
        if kind and direction != kind:
            raise FlatPatternError(
                f"{label}: its note {note.text!r} contradicts its layer {layer!r}; make them agree",
                field=field,
            )
        bend_lines.append(BendLine(a, b, note.angle, int(direction), note.inner_radius, label))
    pattern = FlatPattern(outline, tuple(bend_lines), holes, tuple(notes + more))
    return check_flat_pattern(pattern, field)
