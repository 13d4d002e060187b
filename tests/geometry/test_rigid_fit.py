"""Rigid fit: exact recovery, a generic optimiser as the slow twin, refusals, outliers."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import least_squares
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.geometry.rigid_fit import fit_rigid, fit_rigid_robust


def _random_transform(rng: np.random.Generator) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3] = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
    T[:3, 3] = rng.uniform(-500.0, 500.0, 3)
    return T


def _apply(T: np.ndarray, p: np.ndarray) -> np.ndarray:
    return p @ T[:3, :3].T + T[:3, 3]


@pytest.mark.parametrize("seed", range(10))
def test_recovers_a_known_transform_exactly(seed: int) -> None:
    rng = np.random.default_rng(seed)
    T = _random_transform(rng)
    src = rng.uniform(-300.0, 300.0, (int(rng.integers(3, 12)), 3))
    fit = fit_rigid(src, _apply(T, src))
    np.testing.assert_allclose(fit.T, T, atol=1e-9)
    assert fit.max < 1e-9


@pytest.mark.parametrize("seed", range(5))
def test_noisy_fit_matches_a_generic_optimiser(seed: int) -> None:
    """The twin: scipy's least_squares over a rotation vector and a translation."""
    rng = np.random.default_rng(100 + seed)
    T = _random_transform(rng)
    src = rng.uniform(-300.0, 300.0, (8, 3))
    tgt = _apply(T, src) + rng.normal(0.0, 0.5, src.shape)
    fit = fit_rigid(src, tgt)

    def residual(x: np.ndarray) -> np.ndarray:
        return (src @ Rotation.from_rotvec(x[:3]).as_matrix().T + x[3:] - tgt).ravel()

    x0 = np.concatenate([Rotation.from_matrix(T[:3, :3]).as_rotvec(), T[:3, 3]])
    twin = least_squares(residual, x0, xtol=1e-14, ftol=1e-14)
    ours = np.sum(fit.residuals**2)
    assert ours <= np.sum(twin.fun**2) * (1 + 1e-9) + 1e-12
    np.testing.assert_allclose(fit.T[:3, 3], twin.x[3:], atol=1e-6)


def test_mirrored_points_give_a_proper_rotation() -> None:
    rng = np.random.default_rng(7)
    src = rng.uniform(-1.0, 1.0, (6, 3))
    fit = fit_rigid(src, src * np.array([1.0, 1.0, -1.0]))
    assert np.linalg.det(fit.T[:3, :3]) == pytest.approx(1.0)


@pytest.mark.parametrize(
    ("src", "reason"),
    [
        ([[0, 0, 0], [1, 0, 0]], "at least 3 points"),
        ([[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 1e-6, 0]], "one line"),
        ([[0, 0, 0], [1, 0, 0], [0, float("nan"), 0]], "NaN"),
    ],
)
def test_refuses_what_cannot_be_fitted(src: list[list[float]], reason: str) -> None:
    with pytest.raises(InputError, match=reason):
        fit_rigid(src, src)


def test_robust_fit_names_the_one_point_that_moved_alone() -> None:
    rng = np.random.default_rng(3)
    T = _random_transform(rng)
    src = rng.uniform(-300.0, 300.0, (7, 3))
    tgt = _apply(T, src) + rng.normal(0.0, 0.02, src.shape)
    tgt[4] += [5.0, 0.0, 0.0]
    fit = fit_rigid_robust(src, tgt, tolerance=0.5)
    assert fit.dropped == (4,)
    assert fit.max < 0.1
    assert fit.residuals[4] == pytest.approx(5.0, abs=0.2)
    np.testing.assert_allclose(fit.T[:3, 3], T[:3, 3], atol=0.2)


def test_robust_fit_keeps_three_points_when_all_disagree() -> None:
    src = np.array([[0.0, 0, 0], [100, 0, 0], [0, 100, 0]])
    tgt = src + np.array([[0.0, 0, 0], [0, 10, 0], [10, 0, 0]])
    fit = fit_rigid_robust(src, tgt, tolerance=0.1)
    assert fit.dropped == () and fit.max > 0.1
