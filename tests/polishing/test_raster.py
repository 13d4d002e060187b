"""Raster paths: on the fitted surface, chord steps, rows covering the panel."""

from __future__ import annotations

import numpy as np

from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.coverage import path_coverage
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.raster import raster_toolpath


def test_raster_covers_rows_on_surface() -> None:
    mesh = make_panel()
    surface = fit_bezier_triangles(mesh)
    path = raster_toolpath(mesh, 0.002, 0.01, surface=surface)
    proc = path.is_process
    chords = np.linalg.norm(np.diff(path.points[proc], axis=0), axis=1)
    np.testing.assert_allclose(chords[:-1], 0.002, atol=1e-6)
    np.testing.assert_allclose(
        path.points[proc], surface.evaluate(path.face[proc], path.bary[proc]), atol=1e-15
    )
    assert path.pattern == "raster" and path.n_passes >= 19
    # Rows are at most `spacing` apart on the surface: a tool of radius 0.6 spacing covers all.
    cov = path_coverage(surface, path, 0.006)
    assert cov.fraction > 0.999
