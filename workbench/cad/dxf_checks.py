"""Bounds on a DXF drawing before its entities are expanded, flattened and joined.

Before ezdxf parses the file: its entity count in the text. Before blocks are expanded: the
entities the expansion would make, counted through nested INSERTs without expanding any.
Per entity before it is flattened: its coordinates against the cell's extent and a spline's
degree. Each refusal is a FlatPatternError naming the file, the field and the setting.
"""

from __future__ import annotations

import math
import re
from typing import Any

from workbench.cad.flat_pattern import FlatPatternError
from workbench.cad.step_checks import MAX_COORDINATE_MM

MAX_DXF_ENTITIES = 200_000
"""Most objects (group code 0: entities, table entries, blocks) a DXF file may hold, counted
in its text before ezdxf parses it (a flat pattern has hundreds; a million lines took ezdxf
125 s and 2.2 GB)."""
MAX_EXPANDED_ENTITIES = 200_000
"""Most entities the model space may hold once its block references (INSERT, nested up to 8
deep) are expanded, counted before expanding any."""
MAX_SPLINE_DEGREE = 11
"""Highest degree of a SPLINE (CAD systems write 3; ezdxf fails near 30)."""
MAX_BEND_LINES = 100
"""Most bend lines a flat pattern may hold (a press-brake part has a few dozen at most)."""
MAX_INSERT_DEPTH = 8
"""How deeply nested block references are expanded (deeper ones stay unexpanded)."""

_OBJECT = re.compile(rb"(?m)^[ \t]*0[ \t]*\r?\n[ \t]*[A-Za-z_][A-Za-z_0-9]*[ \t]*\r?$")


def check_text(data: bytes, name: str, field: str) -> None:
    """Refuse an ASCII DXF with more than `MAX_DXF_ENTITIES` objects before it is parsed (a
    group code 0 line followed by a name: the line after a value is always a code)."""
    if data.startswith(b"AutoCAD Binary DXF"):
        return  # counted after loading (`check_expansion`)
    count = sum(1 for _ in _OBJECT.finditer(data))
    if count > MAX_DXF_ENTITIES:
        raise FlatPatternError(
            f"{name!r} holds {count:,} objects, more than {MAX_DXF_ENTITIES:,}"
            " (workbench.cad.dxf_checks.MAX_DXF_ENTITIES); save the flat pattern alone",
            field=field,
        )


def _count(entities: Any, doc: Any, depth: int, memo: dict, stack: tuple, budget: int) -> int:
    n = 0
    for e in entities:
        n += 1
        if e.dxftype() != "INSERT" or depth >= MAX_INSERT_DEPTH:
            continue
        block = str(e.dxf.get("name", ""))
        if block in stack:
            raise ValueError(f"block {block!r} inserts itself")
        key = (block, depth)
        if key not in memo:
            inner = doc.blocks.get(block)
            memo[key] = (
                0 if inner is None else _count(inner, doc, depth + 1, memo, (*stack, block), budget)
            )
        copies = max(1, int(e.dxf.get("row_count", 1))) * max(1, int(e.dxf.get("column_count", 1)))
        n += copies * memo[key] + len(getattr(e, "attribs", ()))
        if n > budget:
            return n
    return n


def check_expansion(doc: Any, name: str, field: str) -> None:
    """Refuse a drawing whose model space, its blocks expanded, holds more than
    `MAX_EXPANDED_ENTITIES` entities, or whose blocks insert themselves."""
    try:
        count = _count(doc.modelspace(), doc, 0, {}, (), MAX_EXPANDED_ENTITIES)
    except ValueError as exc:
        raise FlatPatternError(f"{name!r}: {exc}; redraw the block", field=field) from None
    if count > MAX_EXPANDED_ENTITIES:
        raise FlatPatternError(
            f"{name!r} expands to more than {MAX_EXPANDED_ENTITIES:,} entities through its"
            " block references (INSERT) (workbench.cad.dxf_checks.MAX_EXPANDED_ENTITIES);"
            " explode or simplify the blocks and save the flat pattern alone",
            field=field,
        )


def _points(e: Any) -> list[Any]:
    kind, pts = e.dxftype(), []
    for key in ("start", "end", "center", "insert", "defpoint"):
        if e.dxf.hasattr(key):
            pts.append(e.dxf.get(key))
    if kind == "LWPOLYLINE":
        pts += [(x, y) for x, y, *_ in e.get_points()]
    elif kind == "POLYLINE":
        pts += [v.dxf.location for v in e.vertices]
    elif kind == "SPLINE":
        pts += list(e.control_points) + list(e.fit_points)
    return pts


def check_entity(e: Any, scale: float, name: str, field: str, label: str) -> None:
    """Refuse entity `e` (`scale` m per drawing unit) that reaches past `MAX_COORDINATE_MM`
    from the origin (points, plus a circle's or arc's radius, an ellipse's axis) or, for a
    SPLINE, has a degree above `MAX_SPLINE_DEGREE`."""
    kind = e.dxftype()
    if kind == "SPLINE" and int(e.dxf.get("degree") or 3) > MAX_SPLINE_DEGREE:
        raise FlatPatternError(
            f"{name!r}: a SPLINE on layer {label!r} has degree {int(e.dxf.degree)}, more than"
            f" {MAX_SPLINE_DEGREE} (workbench.cad.dxf_checks.MAX_SPLINE_DEGREE); export it with"
            " cubic splines or as a polyline",
            field=field,
        )
    far = 0.0
    for p in _points(e):
        far = max(far, *(abs(float(c)) for c in tuple(p)[:3]))
    reach = abs(float(e.dxf.get("radius") or 0.0)) if e.dxf.hasattr("radius") else 0.0
    if e.dxf.hasattr("major_axis"):
        reach = max(reach, max(abs(float(c)) for c in e.dxf.major_axis))
    far = (far + reach) * scale * 1e3  # mm
    if not math.isfinite(far) or far > MAX_COORDINATE_MM:
        raise FlatPatternError(
            f"{name!r}: a {kind} on layer {label!r} reaches {far:.4g} mm from the origin, beyond"
            f" the cell's {MAX_COORDINATE_MM:,.0f} mm (workbench.cad.step_checks."
            "MAX_COORDINATE_MM); check the drawing's units ($INSUNITS) and its geometry",
            field=field,
        )


def check_bend_count(count: int, name: str, field: str) -> None:
    """Refuse a flat pattern with more than `MAX_BEND_LINES` bend lines."""
    if count > MAX_BEND_LINES:
        raise FlatPatternError(
            f"{name!r} has {count:,} bend lines, more than {MAX_BEND_LINES}"
            " (workbench.cad.dxf_checks.MAX_BEND_LINES); check the bend layer",
            field=field,
        )
