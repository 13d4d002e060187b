"""K factor (seed 000 Table 1), bend allowance (eq. 1) and the flange extension (eq. 2 re-derived)."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.sheetmetal import bend_allowance, flange_extension, flange_rise, k_factor

TABLE = {
    0.5: 0.24,
    0.6: 0.25,
    0.7: 0.26,
    1.0: 0.30,
    1.1: 0.32,
    1.2: 0.33,
    1.5: 0.36,
    1.8: 0.39,
    2.0: 0.40,
    2.5: 0.43,
    3.0: 0.46,
    4.0: 0.48,
    8.0: 0.50,
}


def test_table_entries_and_interpolation() -> None:
    for x, k in TABLE.items():
        assert k_factor(x) == pytest.approx(k, abs=1e-12)
    assert k_factor(0.85) == pytest.approx(0.28)  # halfway between 0.7 -> 0.26 and 1.0 -> 0.30
    assert k_factor(6.0) == pytest.approx(0.49)
    np.testing.assert_allclose(k_factor([8.0, 12.0, 100.0]), 0.5)


def test_below_table_range_is_an_error() -> None:
    with pytest.raises(InputError, match="0.5"):
        k_factor(0.3)
    with pytest.raises(InputError, match="inner_radius.*minimum"):
        bend_allowance(0.0005, 0.002, np.pi / 2)


def test_bend_allowance_is_neutral_arc_and_matches_seed_eq1() -> None:
    r, t = 0.003, 0.0015  # r/t = 2 -> K = 0.40
    theta = np.radians(60.0)
    assert bend_allowance(r, t, theta) == pytest.approx(theta * (r + 0.40 * t), rel=1e-12)
    # Seed eq. (1) with `a` the included angle in degrees: pi (r + K d)(180 - a) / 180.
    a = 180.0 - 60.0
    assert bend_allowance(r, t, theta) == pytest.approx(np.pi * (r + 0.40 * t) * (180 - a) / 180)
    # Neutral arc from geometry: polyline length of the arc of radius r + K t.
    phi = np.linspace(0, theta, 100_001)
    pts = (r + 0.4 * t) * np.c_[np.cos(phi), np.sin(phi)]
    assert bend_allowance(r, t, theta) == pytest.approx(
        np.sum(np.linalg.norm(np.diff(pts, axis=0), axis=1)), rel=1e-9
    )
    assert bend_allowance(r, t, 0.0) == 0.0
    assert bend_allowance(r, t, theta, k=0.5) == pytest.approx(theta * (r + 0.5 * t))


@pytest.mark.parametrize(
    "args, word",
    [
        ((0.002, -0.001, 1.0), "thickness"),
        ((0.002, 0.0, 1.0), "thickness"),
        ((0.002, 0.001, -0.1), "bend_angle"),
        ((0.002, 0.001, np.pi), "bend_angle"),
        ((np.nan, 0.001, 1.0), "inner_radius"),
    ],
)
def test_bad_input(args, word) -> None:
    with pytest.raises(InputError, match=word):
        bend_allowance(*args)
    with pytest.raises(InputError, match="k"):
        bend_allowance(0.002, 0.001, 1.0, k=1.5)


def half_bend_points(r: float, t: float, theta: float) -> np.ndarray:
    """Dense samples (x along the flange past the bend line, z above the inner surface) of half a bend."""
    rho, phi = np.meshgrid(np.linspace(r, r + t, 41), np.linspace(0, theta / 2, 401))
    return np.c_[(rho * np.sin(phi)).ravel(), (r - rho * np.cos(phi)).ravel()]


@pytest.mark.parametrize("included_deg", [30.0, 60.0, 90.0, 120.0, 170.0])
def test_extension_and_rise_cover_half_bend_tightly(included_deg: float) -> None:
    r, t = 0.002, 0.001
    theta = np.radians(180.0 - included_deg)
    pts = half_bend_points(r, t, theta)
    ext, rise = flange_extension(r, t, theta), flange_rise(r, theta)
    assert pts[:, 0].max() <= ext + 1e-15 and pts[:, 1].max() <= rise + 1e-15
    assert pts[:, 0].max() == pytest.approx(ext, rel=1e-6)  # tight: attained at the outer bisector
    assert pts[:, 1].max() == pytest.approx(rise, rel=1e-6, abs=1e-15)


def test_seed_eq2_does_not_cover_sharp_bends() -> None:
    # Seed eq. (2): l_c = r cot((180 - a)/2), a = included angle; no in-plane length covers
    # the inner arc (it rises above the flange), and for a = 30 deg it is too short as well.
    r, t, a = 0.002, 0.001, 30.0
    theta = np.radians(180 - a)
    l_c = r / np.tan(np.radians((180 - a) / 2))
    pts = half_bend_points(r, t, theta)
    assert pts[:, 0].max() > l_c
    assert pts[:, 1].max() > 0.0
