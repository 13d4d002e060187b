"""Writing DXF flat patterns (ezdxf) that `workbench.cad.dxf.read_flat_pattern` reads back.

Useful to hand a part's flat blank (`workbench.sheetmetal.flat_blank.flat_pattern_of_part`) to
a laser or punch programmer, and for round-trip tests of the reader.
"""

from __future__ import annotations

import io

import numpy as np

from workbench.cad.dxf import UNITS
from workbench.cad.flat_pattern import FlatPattern
from workbench.errors import InputError


def write_flat_pattern(
    pattern: FlatPattern,
    *,
    bend_layer: str = "BEND",
    notes: bool = True,
    layers: bool = False,
    units: str = "mm",
    version: str = "R2010",
) -> bytes:
    """Return the DXF file (bytes) of `pattern` [m] that `read_flat_pattern` reads back.

    The outline and holes are closed polylines on layer OUTLINE; bend lines are LINEs on
    `bend_layer` (`layers`: on ``<bend_layer>_UP``/``_DOWN``); `notes` puts a note such as
    "UP 90° R1.5" (radius only where the bend has one) at each line's midpoint. `units` is a
    unit name of `UNITS` ("mm", "in", ...), written as $INSUNITS (R12 has no $INSUNITS: mm).
    """
    import ezdxf
    from ezdxf.enums import TextEntityAlignment

    code = {name: c for c, (name, _) in UNITS.items()}.get(units)
    if code is None or (version == "R12" and units != "mm"):
        raise InputError(f"units: one of {[n for n, _ in UNITS.values()]} (R12: mm), got {units!r}")
    scale = UNITS[code][1]
    doc = ezdxf.new(version, units=code)
    msp = doc.modelspace()
    for ring in (pattern.outline, *pattern.holes):
        pts = [tuple(p) for p in np.asarray(ring) / scale]
        if version == "R12":
            msp.add_polyline2d(pts, close=True, dxfattribs={"layer": "OUTLINE"})
        else:
            msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": "OUTLINE"})
    for line in pattern.bend_lines:
        word = "UP" if line.direction > 0 else "DOWN"
        layer = f"{bend_layer}_{word}" if layers else bend_layer
        a, b = np.asarray(line.start) / scale, np.asarray(line.end) / scale
        msp.add_line(tuple(a), tuple(b), dxfattribs={"layer": layer})
        if notes:
            text = f"{word} {np.degrees(line.angle):.10g}%%d"
            if line.inner_radius is not None:
                text += f" R{line.inner_radius / scale:.10g}"
            note = msp.add_text(text, height=2.5e-3 / scale, dxfattribs={"layer": "NOTES"})
            note.set_placement(tuple((a + b) / 2), align=TextEntityAlignment.MIDDLE_CENTER)
    stream = io.StringIO()
    doc.write(stream)
    return stream.getvalue().encode(doc.output_encoding)
