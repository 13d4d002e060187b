"""The polishing path of a job (`process_path.py`): the pattern's planner, coverage, pressed
points, point names and the length check.

Twins: the planners and `path_coverage` called directly; D = F/k by hand.
"""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.polishing import PATTERNS, build_chart, fit_bezier_triangles, path_coverage
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.process_path import check_path_lengths, plan_process_path, point_labels
from workbench.polishing.raster import raster_toolpath
from workbench.polishing.toolpath import spiral_toolpath

PLANNERS = {"spiral": spiral_toolpath, "raster": raster_toolpath}


@pytest.fixture(scope="module")
def panel():  # type: ignore[no-untyped-def]
    mesh = make_panel(30, 20)
    chart = build_chart(mesh)
    return mesh, chart, fit_bezier_triangles(mesh, vertex_normals=chart.vertex_normals)


@pytest.mark.parametrize("pattern", PATTERNS)
def test_the_path_is_the_patterns_planner_with_coverage_and_pressed_points(panel, pattern) -> None:  # type: ignore[no-untyped-def]
    mesh, chart, surface = panel
    kw = dict(lead_height=0.01, n_lead=3)
    stages = []
    pp = plan_process_path(
        mesh, chart, surface, pattern=pattern, step=0.004, spacing=0.02, tool_radius=0.012,
        force=25.0, stiffness=5000.0, progress=lambda f, m: stages.append((f, m)), **kw,
    )  # fmt: skip
    twin = PLANNERS[pattern](mesh, 0.004, 0.02, surface=surface, chart=chart, **kw)
    np.testing.assert_array_equal(pp.path.points, twin.points)
    assert pp.path.pattern == pattern and pp.force == 25.0
    assert pp.offset == pytest.approx(25.0 / 5000.0)
    proc = pp.path.is_process
    np.testing.assert_allclose(
        pp.commanded[proc], twin.points[proc] - 0.005 * twin.normals[proc], atol=1e-15
    )
    np.testing.assert_array_equal(pp.commanded[~proc], twin.points[~proc])
    cov = path_coverage(surface, twin, 0.012)
    assert pp.coverage.fraction == cov.fraction
    seg = np.diff(twin.points[proc], axis=0)
    assert pp.length == pytest.approx(np.linalg.norm(seg, axis=1).sum())
    assert [m for _, m in stages] == [f"{pattern} path", "coverage"]
    assert f"{pattern}: {int(proc.sum())} points" in pp.summary()


def test_unknown_pattern_and_long_steps_are_named(panel) -> None:  # type: ignore[no-untyped-def]
    mesh, chart, surface = panel
    with pytest.raises(InputError, match=r"pattern: 'zigzag' is not one of \('spiral', 'raster'\)"):
        plan_process_path(
            mesh, chart, surface, pattern="zigzag", step=0.004, spacing=0.02,  # type: ignore[arg-type]
            lead_height=0.01, n_lead=3, tool_radius=0.01, force=20.0, stiffness=5000.0,
        )  # fmt: skip
    size = float(np.ptp(mesh.vertices, axis=0).max())
    check_path_lengths(mesh, 0.99 * size, 0.99 * size)
    with pytest.raises(
        InputError, match=r"^step: 400 mm is larger than the part \(largest extent 300\.0 mm\)"
    ):
        check_path_lengths(mesh, 0.4, 0.01)
    with pytest.raises(InputError, match=r"^spacing: .* give a spacing well below"):
        check_path_lengths(mesh, 0.01, size)


def test_points_are_named_by_kind_and_count(panel) -> None:  # type: ignore[no-untyped-def]
    mesh, chart, surface = panel
    path = spiral_toolpath(mesh, 0.004, 0.02, surface=surface, chart=chart, n_lead=2)
    names = point_labels(path)
    n_proc = int(path.is_process.sum())
    assert names[:3] == ["lead-in 1", "lead-in 2", "process point 1"]
    assert names[-3:] == [f"process point {n_proc}", "lead-out 1", "lead-out 2"]
