"""Air bending: the apex depth against a brute-force tangency construction, its limits, and
the inner radius rule.

The twin of `apex_depth` builds the cross-section in the die frame (y across the die, z up)
without the closed form: the outer arc of radius r + t hangs on the die's axis, the flange's
outer line leaves it tangentially at slope θ/2, and the arc's centre height is found by
bisection where that line's distance to the shoulder centre (V/2, −Rs) equals Rs.
"""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.pressbrake.airbend import (
    AIR_BEND_RATIO,
    air_bend_radius,
    apex_depth,
    punch_height,
)
from workbench.sheetmetal.kfactor import k_factor


def _shoulder_gap(zc: float, theta: float, rho: float, v: float, rs: float) -> float:
    """Return how far the shoulder circle lies below the flange's outer line [m] (its centre's
    distance from the line, minus Rs; > 0: a gap, < 0: the line cuts into the shoulder)."""
    a = theta / 2.0
    # the arc's point where the +y flange leaves it: the arc's bottom turned by a
    p = np.array([rho * np.sin(a), zc - rho * np.cos(a)])
    q = p + np.array([np.cos(a), np.sin(a)])  # a second point on the outer line
    s = np.array([v / 2.0, -rs])
    # signed distance of S below the line through p and q (cross product of 2-vectors)
    below = -((q[0] - p[0]) * (s[1] - p[1]) - (q[1] - p[1]) * (s[0] - p[0]))
    return float(below - rs)


def brute_depth(theta: float, r: float, t: float, v: float, rs: float) -> float:
    """Return the apex depth [m] by bisection on the arc centre's height (see the docstring)."""
    rho = r + t
    lo, hi = -1.0, 1.0  # [m] the line is far under the shoulder at lo, far over it at hi
    assert _shoulder_gap(lo, theta, rho, v, rs) < 0 < _shoulder_gap(hi, theta, rho, v, rs)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if _shoulder_gap(mid, theta, rho, v, rs) < 0:
            lo = mid
        else:
            hi = mid
    zc = 0.5 * (lo + hi)
    # the construction holds when the shoulder touches the straight flange, not the arc:
    # its foot point on the line lies beyond the line's tangent point on the arc
    a = theta / 2.0
    p = np.array([rho * np.sin(a), zc - rho * np.cos(a)])
    along = (np.array([v / 2.0, -rs]) - p) @ np.array([np.cos(a), np.sin(a)])
    assert along > 0, "the shoulder would touch the arc, outside the construction"
    return rho - zc  # the arc's lowest point lies at zc - rho


def _random_bend(rng: np.random.Generator) -> tuple[float, float, float, float, float]:
    """Return (θ, r, t, V, Rs) of a realistic air bend: V 6..60 mm, t = V/12..V/6, r 13-22 %
    of V (Benson), Rs up to 10 % of V, θ up to 160°."""
    v = rng.uniform(0.006, 0.060)
    t = v / rng.uniform(6.0, 12.0)
    r = v * rng.uniform(0.13, 0.22)
    rs = v * rng.uniform(0.0, 0.10)
    theta = np.radians(rng.uniform(0.5, 160.0))
    return theta, r, t, v, rs


def test_apex_depth_equals_the_brute_force_tangency() -> None:
    rng = np.random.default_rng(0)
    for _ in range(300):
        theta, r, t, v, rs = _random_bend(rng)
        expected = brute_depth(theta, r, t, v, rs)
        got = float(apex_depth(theta, r, t, v, rs))
        assert got == pytest.approx(expected, abs=1e-9), (theta, r, t, v, rs)


def test_apex_depth_broadcasts_over_angles_and_radii() -> None:
    rng = np.random.default_rng(1)
    t, v, rs = 0.002, 0.016, 0.001
    theta = np.radians(rng.uniform(1, 150, (4, 1)))
    r = rng.uniform(0.002, 0.003, (1, 5))
    got = apex_depth(theta, r, t, v, rs)
    assert got.shape == (4, 5)
    for i in range(4):
        for j in range(5):
            assert got[i, j] == pytest.approx(brute_depth(theta[i, 0], r[0, j], t, v, rs), abs=1e-9)


def test_sharp_bend_on_a_knife_edge_die_is_the_textbook_depth() -> None:
    rng = np.random.default_rng(2)
    theta = np.radians(rng.uniform(0.1, 170.0, 200))
    v = rng.uniform(0.004, 0.1, 200)
    got = apex_depth(theta, 0.0, 0.0, 1.0, 0.0) * v  # depth scales with V when r = t = Rs = 0
    np.testing.assert_allclose(got, v / 2 * np.tan(theta / 2), rtol=1e-12, atol=0)
    for th, vi in zip(theta[:20], v[:20], strict=True):
        assert float(apex_depth(th, 0.0, 0.0, vi, 0.0)) == pytest.approx(
            vi / 2 * np.tan(th / 2), rel=1e-12
        )


def test_depth_is_zero_flat_and_grows_with_the_angle() -> None:
    rng = np.random.default_rng(3)
    theta = np.radians(np.linspace(0.0, 170.0, 1000))
    for _ in range(30):
        _, r, t, v, rs = _random_bend(rng)
        assert float(apex_depth(0.0, r, t, v, rs)) == 0.0
        assert float(apex_depth(0.0, np.inf, t, v, rs)) == 0.0  # flat: no radius yet
        d = apex_depth(theta, r, t, v, rs)
        assert d[0] == 0.0 and np.all(d[1:] > 0)
        assert np.all(np.diff(d) > 0), "depth must grow with the bend angle (fixed radius)"
        # folding in air: the neutral arc BA stays, the inner radius shrinks as θ grows
        k = float(k_factor(r / t))
        ba = np.pi / 2 * (r + k * t)
        th = theta[1:]
        r_now = ba / th - k * t
        ok = r_now > 0
        d_air = apex_depth(th[ok], r_now[ok], t, v, rs)
        assert np.all(np.diff(d_air) > 0), "depth must grow along an air bend"


def test_punch_height_is_thickness_less_depth() -> None:
    rng = np.random.default_rng(4)
    for _ in range(50):
        theta, r, t, v, rs = _random_bend(rng)
        assert float(punch_height(theta, r, t, v, rs)) == pytest.approx(
            t - brute_depth(theta, r, t, v, rs), abs=1e-9
        )
    assert float(punch_height(0.0, np.inf, 0.003, 0.024, 0.002)) == 0.003  # flat: on the sheet


def test_air_bend_radius_is_ratio_times_opening() -> None:
    assert air_bend_radius(0.012) == pytest.approx(AIR_BEND_RATIO * 0.012, rel=1e-15)
    assert AIR_BEND_RATIO == 0.16
    rng = np.random.default_rng(5)
    for v, k in zip(rng.uniform(1e-3, 0.2, 20), rng.uniform(0.01, 0.99, 20), strict=True):
        assert air_bend_radius(v, k) == pytest.approx(v * k, rel=1e-15)


@pytest.mark.parametrize("v", [0.0, -0.01, np.nan, np.inf])
def test_air_bend_radius_refuses_a_bad_opening(v: float) -> None:
    with pytest.raises(InputError, match=r"v_opening: must be > 0 m"):
        air_bend_radius(v)


@pytest.mark.parametrize("ratio", [0.0, 1.0, -0.1, 1.5, np.nan, np.inf])
def test_air_bend_radius_refuses_a_bad_ratio(ratio: float) -> None:
    with pytest.raises(InputError, match=r"radius_ratio: must be in \(0, 1\)"):
        air_bend_radius(0.012, ratio)
