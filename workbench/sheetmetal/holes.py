"""Holes and cutouts of a flange: inner loops in the flange's own 2-D frame, checked and chorded.

A hole is a simple polygon (k, 2) [m] strictly inside its flange's outline. Circles and arcs
become polygons whose chords stay within `CHORD_TOLERANCE` of the true curve. The checks
(`check_holes`) refuse, naming the flange and the hole:

- a hole that is not simple or has no area;
- a hole closer than `MIN_HOLE_GAP` to the outline or to another hole (a web thinner than
  that tears when punched or laser cut; it also keeps the solid's walls apart);
- a hole inside a bend's deformation zone: closer to a bend edge than the bend's inner
  radius plus the thickness (the material there is stretched and the hole would distort).
  Published practice asks for more (Protolabs, "Sheet metal design guidelines": holes at
  least 2.5·t + r from a bend); that is advice, not a refusal here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import shapely
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.polygon import signed_area

if TYPE_CHECKING:
    from workbench.sheetmetal.part import SheetMetalPart

MIN_HOLE_GAP = 0.5e-3
"""Smallest web [m] between a hole and the outline or another hole: a check of the model (a
hole that touches the outline is a notch, and must be drawn as one), not a design rule; the
manufacturing rules (e.g. hole-to-edge distance against thickness) are the designer's."""

CHORD_TOLERANCE = 0.05e-3
"""Largest distance [m] between a chorded circle or arc and the true curve."""


def ccw(ring: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return the ring (k, 2) counter-clockwise (reversed when clockwise)."""
    ring = np.asarray(ring, dtype=float)
    return ring[::-1].copy() if signed_area(ring) < 0 else ring


def circle(
    center: tuple[float, float], radius: float, tol: float = CHORD_TOLERANCE
) -> NDArray[np.float64]:
    """Return a CCW polygon inscribed in a circle, chord sagitta <= `tol` [m] (at least 8 sides)."""
    if not radius > 0:
        raise InputError(f"hole radius: must be > 0 m, got {radius!r}")
    half = np.arccos(max(-1.0, 1.0 - min(tol, radius) / radius))  # half the angle per chord
    n = max(8, int(np.ceil(np.pi / half)))
    a = 2 * np.pi * np.arange(n) / n
    return np.c_[center[0] + radius * np.cos(a), center[1] + radius * np.sin(a)]


def bend_zone_width(part: SheetMetalPart, bend: int) -> float:
    """Return how far [m] into its flanges bend `bend`'s deformation zone reaches (r + t)."""
    return float(part.bends[bend].inner_radius + part.thickness)


def check_holes(part: SheetMetalPart) -> None:
    """Raise InputError naming the flange and hole of the first hole that breaks a rule above."""
    for fi, fl in enumerate(part.flanges):
        if not fl.holes:
            continue
        outline = shapely.Polygon(fl.polygon)
        zones = []
        for bi, b in enumerate(part.bends):
            for f, e in ((b.parent, b.parent_edge), (b.child, b.child_edge)):
                if f == fi:
                    p, q = fl.polygon[e], fl.polygon[(e + 1) % len(fl.polygon)]
                    zones.append((b.name, bend_zone_width(part, bi), shapely.LineString([p, q])))
        shapes: list[shapely.Polygon] = []
        for hi, h in enumerate(fl.holes):
            where = f"flanges[{fi}] ('{fl.name}').holes[{hi}]"
            poly = shapely.Polygon(h)
            if len(h) < 3 or abs(signed_area(h)) <= 0 or not poly.is_valid:
                raise InputError(
                    f"{where}: a hole must be a simple polygon with area > 0", field=where
                )
            gap = outline.exterior.distance(poly)
            if not outline.contains(poly) or gap < MIN_HOLE_GAP:
                raise InputError(
                    f"{where}: must lie inside the flange's outline with at least "
                    f"{MIN_HOLE_GAP * 1e3:g} mm of material (gap {gap * 1e3:.3g} mm); "
                    "move or shrink the hole",
                    field=where,
                )
            for name, width, line in zones:
                d = line.distance(poly)
                if d < width:
                    raise InputError(
                        f"{where}: lies in bend '{name}''s zone ({d * 1e3:.3g} mm from the bend "
                        f"edge, the zone reaches {width * 1e3:.3g} mm = inner radius + thickness); "
                        "move the hole away from the bend",
                        field=where,
                    )
            for hj, other in enumerate(shapes):
                d = other.distance(poly)
                if d < MIN_HOLE_GAP:
                    raise InputError(
                        f"{where}: overlaps or comes within {d * 1e3:.3g} mm of holes[{hj}]; "
                        f"holes need {MIN_HOLE_GAP * 1e3:g} mm of material between them",
                        field=where,
                    )
            shapes.append(poly)


def cap_triangles(
    outline: NDArray[np.float64], holes: tuple[NDArray[np.float64], ...]
) -> NDArray[np.int64]:
    """Return CCW triples indexing [outline, *holes] stacked that cover the outline minus holes."""
    pts = np.concatenate([outline, *holes]) if holes else outline
    poly = shapely.Polygon(outline, [h for h in holes])
    tris = shapely.get_parts(shapely.constrained_delaunay_triangles(poly))
    index = {(float(x), float(y)): i for i, (x, y) in enumerate(pts)}
    out = []
    for tri in tris:
        xy = np.asarray(tri.exterior.coords)[:3]
        try:
            ids = [index[(float(x), float(y))] for x, y in xy]
        except KeyError as exc:  # the triangulator added a point: not expected of GEOS
            raise InputError(f"flange outline: cannot triangulate with its holes ({exc})") from exc
        if signed_area(pts[ids]) < 0:
            ids = ids[::-1]
        out.append(ids)
    return np.array(out, dtype=np.int64)
