"""Polishing free-form surfaces (seed 004): import, Bézier fit, tool paths, hybrid force control.

The public names load on first use (PEP 562): the project file's schema imports the light
modules (`choices`, `force_control`, `orientation`) without pulling in trimesh and scipy.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from workbench.polishing.bezier import BezierSurface, fit_bezier_triangles
    from workbench.polishing.chart import SurfaceChart, build_chart
    from workbench.polishing.choices import MESH_UNITS, PATTERNS, MeshUnits, Pattern
    from workbench.polishing.coverage import Coverage, path_coverage
    from workbench.polishing.example_workpiece import make_panel
    from workbench.polishing.fitted_workpiece import FittedWorkpiece, fit_workpiece
    from workbench.polishing.force_control import (
        ForceControlResult,
        HybridForceParams,
        simulate_hybrid_force_control,
    )
    from workbench.polishing.process_motion import ProcessMotion, plan_process_motion
    from workbench.polishing.process_path import PolishingPath, plan_process_path
    from workbench.polishing.raster import raster_toolpath
    from workbench.polishing.robot_path import tool_frames
    from workbench.polishing.simulation_report import PolishingSimulation, simulate_process
    from workbench.polishing.surface_mesh import subdivided_surface_mesh
    from workbench.polishing.toolpath import (
        LEAD_IN,
        LEAD_OUT,
        PROCESS,
        ToolPath,
        force_offset,
        spiral_toolpath,
    )
    from workbench.polishing.workpiece import WorkpieceReport, inspect_mesh, load_workpiece

_WHERE = {
    "bezier": ("BezierSurface", "fit_bezier_triangles"),
    "chart": ("SurfaceChart", "build_chart"),
    "choices": ("MESH_UNITS", "PATTERNS", "MeshUnits", "Pattern"),
    "coverage": ("Coverage", "path_coverage"),
    "example_workpiece": ("make_panel",),
    "fitted_workpiece": ("FittedWorkpiece", "fit_workpiece"),
    "force_control": ("ForceControlResult", "HybridForceParams", "simulate_hybrid_force_control"),
    "process_motion": ("ProcessMotion", "plan_process_motion"),
    "process_path": ("PolishingPath", "plan_process_path"),
    "raster": ("raster_toolpath",),
    "robot_path": ("tool_frames",),
    "simulation_report": ("PolishingSimulation", "simulate_process"),
    "surface_mesh": ("subdivided_surface_mesh",),
    "toolpath": ("LEAD_IN", "LEAD_OUT", "PROCESS", "ToolPath", "force_offset", "spiral_toolpath"),
    "workpiece": ("WorkpieceReport", "inspect_mesh", "load_workpiece"),
}
_MODULE = {name: module for module, names in _WHERE.items() for name in names}

__all__ = [
    "LEAD_IN",
    "LEAD_OUT",
    "MESH_UNITS",
    "PATTERNS",
    "PROCESS",
    "BezierSurface",
    "Coverage",
    "FittedWorkpiece",
    "ForceControlResult",
    "HybridForceParams",
    "MeshUnits",
    "Pattern",
    "PolishingPath",
    "PolishingSimulation",
    "ProcessMotion",
    "SurfaceChart",
    "ToolPath",
    "WorkpieceReport",
    "build_chart",
    "fit_bezier_triangles",
    "fit_workpiece",
    "force_offset",
    "inspect_mesh",
    "load_workpiece",
    "make_panel",
    "path_coverage",
    "plan_process_motion",
    "plan_process_path",
    "raster_toolpath",
    "simulate_hybrid_force_control",
    "simulate_process",
    "spiral_toolpath",
    "subdivided_surface_mesh",
    "tool_frames",
]


def __getattr__(name: str) -> Any:
    module = _MODULE.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted([*globals(), *__all__])
