"""N known points to a frame, and the robot's base from reference points: synthetic truth with
noise over many seeds, outliers named, and the roles of the two fits."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import least_squares
from scipy.spatial.transform import Rotation

from workbench.calibration import fit_points, fit_robot_base
from workbench.errors import InputError
from workbench.geometry.transforms import make_transform


def _case(seed: int, n: int = 6) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    T = make_transform(Rotation.random(random_state=seed).as_matrix(), rng.uniform(-1, 1, 3))
    known = rng.uniform(-0.15, 0.15, (n, 3))
    noise = rng.normal(0.0, rng.uniform(0.02e-3, 0.1e-3), (n, 3))
    return T, known, known @ T[:3, :3].T + T[:3, 3] + noise, noise


@pytest.mark.parametrize("seed", range(30))
def test_the_frame_is_recovered_within_the_noise_bound(seed: int) -> None:
    T, known, measured, noise = _case(seed)
    fit = fit_points([f"p{i}" for i in range(6)], known, measured)
    # The fitted frame puts each known point within 3 times the largest measuring error of
    # where the true frame puts it (least squares averages the errors over the points).
    err = np.linalg.norm(known @ (fit.T[:3, :3] - T[:3, :3]).T + fit.T[:3, 3] - T[:3, 3], axis=1)
    assert err.max() <= 3.0 * np.linalg.norm(noise, axis=1).max()
    assert fit.dropped == () and fit.rms <= fit.max_error


def test_the_fit_matches_a_nonlinear_least_squares_twin() -> None:
    T, known, measured, _ = _case(3, 8)
    fit = fit_points([f"p{i}" for i in range(8)], known, measured)

    def resid(x: np.ndarray) -> np.ndarray:
        R = Rotation.from_rotvec(x[:3]).as_matrix()
        return (known @ R.T + x[3:] - measured).reshape(-1)

    x0 = np.concatenate([Rotation.from_matrix(T[:3, :3]).as_rotvec(), T[:3, 3]])
    twin = least_squares(resid, x0, xtol=1e-15, ftol=1e-15, gtol=1e-15).x
    assert np.allclose(fit.T[:3, :3], Rotation.from_rotvec(twin[:3]).as_matrix(), atol=1e-9)
    assert np.allclose(fit.T[:3, 3], twin[3:], atol=1e-9)


def test_a_mis_touched_point_is_dropped_and_named() -> None:
    T, known, measured, _ = _case(5, 7)
    measured[4] += [0.0, 0.0, 0.004]
    labels = ["a", "b", "c", "d", "e", "f", "g"]
    fit = fit_points(labels, known, measured)
    assert fit.dropped == ("e",) and fit.residuals[4] > 0.003
    assert fit.max_error < 0.5e-3


def test_collinear_points_and_unequal_lists_are_refused() -> None:
    line = np.array([[0, 0, 0], [0.1, 0, 0], [0.2, 0, 0]])
    with pytest.raises(InputError, match="points a, b, c: .*lie on one line"):
        fit_points(["a", "b", "c"], line, line)
    with pytest.raises(InputError, match="2 labels, 3 known"):
        fit_points(["a", "b"], line, line)


@pytest.mark.parametrize("seed", range(10))
def test_the_robot_base_maps_measured_points_onto_the_world(seed: int) -> None:
    T_world_base, in_base, _, _ = _case(seed)
    world = in_base @ T_world_base[:3, :3].T + T_world_base[:3, 3]
    fit = fit_robot_base([f"m{i}" for i in range(6)], world, in_base)
    assert np.allclose(fit.T, T_world_base, atol=1e-12)
    assert np.allclose(fit.known, world) and np.allclose(fit.measured, in_base)
