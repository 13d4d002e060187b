"""The flat blank of a part as a flat pattern: outline and bend lines in the part frame [m]."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import shapely

from workbench.cad.flat_pattern import BendLine, FlatPattern, ccw_ring
from workbench.errors import InputError

if TYPE_CHECKING:
    from workbench.sheetmetal.part import SheetMetalPart


def flat_pattern_of_part(part: SheetMetalPart) -> FlatPattern:
    """Return the flat pattern of `part` [m]: its flat blank's outline, bend lines and holes.

    The outline is the union of the flanges placed flat (`part.fold(0)`) and the bend zones;
    each bend line runs along the middle of its zone, half a bend allowance off the parent's
    edge. The holes are the flanges' own, placed flat, then any gap the union leaves.
    """
    from workbench.sheetmetal.folding import edge_frame

    T = part.fold(0).T_part_flange
    pieces = []
    for f, fl in enumerate(part.flanges):
        p = fl.polygon @ T[f, :2, :2].T + T[f, :2, 3]
        pieces.append(shapely.Polygon(p))
    lines = []
    for i, b in enumerate(part.bends):
        a, d, n = edge_frame(part.flanges[b.parent].polygon, b.parent_edge)
        R, o = T[b.parent, :2, :2], T[b.parent, :2, 3]
        ba, length = float(part.bend_allowances[i]), float(part.bend_lengths[i])
        a, d, n = R @ a + o, R @ d, R @ n
        pieces.append(shapely.Polygon([a, a + length * d, a + length * d + ba * n, a + ba * n]))
        mid_a = a + 0.5 * ba * n
        lines.append(
            BendLine(
                mid_a, mid_a + length * d, b.angle, b.direction, b.inner_radius, f"bend {b.name!r}"
            )
        )
    # On a 1 nm grid, then closed by 10 nm: pieces that float rounding left a hair apart fuse
    # (GEOS may drop a piece whose edges nearly, but not exactly, coincide with another's).
    grid = shapely.set_precision(np.array(pieces, dtype=object), 1e-9)
    blank = shapely.unary_union(grid, grid_size=1e-9).buffer(1e-8, join_style="mitre")
    blank = blank.buffer(-1e-8, join_style="mitre")
    if not isinstance(blank, shapely.Polygon):
        raise InputError("part: its flat blank is not one piece")
    own = tuple(
        ccw_ring(h @ T[f, :2, :2].T + T[f, :2, 3])
        for f, fl in enumerate(part.flanges)
        for h in fl.holes
    )
    holes = own + tuple(ccw_ring(np.asarray(r.coords)[:-1]) for r in blank.interiors)
    outline = ccw_ring(np.asarray(blank.exterior.coords)[:-1])
    return FlatPattern(outline, tuple(lines), holes)
