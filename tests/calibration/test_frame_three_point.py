"""Each vendor's three-point frame against a frame worked out by hand, and the refusals."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.calibration import three_point_frame
from workbench.errors import InputError

MM = 1e-3


def test_kuka_fanuc_origin_x_y_by_hand() -> None:
    # origin (100, 200, 50) mm; x at (100, 300, 50): +X is the world's +Y; y at (50, 250, 50)
    # lies on the world's -X side of it, so +Y is the world's -X and +Z = X x Y the world's +Z.
    frame = three_point_frame(
        {"origin": [0.1, 0.2, 0.05], "x": [0.1, 0.3, 0.05], "y": [0.05, 0.25, 0.05]}
    )
    expected = np.array(
        [[0.0, -1.0, 0.0, 0.1], [1.0, 0.0, 0.0, 0.2], [0.0, 0.0, 1.0, 0.05], [0, 0, 0, 1]]
    )
    assert np.allclose(frame.T, expected, atol=1e-15)
    assert frame.method == "kuka/fanuc"
    assert np.allclose(frame.local, [[0, 0, 0], [0.1, 0, 0], [0.05, 0.05, 0]], atol=1e-15)


def test_abb_x1_x2_y1_origin_at_the_foot_of_y1_by_hand() -> None:
    # X1 (0, 0, 0), X2 (200, 0, 0) mm: X along the world's X. Y1 (50, 80, 30): its foot on the
    # X line is (50, 0, 0), the origin; Y toward Y1 across X: (0, 80, 30)/|(0, 80, 30)|.
    frame = three_point_frame({"x1": [0, 0, 0], "x2": [0.2, 0, 0], "y1": [0.05, 0.08, 0.03]})
    ey = np.array([0.0, 80.0, 30.0]) / np.hypot(80.0, 30.0)
    assert np.allclose(frame.T[:3, 3], [0.05, 0.0, 0.0], atol=1e-15)
    assert np.allclose(frame.T[:3, 0], [1, 0, 0]) and np.allclose(frame.T[:3, 1], ey)
    assert np.allclose(frame.T[:3, 2], np.cross([1, 0, 0], ey))
    assert frame.method == "abb"
    assert np.allclose(frame.local[:, 1:][:2], 0.0, atol=1e-15)  # X1, X2 on the X axis
    assert np.allclose(frame.local[2], [0, np.hypot(0.08, 0.03), 0], atol=1e-15)  # Y1 on +Y


def test_the_same_points_give_each_vendor_its_own_origin() -> None:
    # The same three touches named the KUKA way and the ABB way: same axes, origins apart by
    # the foot of the third point on the X line (ABB) against the first point (KUKA).
    a, b, c = np.array([0.3, 0.0, 0.1]), np.array([0.5, 0.0, 0.1]), np.array([0.42, 0.1, 0.1])
    kuka = three_point_frame({"origin": a, "x": b, "y": c})
    abb = three_point_frame({"x1": a, "x2": b, "y1": c})
    assert np.allclose(kuka.T[:3, :3], abb.T[:3, :3])
    assert np.allclose(abb.T[:3, 3] - kuka.T[:3, 3], [0.12, 0.0, 0.0])


@pytest.mark.parametrize("seed", range(20))
def test_a_random_frame_is_recovered_exactly(seed: int) -> None:
    rng = np.random.default_rng(seed)
    R = Rotation.random(random_state=seed).as_matrix()
    o = rng.uniform(-1, 1, 3)
    local = np.array(
        [
            [0, 0, 0],
            [rng.uniform(0.05, 0.3), 0, 0],
            [rng.uniform(-0.1, 0.1), rng.uniform(0.05, 0.3), 0],
        ]
    )
    pts = local @ R.T + o
    frame = three_point_frame(dict(zip(["origin", "x", "y"], pts, strict=True)))
    assert np.allclose(frame.T[:3, :3], R, atol=1e-12) and np.allclose(frame.T[:3, 3], o)


def test_collinear_and_close_points_are_refused_naming_them() -> None:
    with pytest.raises(InputError, match=r"x1, x2, y1 are collinear: y1 lies 1\.00 mm"):
        three_point_frame({"x1": [0, 0, 0], "x2": [0.1, 0, 0], "y1": [0.3, 0.001, 0]})
    with pytest.raises(InputError, match=r"points origin and y are 0\.50 mm apart"):
        three_point_frame({"origin": [0, 0, 0], "x": [0.1, 0, 0], "y": [0.0005, 0, 0]})
    with pytest.raises(InputError, match="three-point labels"):
        three_point_frame({"origin": [0, 0, 0], "x": [0.1, 0, 0], "y1": [0, 0.1, 0]})
    with pytest.raises(InputError, match="three finite coordinates"):
        three_point_frame({"origin": [0, 0, np.nan], "x": [0.1, 0, 0], "y": [0, 0.1, 0]})
