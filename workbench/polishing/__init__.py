"""Polishing free-form surfaces (seed 004): import, Bézier fit, tool paths, hybrid force control."""

from __future__ import annotations

from workbench.polishing.bezier import BezierSurface, fit_bezier_triangles
from workbench.polishing.chart import SurfaceChart, build_chart
from workbench.polishing.coverage import Coverage, path_coverage
from workbench.polishing.force_control import (
    ForceControlResult,
    HybridForceParams,
    simulate_hybrid_force_control,
)
from workbench.polishing.raster import raster_toolpath
from workbench.polishing.toolpath import (
    LEAD_IN,
    LEAD_OUT,
    PROCESS,
    ToolPath,
    force_offset,
    spiral_toolpath,
)
from workbench.polishing.workpiece import WorkpieceReport, inspect_mesh, load_workpiece

__all__ = [
    "LEAD_IN",
    "LEAD_OUT",
    "PROCESS",
    "BezierSurface",
    "Coverage",
    "ForceControlResult",
    "HybridForceParams",
    "SurfaceChart",
    "ToolPath",
    "WorkpieceReport",
    "build_chart",
    "fit_bezier_triangles",
    "force_offset",
    "inspect_mesh",
    "load_workpiece",
    "path_coverage",
    "raster_toolpath",
    "simulate_hybrid_force_control",
    "spiral_toolpath",
]
