"""Where a gripper pad or suction cup touches the part: its footprint against holes and edges.

SI units. A `Footprint` is a polygon (k, 2) [m] in the TCP's x-y plane, centred on the TCP
(a cup: a chorded circle; a pad: a rectangle, x along the gripper's yaw). At a grasp it is
turned by the grasp's yaw and placed at the grasp point in the flange's frame. A grasp is
refused when its footprint

- overlaps a hole of the flange (a cup over a hole leaks, a pad over one holds nothing); or
- hangs over the flange's outline by more than `max_overhang`, a fraction of its area.

`MAX_OVERHANG` = 0: a vacuum cup seals only where its whole lip rests on the part, so any
overhang is a leak. This is the seal's geometry, not a vendor's figure: the strictest
choice, and the project's `bending.grasp_grid.max_overhang` relaxes it (a pad gripper may take
a larger fraction).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
import shapely.affinity
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.pressbrake.grasp import Grasp, grasp_point
from workbench.sheetmetal.holes import circle
from workbench.sheetmetal.part import SheetMetalPart

MAX_OVERHANG = 0.0
"""Largest fraction of a footprint's area outside its flange (see the module docstring)."""


@dataclass(frozen=True, eq=False)
class Footprint:
    """The contact polygon (k, 2) [m] of a cup or pad in the TCP frame, centred on the TCP."""

    polygon: NDArray[np.float64]

    @classmethod
    def cup(cls, diameter: float) -> Footprint:
        """Return a round suction cup of `diameter` [m] (its sealing lip's outer diameter)."""
        if not (np.isfinite(diameter) and diameter > 0):
            raise InputError(f"must be > 0 m, got {diameter!r}", field="cup diameter")
        return cls(circle((0.0, 0.0), diameter / 2))

    @classmethod
    def pad(cls, length: float, width: float) -> Footprint:
        """Return a rectangular pad `length` (along the TCP x) by `width` [m]."""
        if not all(np.isfinite(v) and v > 0 for v in (length, width)):
            raise InputError(f"must be > 0 m, got {length!r} x {width!r}", field="pad size")
        a, b = length / 2, width / 2
        return cls(np.array([[-a, -b], [a, -b], [a, b], [-a, b]]))

    @property
    def area(self) -> float:
        """Return the footprint's area [m²]."""
        return float(shapely.Polygon(self.polygon).area)


def placed(part: SheetMetalPart, grasp: Grasp, footprint: Footprint) -> shapely.Polygon:
    """Return the footprint of `grasp` in its flange's frame [m] (turned by its yaw)."""
    c, s = np.cos(grasp.yaw), np.sin(grasp.yaw)
    pts = footprint.polygon @ np.array([[c, s], [-s, c]]) + grasp_point(part, grasp)
    return shapely.Polygon(pts)


def footprint_problem(
    part: SheetMetalPart, grasp: Grasp, footprint: Footprint, max_overhang: float = MAX_OVERHANG
) -> str | None:
    """Return why `grasp`'s footprint may not hold the part ("covers hole H1 of flange F2"),
    or None. Holes are named H1.. in the flange's order."""
    f = part.flange_index(grasp.flange)
    fl = part.flanges[f]
    foot = placed(part, grasp, footprint)
    for k, h in enumerate(fl.holes):
        if foot.intersection(shapely.Polygon(h)).area > 0:
            return f"covers hole H{k + 1} of flange {fl.name}"
    out = foot.difference(shapely.Polygon(fl.polygon)).area / foot.area
    if out > max_overhang + 1e-12:
        return (
            f"hangs {100 * out:.3g} % over the edge of flange {fl.name} "
            f"(limit {100 * max_overhang:g} %, bending.grasp_grid.max_overhang)"
        )
    return None


def screen_grasps(
    part: SheetMetalPart,
    grasps: Sequence[Grasp],
    footprint: Footprint,
    max_overhang: float = MAX_OVERHANG,
) -> tuple[list[Grasp], list[tuple[Grasp, str]]]:
    """Return the grasps whose footprint holds and, apart, the others with why.

    InputError naming the flanges (and the first reason of each) when none holds.
    """
    kept, refused = [], []
    for g in grasps:
        why = footprint_problem(part, g, footprint, max_overhang)
        if why is None:
            kept.append(g)
        else:
            refused.append((g, why))
    if grasps and not kept:
        first: dict[str, str] = {}
        for g, why in refused:
            first.setdefault(g.flange, why)
        said = "; ".join(f"flange {n}: {w}" for n, w in first.items())
        raise InputError(
            f"no candidate grasp's footprint holds the part ({said}); grasp another flange, "
            "use a smaller cup or pad, or a finer grid",
            field="grasp grid",
        )
    return kept, refused
