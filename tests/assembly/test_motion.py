from __future__ import annotations

import numpy as np
import pytest

from workbench.assembly.motion import interpolate, motion_samples, pose_distance, unit_quaternion
from workbench.geometry.transforms import make_transform, matrix_to_wxyz, rpy_to_matrix


def _rotations():
    rng = np.random.default_rng(3)
    R = list(rpy_to_matrix(rng.uniform(-np.pi, np.pi, (200, 3))))
    # One per branch of Shepperd's method, and half turns (w = 0).
    R += [np.eye(3), np.diag([1.0, -1.0, -1.0]), np.diag([-1.0, 1.0, -1.0])]
    R += [np.diag([-1.0, -1.0, 1.0]), rpy_to_matrix([0.0, 0.0, np.pi - 1e-9])]
    return R


@pytest.mark.parametrize("R", _rotations())
def test_scalar_quaternion_matches_the_vectorised_one(R):
    np.testing.assert_allclose(unit_quaternion(R), matrix_to_wxyz(R), atol=1e-12)


def test_motion_samples_are_at_most_resolution_apart():
    rng = np.random.default_rng(4)
    pts = rng.normal(0.0, 0.05, (50, 3))  # points of a part, radius >= their norms
    r = float(np.max(np.linalg.norm(pts, axis=1)))
    for _ in range(20):
        T0 = make_transform(rpy_to_matrix(rng.uniform(-3, 3, 3)), rng.normal(0, 0.3, 3))
        T1 = make_transform(rpy_to_matrix(rng.uniform(-3, 3, 3)), rng.normal(0, 0.3, 3))
        S = motion_samples(T0, T1, r, 0.01, include_start=True)
        np.testing.assert_allclose(S[0], T0, atol=1e-9)
        np.testing.assert_allclose(S[-1], T1, atol=1e-9)
        W = pts @ np.swapaxes(S[:, :3, :3], 1, 2) + S[:, None, :3, 3]
        # Twin: the largest true point displacement between consecutive samples.
        assert np.max(np.linalg.norm(np.diff(W, axis=0), axis=2)) <= 0.01 + 1e-12
        assert np.all(pose_distance(S[:-1], S[1:], r) <= 0.01 + 1e-12)
        np.testing.assert_allclose(interpolate(T0, T1, [0.0, 1.0])[1], T1, atol=1e-9)
