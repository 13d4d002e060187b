"""Polishing tool paths: the `ToolPath` record, lead moves, force offset and the spiral.

Paths are planned in the surface's planar chart (`chart.py`) and lifted onto the fitted
Bézier surface (`bezier.py`) with chord stepping (`stepping.py`), so every process point
lies on the fitted surface. The raster pattern is in `raster.py`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.polishing.bezier import BezierSurface
from workbench.polishing.chart import SurfaceChart, build_chart
from workbench.polishing.offsets import offset_ring, resample_closed, ring_area
from workbench.polishing.stepping import chord_step

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]

LEAD_IN, PROCESS, LEAD_OUT = 0, 1, 2


@dataclass(frozen=True)
class ToolPath:
    """A polishing path. points (N, 3) [m]; normals (N, 3) unit surface normals on the tool
    side; kind (N,) LEAD_IN / PROCESS / LEAD_OUT; face (N,) and bary (N, 3) locate process
    points on the fitted surface (-1 / NaN for lead points). The tool z axis is -normals."""

    points: F64
    normals: F64
    kind: NDArray[np.int8]
    face: I64
    bary: F64
    pattern: str
    step: float  # chord step [m]
    spacing: float  # distance between neighbouring passes [m]
    n_passes: int

    @property
    def tool_z(self) -> F64:
        """Return the tool z axes (N, 3): along the surface normal, pointing into the surface."""
        return -self.normals

    @property
    def is_process(self) -> NDArray[np.bool_]:
        """Return the mask (N,) of points on the surface (not lead-in/out)."""
        return self.kind == PROCESS

    @property
    def is_lead_in(self) -> NDArray[np.bool_]:
        """Return the mask (N,) of lead-in points."""
        return self.kind == LEAD_IN

    @property
    def is_lead_out(self) -> NDArray[np.bool_]:
        """Return the mask (N,) of lead-out points."""
        return self.kind == LEAD_OUT

    def pressed_points(self, force: float, stiffness: float) -> F64:
        """Return the commanded points (N, 3) [m]: process points moved D = F/k into the surface."""
        d = force_offset(force, stiffness)
        return self.points - d * self.is_process[:, None] * self.normals


def force_offset(force: float, stiffness: float) -> float:
    """Return D = F / k [m], the offset into the surface that gives contact force F [N] at stiffness k [N/m]."""
    if not np.isfinite(force) or force <= 0:
        raise InputError(f"force must be > 0 N, got {force!r}")
    if not np.isfinite(stiffness) or stiffness <= 0:
        raise InputError(f"stiffness must be > 0 N/m, got {stiffness!r}")
    return float(force) / float(stiffness)


def check_lengths(mesh: trimesh.Trimesh, step: float, spacing: float) -> float:
    """Return the part's largest extent [m]; raise `InputError` for a bad step or spacing."""
    rows = np.ascontiguousarray(np.asarray(mesh.vertices, dtype=float).T)  # fast reductions
    size = float((rows.max(axis=1) - rows.min(axis=1)).max())
    for name, val in (("step", step), ("spacing", spacing)):
        if not np.isfinite(val) or val <= 0:
            raise InputError(f"{name} must be a positive length in m, got {val!r}")
        if val >= size:
            raise InputError(
                f"{name} = {val:g} m is larger than the part (largest extent {size:g} m); "
                f"give {name} in metres, well below the part size"
            )
    return size


def with_leads(
    pts: F64,
    nrm: F64,
    face: I64,
    bary: F64,
    *,
    pattern: str,
    step: float,
    spacing: float,
    n_passes: int,
    lead_height: float,
    n_lead: int,
) -> ToolPath:
    """Return the `ToolPath` of process points with n_lead lead-in/out points along the normal."""
    if not isinstance(n_lead, int | np.integer) or n_lead < 1:
        raise InputError(f"n_lead must be an integer >= 1, got {n_lead!r}")
    if not np.isfinite(lead_height) or lead_height <= 0:
        raise InputError(f"lead_height must be > 0 m, got {lead_height!r}")
    h = lead_height * np.linspace(1.0, 1.0 / n_lead, n_lead)[:, None]
    lead_in = pts[0] + h * nrm[0]
    lead_out = pts[-1] + h[::-1] * nrm[-1]
    kind = np.concatenate(
        [np.full(n_lead, LEAD_IN), np.full(len(pts), PROCESS), np.full(n_lead, LEAD_OUT)]
    )
    nan3 = np.full((n_lead, 3), np.nan)
    return ToolPath(
        points=np.vstack([lead_in, pts, lead_out]),
        normals=np.vstack([np.repeat(nrm[:1], n_lead, 0), nrm, np.repeat(nrm[-1:], n_lead, 0)]),
        kind=kind.astype(np.int8),
        face=np.concatenate([np.full(n_lead, -1), face, np.full(n_lead, -1)]).astype(np.int64),
        bary=np.vstack([nan3, bary, nan3]),
        pattern=pattern,
        step=float(step),
        spacing=float(spacing),
        n_passes=n_passes,
    )


def chart_surface(chart: SurfaceChart) -> BezierSurface:
    """Return the `BezierSurface` of the chart's mesh fitted with the chart's vertex normals:
    `fit_bezier_triangles(mesh, vertex_normals=chart.vertex_normals)` without its O(V + F)
    checks and normalisation (the chart's normals are unit, nonzero at every used vertex:
    no face folds, so each vertex's area vectors sum to a positive e_n component)."""
    return BezierSurface(
        vertices=chart.vertices, faces=chart.faces, vertex_normals=chart.vertex_normals
    )


def spiral_rings(
    chart: SurfaceChart, spacing: float, ds: float, *, max_rings: int = 10000
) -> list[tuple[F64, F64]]:
    """Return [(ring (n,2), foot (n,2)), ...]: nested offset rings in the chart, outermost first.

    The first ring lies spacing/2 inside the boundary; each next one `spacing` [m, on the
    surface] inside the last. foot[j] is the point of the previous ring ring[j] grew from.
    """
    boundary = resample_closed(chart.boundary, ds)
    ring, foot, _ = offset_ring(chart, boundary, 0.5 * spacing, ds)
    rings: list[tuple[F64, F64]] = []
    last_area = np.inf
    while len(ring) >= 3 and len(rings) < max_rings:
        area = ring_area(ring)
        if area <= 0 or area >= last_area:
            break
        rings.append((ring, foot))
        last_area = area
        ref = resample_closed(ring, ds)
        nxt, nfoot, _ = offset_ring(chart, ref, spacing, ds)
        if len(nxt) < 3:
            # A last, narrow lap around the middle, half a spacing in.
            nxt, nfoot, _ = offset_ring(chart, ref, 0.5 * spacing, ds)
            if len(nxt) >= 3 and ring_area(nxt) > 0:
                rings.append((nxt, nfoot))
            break
        ring, foot = nxt, nfoot
    return rings


def _spiral_uv(rings: list[tuple[F64, F64]], ds: float) -> F64:
    """Return one continuous chart polyline: the outer ring once round (less the first two
    spacings, which lap 0 covers), then laps that each move from one ring to the next, then
    nine tenths of the innermost ring. ds: the rings' sampling step [m] (spacing / 8)."""
    parts = []
    if len(rings) > 1:
        # The outer ring as the next one grew from it (resampled), starting where lap 0 starts.
        first = resample_closed(rings[0][0], ds)
        k = int(np.argmin(np.linalg.norm(first - rings[1][1][0], axis=1)))
        first = np.roll(first, -k, axis=0)
        # Start two spacings (16 ds) after lap 0's start, so the path never returns to its
        # first point: lap 0 passes the start a fraction of a spacing inside the rim pass.
        arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(first, axis=0), axis=1))])
        j = min(int(np.searchsorted(arc, 16.0 * ds)), len(first) - 2)
        parts.append(np.vstack([first[j:], first[:1]]))
    for i in range(len(rings) - 1):
        nxt, foot = rings[i + 1]
        # Lap i runs along ring i (through the feet of ring i+1) while drifting linearly to ring i+1.
        seg = np.linalg.norm(np.diff(foot, axis=0), axis=1)
        s = np.concatenate([[0.0], np.cumsum(seg)])
        phi = (s / s[-1])[:, None] if s[-1] > 0 else np.zeros((len(foot), 1))
        parts.append(foot + phi * (nxt - foot))
    last = rings[-1][0]
    if len(rings) == 1:
        parts.append(np.vstack([last, last[:1]]))
    else:
        # Round the innermost ring, stopping a tenth short of where the last lap joined it:
        # the lap's end runs alongside the ring there, within a tenth of a spacing.
        parts.append(last[: max(int(0.9 * len(last)), 2)])
    return np.vstack(parts)


def spiral_toolpath(
    mesh: trimesh.Trimesh,
    step: float,
    spacing: float,
    *,
    surface: BezierSurface | None = None,
    chart: SurfaceChart | None = None,
    lead_height: float = 0.01,
    n_lead: int = 3,
) -> ToolPath:
    """Return a spiral `ToolPath` on the fitted surface of `mesh` (lengths in m).

    step: chord between consecutive points [m]; spacing: distance between laps on the
    surface [m]; lead_height: height of the first lead-in / last lead-out point above the
    surface along the normal [m], with n_lead points each. surface/chart: reuse a fit.
    Raises `InputError` for step or spacing <= 0 or not below the part's size, and for a
    surface that folds over its mean plane.
    """
    check_lengths(mesh, step, spacing)
    chart = chart or build_chart(mesh)
    surface = surface or chart_surface(chart)
    ds = spacing / 8.0  # ring sampling; the path is densified to step/4 before stepping
    rings = spiral_rings(chart, spacing, ds)
    if not rings:
        raise InputError(
            f"spacing = {spacing:g} m leaves no lap on this part; give a smaller spacing"
        )
    pts, nrm, face, bary = chord_step(chart, surface, _spiral_uv(rings, ds), step)
    return with_leads(
        pts,
        nrm,
        face,
        bary,
        pattern="spiral",
        step=step,
        spacing=spacing,
        n_passes=len(rings),
        lead_height=lead_height,
        n_lead=n_lead,
    )
