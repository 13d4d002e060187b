"""Surface chart: point location against brute force, Jacobian, normals, boundary, errors."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError
from workbench.polishing.bezier import area_weighted_normals
from workbench.polishing.chart import build_chart
from workbench.polishing.example_workpiece import make_panel


def _brute_locate(uv: np.ndarray, faces: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Twin: barycentrics of every point in every face; the face where all are >= -1e-12.

    Points go 32 at a time (the same arithmetic; blocks that stay in the CPU's cache make it
    about 6x faster than one (points x faces) block)."""
    a, b, c = (uv[faces[:, i]] for i in range(3))
    v0, v1 = a - c, b - c
    det = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
    out = np.empty(len(p), dtype=np.intp)
    for s in range(0, len(p), 32):
        d = p[s : s + 32, None, :] - c[None]
        u = (d[..., 0] * v1[:, 1] - d[..., 1] * v1[:, 0]) / det
        v = (v0[:, 0] * d[..., 1] - v0[:, 1] * d[..., 0]) / det
        inside = (u >= -1e-12) & (v >= -1e-12) & (1 - u - v >= -1e-12)
        out[s : s + 32] = np.where(inside.any(axis=1), np.argmax(inside, axis=1), -1)
    return out


def test_locate_matches_brute_force() -> None:
    mesh = make_panel(25, 18)
    chart = build_chart(mesh)
    rng = np.random.default_rng(0)
    lo, hi = chart.uv.min(axis=0), chart.uv.max(axis=0)
    p = rng.uniform(lo - 0.02, hi + 0.02, (3000, 2))  # some outside the part
    face, bary = chart.locate(p)
    ref = _brute_locate(chart.uv, chart.faces, p)
    assert np.array_equal(face < 0, ref < 0)
    ok = face >= 0
    # Points on a shared edge may legitimately land in either face: compare positions instead.
    back = np.einsum("nk,nkj->nj", bary[ok], chart.uv[chart.faces[face[ok]]])
    np.testing.assert_allclose(back, p[ok], atol=1e-14)
    assert (bary[ok] >= 0).all()


def test_jacobian_and_normals() -> None:
    mesh = make_panel(20, 15)
    chart = build_chart(mesh)
    f = np.arange(len(mesh.faces))
    jac = chart.jacobian(f)
    tri3, tri2 = mesh.vertices[mesh.faces], chart.uv[mesh.faces]
    np.testing.assert_allclose(
        np.einsum("nij,nj->ni", jac, tri2[:, 0] - tri2[:, 2]), tri3[:, 0] - tri3[:, 2], atol=1e-15
    )
    np.testing.assert_allclose(
        np.einsum("nij,nj->ni", jac, tri2[:, 1] - tri2[:, 2]), tri3[:, 1] - tri3[:, 2], atol=1e-15
    )
    np.testing.assert_allclose(
        chart.vertex_normals,
        area_weighted_normals(np.asarray(mesh.vertices), np.asarray(mesh.faces)),
        atol=1e-12,
    )
    # The chart normal axis points to the faces' side (+z for the panel).
    assert chart.axes[2] @ [0.0, 0.0, 1.0] > 0.9
    flipped = trimesh.Trimesh(mesh.vertices, mesh.faces[:, ::-1], process=False)
    assert build_chart(flipped).axes[2] @ [0.0, 0.0, 1.0] < -0.9


def test_boundary_is_the_outline_counter_clockwise() -> None:
    mesh = make_panel(20, 15)
    chart = build_chart(mesh)
    outline = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False).outline()
    assert len(chart.boundary) == len(outline.entities[0].points) - 1  # trimesh closes the loop
    x, y = chart.boundary[:, 0], chart.boundary[:, 1]
    area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    assert area == pytest.approx(0.3 * 0.2, rel=0.05)  # projected panel area, positive: CCW


def test_folded_and_closed_meshes_are_refused() -> None:
    with pytest.raises(InputError, match="folds"):
        build_chart(trimesh.creation.icosphere(subdivisions=1, radius=0.1))
    # A closed, non-folding shape does not exist; an open hemisphere's rim faces fold (vertical).
    half = trimesh.creation.icosphere(subdivisions=2, radius=0.1)
    half = trimesh.Trimesh(
        half.vertices, half.faces[half.vertices[half.faces].mean(axis=1)[:, 2] > 0.02]
    )
    chart = build_chart(half)  # a cap well above the equator is a height field
    assert len(chart.boundary) > 10


def _uneven_mesh() -> trimesh.Trimesh:
    """A Delaunay mesh of a dense cluster in a sparse field: faces of very different sizes."""
    from scipy.spatial import Delaunay

    rng = np.random.default_rng(3)
    sparse = rng.uniform(-0.1, 0.1, (150, 2))
    dense = 0.03 + rng.normal(0.0, 0.004, (3000, 2))
    corners = np.array([[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]])
    xy = np.vstack([corners, sparse, dense])
    tri = Delaunay(xy).simplices
    z = 0.2 * (xy[:, 0] ** 2 + xy[:, 1] ** 2)
    return trimesh.Trimesh(np.column_stack([xy, z]), tri, process=False)


def test_locate_on_an_uneven_mesh_matches_brute_force() -> None:
    mesh = _uneven_mesh()
    chart = build_chart(mesh)
    rng = np.random.default_rng(1)
    lo, hi = chart.uv.min(axis=0), chart.uv.max(axis=0)
    tri = chart.uv[chart.faces[:500]]  # points just inside the faces' corners
    near_corner = (1 - 1e-9) * tri[:, 0] + 1e-9 * tri.mean(axis=1)
    p = np.vstack([rng.uniform(lo - 0.01, hi + 0.01, (2000, 2)), near_corner])
    cluster = chart.uv[np.argsort(np.linalg.norm(chart.uv - chart.uv[-1], axis=1))[:40]]
    p = np.vstack([p, cluster.mean(axis=0) + rng.normal(0, 0.003, (1000, 2))])
    face, bary = chart.locate(p)
    ref = _brute_locate(chart.uv, chart.faces, p)
    assert np.array_equal(face < 0, ref < 0)
    ok = face >= 0
    back = np.einsum("nk,nkj->nj", bary[ok], chart.uv[chart.faces[face[ok]]])
    np.testing.assert_allclose(back, p[ok], atol=1e-14)


def _check_against_brute(chart, p: np.ndarray) -> None:
    face, bary = chart.locate(p)
    ref = _brute_locate(chart.uv, chart.faces, p)
    assert np.array_equal(face < 0, ref < 0)
    ok = face >= 0
    back = np.einsum("nk,nkj->nj", bary[ok], chart.uv[chart.faces[face[ok]]])
    np.testing.assert_allclose(back, p[ok], atol=1e-14)
    assert (bary[ok] >= 0).all()


@pytest.mark.parametrize(
    ("even", "locator"),
    [
        (True, "grid"),
        (True, "tree"),
        (False, "tree"),
        # The grid forced on the uneven mesh (the chart picks the tree there): 10 s, slow run.
        pytest.param(False, "grid", marks=pytest.mark.slow),
    ],
)
def test_grid_and_tree_locators_both_match_brute_force(even: bool, locator: str) -> None:
    # The chart picks the centroid grid on an even mesh and the KD-tree on an uneven one;
    # each locator is checked on both meshes (the other one forced) against the brute force.
    import dataclasses

    from workbench.polishing.facegrid import FaceGrid

    rng = np.random.default_rng(5)
    mesh = make_panel(25, 18) if even else _uneven_mesh()
    chart = build_chart(mesh)
    assert (chart.grid is not None) == even
    lo, hi = chart.uv.min(axis=0), chart.uv.max(axis=0)
    tri = chart.uv[chart.faces]
    # Random points, points on edges and at vertices (ties), points just outside the rim.
    p = np.vstack(
        [
            rng.uniform(lo - 0.01, hi + 0.01, (2000, 2)),
            0.5 * (tri[:300, 0] + tri[:300, 1]),
            tri[:300, 2],
            chart.boundary + 1e-7 * rng.normal(size=chart.boundary.shape),
        ]
    )
    cu, cv = chart.centroids
    grid = FaceGrid.build(cu, cv, chart.reach, max_per_cell=10**9)
    assert grid is not None
    _check_against_brute(dataclasses.replace(chart, grid=grid if locator == "grid" else None), p)


def test_locate_near_with_hint_columns_matches_brute_force() -> None:
    # Hints right, wrong, -1, in one or two columns: the answer is the brute force's either way.
    mesh = make_panel(25, 18)
    chart = build_chart(mesh)
    rng = np.random.default_rng(7)
    lo, hi = chart.uv.min(axis=0), chart.uv.max(axis=0)
    p = rng.uniform(lo - 0.01, hi + 0.01, (3000, 2))
    ref = _brute_locate(chart.uv, chart.faces, p)
    right = np.where(ref >= 0, ref, 0)
    wrong = rng.integers(0, len(chart.faces), len(p))
    pick = rng.integers(0, 3, len(p))
    col0 = np.choose(pick, [right, wrong, np.full(len(p), -1)])
    col1 = np.choose(rng.integers(0, 3, len(p)), [right, wrong, np.full(len(p), -1)])
    for hint in (col0, np.stack([col0, col1], axis=1)):
        face, bary = chart.locate_near(p, hint)
        assert np.array_equal(face < 0, ref < 0)
        ok = face >= 0
        back = np.einsum("nk,nkj->nj", bary[ok], chart.uv[chart.faces[face[ok]]])
        np.testing.assert_allclose(back, p[ok], atol=1e-14)
        assert (bary[ok] >= 0).all()
