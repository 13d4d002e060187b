"""The rigid transform that best maps one set of points onto another (least squares).

`fit_rigid(source, target)` returns the rotation and translation T minimising
sum_i w_i |T source_i - target_i|^2 (Kabsch's SVD solution, with the reflection case turned
into the nearest proper rotation: W. Kabsch, "A solution for the best rotation to relate two
sets of vectors", Acta Cryst. A32 (1976) 922; S. Umeyama, "Least-squares estimation of
transformation parameters between two point patterns", IEEE PAMI 13(4) 1991, eq. 39-42).
It refuses fewer than three points and points on one line (the rotation about that line is
then free), naming the reason.

`fit_rigid_robust(source, target, tolerance)` drops the worst point while its residual exceeds
`tolerance` and at least three non-collinear points remain, and names the dropped ones: the
calibration of a work object from measured points and the touch-up of a program (which moved
targets share one cause) both use it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError

FloatArray = NDArray[np.float64]

COLLINEAR_RATIO = 1e-3
"""Points whose second principal spread is below this fraction of the first are on one line."""


@dataclass(frozen=True)
class RigidFit:
    """A fitted rigid transform and how well it maps the points it was fitted to."""

    T: FloatArray  # (4, 4): target = R @ source + t
    residuals: FloatArray  # (n,) |T source_i - target_i| of every point given, kept or not
    kept: tuple[int, ...]  # indices of the points the fit used
    dropped: tuple[int, ...]  # indices dropped as outliers (largest residual first)

    @property
    def rms(self) -> float:
        """Return the root-mean-square residual of the kept points."""
        return float(np.sqrt(np.mean(self.residuals[list(self.kept)] ** 2)))

    @property
    def max(self) -> float:
        """Return the largest residual of the kept points."""
        return float(np.max(self.residuals[list(self.kept)]))


def _points(points: object, name: str) -> FloatArray:
    array = np.asarray(points, dtype=float)
    if array.ndim != 2 or array.shape[1] != 3:
        raise InputError(f"{name} must be a list of 3-D points, got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise InputError(f"{name} holds a NaN or infinite coordinate; give finite numbers")
    return array


def check_spread(points: FloatArray, what: str = "the points") -> None:
    """Raise InputError when `points` (n, 3) are fewer than 3 or lie on one line."""
    if len(points) < 3:
        raise InputError(f"{what}: a rigid fit needs at least 3 points, got {len(points)}")
    spread = np.linalg.svd(points - points.mean(axis=0), compute_uv=False)
    if spread[0] == 0.0 or spread[1] < COLLINEAR_RATIO * spread[0]:
        raise InputError(
            f"{what} lie on one line (spread {spread[1]:.3g} across vs {spread[0]:.3g} along):"
            " the rotation about that line is undetermined; measure a point off the line"
        )


def _kabsch(source: FloatArray, target: FloatArray, weights: FloatArray) -> FloatArray:
    w = weights / weights.sum()
    cs, ct = w @ source, w @ target
    H = (source - cs).T @ ((target - ct) * w[:, None])
    U, _, Vt = np.linalg.svd(H)
    D = np.diag([1.0, 1.0, np.sign(np.linalg.det(Vt.T @ U.T)) or 1.0])
    R = Vt.T @ D @ U.T
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = ct - R @ cs
    return T


def _residuals(T: FloatArray, source: FloatArray, target: FloatArray) -> FloatArray:
    moved = source @ T[:3, :3].T + T[:3, 3]
    return np.asarray(np.linalg.norm(moved - target, axis=1))


def fit_rigid(source: object, target: object, weights: object | None = None) -> RigidFit:
    """Return the rigid transform mapping `source` (n, 3) onto `target` (n, 3), least squares.

    `weights` (n,), positive, weigh each point's squared residual (default all 1).
    Raises InputError for fewer than 3 points, collinear points, NaN or unequal lengths.
    """
    src, tgt = _points(source, "source points"), _points(target, "target points")
    if len(src) != len(tgt):
        raise InputError(f"{len(src)} source points but {len(tgt)} target points; give pairs")
    w = np.ones(len(src)) if weights is None else np.asarray(weights, dtype=float)
    if w.shape != (len(src),) or not np.all(np.isfinite(w)) or np.any(w <= 0.0):
        raise InputError("weights must be one positive finite number per point")
    check_spread(src, "the source points")
    T = _kabsch(src, tgt, w)
    return RigidFit(T, _residuals(T, src, tgt), tuple(range(len(src))), ())


def fit_rigid_robust(source: object, target: object, tolerance: float) -> RigidFit:
    """Fit as `fit_rigid`, dropping the worst point while its residual exceeds `tolerance`.

    Stops when every kept residual is within `tolerance`, or when dropping another point
    would leave fewer than 3 points or collinear ones (the fit then keeps that point and its
    residual says so). `tolerance` is in the points' unit.
    """
    if not (np.isfinite(tolerance) and tolerance > 0.0):
        raise InputError(f"tolerance must be a positive number, got {tolerance}")
    fit = fit_rigid(source, target)
    src, tgt = np.asarray(source, float), np.asarray(target, float)
    kept, dropped = list(fit.kept), list[int]()
    while True:
        worst = max(kept, key=lambda i: fit.residuals[i])
        if fit.residuals[worst] <= tolerance:
            break
        rest = [i for i in kept if i != worst]
        try:
            check_spread(src[rest])
        except InputError:
            break
        kept, dropped = rest, [*dropped, worst]
        T = _kabsch(src[kept], tgt[kept], np.ones(len(kept)))
        fit = RigidFit(T, _residuals(T, src, tgt), tuple(kept), tuple(dropped))
    return fit
