"""Flat pattern of a sheet-metal part: the blank's outline and its bend lines, checked.

A flat pattern (a DXF's, `workbench.cad.dxf.read_flat_pattern`) gives the blank's outline and,
per bend, the bend line: the centre line of the bend zone, with the bend angle, the direction
and optionally the inner radius. It is drawing data, below the part model: the DXF reader and
writer use it here, and `sheetmetal.flat_split.part_spec_from_flat_pattern` cuts the outline
along the bend zones (each as wide as its bend allowance) into the part's flanges;
`sheetmetal.flat_blank.flat_pattern_of_part` is the inverse (the part's flat blank).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import shapely
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.polygon import clean_ring, signed_area

#: A bend line's end inside the blank within this distance [m] of its edge is moved onto it.
SNAP_TOL = 0.5e-3
#: Geometry closer than this [m] counts as touching (bend lines, zones, outline crossings).
TOUCH_TOL = 1e-7


class FlatPatternError(InputError):
    """A flat pattern (or the file it came from) cannot make a part; `field` names the input."""


@dataclass(frozen=True, eq=False)
class BendLine:
    """A bend line from `start` to `end` (2,) [m]: the centre line of its bend zone.

    `angle` is the bend (deflection) angle [rad] in (0, π) as `Bend.angle`, `direction` +1 up
    (towards the viewer of the drawing, the flat blank's +z) or -1 down, `inner_radius` [m] or
    None (the caller's default applies), `label` says where it came from, for messages.
    """

    start: NDArray[np.float64]
    end: NDArray[np.float64]
    angle: float
    direction: int
    inner_radius: float | None = None
    label: str = ""

    @property
    def length(self) -> float:
        """Return the bend line's length [m]."""
        return float(np.linalg.norm(self.end - self.start))


@dataclass(frozen=True, eq=False)
class FlatPattern:
    """A flat blank: `outline` (n, 2) [m] counter-clockwise, `bend_lines`, `holes` (inner
    contours, (m, 2) [m] each; the part model has none, so they do not reach the part) and
    `notes` (what the reader assumed or left out, for the user)."""

    outline: NDArray[np.float64]
    bend_lines: tuple[BendLine, ...]
    holes: tuple[NDArray[np.float64], ...] = ()
    notes: tuple[str, ...] = ()


def bend_label(i: int, line: BendLine) -> str:
    """Return how messages name bend line `i` (0-based): its label or its ends in mm."""
    if line.label:
        return line.label
    a, b = np.asarray(line.start) * 1e3, np.asarray(line.end) * 1e3
    return f"bend line {i + 1} from ({a[0]:.6g}, {a[1]:.6g}) to ({b[0]:.6g}, {b[1]:.6g}) mm"


def ccw_ring(points: ArrayLike) -> NDArray[np.float64]:
    """Return the ring (n, 2) cleaned (`clean_ring`) and counter-clockwise."""
    p = clean_ring(points)
    return p if signed_area(p) > 0 else p[::-1].copy()


def _snap(i: int, line: BendLine, ring: shapely.LinearRing, field: str) -> BendLine:
    """Return `line` cut to the outline: an end inside the blank within SNAP_TOL of its edge is
    moved onto it, an end outside (a line drawn past the edge) back to where it enters."""
    a, b = np.asarray(line.start, float), np.asarray(line.end, float)
    length = float(np.linalg.norm(b - a))
    if not np.isfinite(length) or length <= SNAP_TOL:
        raise FlatPatternError(
            f"{bend_label(i, line)} is {length * 1e3:.4g} mm long; delete it or redraw it",
            field=field,
        )
    d = (b - a) / length
    probe = shapely.LineString([a - 2 * SNAP_TOL * d, b + 2 * SNAP_TOL * d])
    hits = shapely.get_coordinates(ring.intersection(probe))
    s = np.unique(np.round((hits - a) @ d, 12)) if len(hits) else np.zeros(0)
    blank = shapely.Polygon(ring)
    fix = "draw each bend line from edge to edge of the blank"
    ends = []
    for which, p, sign in (("start", a, 1.0), ("end", b, -1.0)):
        t0 = 0.0 if sign > 0 else length
        u = sign * (s - t0)  # distance from this end along the line, positive inwards
        if blank.contains(shapely.Point(p)):
            near = u[(u <= 0) & (u >= -SNAP_TOL)]
            if len(near) == 0:
                gap = blank.exterior.distance(shapely.Point(p)) * 1e3
                raise FlatPatternError(
                    f"{bend_label(i, line)} does not cross the outline from edge to edge: its "
                    f"{which} is {gap:.4g} mm inside the outline; {fix}",
                    field=field,
                )
            ends.append(t0 + sign * float(near.max()))
        else:
            ahead = u[(u >= -TOUCH_TOL) & (u <= length)]
            if len(ahead) == 0:
                raise FlatPatternError(
                    f"{bend_label(i, line)} does not cross the outline from edge to edge: it "
                    f"does not reach the blank; {fix}",
                    field=field,
                )
            ends.append(t0 + sign * float(ahead.min()))
    inner = s[(s > ends[0] + TOUCH_TOL) & (s < ends[1] - TOUCH_TOL)]
    mid = a + d * (ends[0] + ends[1]) / 2
    if ends[1] - ends[0] <= SNAP_TOL or len(inner) or not blank.contains(shapely.Point(mid)):
        where = a + d * (inner[0] if len(inner) else ends[0])
        raise FlatPatternError(
            f"{bend_label(i, line)} does not cross the outline from edge to edge: it leaves the "
            f"blank at ({where[0] * 1e3:.6g}, {where[1] * 1e3:.6g}) mm; {fix}",
            field=field,
        )
    return replace(line, start=a + d * ends[0], end=a + d * ends[1])


def check_flat_pattern(pattern: FlatPattern, field: str) -> FlatPattern:
    """Return `pattern` with a counter-clockwise outline and bend-line ends on the outline.

    FlatPatternError names `field` and the fix: an outline that is not a simple polygon; a bend
    line without an angle in (0°, 180°), or that does not run from edge to edge of the blank,
    or crosses a hole; two bend lines that cross or touch.
    """
    outline = np.asarray(pattern.outline, dtype=float)
    if outline.ndim != 2 or outline.shape[1] != 2 or not np.all(np.isfinite(outline)):
        raise FlatPatternError(
            f"outline: expected (n, 2) finite points, got {outline.shape}", field=field
        )
    outline = ccw_ring(outline)
    poly = shapely.Polygon(outline) if len(outline) >= 3 else None
    if poly is None or not poly.is_valid or poly.area <= 0:
        why = shapely.is_valid_reason(poly) if poly is not None else "fewer than 3 corners"
        raise FlatPatternError(
            f"the outline is not a simple polygon ({why}); redraw it as one closed contour",
            field=field,
        )
    ring = shapely.LinearRing(outline)
    lines = []
    for i, line in enumerate(pattern.bend_lines):
        if not (np.isfinite(line.angle) and 0.0 < line.angle < np.pi):
            raise FlatPatternError(
                f"{bend_label(i, line)}: bend angle {np.degrees(line.angle):.6g} deg is not in "
                "(0, 180); write the bend angle (90 for a right angle) in its note",
                field=field,
            )
        if line.direction not in (1, -1):
            raise FlatPatternError(
                f"{bend_label(i, line)}: direction must be +1 or -1", field=field
            )
        r = line.inner_radius
        if r is not None and not (np.isfinite(r) and r > 0):
            raise FlatPatternError(f"{bend_label(i, line)}: inner radius must be > 0", field=field)
        lines.append(_snap(i, line, ring, field))
    segs = [shapely.LineString([ln.start, ln.end]) for ln in lines]
    for hole in pattern.holes:
        h = shapely.Polygon(hole)
        for i, seg in enumerate(segs):
            if seg.distance(h) <= TOUCH_TOL:
                raise FlatPatternError(
                    f"{bend_label(i, lines[i])} crosses or touches an inner contour (a hole or "
                    "cutout); the part model has no holes in bend zones: end the bend line at "
                    "the hole's edge or remove the hole",
                    field=field,
                )
    for i in range(len(segs)):
        for j in range(i + 1, len(segs)):
            if segs[i].distance(segs[j]) <= TOUCH_TOL:
                at = shapely.get_coordinates(segs[i].intersection(segs[j]))
                p = at[0] * 1e3 if len(at) else lines[i].start * 1e3
                raise FlatPatternError(
                    f"{bend_label(i, lines[i])} and {bend_label(j, lines[j])} cross or touch at "
                    f"({p[0]:.6g}, {p[1]:.6g}) mm; bend zones must not meet: add a corner relief",
                    field=field,
                )
    return replace(pattern, outline=outline, bend_lines=tuple(lines))
