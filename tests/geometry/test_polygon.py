"""Polygon helpers against independent computations: the shoelace sum in plain Python, the
triangles' areas adding up to the polygon's with every triangle inside it (a
crossing-number point-in-polygon), and the least-area rectangle against a sweep of the rotation angle."""

from __future__ import annotations

import numpy as np

from workbench.geometry.polygon import clean_ring, min_area_rect, signed_area, triangulate


def _star(n: int = 9, seed: int = 0) -> np.ndarray:
    """A simple counter-clockwise polygon with reflex corners (radii alternate)."""
    a = np.linspace(0.0, 2 * np.pi, 2 * n, endpoint=False)
    r = np.where(np.arange(2 * n) % 2 == 0, 1.0, 0.4)
    r = r * np.random.default_rng(seed).uniform(0.9, 1.1, 2 * n)
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


def _inside(p: np.ndarray, x: float, y: float) -> bool:
    """Crossing number: a ray to +x crosses the boundary an odd number of times."""
    odd = False
    for (x0, y0), (x1, y1) in zip(p, np.roll(p, -1, axis=0), strict=True):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            odd = not odd
    return odd


def _shoelace(p: np.ndarray) -> float:
    return 0.5 * sum(
        float(p[i, 0] * p[(i + 1) % len(p), 1] - p[(i + 1) % len(p), 0] * p[i, 1])
        for i in range(len(p))
    )


def test_signed_area_is_the_shoelace_sum_and_flips_with_the_direction() -> None:
    p = _star()
    assert abs(signed_area(p) - _shoelace(p)) < 1e-12
    assert signed_area(p) > 0 and abs(signed_area(p[::-1]) + signed_area(p)) < 1e-12
    assert signed_area(np.array([[0, 0], [2, 0], [2, 3], [0, 3]], float)) == 6.0


def test_ear_clipping_covers_the_polygon_with_ccw_triangles_inside_it() -> None:
    for seed in range(5):
        p = _star(seed=seed)
        tris = triangulate(p)
        assert tris.shape == (len(p) - 2, 3)
        areas = [signed_area(p[t]) for t in tris]
        assert min(areas) > 0
        assert abs(sum(areas) - signed_area(p)) < 1e-12
        assert all(_inside(p, *c) for c in p[tris].mean(axis=1))


def test_clean_ring_drops_repeats_and_straight_vertices_but_not_kept_ones() -> None:
    square = np.array([[0, 0], [1, 0], [1, 0], [2, 0], [2, 2], [1, 2], [0, 2]], float)
    assert clean_ring(square).tolist() == [[0, 0], [2, 0], [2, 2], [0, 2]]
    kept = clean_ring(square, keep=[[1, 2]])
    assert kept.tolist() == [[0, 0], [2, 0], [2, 2], [1, 2], [0, 2]]


def test_min_area_rect_encloses_the_points_and_no_rotation_does_better() -> None:
    rng = np.random.default_rng(4)
    t = np.radians(27.0)
    R = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
    pts = rng.uniform([-2.0, -0.5], [2.0, 0.5], (60, 2)) @ R.T + [3.0, -1.0]
    axes, centre, half = min_area_rect(pts)
    np.testing.assert_allclose(axes.T @ axes, np.eye(2), atol=1e-12)
    local = (pts - centre) @ axes
    assert (np.abs(local) <= half + 1e-12).all()
    best = min(
        np.ptp(pts @ [np.cos(a), np.sin(a)]) * np.ptp(pts @ [-np.sin(a), np.cos(a)])
        for a in np.linspace(0.0, np.pi / 2, 20001)
    )
    assert 4 * half[0] * half[1] <= best + 1e-12
    assert 4 * half[0] * half[1] >= best * (
        1 - 1e-3
    )  # a kink at the optimum: first order in the step
