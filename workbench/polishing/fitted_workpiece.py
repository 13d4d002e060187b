"""A workpiece ready for path planning: loaded, placed in the world, charted and fitted."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.cad.step import StepTolerance, is_step
from workbench.errors import InputError
from workbench.polishing.bezier import BezierSurface, fit_bezier_triangles
from workbench.polishing.chart import SurfaceChart, build_chart
from workbench.polishing.choices import MeshUnits
from workbench.polishing.solid_workpiece import SolidWorkpiece, load_solid_workpiece
from workbench.polishing.workpiece import WorkpieceReport, load_workpiece


@dataclass(frozen=True)
class FittedWorkpiece:
    """The workpiece `mesh` in the world frame [m], the checks of its file (`report`), its
    planar `chart` and the quadratic Bézier `surface` fitted to it; `solid`: the STEP solid
    whose picked faces `mesh` is (None when the whole file is the surface)."""

    mesh: trimesh.Trimesh
    report: WorkpieceReport
    chart: SurfaceChart
    surface: BezierSurface
    solid: SolidWorkpiece | None = None


def fit_workpiece(
    path: str | Path,
    units: MeshUnits,
    T_world_workpiece: ArrayLike,
    tolerance: StepTolerance | None = None,
    name: str | None = None,
    faces: Sequence[int] | None = None,
) -> FittedWorkpiece:
    """Return the `FittedWorkpiece` of the mesh file `path` read in `units`, placed at
    `T_world_workpiece` (4, 4) [m]; a STEP file is tessellated with `tolerance`.

    A STEP file's mesh carries the exact surface normals at its vertices
    (``vertex_attributes["surface_normals"]``): the Bézier fit uses them instead of the
    area-weighted ones (on a tessellation's long triangles those are off by up to ~0.7 deg).

    Raises `MeshError` for a missing, empty or non-mesh file or a part in the wrong units
    (`load_workpiece`; messages name the file `name`, default `path`), and the chart's errors
    for a part that folds over (`build_chart`). `faces`: the STEP solid's faces to polish
    (`load_solid_workpiece`; None: the whole file is the surface)."""
    T = np.asarray(T_world_workpiece, dtype=float)
    solid = None
    if faces is None:
        mesh, report = load_workpiece(path, units=units, tolerance=tolerance, name=name)
    else:
        mesh, report, solid = load_solid_workpiece(path, faces, T, tolerance, name)
    if solid is None and report.is_watertight and is_step(path):
        raise InputError(
            f"workpiece {name or str(path)!r} is a closed STEP solid: its faces face every way;"
            " pick the faces to polish (`faces`: indices from `workbench polishing-faces` or"
            " the Polishing tab); the rest of the solid is then an obstacle",
            field="faces",
        )
    mesh.apply_transform(T)
    chart = build_chart(mesh)
    normals = chart.vertex_normals
    exact = mesh.vertex_attributes.get("surface_normals")
    if exact is not None:  # a STEP file: fit with the surface's own normals
        normals = _oriented(np.asarray(exact) @ T[:3, :3].T, chart.vertex_normals)
        mesh.vertex_attributes["surface_normals"] = normals
    surface = fit_bezier_triangles(mesh, vertex_normals=normals)
    return FittedWorkpiece(mesh, report, chart, surface, solid)


def _oriented(exact: NDArray[np.float64], area: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return the exact unit normals on the side of the area-weighted ones; the area-weighted
    one where an exact normal is missing (zero length: a singular point of the surface)."""
    length = np.linalg.norm(exact, axis=1, keepdims=True)
    unit = np.where(length > 0.5, exact / np.maximum(length, 1e-300), area)
    return np.where(np.einsum("ij,ij->i", unit, area)[:, None] < 0, -unit, unit)
