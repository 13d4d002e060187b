"""Chord stepping against a closed form: points on a circle a fixed chord apart."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.polishing.stepping import chord_parameters, densify


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
