"""Tool paths: on the fitted surface, chord steps, nested non-crossing laps, leads, bad input.

Twins: a least-squares projection onto the fitted surface, shapely's polygon buffer
(flat plate) and predicates (simple, nested), KD-tree distances between laps.
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from scipy.optimize import least_squares
from scipy.spatial import cKDTree
from shapely.geometry import LineString, Polygon

from workbench.errors import InputError
from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.chart import build_chart
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.raster import raster_toolpath
from workbench.polishing.toolpath import (
    LEAD_IN,
    LEAD_OUT,
    force_offset,
    spiral_rings,
    spiral_toolpath,
)


def _grid(nx: int, ny: int, hx: float, hy: float, height, keep=None) -> trimesh.Trimesh:
    mesh = make_panel(nx, ny, half_x=hx, half_y=hy)
    v = np.asarray(mesh.vertices).copy()
    v[:, 2] = height(v[:, 0], v[:, 1])
    faces = np.asarray(mesh.faces)
    if keep is not None:
        c = v[faces].mean(axis=1)
        faces = faces[keep(c[:, 0], c[:, 1])]
    m = trimesh.Trimesh(v, faces, process=False)
    m.remove_unreferenced_vertices()
    return m


WORKPIECES = {
    "panel": lambda: make_panel(),
    "saddle": lambda: _grid(40, 30, 0.12, 0.08, lambda x, y: 2.0 * (x**2 - y**2)),
    "flat": lambda: _grid(20, 15, 0.1, 0.06, lambda x, y: 0.0 * x),
    "l_shape": lambda: _grid(
        41,
        41,
        0.1,
        0.1,
        lambda x, y: 0.3 * (x**2 + y**2),
        keep=lambda x, y: ~((x > 0.02) & (y > 0.02)),
    ),
    "ellipse_dome": lambda: _grid(
        50,
        40,
        0.1,
        0.07,
        lambda x, y: 0.05 - 1.5 * (x**2 + y**2),
        keep=lambda x, y: (x / 0.1) ** 2 + (y / 0.07) ** 2 < 0.9,
    ),
}


def _project(surface, face0: int, bary0: np.ndarray, p: np.ndarray, faces: np.ndarray) -> float:
    """Twin: distance from p to the fitted surface by least squares over nearby patches."""
    best = np.inf
    for f in faces:

        def res(x, f=f):
            b = np.array([x[0], x[1], 1.0 - x[0] - x[1]])
            return surface.evaluate([f], b[None])[0] - p

        sol = least_squares(
            res, x0=[1 / 3, 1 / 3], bounds=([0, 0], [1, 1]), xtol=1e-15, ftol=1e-15, gtol=1e-15
        )
        u, v = sol.x
        if u + v <= 1 + 1e-12:
            best = min(best, float(np.linalg.norm(sol.fun)))
    return best


def test_spiral_points_lie_on_fitted_surface_with_chord_steps() -> None:
    mesh = make_panel()
    surface = fit_bezier_triangles(mesh)
    path = spiral_toolpath(mesh, 0.002, 0.01, surface=surface)
    proc = path.is_process
    pts, face = path.points[proc], path.face[proc]
    rng = np.random.default_rng(0)
    idx = rng.choice(len(pts), 15, replace=False)
    adj = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False).face_adjacency
    for i in idx:
        near = np.unique(np.concatenate([[face[i]], adj[(adj == face[i]).any(axis=1)].ravel()]))
        assert _project(surface, face[i], path.bary[proc][i], pts[i], near) < 1e-6
    chords = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    np.testing.assert_allclose(chords[:-1], 0.002, atol=1e-6)
    assert 0 < chords[-1] <= 0.002 + 1e-6
    # Normals are the fitted surface's, facing the tool side (+z for this dome).
    np.testing.assert_allclose(
        path.normals[proc], surface.normal(face, path.bary[proc]), atol=1e-12
    )
    assert (path.tool_z[proc][:, 2] < -0.9).all()


@pytest.mark.parametrize("name", sorted(WORKPIECES))
def test_laps_are_nested_never_cross_and_keep_spacing(name: str) -> None:
    mesh = WORKPIECES[name]()
    chart = build_chart(mesh)
    surface = fit_bezier_triangles(mesh)
    spacing = 0.01
    rings = spiral_rings(chart, spacing, spacing / 8)
    assert len(rings) >= 3
    polys = [Polygon(r) for r, _ in rings]
    for a, b in zip(polys, polys[1:], strict=False):
        assert a.is_valid and b.is_valid
        assert a.contains(b)  # nested: ring i+1 strictly inside ring i, so no crossing
    # On the surface the laps are `spacing` apart: distances of ring i+1 to ring i in 3D.
    lifted = []
    for r, _ in rings:
        f, b = chart.locate(r)
        lifted.append(surface.evaluate(f, b))
    for i in range(len(rings) - 2):  # the last ring is the narrow half-spacing lap
        d, _ = cKDTree(_dense(lifted[i])).query(lifted[i + 1])
        assert np.median(d) == pytest.approx(spacing, rel=0.03)
        assert d.min() > 0.85 * spacing
    # The spiral itself does not cross itself in the chart.
    path = spiral_toolpath(mesh, 0.003, spacing, surface=surface, chart=chart)
    uv = (path.points[path.is_process] - chart.origin) @ chart.axes[:2].T
    assert LineString(uv).is_simple


def _dense(p: np.ndarray, n: int = 8) -> np.ndarray:
    closed = np.vstack([p, p[:1]])
    t = np.linspace(0, 1, n, endpoint=False)[:, None, None]
    return (closed[:-1][None] * (1 - t) + closed[1:][None] * t).reshape(-1, 3)


def test_flat_plate_rings_match_shapely_buffer() -> None:
    mesh = WORKPIECES["flat"]()
    chart = build_chart(mesh)
    spacing, ds = 0.01, 0.0005
    rings = spiral_rings(chart, spacing, ds)
    outline = Polygon(chart.boundary)
    expected = outline.buffer(-0.5 * spacing, join_style="mitre")
    assert Polygon(rings[0][0]).hausdorff_distance(expected) < 2 * ds
    for (a, _), (b, _) in zip(rings[:-2], rings[1:-1], strict=True):
        twin = Polygon(a).buffer(-spacing, join_style="mitre")
        assert Polygon(b).hausdorff_distance(twin) < 2 * ds


def test_leads_and_force_offset() -> None:
    mesh = make_panel(30, 20)
    path = spiral_toolpath(mesh, 0.004, 0.015, lead_height=0.01, n_lead=3)
    assert path.kind[:3].tolist() == [LEAD_IN] * 3 and path.kind[-3:].tolist() == [LEAD_OUT] * 3
    assert path.is_lead_in.sum() == 3 and path.is_lead_out.sum() == 3
    first = path.points[path.is_process][0]
    heights = (path.points[:3] - first) @ path.normals[3]
    np.testing.assert_allclose(heights, [0.01, 0.01 * 2 / 3, 0.01 / 3], atol=1e-12)
    last = path.points[path.is_process][-1]
    np.testing.assert_allclose(
        (path.points[-3:] - last) @ path.normals[-4], [0.01 / 3, 0.01 * 2 / 3, 0.01], atol=1e-12
    )
    # D = F / k = 20 N / 5000 N/m = 4 mm (the seed's N/m^2 is a typo), into the surface.
    assert force_offset(20.0, 5000.0) == pytest.approx(0.004)
    pressed = path.pressed_points(20.0, 5000.0)
    d = pressed - path.points
    np.testing.assert_allclose(np.linalg.norm(d[path.is_process], axis=1), 0.004, atol=1e-12)
    np.testing.assert_allclose(d[path.is_process] / 0.004, path.tool_z[path.is_process], atol=1e-12)
    assert np.all(d[~path.is_process] == 0)


def test_bad_input() -> None:
    mesh = make_panel(20, 15)
    with pytest.raises(InputError, match="step"):
        spiral_toolpath(mesh, 0.5, 0.01)  # step larger than the 0.3 m part
    with pytest.raises(InputError, match="spacing"):
        spiral_toolpath(mesh, 0.002, 0.0)
    with pytest.raises(InputError, match="spacing"):
        raster_toolpath(mesh, 0.002, -0.01)
    with pytest.raises(InputError, match="step"):
        raster_toolpath(mesh, float("nan"), 0.01)
    with pytest.raises(InputError, match="folds"):
        spiral_toolpath(trimesh.creation.icosphere(subdivisions=2, radius=0.1), 0.002, 0.01)
    with pytest.raises(InputError, match="n_lead"):
        spiral_toolpath(mesh, 0.004, 0.015, n_lead=0)
    with pytest.raises(InputError, match="lead_height"):
        raster_toolpath(mesh, 0.004, 0.015, lead_height=-0.01)
    with pytest.raises(InputError, match="force"):
        force_offset(0.0, 5000.0)
    with pytest.raises(InputError, match="stiffness"):
        force_offset(20.0, 0.0)
