"""The TCP from the tip on one fixed point: synthetic truth over many seeds, refusals, the twin.

The bound on the recovered TCP is the linear least-squares one: the system A x = b with the
noisy flange poses misses the true x by exactly A^+ e, where e_i is how far the noise moved the
true tip of reading i, so |x - x_true| <= ||A^+|| |e|.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import least_squares
from scipy.spatial.transform import Rotation

from workbench.calibration import calibrate_tcp
from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform, make_transform


def _readings(
    rng: np.random.Generator, t: np.ndarray, P: np.ndarray, n: int, tilt: float
) -> np.ndarray:
    """Return flange poses (n, 4, 4) putting the tip t (flange) on P, tool tilted up to `tilt`."""
    down = Rotation.from_euler("x", np.pi)
    poses = []
    for _ in range(n):
        R = (Rotation.from_rotvec(rng.uniform(-tilt, tilt, 3)) * down).as_matrix()
        T_tcp = make_transform(R, P)
        poses.append(T_tcp @ invert_transform(make_transform(np.eye(3), t)))
    return np.array(poses)


def _noisy(rng: np.random.Generator, T: np.ndarray, mm: float, deg: float) -> np.ndarray:
    out = T.copy()
    for Ti in out:
        Ti[:3, :3] = (
            Rotation.from_rotvec(rng.normal(0, np.radians(deg), 3)).as_matrix() @ Ti[:3, :3]
        )
        Ti[:3, 3] += rng.normal(0, mm * 1e-3, 3)
    return out


@pytest.mark.parametrize("seed", range(40))
def test_the_tcp_is_recovered_within_the_noise_bound(seed: int) -> None:
    rng = np.random.default_rng(seed)
    t = rng.uniform([-0.05, -0.05, 0.05], [0.05, 0.05, 0.3])
    P = rng.uniform([0.3, -0.3, 0.0], [0.7, 0.3, 0.4])
    n = int(rng.integers(4, 9))
    T = _noisy(rng, _readings(rng, t, P, n, np.radians(40)), rng.uniform(0.02, 0.1), 0.01)
    fit = calibrate_tcp(T)
    R, p = T[:, :3, :3], T[:, :3, 3]
    e = (R @ t + p - P).reshape(-1)  # how far the noise moved each true tip
    A = np.concatenate([R, -np.broadcast_to(np.eye(3), (n, 3, 3))], axis=2).reshape(-1, 6)
    bound = np.linalg.norm(np.linalg.pinv(A), 2) * np.linalg.norm(e)
    err = np.linalg.norm(np.concatenate([fit.T_flange_tcp[:3, 3] - t, fit.point - P]))
    assert err <= bound + 1e-12
    assert fit.max_error >= fit.mean_error >= 0.0
    assert np.allclose(fit.residuals, np.linalg.norm(fit.tips(T) - fit.point, axis=1))


@pytest.mark.parametrize("seed", range(5))
def test_the_fit_matches_a_nonlinear_least_squares_twin(seed: int) -> None:
    rng = np.random.default_rng(100 + seed)
    t, P = np.array([0.01, -0.02, 0.18]), np.array([0.5, 0.1, 0.2])
    T = _noisy(rng, _readings(rng, t, P, 6, np.radians(35)), 0.1, 0.02)
    fit = calibrate_tcp(T)

    def resid(x: np.ndarray) -> np.ndarray:
        return (T[:, :3, :3] @ x[:3] + T[:, :3, 3] - x[3:]).reshape(-1)

    twin = least_squares(resid, np.zeros(6), xtol=1e-15, ftol=1e-15, gtol=1e-15).x
    assert np.allclose(fit.T_flange_tcp[:3, 3], twin[:3], atol=1e-9)
    assert np.allclose(fit.point, twin[3:], atol=1e-9)


def test_exact_readings_give_the_tcp_and_zero_error() -> None:
    rng = np.random.default_rng(7)
    t, P = np.array([0.0, 0.03, 0.2]), np.array([0.4, 0.0, 0.1])
    fit = calibrate_tcp(_readings(rng, t, P, 4, np.radians(30)))
    assert np.allclose(fit.T_flange_tcp[:3, 3], t, atol=1e-12)
    assert fit.max_error < 1e-12
    assert not fit.oriented and np.allclose(fit.T_flange_tcp[:3, :3], np.eye(3))
    tilted = make_transform(Rotation.from_euler("y", 0.3).as_matrix(), [0.0, 0.0, 0.1])
    kept = fit.keeping(tilted)  # the tool's orientation as it was, the position fitted
    assert np.allclose(kept[:3, :3], tilted[:3, :3]) and np.allclose(kept[:3, 3], t)


def test_four_near_identical_orientations_are_refused_naming_why() -> None:
    rng = np.random.default_rng(3)
    T = _readings(rng, np.array([0.0, 0.0, 0.15]), np.array([0.5, 0.0, 0.2]), 4, np.radians(0.5))
    with pytest.raises(InputError, match="orientations are too alike.*undetermined"):
        calibrate_tcp(T)


def test_orientations_about_one_axis_leave_that_axis_undetermined() -> None:
    # Turning only about the flange's Z (J6) never shows the TCP's Z: named in the refusal.
    t, P = np.array([0.0, 0.0, 0.15]), np.array([0.5, 0.0, 0.2])
    base = make_transform(Rotation.from_euler("x", np.pi).as_matrix(), P)
    T = np.array(
        [
            base
            @ make_transform(Rotation.from_euler("z", a).as_matrix(), np.zeros(3))
            @ invert_transform(make_transform(np.eye(3), t))
            for a in (0.0, 1.0, 2.0, 3.0)
        ]
    )
    with pytest.raises(InputError, match=r"flange's [+-]Z"):
        calibrate_tcp(T)


def test_fewer_than_four_readings_are_refused() -> None:
    rng = np.random.default_rng(1)
    T = _readings(rng, np.array([0.0, 0.0, 0.1]), np.zeros(3), 3, np.radians(40))
    with pytest.raises(InputError, match="at least 4 readings"):
        calibrate_tcp(T)


def _oriented_case(rng: np.random.Generator) -> tuple[np.ndarray, ...]:
    R_ft = Rotation.from_euler("xyz", rng.uniform(-0.6, 0.6, 3)).as_matrix()
    t, P = np.array([0.02, -0.01, 0.17]), np.array([0.5, 0.05, 0.2])
    T = _readings(rng, t, P, 5, np.radians(35))
    # Elongator readings: the orientation of the last approach reading, the tool moved back so
    # that P lies 80 mm along the tool's +Z (then +X) from the TCP.
    R_last = T[-1, :3, :3]
    T_z, T_x = T[-1].copy(), T[-1].copy()
    T_z[:3, 3] -= R_last @ R_ft[:, 2] * 0.08
    T_x[:3, 3] -= R_last @ R_ft[:, 0] * 0.08
    return T, T_z, T_x, R_ft, t


def test_tcp_and_z_x_recovers_the_orientation() -> None:
    T, T_z, T_x, R_ft, t = _oriented_case(np.random.default_rng(11))
    fit = calibrate_tcp(T, z_reading=T_z, x_reading=T_x)
    assert fit.oriented and fit.skew < 1e-9
    assert np.allclose(fit.T_flange_tcp[:3, :3], R_ft, atol=1e-9)
    assert np.allclose(fit.T_flange_tcp[:3, 3], t, atol=1e-12)
    assert np.allclose(fit.keeping(np.eye(4)), fit.T_flange_tcp)  # measured: not kept
    only_z = calibrate_tcp(T, z_reading=T_z)  # ABB's TCP and Z: Z measured, X chosen across it
    assert np.allclose(only_z.T_flange_tcp[:3, 2], R_ft[:, 2], atol=1e-9)


def test_an_x_reading_without_z_and_a_short_elongation_are_refused() -> None:
    T, T_z, T_x, _, _ = _oriented_case(np.random.default_rng(12))
    with pytest.raises(InputError, match="needs a Z one"):
        calibrate_tcp(T, x_reading=T_x)
    with pytest.raises(InputError, match="elongator reading puts the fixed point"):
        calibrate_tcp(T, z_reading=T[-1])
