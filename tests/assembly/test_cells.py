from __future__ import annotations

import numpy as np
import pytest
import trimesh

from workbench.assembly.cells import subdivide, winding_number
from workbench.assembly.example_scene import plate_mesh, screw_mesh
from workbench.errors import InputError, MeshError


def _cell_of(grid, p):
    return np.floor((p - grid.origin) / grid.cell_size).astype(int)


@pytest.mark.parametrize("make,c", [(plate_mesh, 0.004), (screw_mesh, 0.001)])
def test_cells_cover_the_solid_and_its_surface(make, c):
    mesh = make()
    g = subdivide(mesh, c)
    rng = np.random.default_rng(0)
    lo, hi = mesh.bounds
    pts = rng.uniform(lo, hi, (4000, 3))
    inside = mesh.contains(pts)  # trimesh ray test: the independent twin
    idx = _cell_of(g, pts[inside])
    assert inside.sum() > 200
    assert g.occupied[idx[:, 0], idx[:, 1], idx[:, 2]].all()
    surf, _ = trimesh.sample.sample_surface(mesh, 3000, seed=0)
    idx = _cell_of(g, surf)
    assert g.boundary[idx[:, 0], idx[:, 1], idx[:, 2]].all()
    # Kept cells are not much more than the solid: total cell volume vs mesh volume.
    assert g.occupied.sum() * c**3 < mesh.volume + g.boundary.sum() * c**3


def test_interior_cells_lie_inside_by_winding_number():
    mesh = trimesh.creation.box([0.1, 0.08, 0.06])
    g = subdivide(mesh, 0.01)
    interior = g.occupied & ~g.boundary
    centers = g.origin + (np.argwhere(interior) + 0.5) * g.cell_size
    assert len(centers) == 8 * 6 * 4 or len(centers) > 0
    assert np.all(np.abs(winding_number(centers, mesh) - 1.0) < 1e-9)


def test_winding_number_matches_trimesh_contains():
    mesh = plate_mesh()
    rng = np.random.default_rng(3)
    pts = rng.uniform(mesh.bounds[0] - 0.01, mesh.bounds[1] + 0.01, (500, 3))
    w = winding_number(pts, mesh)
    assert np.array_equal(w > 0.5, mesh.contains(pts))
    assert np.all((np.abs(w) < 1e-6) | (np.abs(w - 1) < 1e-6))


@pytest.mark.parametrize("c", [0.0, -0.001, float("nan"), 0.5])
def test_bad_cell_size_is_refused(c):
    with pytest.raises(InputError, match="cell_size"):
        subdivide(screw_mesh(), c)


def test_open_mesh_is_refused_by_checker():
    from workbench.assembly.interference import InterferenceChecker

    open_mesh = trimesh.creation.box([0.1, 0.1, 0.1])
    open_mesh.update_faces(np.arange(len(open_mesh.faces)) != 0)
    with pytest.raises(MeshError, match="not closed"):
        InterferenceChecker(open_mesh, [trimesh.creation.box([1, 1, 1])])
    with pytest.warns(RuntimeWarning, match="not closed"):
        InterferenceChecker(screw_mesh(), [open_mesh])
