"""Homogeneous transforms: construction from xyz/rpy and quaternions, batched.

Convention (DESIGN.md): R = Rz(yaw) @ Ry(pitch) @ Rx(roll); angles in radians here.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def rot_x(a: ArrayLike) -> NDArray[np.float64]:
    """Return rotation matrices (..., 3, 3) about x by angle `a` [rad]."""
    ang = np.asarray(a, dtype=float)
    c, s = np.cos(ang), np.sin(ang)
    o, z = np.ones_like(ang), np.zeros_like(ang)
    return np.stack([o, z, z, z, c, -s, z, s, c], axis=-1).reshape(ang.shape + (3, 3))


def rot_y(a: ArrayLike) -> NDArray[np.float64]:
    """Return rotation matrices (..., 3, 3) about y by angle `a` [rad]."""
    ang = np.asarray(a, dtype=float)
    c, s = np.cos(ang), np.sin(ang)
    o, z = np.ones_like(ang), np.zeros_like(ang)
    return np.stack([c, z, s, z, o, z, -s, z, c], axis=-1).reshape(ang.shape + (3, 3))


def rot_z(a: ArrayLike) -> NDArray[np.float64]:
    """Return rotation matrices (..., 3, 3) about z by angle `a` [rad]."""
    ang = np.asarray(a, dtype=float)
    c, s = np.cos(ang), np.sin(ang)
    o, z = np.ones_like(ang), np.zeros_like(ang)
    return np.stack([c, -s, z, s, c, z, z, z, o], axis=-1).reshape(ang.shape + (3, 3))


def rpy_to_matrix(rpy: ArrayLike) -> NDArray[np.float64]:
    """Return R = Rz(yaw) Ry(pitch) Rx(roll) (..., 3, 3) from (..., 3) [roll, pitch, yaw] rad."""
    angles = np.asarray(rpy, dtype=float)
    return rot_z(angles[..., 2]) @ rot_y(angles[..., 1]) @ rot_x(angles[..., 0])


GIMBAL_LOCK = 1e-7
"""cos(pitch) below which `matrix_to_rpy` reads a rotation as gimbal-locked (pitch ±90°)."""


def matrix_to_rpy(R: ArrayLike) -> NDArray[np.float64]:
    """Return (..., 3) [roll, pitch, yaw] rad with R = Rz(yaw) Ry(pitch) Rx(roll).

    At pitch = ±90° (gimbal lock) roll is set to 0 and yaw carries the whole rotation. Within
    `GIMBAL_LOCK` (cos pitch below it) the lock's answer is taken too: there roll and yaw alone
    come from elements of the size of rounding noise, and a program that writes them (with
    the pitch rounded) would turn the frame by any angle; the lock's answer is exact to
    `GIMBAL_LOCK` rad.
    """
    R = np.asarray(R, dtype=float)  # type: ignore[assignment]
    pitch = np.arcsin(np.clip(-R[..., 2, 0], -1.0, 1.0))
    lock = np.hypot(R[..., 0, 0], R[..., 1, 0]) < GIMBAL_LOCK
    pitch = np.where(lock, np.copysign(np.pi / 2, -R[..., 2, 0]), pitch)
    roll = np.where(lock, 0.0, np.arctan2(R[..., 2, 1], R[..., 2, 2]))
    yaw = np.where(
        lock,
        np.arctan2(-R[..., 0, 1], R[..., 1, 1]),
        np.arctan2(R[..., 1, 0], R[..., 0, 0]),
    )
    return np.stack([roll, pitch, yaw], axis=-1)


def make_transform(rotation: ArrayLike, translation: ArrayLike) -> NDArray[np.float64]:
    """Return (..., 4, 4) homogeneous transforms from (..., 3, 3) rotations and (..., 3) translations."""
    rotation = np.asarray(rotation, dtype=float)
    translation = np.asarray(translation, dtype=float)
    shape = np.broadcast_shapes(rotation.shape[:-2], translation.shape[:-1])
    T = np.zeros(shape + (4, 4))
    T[..., :3, :3] = rotation
    T[..., :3, 3] = translation
    T[..., 3, 3] = 1.0
    return T


def xyz_rpy_to_transform(xyz: ArrayLike, rpy: ArrayLike) -> NDArray[np.float64]:
    """Return (..., 4, 4) transforms from positions [m] and roll-pitch-yaw angles [rad]."""
    return make_transform(rpy_to_matrix(rpy), xyz)


def transform_to_xyz_rpy(T: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return (xyz [m], rpy [rad]) of (..., 4, 4) transforms."""
    T = np.asarray(T, dtype=float)
    return T[..., :3, 3].copy(), matrix_to_rpy(T[..., :3, :3])


def invert_transform(T: ArrayLike) -> NDArray[np.float64]:
    """Return the inverse of rigid (..., 4, 4) transforms."""
    T = np.asarray(T, dtype=float)
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    return make_transform(Rt, -(Rt @ T[..., :3, 3, None])[..., 0])


def matrix_to_wxyz(R: ArrayLike) -> NDArray[np.float64]:
    """Return unit quaternions (..., 4) in (w, x, y, z) order, w >= 0, from (..., 3, 3) rotations."""
    R = np.asarray(R, dtype=float)
    m = R.reshape(-1, 3, 3)
    q = np.empty((m.shape[0], 4))
    tr = np.trace(m, axis1=1, axis2=2)
    # Pick the numerically largest of the four candidate components per matrix.
    cand = np.stack([tr, m[:, 0, 0], m[:, 1, 1], m[:, 2, 2]], axis=1)
    k = np.argmax(cand, axis=1)
    for case in range(4):
        idx = k == case
        if not np.any(idx):
            continue
        r = m[idx]
        if case == 0:
            s = np.sqrt(1.0 + tr[idx]) * 2.0
            q[idx] = np.stack(
                [
                    0.25 * s,
                    (r[:, 2, 1] - r[:, 1, 2]) / s,
                    (r[:, 0, 2] - r[:, 2, 0]) / s,
                    (r[:, 1, 0] - r[:, 0, 1]) / s,
                ],
                axis=1,
            )
        elif case == 1:
            s = np.sqrt(1.0 + r[:, 0, 0] - r[:, 1, 1] - r[:, 2, 2]) * 2.0
            q[idx] = np.stack(
                [
                    (r[:, 2, 1] - r[:, 1, 2]) / s,
                    0.25 * s,
                    (r[:, 0, 1] + r[:, 1, 0]) / s,
                    (r[:, 0, 2] + r[:, 2, 0]) / s,
                ],
                axis=1,
            )
        elif case == 2:
            s = np.sqrt(1.0 + r[:, 1, 1] - r[:, 0, 0] - r[:, 2, 2]) * 2.0
            q[idx] = np.stack(
                [
                    (r[:, 0, 2] - r[:, 2, 0]) / s,
                    (r[:, 0, 1] + r[:, 1, 0]) / s,
                    0.25 * s,
                    (r[:, 1, 2] + r[:, 2, 1]) / s,
                ],
                axis=1,
            )
        else:
            s = np.sqrt(1.0 + r[:, 2, 2] - r[:, 0, 0] - r[:, 1, 1]) * 2.0
            q[idx] = np.stack(
                [
                    (r[:, 1, 0] - r[:, 0, 1]) / s,
                    (r[:, 0, 2] + r[:, 2, 0]) / s,
                    (r[:, 1, 2] + r[:, 2, 1]) / s,
                    0.25 * s,
                ],
                axis=1,
            )
    q *= np.where(q[:, :1] < 0, -1.0, 1.0)
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    return q.reshape(R.shape[:-2] + (4,))


def wxyz_to_matrix(q: ArrayLike) -> NDArray[np.float64]:
    """Return (..., 3, 3) rotations from (..., 4) quaternions in (w, x, y, z) order."""
    qa = np.asarray(q, dtype=float)
    qa = qa / np.linalg.norm(qa, axis=-1, keepdims=True)
    w, x, y, z = qa[..., 0], qa[..., 1], qa[..., 2], qa[..., 3]
    return np.stack(
        [
            1 - 2 * (y * y + z * z),
            2 * (x * y - w * z),
            2 * (x * z + w * y),
            2 * (x * y + w * z),
            1 - 2 * (x * x + z * z),
            2 * (y * z - w * x),
            2 * (x * z - w * y),
            2 * (y * z + w * x),
            1 - 2 * (x * x + y * y),
        ],
        axis=-1,
    ).reshape(qa.shape[:-1] + (3, 3))
