"""Chord stepping against a closed form (points on a circle a fixed chord apart), the Newton
chain against a point-by-point root search (brentq), and the dense walk where it must run."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from scipy.optimize import brentq

from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.chart import build_chart
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.stepping import chord_parameters, chord_step, chord_step_dense, densify
from workbench.polishing.toolpath import _spiral_uv, spiral_rings


def test_chord_parameters_on_a_circle() -> None:
    # A dense polygon on a circle of radius R: successive chord-S points are 2 asin(S/2R) apart
    # in angle when measured on the polygon (exact on its vertices and segments).
    R, S = 0.05, 0.004
    th = np.linspace(0.0, np.pi, 2001)
    p = R * np.stack([np.cos(th), np.sin(th), np.zeros_like(th)], axis=1)
    t = chord_parameters(p, S)
    j = np.floor(t).astype(int).clip(0, len(p) - 2)
    f = (t - j)[:, None]
    q = (1 - f) * p[j] + f * p[j + 1]
    chords = np.linalg.norm(np.diff(q, axis=0), axis=1)
    np.testing.assert_allclose(chords[:-1], S, atol=1e-12)
    assert 0 < chords[-1] <= S
    # The polygon's chord S spans nearly the circle's angle 2 asin(S / 2R).
    ang = np.arctan2(q[:, 1], q[:, 0])
    np.testing.assert_allclose(np.diff(ang)[:-1], 2 * np.arcsin(S / (2 * R)), rtol=1e-5)


def test_densify_keeps_vertices_and_bounds_segments() -> None:
    uv = np.array([[0.0, 0.0], [0.01, 0.0], [0.01, 0.003]])
    d = densify(uv, 0.001)
    assert np.linalg.norm(np.diff(d, axis=0), axis=1).max() <= 0.001 + 1e-15
    for v in uv:
        assert np.min(np.linalg.norm(d - v, axis=1)) == pytest.approx(0.0, abs=1e-15)


def _lift_one(chart, surface, uv: np.ndarray, t: float) -> np.ndarray:
    """Twin helper: the polyline point at fractional vertex index t, lifted (one at a time)."""
    j = min(int(t), len(uv) - 2)
    p = uv[j] + (t - j) * (uv[j + 1] - uv[j])
    f, b = chart.locate(p[None])
    return surface.evaluate(f, b)[0]


def test_newton_chain_matches_a_point_by_point_root_search() -> None:
    # Twin: each next point found alone, by bracketing along the lifted polyline and brentq.
    mesh = make_panel(60, 45)
    chart = build_chart(mesh)
    surface = fit_bezier_triangles(mesh, vertex_normals=chart.vertex_normals)
    rings = spiral_rings(chart, 0.02, 0.02 / 8)
    uv = _spiral_uv(rings, 0.02 / 8)[:120]  # a part of the path, through a lap join
    step = 0.003
    pts, nrm, face, bary = chord_step(chart, surface, uv, step)
    ref = [_lift_one(chart, surface, uv, 0.0)]
    t0 = 0.0
    end = len(uv) - 1.0
    while True:

        def g(t: float) -> float:
            return float(np.linalg.norm(_lift_one(chart, surface, uv, t) - ref[-1])) - step

        hi = t0
        while hi < end and g(hi) < 0:
            hi = min(np.floor(hi) + 1.0, end)
        if g(hi) < 0:
            break
        t0 = brentq(g, max(np.floor(hi) - 1.0, t0), hi, xtol=1e-14)
        ref.append(_lift_one(chart, surface, uv, t0))
    last = _lift_one(chart, surface, uv, end)
    if np.linalg.norm(last - ref[-1]) > 1e-3 * step:
        ref.append(last)
    ref = np.asarray(ref)
    assert pts.shape == ref.shape
    np.testing.assert_allclose(pts, ref, atol=1e-9)
    chords = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    np.testing.assert_allclose(chords[:-1], step, atol=1e-9 * step)
    np.testing.assert_allclose(surface.evaluate(face, bary), pts, atol=0)
    np.testing.assert_allclose(nrm, surface.normal(face, bary), atol=1e-12)


def test_a_polyline_over_a_hole_takes_the_dense_walk() -> None:
    mesh = make_panel(40, 30)
    c = mesh.vertices[mesh.faces].mean(axis=1)
    keep = np.hypot(c[:, 0], c[:, 1]) > 0.03  # a round hole in the middle
    holed = trimesh.Trimesh(mesh.vertices, mesh.faces[keep], process=False)
    holed.remove_unreferenced_vertices()
    chart = build_chart(holed)
    surface = fit_bezier_triangles(holed, vertex_normals=chart.vertex_normals)
    uv = densify(np.array([[-0.1, 0.0], [0.1, 0.0]]), 0.001)  # straight across the hole
    got = chord_step(chart, surface, uv, 0.002)
    want = chord_step_dense(chart, surface, uv, 0.002)
    for a, b in zip(got, want, strict=True):
        np.testing.assert_array_equal(a, b)
    assert (chart.locate(uv)[0] < 0).any()  # the line does cross the hole
