"""Chord stepping against a closed form (points on a circle a fixed chord apart), the Newton
chain against a point-by-point root search (brentq), and the dense walk where it must run."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from scipy.optimize import brentq

from workbench.polishing import stepping
from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.chart import build_chart
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.stepping import (
    chord_parameters,
    chord_step,
    chord_step_dense,
    densify,
    linear_recurrence,
)
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


def _chain_by_brentq(chart, surface, uv: np.ndarray, step: float) -> np.ndarray:
    """Twin of the Newton chain: each next point found alone, by bracketing along the lifted
    polyline vertex by vertex and brentq; the end appended as `chord_step` does."""
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
    return np.asarray(ref)


def test_newton_chain_matches_a_point_by_point_root_search() -> None:
    # Twin: each next point found alone, by bracketing along the lifted polyline and brentq.
    mesh = make_panel(60, 45)
    chart = build_chart(mesh)
    surface = fit_bezier_triangles(mesh, vertex_normals=chart.vertex_normals)
    rings = spiral_rings(chart, 0.02, 0.02 / 8)
    uv = _spiral_uv(rings, 0.02 / 8)[:120]  # a part of the path, through a lap join
    step = 0.003
    pts, nrm, face, bary = chord_step(chart, surface, uv, step)
    ref = _chain_by_brentq(chart, surface, uv, step)
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


def _recurrence_loop(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Twin: x_k = a_k x_{k-1} + b_k, x_{-1} = 0, one term at a time."""
    x, prev = np.empty(len(a)), 0.0
    for k in range(len(a)):
        prev = a[k] * prev + b[k]
        x[k] = prev
    return x


def test_linear_recurrence_matches_the_plain_loop() -> None:
    rng = np.random.default_rng(0)
    n = 3000
    typical = rng.uniform(0.5, 1.5, n) * rng.choice([-1.0, 1.0], n, p=[0.05, 0.95])
    one_zero = typical.copy()
    one_zero[1234] = 0.0  # a chord perpendicular to the previous tangent: beta = 0
    many_tiny = typical.copy()
    many_tiny[::40] = 1e-17  # each finite, their product underflows
    growing = np.full(n, 1.3)  # the product overflows a float (1.3^3000 ~ 1e342) ...
    for a in (typical, one_zero, many_tiny, growing):
        b = rng.normal(0.0, 1e-4, n)
        if a is growing:
            b[:-100] = 0.0  # ... while x stays finite
        want = _recurrence_loop(a, b)
        # Rounding scale of each term: the same recurrence on |a|, |b| (no cancellation).
        scale = _recurrence_loop(np.abs(a), np.abs(b))
        for window in (4096, 64):  # one segment, and segments ended by the window as well
            got = linear_recurrence(a, b, window=window)
            assert np.all(np.abs(got - want) <= 1e-12 * scale)
    # The single cumulative product (the earlier solve) breaks on the last three.
    with np.errstate(all="ignore"):
        for a in (one_zero, many_tiny, growing):
            cum = np.cumprod(a)
            assert not np.isfinite(cum * np.cumsum(rng.normal(size=n) / cum)).all()
    assert linear_recurrence(np.array([5.0]), np.array([2.0])).tolist() == [2.0]


def test_chords_perpendicular_to_the_previous_tangent_keep_the_newton_chain(monkeypatch) -> None:
    # A sawtooth in the chart: legs along +u, each followed by a leg back at 60 degrees, so
    # that the point h = S / tan(60) before each corner has its next point straight across
    # (in the chart exactly, on the gently curved panel nearly: |beta / alpha| ~ 1e-4..1e-3).
    # 160 such chords multiply to ~1e-365: a single cumulative product underflowed to 0, the
    # step became NaN and the whole path took the dense walk (chords to ~1e-7 m only).
    mesh = make_panel(60, 45)
    chart = build_chart(mesh)
    surface = fit_bezier_triangles(mesh, vertex_normals=chart.vertex_normals)
    step = 0.0008
    phi = np.deg2rad(60.0)
    h = step / np.tan(phi)
    across = h / np.cos(phi)  # from the corner along the back leg to the point across
    back = np.array([-np.cos(phi), np.sin(phi)])
    # Past the point across, 0.4 step to the next corner; the next point then lies
    # q = 0.4 step cos(phi) + step sqrt(1 - (0.4 sin(phi))^2) along the next forward leg,
    # which ends h after it: the next tooth repeats the construction.
    q = 0.4 * step * np.cos(phi) + step * np.sqrt(1.0 - (0.4 * np.sin(phi)) ** 2)
    uv = [np.array([-0.06, -0.088])]
    for tooth in range(160):
        uv.append(uv[-1] + [(h + step) if tooth == 0 else (q + h), 0.0])
        uv.append(uv[-1] + (across + 0.4 * step) * back)
    uv = np.asarray(uv)
    assert (chart.locate(uv)[0] >= 0).all()  # on the panel: no reason for the dense walk

    def no_dense_walk(*args, **kwargs):
        raise AssertionError("chord_step fell back to the dense walk")

    ratios = []
    solve = stepping.linear_recurrence

    def spy(a, b, **kwargs):
        ratios.append(a)
        return solve(a, b, **kwargs)

    monkeypatch.setattr(stepping, "chord_step_dense", no_dense_walk)
    monkeypatch.setattr(stepping, "linear_recurrence", spy)
    pts, nrm, face, bary = chord_step(chart, surface, uv, step)
    # The construction does what it says: near-perpendicular chords, their product below
    # the smallest float (log10 < -324).
    assert ratios and max(np.sum(np.log10(np.abs(a))) for a in ratios) < -324
    assert min(np.abs(a).min() for a in ratios) < 1e-3
    ref = _chain_by_brentq(chart, surface, uv, step)
    assert pts.shape == ref.shape
    np.testing.assert_allclose(pts, ref, atol=1e-9)
    chords = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    np.testing.assert_allclose(chords[:-1], step, atol=1e-9 * step)
    np.testing.assert_allclose(surface.evaluate(face, bary), pts, atol=0)
    np.testing.assert_allclose(nrm, surface.normal(face, bary), atol=1e-12)
