"""Raster (zig-zag) polishing paths on the fitted surface, with a contour pass round the rim."""

from __future__ import annotations

import numpy as np
import trimesh
from numpy.typing import NDArray
from shapely.geometry import LineString, Polygon

from workbench.errors import InputError
from workbench.polishing.bezier import BezierSurface
from workbench.polishing.chart import SurfaceChart, build_chart
from workbench.polishing.offsets import offset_ring, resample_closed
from workbench.polishing.stepping import chord_step
from workbench.polishing.toolpath import ToolPath, chart_surface, check_lengths, with_leads

F64 = NDArray[np.float64]


def raster_toolpath(
    mesh: trimesh.Trimesh,
    step: float,
    spacing: float,
    *,
    surface: BezierSurface | None = None,
    chart: SurfaceChart | None = None,
    lead_height: float = 0.01,
    n_lead: int = 3,
) -> ToolPath:
    """Return a zig-zag raster `ToolPath` along the part's long axis (lengths in m).

    A contour pass runs round the rim first (the first spiral ring, spacing/2 in from the
    boundary); then rows run along the chart's u axis inside it; the next row's chart offset is `spacing` divided by the largest stretch of
    the faces between them, so no two rows lie more than `spacing` apart on the surface.
    Same arguments and errors as `spiral_toolpath`.
    """
    check_lengths(mesh, step, spacing)
    chart = chart or build_chart(mesh)
    surface = surface or chart_surface(chart)
    ds = spacing / 8.0  # ring sampling; the path is densified to step/4 before stepping
    boundary = resample_closed(chart.boundary, ds)
    inner, _, _ = offset_ring(chart, boundary, 0.5 * spacing, ds)
    if len(inner) < 3:
        raise InputError(
            f"spacing = {spacing:g} m leaves no row on this part; give a smaller spacing"
        )
    poly = Polygon(inner)
    tri_v = chart.uv[chart.faces][:, :, 1]
    vmin, vmax = tri_v.min(axis=1), tri_v.max(axis=1)
    stretch_v = np.linalg.norm(chart.jacobian(np.arange(len(chart.faces)))[:, :, 1], axis=1)
    lo, hi = float(inner[:, 1].min()), float(inner[:, 1].max())
    ulo, uhi = float(inner[:, 0].min()) - 1.0, float(inner[:, 0].max()) + 1.0
    # A contour pass round the rim first, then rows from half a spacing above it.
    rows: list[F64] = [np.vstack([inner, inner[:1]])]
    band0 = (vmax >= lo) & (vmin <= lo + spacing)
    v = lo + 0.5 * spacing / float(stretch_v[band0].max() if band0.any() else 1.0)
    while v < hi:
        cut = poly.intersection(LineString([(ulo, v), (uhi, v)]))
        segs = [
            np.asarray(g.coords)
            for g in getattr(cut, "geoms", [cut])
            if not g.is_empty and g.length > 0
        ]
        segs.sort(key=lambda a: a[:, 0].min())
        for seg in segs:
            a, b = seg[:, 0].min(), seg[:, 0].max()
            n = max(int(np.ceil((b - a) / ds)), 1) + 1
            line = np.stack([np.linspace(a, b, n), np.full(n, v)], axis=1)
            rows.append(line if len(rows) % 2 == 1 else line[::-1])
        band = (vmax >= v) & (vmin <= v + spacing)
        v += spacing / float(stretch_v[band].max() if band.any() else 1.0)
    if not rows:
        raise InputError(
            f"spacing = {spacing:g} m leaves no row on this part; give a smaller spacing"
        )
    pts, nrm, face, bary = chord_step(chart, surface, np.vstack(rows), step)
    return with_leads(
        pts,
        nrm,
        face,
        bary,
        pattern="raster",
        step=step,
        spacing=spacing,
        n_passes=len(rows) - 1,
        lead_height=lead_height,
        n_lead=n_lead,
    )
