"""A workpiece ready for path planning: loaded, placed in the world, charted and fitted."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh
from numpy.typing import ArrayLike

from workbench.polishing.bezier import BezierSurface, fit_bezier_triangles
from workbench.polishing.chart import SurfaceChart, build_chart
from workbench.polishing.choices import MeshUnits
from workbench.polishing.workpiece import WorkpieceReport, load_workpiece


@dataclass(frozen=True)
class FittedWorkpiece:
    """The workpiece `mesh` in the world frame [m], the checks of its file (`report`), its
    planar `chart` and the quadratic Bézier `surface` fitted to it."""

    mesh: trimesh.Trimesh
    report: WorkpieceReport
    chart: SurfaceChart
    surface: BezierSurface


def fit_workpiece(
    path: str | Path, units: MeshUnits, T_world_workpiece: ArrayLike
) -> FittedWorkpiece:
    """Return the `FittedWorkpiece` of the mesh file `path` read in `units`, placed at
    `T_world_workpiece` (4, 4) [m].

    Raises `MeshError` for a missing, empty or non-mesh file or a part in the wrong units
    (`load_workpiece`), and the chart's errors for a part that folds over (`build_chart`)."""
    mesh, report = load_workpiece(path, units=units)
    mesh.apply_transform(np.asarray(T_world_workpiece, dtype=float))
    chart = build_chart(mesh)
    surface = fit_bezier_triangles(mesh, vertex_normals=chart.vertex_normals)
    return FittedWorkpiece(mesh, report, chart, surface)
