"""Candidate grasps of a sequence search: a grid of points on every flange, yaws and faces.

SI units. A flange's candidates are its centroid and the points of a square grid of
`spacing` [m] (aligned with the flange's frame) that lie at least `inset` [m] inside its
polygon, each with every yaw [rad] and face (+1 top, -1 bottom) asked for. The order is
fixed (flange, then point, then yaw, then face), so a search is repeatable. With a gripper
`footprint` the candidates whose cup or pad covers a hole or hangs over an edge are set apart
with why (`workbench.pressbrake.grasp_footprint`, `screened_grid`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.grasp_footprint import MAX_OVERHANG, Footprint, screen_grasps
from workbench.sheetmetal.part import SheetMetalPart

#: Most candidates a search takes (each is checked by IK at every bend it could serve).
MAX_GRASPS = 2000
MAX_GRID_POINTS = 100_000
"""Most points the sequence search's grasp grid looks at, over the flanges' bounding boxes
(each is tested against the flange's outline, one by one: a million take about ten seconds),
counted from `bending.grasp_grid.spacing` before any is made."""


@dataclass(frozen=True)
class GridSettings:
    """The candidate grid of a search (SI): `spacing` and `inset` [m], the gripper's `yaws`
    [rad] about the flange normal and the `faces` held (+1 top, -1 bottom), the gripper's
    `footprint` (None: not checked against holes and edges) and the fraction of it that may
    hang over an edge, `max_overhang`; the project's `bending.grasp_grid`."""

    spacing: float = 0.025
    inset: float = 0.008
    yaws: tuple[float, ...] = (0.0, np.pi / 2, np.pi, -np.pi / 2)
    faces: tuple[int, ...] = (1,)
    footprint: Footprint | None = None
    max_overhang: float = MAX_OVERHANG


def screened_grid(
    part: SheetMetalPart, g: GridSettings
) -> tuple[list[Grasp], list[tuple[Grasp, str]]]:
    """Return the candidates of grid `g` whose footprint holds, and the others with why."""
    grasps = grasp_grid(part, spacing=g.spacing, inset=g.inset, yaws=g.yaws, faces=g.faces)
    if g.footprint is None:
        return grasps, []
    return screen_grasps(part, grasps, g.footprint, g.max_overhang)


def grasp_grid(
    part: SheetMetalPart,
    *,
    spacing: float,
    inset: float,
    yaws: Sequence[float] = (0.0,),
    faces: Sequence[int] = (1,),
    flanges: Sequence[str] | None = None,
) -> list[Grasp]:
    """Return the candidate grasps of `part` (see the module docstring).

    InputError when `spacing` is not positive, the flanges' boxes hold more than
    `MAX_GRID_POINTS` grid points (counted before any is made) or the grid more than
    `MAX_GRASPS` candidates.
    """
    if not (np.isfinite(spacing) and spacing > 0):
        raise InputError(f"must be > 0 m, got {spacing!r}", field="grasp spacing")
    out: list[Grasp] = []
    names = [f.name for f in part.flanges] if flanges is None else list(flanges)
    _check_grid_points(part, names, spacing)
    for name in names:
        poly = part.flanges[part.flange_index(name)].polygon
        shape = shapely.Polygon(poly)
        inner = shape.buffer(-inset) if inset > 0 else shape
        c = shape.centroid
        points = [(c.x, c.y)]
        lo, hi = poly.min(axis=0), poly.max(axis=0)
        xs = np.arange(lo[0] + spacing / 2, hi[0], spacing)
        ys = np.arange(lo[1] + spacing / 2, hi[1], spacing)
        for y in ys:
            for x in xs:
                if inner.contains(shapely.Point(x, y)) and np.hypot(x - c.x, y - c.y) > 1e-6:
                    points.append((float(x), float(y)))
        for p in points:
            for yaw in yaws:
                for face in faces:
                    out.append(Grasp(name, np.array(p), float(yaw), int(face)))  # type: ignore[call-arg]
    if len(out) > MAX_GRASPS:
        raise InputError(
            f"{len(out)} candidates, above {MAX_GRASPS} "
            "(workbench.pressbrake.grasp_grid.MAX_GRASPS); widen the spacing or name fewer "
            "yaws or faces",
            field="grasp grid",
        )
    return out


def _grid_points(extents: NDArray[np.float64], spacing: float) -> float:
    """Return how many points `np.arange(lo + spacing / 2, hi, spacing)` makes per axis of
    each box of `extents` (K, 2) [m], multiplied per box and summed (a float: no overflow)."""
    per_axis = np.maximum(np.ceil(extents / spacing - 0.5), 0.0)
    return float(np.prod(per_axis, axis=1).sum())


def _check_grid_points(part: SheetMetalPart, names: Sequence[str], spacing: float) -> None:
    """Refuse a grid of more than `MAX_GRID_POINTS` points, naming the least spacing that fits."""
    polys = [part.flanges[part.flange_index(n)].polygon for n in names]
    extents = np.array([p.max(axis=0) - p.min(axis=0) for p in polys], float).reshape(-1, 2)
    n = _grid_points(extents, spacing)
    if n <= MAX_GRID_POINTS:
        return
    least = spacing
    while _grid_points(extents, least) > MAX_GRID_POINTS:
        least *= 1.05
    raise InputError(
        f"{spacing * 1e3:g} mm makes {n:.3g} grid points on the flanges, above the budget of "
        f"{MAX_GRID_POINTS:,} (workbench.pressbrake.grasp_grid.MAX_GRID_POINTS); use a spacing "
        f"of at least {least * 1e3:.2g} mm",
        field="grasp spacing",
    )
