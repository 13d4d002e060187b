"""The fitted surface's display mesh (`surface_mesh.py`), each patch split into four.

Twins: the patches evaluated directly at their corners and edge midpoints; the flat mesh's
area (the curved panel's patches bulge little over a fine grid).
"""

from __future__ import annotations

import numpy as np

from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.surface_mesh import subdivided_surface_mesh


def _area(v: np.ndarray, f: np.ndarray) -> float:
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    return float(0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum())


def test_each_patch_becomes_four_triangles_through_its_edge_midpoints() -> None:
    mesh = make_panel(12, 9)
    surface = fit_bezier_triangles(mesh)
    v, f = subdivided_surface_mesh(surface)
    n = len(mesh.faces)
    assert f.shape == (4 * n, 3) and v.shape == (len(mesh.vertices) + 3 * n, 3)
    assert f.min() == 0 and f.max() == len(v) - 1
    # Corners are the mesh's vertices; the new vertices are the patches at their midpoints.
    np.testing.assert_array_equal(v[: len(mesh.vertices)], surface.vertices)
    mids = np.array([[0.5, 0.5, 0.0], [0.0, 0.5, 0.5], [0.5, 0.0, 0.5]])
    for i in (0, n // 2, n - 1):
        on = surface.evaluate(np.full(3, i), mids)
        np.testing.assert_allclose(
            v[len(mesh.vertices) + 3 * i : len(mesh.vertices) + 3 * i + 3], on
        )
    # Same orientation as the flat mesh, and nearly its area.
    flat = np.asarray(mesh.faces)
    assert abs(_area(v, f) / _area(np.asarray(mesh.vertices), flat) - 1) < 1e-3
    n_flat = np.cross(*(mesh.vertices[flat[:, k]] - mesh.vertices[flat[:, 0]] for k in (1, 2)))
    n_sub = np.cross(*(v[f[:n, k]] - v[f[:n, 0]] for k in (1, 2)))
    assert (np.einsum("ij,ij->i", n_flat, n_sub) > 0).all()


def test_large_meshes_are_drawn_flat() -> None:
    mesh = make_panel(12, 9)
    surface = fit_bezier_triangles(mesh)
    v, f = subdivided_surface_mesh(surface, max_faces=len(mesh.faces) - 1)
    np.testing.assert_array_equal(v, surface.vertices)
    np.testing.assert_array_equal(f, surface.faces)
