"""Tests of workbench/geometry/transforms.py against scipy's Rotation (the independent twin):
rpy = scipy's extrinsic "xyz" Euler angles, quaternions in scipy's (x, y, z, w) order."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.geometry import transforms as tf


def test_elementary_rotations_and_rpy_against_scipy() -> None:
    rng = np.random.default_rng(0)
    a = rng.uniform(-np.pi, np.pi, 50)
    for f, axis in ((tf.rot_x, "x"), (tf.rot_y, "y"), (tf.rot_z, "z")):
        assert np.allclose(f(a), Rotation.from_euler(axis, a[:, None]).as_matrix(), atol=1e-12)
    rpy = rng.uniform([-np.pi, -np.pi / 2, -np.pi], [np.pi, np.pi / 2, np.pi], (200, 3))
    R = tf.rpy_to_matrix(rpy)  # batched
    assert R.shape == (200, 3, 3)
    assert np.allclose(R, Rotation.from_euler("xyz", rpy).as_matrix(), atol=1e-12)
    back = tf.matrix_to_rpy(R)
    assert np.allclose(back, rpy, atol=1e-9)


def test_gimbal_lock_puts_the_rotation_in_yaw() -> None:
    for pitch in (np.pi / 2, -np.pi / 2):
        R = tf.rpy_to_matrix([0.7, pitch, 0.2])
        roll, p, yaw = tf.matrix_to_rpy(R)
        assert roll == 0.0 and p == pytest.approx(pitch)
        assert np.allclose(tf.rpy_to_matrix([roll, p, yaw]), R, atol=1e-12)
    # within GIMBAL_LOCK of the lock the lock's answer is taken, exact to that size
    R = tf.rpy_to_matrix([0.3, np.pi / 2 - 1e-9, 0.1])
    out = tf.matrix_to_rpy(R)
    assert out[0] == 0.0
    assert np.allclose(tf.rpy_to_matrix(out), R, atol=1e-7)


def test_quaternions_against_scipy() -> None:
    Rs = Rotation.random(300, random_state=4)
    M = Rs.as_matrix()
    q = tf.matrix_to_wxyz(M)
    xyzw = Rs.as_quat()
    want = np.roll(xyzw, 1, axis=1) * np.where(xyzw[:, 3:] < 0, -1.0, 1.0)
    assert np.allclose(q, want, atol=1e-12)
    assert np.all(q[:, 0] >= 0)
    assert np.allclose(tf.wxyz_to_matrix(q), M, atol=1e-12)
    assert np.allclose(tf.wxyz_to_matrix(3.0 * q), M, atol=1e-12)  # normalised
    # the four branches of the extraction: near identity and half turns about x, y, z
    for rv in ([1e-3, 0, 0], [np.pi, 0, 0], [0, np.pi, 0], [0, 0, np.pi]):
        R = Rotation.from_rotvec(rv).as_matrix()
        assert np.allclose(tf.wxyz_to_matrix(tf.matrix_to_wxyz(R)), R, atol=1e-12)


def test_transforms_compose_and_invert() -> None:
    rng = np.random.default_rng(1)
    for _ in range(50):
        xyz, rpy = rng.normal(size=3), rng.uniform(-1, 1, 3)
        T = tf.xyz_rpy_to_transform(xyz, rpy)
        assert np.allclose(T[:3, :3], Rotation.from_euler("xyz", rpy).as_matrix())
        assert np.allclose(T[:3, 3], xyz) and np.allclose(T[3], [0, 0, 0, 1])
        assert np.allclose(tf.invert_transform(T), np.linalg.inv(T), atol=1e-12)
        x2, r2 = tf.transform_to_xyz_rpy(T)
        assert np.allclose(x2, xyz) and np.allclose(r2, rpy, atol=1e-12)
        assert np.allclose(tf.make_transform(T[:3, :3], xyz), T)
