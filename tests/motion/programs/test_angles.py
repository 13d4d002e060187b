"""Tests of workbench/motion/programs/angles.py: controller angle conventions against scipy."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.motion.programs.angles import abc_deg, quaternion_wxyz, rotation_vector, wpr_deg


def test_angle_conventions_against_scipy():
    rng = np.random.default_rng(0)
    for R in Rotation.random(200, random_state=1):
        M = R.as_matrix()
        xyzw = R.as_quat()
        wxyz = np.roll(xyzw, 1) * np.sign(xyzw[3] if xyzw[3] != 0 else 1.0)
        np.testing.assert_allclose(quaternion_wxyz(M), wxyz, atol=1e-12)
        # KUKA A, B, C = intrinsic Z, Y', X'' = scipy "ZYX"
        np.testing.assert_allclose(abc_deg(M), R.as_euler("ZYX", degrees=True), atol=1e-9)
        # FANUC W, P, R = fixed x, y, z = scipy extrinsic "xyz"
        np.testing.assert_allclose(wpr_deg(M), R.as_euler("xyz", degrees=True), atol=1e-9)
        rv = R.as_rotvec()
        np.testing.assert_allclose(rotation_vector(M), rv, atol=1e-9)
    # Near 0 and near pi, where axis-angle formulas lose precision: the angle is kept and the
    # vector rebuilds the matrix.
    axes = rng.normal(size=(50, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = np.concatenate([rng.uniform(0, 1e-6, 25), np.pi - rng.uniform(0, 1e-6, 25)])
    for axis, angle in zip(axes, angles, strict=True):
        M = Rotation.from_rotvec(axis * angle).as_matrix()
        rv = rotation_vector(M)
        assert np.linalg.norm(rv) == pytest.approx(angle, abs=1e-9)
        np.testing.assert_allclose(Rotation.from_rotvec(rv).as_matrix(), M, atol=1e-12)
    np.testing.assert_allclose(rotation_vector(np.eye(3)), 0.0)


def test_orientations_are_canonical_where_the_convention_leaves_a_choice():
    """Rounding noise must not flip what a program states: a half turn about z prints C = +180
    (never -180) and a quaternion with w = 0 has its first printed component positive,
    however the noise falls; the rotation stays the same."""
    rng = np.random.default_rng(3)
    for axis in (np.array([1.0, 0, 0]), np.array([0, 0.6, -0.8]), np.array([0, 0, -1.0])):
        for _ in range(20):
            noise = Rotation.from_rotvec(rng.normal(size=3) * 1e-15)
            M = (noise * Rotation.from_rotvec(axis * np.pi)).as_matrix()
            q = quaternion_wxyz(M)
            lead = q[np.flatnonzero(np.abs(q) >= 5e-10)[0]]
            assert lead > 0, q
            np.testing.assert_allclose(
                Rotation.from_quat(np.roll(q, -1)).as_matrix(), M, atol=1e-12
            )
            for angles in (abc_deg(M), wpr_deg(M)):
                assert np.all(angles > -180.0 + 5e-7) and np.all(angles <= 180.0 + 5e-7), angles
    # C of a tool pointing down with noise on either side of the branch cut
    for eps in (1e-15, -1e-15, 0.0):
        M = Rotation.from_euler("ZYX", [30.0, 0.0, 180.0 + eps], degrees=True).as_matrix()
        assert abc_deg(M)[2] == pytest.approx(180.0, abs=1e-9)
        assert wpr_deg(M)[0] == pytest.approx(180.0, abs=1e-9)
