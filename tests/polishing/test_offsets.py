"""Offset rings (seed Fig. 5) against closed forms (circles) and shapely's buffer."""

from __future__ import annotations

import numpy as np
import trimesh
from shapely.geometry import LinearRing, Polygon

from workbench.polishing.chart import build_chart
from workbench.polishing.offsets import offset_ring, resample_closed, ring_area


def _flat_disc(radius: float, n: int = 64, rings: int = 24) -> trimesh.Trimesh:
    pts = [np.zeros(2)]
    for k in range(1, rings + 1):
        r = radius * k / rings
        m = max(6, int(n * k / rings))
        th = np.linspace(0, 2 * np.pi, m, endpoint=False)
        pts.extend(np.stack([r * np.cos(th), r * np.sin(th)], axis=1))
    xy = np.asarray(np.vstack(pts))
    from scipy.spatial import Delaunay

    return trimesh.Trimesh(np.c_[xy, np.zeros(len(xy))], Delaunay(xy).simplices, process=False)


def test_circle_offset_is_concentric_circle() -> None:
    # Closed form: the inward offset of a circle of radius R by l is the circle of radius R - l.
    chart = build_chart(_flat_disc(0.1))
    th = np.linspace(0, 2 * np.pi, 800, endpoint=False)
    ring = 0.08 * np.stack([np.cos(th), np.sin(th)], axis=1)
    new, foot, dist = offset_ring(chart, ring, 0.01, 0.0005)
    np.testing.assert_allclose(np.linalg.norm(new, axis=1), 0.07, atol=1e-6)
    np.testing.assert_allclose(dist, 0.01, rtol=1e-9)  # flat: chart offset == surface offset
    np.testing.assert_allclose(np.linalg.norm(new - foot, axis=1), 0.01, rtol=1e-9)
    assert len(new) == len(ring)
    # Offsetting by more than the radius leaves nothing.
    gone, _, _ = offset_ring(chart, ring, 0.09, 0.0005)
    assert len(gone) == 0


def test_tight_bend_is_trimmed_not_crossed() -> None:
    # A stadium with a notch: at the notch's convex tip the radius is below the offset, so
    # the raw offset would form a swallow-tail; the kept ring must be simple and match buffer.
    chart = build_chart(_flat_disc(0.1))
    poly = Polygon(
        [
            (-0.06, -0.03),
            (0.06, -0.03),
            (0.06, 0.03),
            (0.005, 0.03),
            (0.0, 0.005),
            (-0.005, 0.03),
            (-0.06, 0.03),
        ]
    )
    ring = resample_closed(np.asarray(poly.exterior.coords)[:-1], 0.0005)
    assert ring_area(ring) > 0
    new, _, _ = offset_ring(chart, ring, 0.008, 0.0005)
    assert LinearRing(new).is_simple
    twin = poly.buffer(-0.008, join_style="round")  # the exact distance offset
    assert Polygon(new).hausdorff_distance(twin) < 1e-4  # 10 um here; ds = 0.5 mm
    assert poly.contains(Polygon(new))
