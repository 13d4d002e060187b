"""Standard Denavit-Hartenberg chains: validation and batched forward kinematics.

Row i is ``[theta_offset rad, d m, a m, alpha rad]`` and the link transform is
``A_i = Rz(q_i + theta_offset) @ Tz(d) @ Tx(a) @ Rx(alpha)``.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.pose_check import check_transform

FloatArray = NDArray[np.float64]


def as_finite_array(value: ArrayLike, name: str, shape: tuple[int | None, ...]) -> FloatArray:
    """Return `value` as a float array of `shape` (None = any size); raise InputError otherwise."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name}: expected numbers of shape {_fmt(shape)}, got {value!r}") from exc
    ok = arr.ndim == len(shape) and all(
        s is None or s == n for s, n in zip(shape, arr.shape, strict=False)
    )
    if not ok:
        raise InputError(f"{name}: expected shape {_fmt(shape)}, got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        bad = np.argwhere(~np.isfinite(arr))[0].tolist()
        raise InputError(
            f"{name}: every entry must be finite, got {arr[tuple(bad)]} at index {bad}"
        )
    return arr


def _fmt(shape: tuple[int | None, ...]) -> str:
    return "(" + ", ".join("n" if s is None else str(s) for s in shape) + ")"


def joint_array(q: ArrayLike, dof: int, name: str = "q") -> FloatArray:
    """Return joint values (..., dof) [rad] as a finite float array; raise InputError otherwise."""
    try:
        arr = np.asarray(q, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name}: expected joint values (..., {dof}) in rad, got {q!r}") from exc
    if arr.ndim == 0 or arr.shape[-1] != dof:
        raise InputError(f"{name}: expected shape (..., {dof}) [rad], got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise InputError(f"{name}: joint values must be finite, got {arr.reshape(-1, dof)[0]}")
    return arr


def joint_vector(q: ArrayLike, dof: int, name: str = "q") -> FloatArray:
    """Return one configuration (dof,) [rad] as a finite float array; raise InputError otherwise."""
    try:
        shape = np.shape(q)
    except ValueError:  # ragged nesting: let joint_array name it
        shape = None
    if shape is not None and shape != (dof,):
        raise InputError(f"{name}: expected {dof} joint values [rad], got shape {shape}")
    return joint_array(q, dof, name)


def transform_array(T: ArrayLike, name: str = "T") -> FloatArray:
    """Return (..., 4, 4) rigid transforms as floats (`geometry.check_transform`, batched)."""
    return check_transform(T, name, batch=True)


def validate_dh(dh: ArrayLike, limits: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Return (dh (n,4), limits (n,2)) checked for shape, finiteness and lower < upper."""
    dh_arr = as_finite_array(dh, "dh", (None, 4))
    n = dh_arr.shape[0]
    if n == 0:
        raise InputError("dh: expected at least one row [theta_offset, d, a, alpha], got none")
    lim = as_finite_array(limits, "limits", (n, 2))
    bad = np.nonzero(lim[:, 0] >= lim[:, 1])[0]
    if bad.size:
        j = int(bad[0])
        raise InputError(
            f"limits: joint {j + 1} lower limit {lim[j, 0]:.6g} rad must be below its upper "
            f"limit {lim[j, 1]:.6g} rad (rows are [lower, upper])"
        )
    return dh_arr, lim


def dh_link_matrices(dh: FloatArray, q: FloatArray) -> FloatArray:
    """Return the link transforms A_i (..., n, 4, 4) for joint values q (..., n) [rad]."""
    theta = q + dh[:, 0]
    ct, st = np.cos(theta), np.sin(theta)
    d, a = dh[:, 1], dh[:, 2]
    ca, sa = np.cos(dh[:, 3]), np.sin(dh[:, 3])
    A = np.zeros(q.shape + (4, 4))
    A[..., 0, 0] = ct
    A[..., 0, 1] = -st * ca
    A[..., 0, 2] = st * sa
    A[..., 0, 3] = a * ct
    A[..., 1, 0] = st
    A[..., 1, 1] = ct * ca
    A[..., 1, 2] = -ct * sa
    A[..., 1, 3] = a * st
    A[..., 2, 1] = sa
    A[..., 2, 2] = ca
    A[..., 2, 3] = d
    A[..., 3, 3] = 1.0
    return A


def dh_fixed_part(dh: FloatArray) -> FloatArray:
    """Return B_i = Rz(offset) Tz(d) Tx(a) Rx(alpha) (n, 4, 4), so that A_i = Rz(q_i) @ B_i."""
    return dh_link_matrices(dh, np.zeros(dh.shape[0]))


def _chain(dh: FloatArray, q: FloatArray, keep: bool) -> list[FloatArray]:
    """Return base -> frame transforms as (4, 4, ...) arrays: every frame if keep, else the last.

    Batch axes trail so each update is a handful of contiguous elementwise operations.
    """
    theta = np.moveaxis(q, -1, 0) + dh[:, 0].reshape((-1,) + (1,) * (q.ndim - 1))
    ct, st = np.cos(theta), np.sin(theta)
    batch = q.shape[:-1]
    one, zero = np.ones(batch), np.zeros(batch)
    # Columns of R (x, y, z axes) and the origin p, each a (3, ...) array.
    cx = np.stack([one, zero, zero])
    cy = np.stack([zero, one, zero])
    cz = np.stack([zero, zero, one])
    p = np.stack([zero, zero, zero])
    frames = [_pack(cx, cy, cz, p)] if keep else []
    for i, (_, d, a, alpha) in enumerate(dh.tolist()):
        ca, sa = math.cos(alpha), math.sin(alpha)
        X = cx * ct[i] + cy * st[i]
        Y = cy * ct[i] - cx * st[i]
        p = p + a * X + d * cz
        cx, cy, cz = X, ca * Y + sa * cz, ca * cz - sa * Y
        if keep:
            frames.append(_pack(cx, cy, cz, p))
    return frames if keep else [_pack(cx, cy, cz, p)]


def _pack(cx: FloatArray, cy: FloatArray, cz: FloatArray, p: FloatArray) -> FloatArray:
    T = np.zeros(cx.shape[1:] + (4, 4))
    T[..., :3, 0] = np.moveaxis(cx, 0, -1)
    T[..., :3, 1] = np.moveaxis(cy, 0, -1)
    T[..., :3, 2] = np.moveaxis(cz, 0, -1)
    T[..., :3, 3] = np.moveaxis(p, 0, -1)
    T[..., 3, 3] = 1.0
    return T


def dh_frames(dh: FloatArray, q: FloatArray) -> FloatArray:
    """Return base -> frame i transforms (..., n+1, 4, 4) for i = 0..n (frame 0 = identity)."""
    return np.stack(_chain(dh, q, keep=True), axis=-3)


def dh_fk(dh: FloatArray, q: FloatArray) -> FloatArray:
    """Return base -> flange transforms (..., 4, 4) for joint values q (..., n) [rad]."""
    return _chain(dh, q, keep=False)[0]


def dh_frames_one(dh_rows: list[list[float]], q: list[float]) -> FloatArray:
    """Return base -> frame i transforms (n+1, 4, 4) for one configuration, in scalar math.

    The same chain as `dh_frames` (frame i+1 = frame i @ Rz(q_i + offset) Tz(d) Tx(a) Rx(alpha),
    column by column) on Python floats: one configuration costs ~10 us here, where the batched
    numpy chain costs ~0.2-0.3 ms of per-call overhead. dh_rows: `dh.tolist()`; q: n floats
    [rad] (finite; the caller checks).
    """
    cos, sin = math.cos, math.sin
    x0, x1, x2 = 1.0, 0.0, 0.0
    y0, y1, y2 = 0.0, 1.0, 0.0
    z0, z1, z2 = 0.0, 0.0, 1.0
    p0, p1, p2 = 0.0, 0.0, 0.0
    out = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]
    for (offset, d, a, alpha), qi in zip(dh_rows, q, strict=True):
        ct, st = cos(qi + offset), sin(qi + offset)
        ca, sa = cos(alpha), sin(alpha)
        X0, X1, X2 = x0 * ct + y0 * st, x1 * ct + y1 * st, x2 * ct + y2 * st
        Y0, Y1, Y2 = y0 * ct - x0 * st, y1 * ct - x1 * st, y2 * ct - x2 * st
        p0, p1, p2 = p0 + a * X0 + d * z0, p1 + a * X1 + d * z1, p2 + a * X2 + d * z2
        x0, x1, x2 = X0, X1, X2
        y0, y1, y2 = ca * Y0 + sa * z0, ca * Y1 + sa * z1, ca * Y2 + sa * z2
        z0, z1, z2 = ca * z0 - sa * Y0, ca * z1 - sa * Y1, ca * z2 - sa * Y2
        out += [x0, y0, z0, p0, x1, y1, z1, p1, x2, y2, z2, p2, 0.0, 0.0, 0.0, 1.0]
    return np.array(out).reshape(len(dh_rows) + 1, 4, 4)
