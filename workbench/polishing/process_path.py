"""The polishing path of a job: the pattern's tool path on the fitted surface, its coverage
and the commanded points pressed D = F/k into the surface (SI: m, N)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.polishing.bezier import BezierSurface
from workbench.polishing.chart import SurfaceChart
from workbench.polishing.choices import PATTERNS, Pattern
from workbench.polishing.coverage import Coverage, path_coverage
from workbench.polishing.raster import raster_toolpath
from workbench.polishing.toolpath import ToolPath, force_offset, spiral_toolpath

F64 = NDArray[np.float64]
_MM = 1e-3  # the summaries and messages speak millimetres
_PLANNERS = {"spiral": spiral_toolpath, "raster": raster_toolpath}
MAX_PASSES = {"spiral": 150, "raster": 1_000}
"""Most passes a pattern may lay on the workpiece (its width / spacing, halved for the
spiral's rings): the spiral's offset curves cost steeply more with each ring."""
MAX_PATH_POINTS = 20_000
"""Most path points (the workpiece's area / (spacing x step)): each gets IK and a ruckig
segment in the motion plan (36,000 points took over 30 s on two cores)."""


def check_path_budget(mesh: trimesh.Trimesh, pattern: str, step: float, spacing: float) -> None:
    """Refuse a path whose estimated passes or points are over `MAX_PASSES` or `MAX_PATH_POINTS`
    before it is planned: InputError naming the field, with the estimate."""
    width = float(np.sort(np.asarray(mesh.extents, float))[-2])
    passes = width / spacing / (2.0 if pattern == "spiral" else 1.0)
    limit = MAX_PASSES.get(pattern, MAX_PASSES["spiral"])
    if passes > limit:
        raise InputError(
            f"spacing: {spacing * 1e3:g} mm lays about {passes:.0f} {pattern} passes over the "
            f"{width * 1e3:g} mm wide workpiece, above the budget of {limit} "
            f"(workbench.polishing.process_path.MAX_PASSES); use a spacing of at least "
            f"{width / limit / (2.0 if pattern == 'spiral' else 1.0) * 1e3:.2g} mm"
        )
    points = float(mesh.area) / (spacing * step)
    if points > MAX_PATH_POINTS:
        raise InputError(
            f"step: {step * 1e3:g} mm with spacing {spacing * 1e3:g} mm makes about "
            f"{points:.3g} path points on the {float(mesh.area) * 1e6:.3g} mm² workpiece, above "
            f"the budget of {MAX_PATH_POINTS:,} (workbench.polishing.process_path."
            "MAX_PATH_POINTS); raise the step or the spacing"
        )


_KIND_NAMES = {0: "lead-in", 1: "process point", 2: "lead-out"}


@dataclass(frozen=True)
class PolishingPath:
    """A planned polishing path in the world frame [m] with its coverage of the fitted surface.

    `path.points`/`path.normals` (N, 3) lie on the fitted surface (process points);
    `commanded` (N, 3) are the TCP targets, process points moved `offset` = F/k [m] into the
    surface; `tool_z` (N, 3) unit tool axes into the surface.
    """

    path: ToolPath
    coverage: Coverage
    force: float  # [N]
    offset: float  # [m] D = F/k
    commanded: F64 = field(repr=False)

    @property
    def length(self) -> float:
        """Return the length [m] of the process part of the path."""
        p = self.path.points[self.path.is_process]
        return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum())

    def summary(self) -> str:
        """Return a one-line human summary (mm, %)."""
        p = self.path
        return (
            f"{p.pattern}: {int(p.is_process.sum())} points, {p.n_passes} passes, "
            f"{self.length * 1000:.0f} mm long; coverage {self.coverage.fraction * 100:.1f} % "
            f"(tool radius {self.coverage.tool_radius / _MM:g} mm), largest gap "
            f"{self.coverage.largest_gap / _MM:.1f} mm; offset D = F/k = {self.offset / _MM:.2f} mm"
        )


def point_labels(path: ToolPath) -> list[str]:
    """Return a name per path point: 'lead-in 1', 'process point 17', 'lead-out 2'."""
    count = {0: 0, 1: 0, 2: 0}
    out = []
    for k in path.kind.tolist():
        count[k] += 1
        out.append(f"{_KIND_NAMES[k]} {count[k]}")
    return out


def check_path_lengths(mesh: trimesh.Trimesh, step: float, spacing: float) -> None:
    """Raise `InputError` naming `step` or `spacing` [m] when it is not below the part's largest
    extent (the message in mm, as the project file gives them)."""
    size = float(np.ptp(np.asarray(mesh.vertices), axis=0).max())
    for name, val in (("step", step), ("spacing", spacing)):
        if val >= size:
            raise InputError(
                f"{val / _MM:g} mm is larger than the part (largest extent "
                f"{size / _MM:.1f} mm); give a {name} well below the part size",
                field=name,
            )


def plan_process_path(
    mesh: trimesh.Trimesh,
    chart: SurfaceChart,
    surface: BezierSurface,
    *,
    pattern: Pattern,
    step: float,
    spacing: float,
    lead_height: float,
    n_lead: int,
    tool_radius: float,
    force: float,
    stiffness: float,
    progress: Callable[[float, str], None] | None = None,
) -> PolishingPath:
    """Return the `PolishingPath` of `pattern` on the fitted `surface` of `mesh` (lengths in m).

    step: chord between points; spacing: between passes; lead_height, n_lead: the lead-in
    and lead-out points; coverage measured for `tool_radius`; commanded points pressed
    D = force/stiffness [N, N/m] into the surface; `progress(fraction, message)` hears of
    each stage. Raises `InputError` from the planner."""
    report = progress or (lambda f, m: None)
    if pattern not in PATTERNS:
        raise InputError(f"pattern: {pattern!r} is not one of {PATTERNS}")
    check_path_budget(mesh, pattern, step, spacing)
    report(0.2, f"{pattern} path")
    path = _PLANNERS[pattern](
        mesh,
        step,
        spacing,
        surface=surface,
        chart=chart,
        lead_height=lead_height,
        n_lead=n_lead,
    )
    report(0.7, "coverage")
    cov = path_coverage(surface, path, tool_radius)
    offset = force_offset(force, stiffness)
    commanded = path.pressed_points(force, stiffness)
    return PolishingPath(path, cov, float(force), offset, commanded)
