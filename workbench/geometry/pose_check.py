"""check_transform: the one validator of rigid transforms (4, 4), in pytransform3d's style.

Every function that takes a pose from a caller turns it into an array here and raises
InputError naming the argument and what was received (shape, NaN, last row, rotation).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError

FloatArray = NDArray[np.float64]
ORTHONORMAL_TOL = 1e-6
"""Largest accepted |R^T R - I| entry of a rotation part (rounding of poses read from files)."""
_LAST_ROW = np.array([0.0, 0.0, 0.0, 1.0])


def check_rotation(R: ArrayLike, name: str = "R") -> FloatArray:
    """Return rotation matrices (..., 3, 3) as floats after checking orthonormality and det +1."""
    arr = _as_float(R, name, "a (3, 3) rotation matrix")
    if arr.ndim < 2 or arr.shape[-2:] != (3, 3):
        raise InputError(f"{name}: expected shape (..., 3, 3), got {arr.shape}")
    _check_rotation_part(arr, name)
    return arr


def check_transform(T: ArrayLike, name: str = "T", *, batch: bool = False) -> FloatArray:
    """Return a rigid transform (4, 4) [m] as floats, or a batch (..., 4, 4) when `batch`.

    Raises InputError naming `name` and what is wrong: the shape received, NaN or infinite
    entries, a last row other than [0, 0, 0, 1], or a rotation part that is not orthonormal
    (|R^T R - I| > ORTHONORMAL_TOL) or is a reflection (det R < 0).
    """
    arr = _as_float(T, name, "a (4, 4) homogeneous transform [m]")
    if batch:
        if arr.ndim < 2 or arr.shape[-2:] != (4, 4):
            raise InputError(f"{name}: expected shape (..., 4, 4), got {arr.shape}")
    elif arr.shape != (4, 4):
        raise InputError(f"{name}: expected one (4, 4) transform [m], got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise InputError(f"{name}: every entry must be finite (no NaN/inf)")
    last = np.max(np.abs(arr[..., 3, :] - _LAST_ROW), initial=0.0)
    if last > 1e-9:
        raise InputError(f"{name}: the last row must be [0, 0, 0, 1] (deviation {last:.2e})")
    _check_rotation_part(arr[..., :3, :3], name)
    return arr


def _as_float(x: ArrayLike, name: str, what: str) -> FloatArray:
    try:
        return np.asarray(x, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name}: expected {what}, got {x!r}") from exc


def _check_rotation_part(R: FloatArray, name: str) -> None:
    c0, c1, c2 = R[..., :, 0], R[..., :, 1], R[..., :, 2]
    err = max(
        float(np.abs(np.sum(a * b, axis=-1) - e).max(initial=0.0))
        for a, b, e in (
            (c0, c0, 1.0),
            (c1, c1, 1.0),
            (c2, c2, 1.0),
            (c0, c1, 0.0),
            (c0, c2, 0.0),
            (c1, c2, 0.0),
        )
    )
    if not err <= ORTHONORMAL_TOL:
        raise InputError(
            f"{name}: the rotation part is not a rotation matrix: not orthonormal "
            f"(|R^T R - I| = {err:.2e} > {ORTHONORMAL_TOL:g})"
        )
    if R.size and float(np.linalg.det(R).min()) < 0.0:
        raise InputError(f"{name}: the rotation part is a reflection (det -1), not a rotation")
