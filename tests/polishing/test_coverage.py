"""Coverage: KD-tree distances against brute-force point-segment distances, and a closed form."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.coverage import path_coverage, polyline_distance
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.toolpath import PROCESS, ToolPath, spiral_toolpath


def _brute(points: np.ndarray, path: np.ndarray) -> np.ndarray:
    a, b = path[:-1], path[1:]
    ab = b - a
    t = np.clip(
        np.einsum("psk,sk->ps", points[:, None] - a[None], ab) / np.sum(ab * ab, axis=1), 0, 1
    )
    closest = a[None] + t[..., None] * ab[None]
    return np.linalg.norm(points[:, None] - closest, axis=2).min(axis=1)


def test_polyline_distance_matches_brute_force() -> None:
    rng = np.random.default_rng(0)
    path = np.cumsum(rng.normal(0, 0.01, (40, 3)), axis=0)
    pts = rng.uniform(path.min(0), path.max(0), (500, 3))
    exact = _brute(pts, path)
    approx = polyline_distance(pts, path, resolution=1e-4)
    assert np.all(approx >= exact - 1e-12)
    assert np.all(approx - exact <= 0.5e-4 + 1e-12)


def _line_path(points: np.ndarray) -> ToolPath:
    n = len(points)
    return ToolPath(
        points=points,
        normals=np.tile([0.0, 0.0, 1.0], (n, 1)),
        kind=np.full(n, PROCESS, dtype=np.int8),
        face=np.zeros(n, dtype=np.int64),
        bary=np.zeros((n, 3)),
        pattern="line",
        step=0.001,
        spacing=0.01,
        n_passes=1,
    )


def test_centre_line_on_flat_strip_covers_2r_over_w() -> None:
    # Flat strip L x W = 0.3 x 0.2 m; a path along its centre line covers 2 r L of L W.
    mesh = make_panel(31, 21)
    mesh.vertices[:, 2] = 0.0
    surface = fit_bezier_triangles(mesh)
    x = np.linspace(-0.15, 0.15, 301)
    path = _line_path(np.stack([x, np.zeros_like(x), np.zeros_like(x)], axis=1))
    r = 0.03
    cov = path_coverage(surface, path, r, n_samples=20000)
    assert cov.fraction == pytest.approx(2 * r / 0.2, abs=0.01)
    assert cov.max_distance == pytest.approx(0.1, abs=2e-3)
    assert cov.largest_gap == pytest.approx(2 * (cov.max_distance - r))


def test_spiral_on_example_covers_the_panel() -> None:
    mesh = make_panel()
    surface = fit_bezier_triangles(mesh)
    path = spiral_toolpath(mesh, 0.002, 0.01, surface=surface)
    cov = path_coverage(surface, path, 0.006)
    assert cov.fraction > 0.99
    assert cov.largest_gap < 0.004  # only the panel's four corners lie beyond the tool
    with pytest.raises(InputError, match="tool_radius"):
        path_coverage(surface, path, 0.0)
