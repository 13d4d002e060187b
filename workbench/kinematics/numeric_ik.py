"""Numeric inverse kinematics on a pinocchio model: damped least squares (CLIK) from many seeds."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


def clik(
    model: pin.Model,
    data: pin.Data,
    frame_id: int,
    T_target: FloatArray,
    q0: FloatArray,
    *,
    tol: float = 1e-12,
    max_iter: int = 200,
    damping: float = 1e-10,
) -> tuple[FloatArray, bool]:
    """Return (q [rad], converged) from damped least squares on log6(T^-1 fk(q)), clamped to limits.

    Converged means |log6| < sqrt(tol) (about 1e-6 m / rad) after at most `max_iter` steps;
    the last steps then polish to ~1e-12.
    """
    target = pin.SE3(np.ascontiguousarray(T_target[:3, :3]), np.ascontiguousarray(T_target[:3, 3]))
    lo, hi = model.lowerPositionLimit, model.upperPositionLimit
    q = np.clip(np.asarray(q0, dtype=float).copy(), lo, hi)
    for _ in range(max_iter):
        pin.forwardKinematics(model, data, q)
        pin.updateFramePlacement(model, data, frame_id)
        dMi = target.actInv(data.oMf[frame_id])
        err = pin.log6(dMi).vector
        if err @ err < tol * 1e-6:
            return q, True
        J = pin.computeFrameJacobian(model, data, q, frame_id, pin.LOCAL)
        J = pin.Jlog6(dMi) @ J
        step = -J.T @ np.linalg.solve(J @ J.T + damping * np.eye(6), err)
        q = np.clip(q + step, lo, hi)
    pin.forwardKinematics(model, data, q)
    pin.updateFramePlacement(model, data, frame_id)
    err = pin.log6(target.actInv(data.oMf[frame_id])).vector
    return q, bool(err @ err < tol)


def numeric_ik(
    model: pin.Model,
    data: pin.Data,
    frame_id: int,
    T_target: FloatArray,
    seeds: FloatArray,
) -> FloatArray:
    """Return distinct converged solutions (k, n) [rad] of CLIK started from each seed (m, n)."""
    found: list[FloatArray] = []
    for seed in seeds:
        q, ok = clik(model, data, frame_id, T_target, seed)
        if ok and not any(np.max(np.abs(q - f)) < 1e-6 for f in found):
            found.append(q)
    return np.asarray(found, dtype=float).reshape(len(found), model.nq)
