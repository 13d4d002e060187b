"""Bézier triangle fit against analytic surfaces (sphere, cylinder), C0 and derivatives."""

from __future__ import annotations

import sys
import threading

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError, MeshError
from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.example_workpiece import make_panel

RNG_BARY = np.random.default_rng(0).dirichlet([1.0, 1.0, 1.0], size=40)


def _errors(mesh: trimesh.Trimesh, radial) -> tuple[np.ndarray, np.ndarray]:
    """Return (fitted, flat) distances to the true surface at the same barycentric samples."""
    surf = fit_bezier_triangles(mesh)
    f = np.repeat(np.arange(len(mesh.faces)), len(RNG_BARY))
    b = np.tile(RNG_BARY, (len(mesh.faces), 1))
    fitted = surf.evaluate(f, b)
    flat = np.einsum("nk,nkj->nj", b, mesh.vertices[mesh.faces[f]])
    return radial(fitted), radial(flat)


def test_sphere_fit_beats_flat_mesh() -> None:
    r = 0.1
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=r)
    fit, flat = _errors(mesh, lambda p: np.abs(np.linalg.norm(p, axis=1) - r))
    assert fit.max() < 0.25 * flat.max()
    assert np.sqrt(np.mean(fit**2)) < 0.25 * np.sqrt(np.mean(flat**2))
    # Here the flat mesh is up to 1.8 mm off the sphere, the fit 0.24 mm.
    assert flat.max() > 1.5e-3 and fit.max() < 3e-4


def test_cylinder_fit_beats_flat_mesh() -> None:
    r = 0.05
    mesh = trimesh.creation.cylinder(radius=r, height=0.1, sections=24)
    # Only the side faces: the caps' rim vertices have normals averaged over cap and side.
    tri = mesh.vertices[mesh.faces]
    fn = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    side = np.abs(fn[:, 2]) < 0.5 * np.linalg.norm(fn, axis=1)
    normals = np.asarray(mesh.vertices) * [1.0, 1.0, 0.0]
    normals[:, 0] += np.linalg.norm(normals, axis=1) == 0  # the unused cap centres
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    sub = trimesh.Trimesh(mesh.vertices, mesh.faces[side], process=False)
    surf = fit_bezier_triangles(sub, vertex_normals=normals)
    f = np.repeat(np.arange(len(sub.faces)), len(RNG_BARY))
    b = np.tile(RNG_BARY, (len(sub.faces), 1))
    fit = np.abs(np.linalg.norm(surf.evaluate(f, b)[:, :2], axis=1) - r)
    flat = np.abs(
        np.linalg.norm(np.einsum("nk,nkj->nj", b, sub.vertices[sub.faces[f]])[:, :2], axis=1) - r
    )
    assert fit.max() < 0.1 * flat.max()
    assert np.sqrt(np.mean(fit**2)) < 0.1 * np.sqrt(np.mean(flat**2))


def test_circle_edge_bulge_matches_derivation() -> None:
    # One edge on a circle of radius R spanning angle theta: the patch edge midpoint bulges
    # R sin^2(theta/2) / 2 beyond the chord (module docstring); the true arc R (1 - cos(theta/2)).
    R, theta = 0.1, 0.6
    a = np.array([R * np.cos(theta / 2), -R * np.sin(theta / 2), 0.0])
    b = np.array([R * np.cos(theta / 2), R * np.sin(theta / 2), 0.0])
    c = np.array([R * np.cos(theta / 2), 0.0, 0.05])
    verts = np.stack([a, b, c])
    normals = np.stack([a / R, b / R, [1.0, 0.0, 0.0]])
    surf = fit_bezier_triangles(
        trimesh.Trimesh(verts, [[0, 1, 2]], process=False), vertex_normals=normals
    )
    mid = surf.evaluate([0], [[0.5, 0.5, 0.0]])[0]
    bulge = mid[0] - R * np.cos(theta / 2)
    assert bulge == pytest.approx(R * np.sin(theta / 2) ** 2 / 2, rel=1e-12)
    assert bulge == pytest.approx(R * (1 - np.cos(theta / 2)), rel=0.03)  # 2.2 % short at 34 deg


def test_c0_across_shared_edges() -> None:
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=0.1)
    surf = fit_bezier_triangles(mesh)
    faces = mesh.faces
    # For each interior edge, evaluate both faces along it at the same edge parameter.
    pairs = mesh.face_adjacency
    edges = mesh.face_adjacency_edges
    t = np.linspace(0.0, 1.0, 7)
    for fa, fb, (p, q) in zip(pairs[:, 0], pairs[:, 1], edges, strict=True):
        pts = []
        for f in (fa, fb):
            b = np.zeros((len(t), 3))
            ip = int(np.nonzero(faces[f] == p)[0][0])
            iq = int(np.nonzero(faces[f] == q)[0][0])
            b[:, ip], b[:, iq] = 1.0 - t, t
            pts.append(surf.evaluate(np.full(len(t), f), b))
        assert np.array_equal(pts[0], pts[1])


def test_flat_mesh_is_reproduced_and_normals_match_finite_differences() -> None:
    rng = np.random.default_rng(0)
    verts = np.c_[rng.uniform(-0.1, 0.1, (30, 2)), np.zeros(30)]
    mesh = trimesh.Trimesh(verts, _delaunay(verts), process=False)
    surf = fit_bezier_triangles(mesh)
    f = rng.integers(0, len(mesh.faces), 200)
    b = rng.dirichlet([1, 1, 1], 200)
    np.testing.assert_allclose(
        surf.evaluate(f, b), np.einsum("nk,nkj->nj", b, verts[mesh.faces[f]]), atol=1e-15
    )
    # Normals against finite differences on a curved patch.
    sphere = trimesh.creation.icosphere(subdivisions=1, radius=0.1)
    s2 = fit_bezier_triangles(sphere)
    f = rng.integers(0, len(sphere.faces), 50)
    b = rng.dirichlet([2, 2, 2], 50)
    h = 1e-6
    du = (s2.evaluate(f, b + [h, 0, -h]) - s2.evaluate(f, b - [h, 0, -h])) / (2 * h)
    dv = (s2.evaluate(f, b + [0, h, -h]) - s2.evaluate(f, b - [0, h, -h])) / (2 * h)
    a_du, a_dv = s2.derivatives(f, b)
    np.testing.assert_allclose(a_du, du, atol=1e-8)
    np.testing.assert_allclose(a_dv, dv, atol=1e-8)
    n_fd = np.cross(du, dv)
    n_fd /= np.linalg.norm(n_fd, axis=1, keepdims=True)
    np.testing.assert_allclose(s2.normal(f, b), n_fd, atol=1e-7)
    # Outward on the sphere, like the winding.
    assert (np.sum(s2.normal(f, b) * s2.evaluate(f, b), axis=1) > 0).all()


def _delaunay(xy: np.ndarray) -> np.ndarray:
    from scipy.spatial import Delaunay

    tri = Delaunay(xy[:, :2]).simplices
    return tri


def test_bad_input() -> None:
    with pytest.raises(MeshError):
        fit_bezier_triangles(
            trimesh.Trimesh(np.zeros((3, 3)), np.zeros((0, 3), dtype=int), process=False)
        )
    mesh = trimesh.creation.icosphere(subdivisions=0)
    with pytest.raises(InputError, match="vertex_normals"):
        fit_bezier_triangles(mesh, vertex_normals=np.ones((3, 3)))
    surf = fit_bezier_triangles(mesh)
    with pytest.raises(InputError, match="bary"):
        surf.evaluate([0], [[0.5, 0.5]])
    with pytest.raises(InputError, match="face indices"):
        surf.evaluate([999], [[0.2, 0.3, 0.5]])


def test_control_points_asked_for_in_pieces_equal_a_fresh_computation() -> None:
    # The per-face cache (filled as patches are asked for, grown in pieces) returns exactly
    # what computing the patches from scratch gives, in any order and with repeats.
    mesh = make_panel(40, 30)
    surface = fit_bezier_triangles(mesh)
    fresh = fit_bezier_triangles(mesh)
    rng = np.random.default_rng(0)
    for n in (1, 7, 500, 3000):
        f = rng.integers(0, len(mesh.faces), (n // 2 + 1, 2))
        np.testing.assert_array_equal(
            surface.control_points_of(f),
            fresh._compute_control_points(f.ravel()).reshape(f.shape + (6, 3)),
        )
    np.testing.assert_array_equal(
        surface.control_points, fresh._compute_control_points(np.arange(len(mesh.faces)))
    )


def test_control_points_asked_for_from_many_threads_at_once_equal_a_fresh_computation() -> None:
    # viser runs callbacks on several threads: concurrent first requests for overlapping faces
    # of one fit must neither take the same cache rows nor grow from a stale store. Twin: the
    # control points computed from scratch for every face, single-threaded. Without the lock
    # most rounds here returned wrong rows (or raised IndexError) on CPython 3.11.
    mesh = make_panel(60, 45)
    want = fit_bezier_triangles(mesh)._compute_control_points(np.arange(len(mesh.faces)))
    n_threads, n_rounds = 8, 30
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)  # switch threads often: more interleavings per round
    try:
        for rnd in range(n_rounds):
            surface = fit_bezier_triangles(mesh)
            start = threading.Barrier(n_threads)
            results: list[tuple[np.ndarray, np.ndarray]] = []
            errors: list[BaseException] = []

            def ask(seed: int, surface=surface, start=start, results=results, errors=errors):
                rng = np.random.default_rng(seed)
                start.wait()
                try:
                    for _ in range(6):
                        f = rng.integers(0, len(mesh.faces), int(rng.integers(1, 400)))
                        results.append((f, surface.control_points_of(f)))
                except BaseException as exc:  # noqa: BLE001 - reported in the main thread
                    errors.append(exc)

            threads = [
                threading.Thread(target=ask, args=(1000 * rnd + i,)) for i in range(n_threads)
            ]
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            assert not errors, f"round {rnd}: {errors[0]!r}"
            assert len(results) == 6 * n_threads
            for f, got in results:
                np.testing.assert_array_equal(got, want[f], err_msg=f"round {rnd}")
            # and the cache is left consistent for later single-threaded use
            np.testing.assert_array_equal(surface.control_points, want)
    finally:
        sys.setswitchinterval(interval)
