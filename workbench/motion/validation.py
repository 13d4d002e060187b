"""Checks of sampled joint trajectories against position, velocity, acceleration and jerk limits."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.motion.trajectory import MAX_SAMPLES, Trajectory


@dataclass(frozen=True)
class Violation:
    """One sample beyond a limit: `joint` is 1-based, `time` in s, value and limit in SI units."""

    kind: str  # "position", "velocity", "acceleration", "jerk" or "waypoint"
    joint: int
    time: float
    value: float
    limit: float


@dataclass(frozen=True)
class ValidationReport:
    """Return value of the checks: `violations` (worst first, at most `max_reported` per kind).

    `worst` maps each checked kind to its largest ratio |value| / limit (for "waypoint": the
    largest position error [rad]); `n_samples` is how many times were checked.
    """

    violations: tuple[Violation, ...]
    worst: dict[str, float]
    n_samples: int

    @property
    def ok(self) -> bool:
        """Return True when no sample violates any limit."""
        return not self.violations


def _limit_violations(
    kind: str,
    times: NDArray,
    values: NDArray,
    limit: NDArray,
    tol: float,
    out: list[Violation],
    max_reported: int,
) -> float:
    """Append violations of |values| <= limit (+tol) and return the worst ratio."""
    ratio = np.abs(values) / limit
    bad = np.argwhere(np.abs(values) > limit + tol)
    order = np.argsort(-ratio[bad[:, 0], bad[:, 1]])
    for k in order[:max_reported]:
        i, j = bad[k]
        out.append(
            Violation(kind, int(j) + 1, float(times[i]), float(values[i, j]), float(limit[j]))
        )
    return float(ratio.max()) if ratio.size else 0.0


def validate_samples(
    times: ArrayLike,
    positions: ArrayLike,
    velocities: ArrayLike,
    accelerations: ArrayLike,
    *,
    max_velocity: ArrayLike,
    max_acceleration: ArrayLike,
    max_jerk: ArrayLike,
    position_limits: ArrayLike | None = None,
    jerks: ArrayLike | None = None,
    tol: float = 1e-9,
    max_reported: int = 100,
) -> ValidationReport:
    """Return a `ValidationReport` of samples (n, dof) at `times` (n,) [s] against limits (dof,).

    Without `jerks`, jerk is the finite difference of accelerations between samples (for a
    piecewise-linear acceleration this is a mean of the true jerk, so never above its peak).
    `position_limits` is (dof, 2) [rad]. Values may exceed a limit by `tol`.
    """
    t = np.asarray(times, float).reshape(-1)
    p, v, a = (np.asarray(x, float) for x in (positions, velocities, accelerations))
    n = t.shape[0]
    for name, x in (("positions", p), ("velocities", v), ("accelerations", a)):
        if x.ndim != 2 or x.shape[0] != n:
            raise InputError(f"{name} must have shape ({n}, dof) to match times, got {x.shape}")
    dof = p.shape[1]
    lims = {}
    for name, lim in (
        ("max_velocity", max_velocity),
        ("max_acceleration", max_acceleration),
        ("max_jerk", max_jerk),
    ):
        arr = np.broadcast_to(np.asarray(lim, float), (dof,))
        if np.any(~np.isfinite(arr) | (arr <= 0)):
            raise InputError(f"{name} must be {dof} finite numbers > 0, got {arr.tolist()}")
        lims[name] = arr
    found: list[Violation] = []
    worst: dict[str, float] = {}
    if position_limits is not None:
        lim = np.asarray(position_limits, float).reshape(dof, 2)
        below, above = lim[:, 0] - p, p - lim[:, 1]
        over = np.maximum(below, above)
        for i, j in np.argwhere(over > tol)[:max_reported]:
            bound = lim[j, 0] if below[i, j] > 0 else lim[j, 1]
            found.append(
                Violation("position", int(j) + 1, float(t[i]), float(p[i, j]), float(bound))
            )
        worst["position"] = float(over.max())
    worst["velocity"] = _limit_violations(
        "velocity", t, v, lims["max_velocity"], tol, found, max_reported
    )
    worst["acceleration"] = _limit_violations(
        "acceleration", t, a, lims["max_acceleration"], tol, found, max_reported
    )
    if jerks is None:
        dt = np.diff(t)
        keep = dt > 1e-12
        jk = np.diff(a, axis=0)[keep] / dt[keep, None]
        tj = t[:-1][keep]
    else:
        jk, tj = np.asarray(jerks, float), t
    worst["jerk"] = _limit_violations("jerk", tj, jk, lims["max_jerk"], tol, found, max_reported)
    return ValidationReport(tuple(found), worst, n)


AccelerationBound = Callable[[NDArray[np.float64], NDArray[np.float64]], NDArray[np.float64]]
"""bound(t0 (M,), t1 (M,)) -> (M, dof): max |q''| [rad/s^2] over each interval [t0, t1]."""


def _piece_bounds(trajectory: Trajectory) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return the start and end times [s] of every joint's constant-jerk pieces, (dof, P) each."""
    start = trajectory.piece_start
    end = np.concatenate([start[:, 1:], np.full((start.shape[0], 1), trajectory.duration)], axis=1)
    return start, end


def acceleration_bound(trajectory: Trajectory) -> NDArray[np.float64]:
    """Return max |q''| per joint [rad/s^2] over the whole trajectory, exactly.

    Within a constant-jerk piece the acceleration is linear in time, so its largest magnitude
    is at one of the piece's ends.
    """
    start, end = _piece_bounds(trajectory)
    length = np.clip(end - start, 0.0, None)
    a0, jerk = trajectory.piece_a, trajectory.piece_j
    return np.maximum(np.abs(a0), np.abs(a0 + jerk * length)).max(axis=1)


def interval_acceleration_bound(
    trajectory: Trajectory,
) -> AccelerationBound:
    """Return bound(t0, t1) -> (M, dof): max |q''| [rad/s^2] over each interval [t0_m, t1_m], exactly.

    The acceleration is linear within each constant-jerk piece, so its largest magnitude on an
    interval is at the interval's ends or at a piece boundary inside it (both one-sided values
    there). Far below the whole trajectory's bound where the motion runs at constant feed.
    """
    start, end = _piece_bounds(trajectory)
    dof, count = start.shape
    length = np.clip(end - start, 0.0, None)
    a0, jerk = trajectory.piece_a, trajectory.piece_j
    # Largest one-sided |a| at each piece's start (its own start, the previous piece's end).
    at_start = np.abs(a0).copy()
    at_start[:, 1:] = np.maximum(at_start[:, 1:], np.abs(a0 + jerk * length)[:, :-1])
    at_start = np.concatenate([at_start, np.zeros((dof, 1))], axis=1)  # sentinel for reduceat

    def bound(t0: NDArray[np.float64], t1: NDArray[np.float64]) -> NDArray[np.float64]:
        lo = np.minimum(t0, t1)
        hi = np.maximum(t0, t1)
        out = np.maximum(np.abs(trajectory.at(lo)[2]), np.abs(trajectory.at(hi)[2]))
        for j in range(dof):
            i0 = np.searchsorted(start[j], lo, side="right")  # first boundary after lo
            i1 = np.searchsorted(start[j], hi, side="right")  # boundaries up to hi
            i0c = np.minimum(i0, count)
            idx = np.stack([i0c, np.maximum(i1, i0c)], axis=1).reshape(-1)
            inner = np.maximum.reduceat(at_start[j], idx)[::2]
            out[:, j] = np.where(i1 > i0, np.maximum(out[:, j], inner), out[:, j])
        return out

    return bound


def critical_times(trajectory: Trajectory) -> NDArray[np.float64]:
    """Return the times [s] where some joint's |velocity| or |position| peaks within a piece.

    With constant jerk per piece, acceleration is linear (extremes at piece ends), velocity
    peaks where the acceleration crosses zero, position where the velocity does.
    """
    start, end = _piece_bounds(trajectory)
    a0, v0, jj = trajectory.piece_a, trajectory.piece_v, trajectory.piece_j
    with np.errstate(divide="ignore", invalid="ignore"):
        t_acc0 = start - a0 / jj
        disc = np.sqrt(a0 * a0 - 2.0 * jj * v0)
        roots = [
            start + (-a0 + disc) / jj,
            start + (-a0 - disc) / jj,
            np.where(jj == 0.0, start - v0 / a0, np.nan),
        ]
    cand = np.concatenate(
        [c.reshape(-1) for c in [t_acc0, *roots]] + [start.reshape(-1), end.reshape(-1)]
    )
    inside = np.isfinite(cand)
    lo = np.concatenate([start.reshape(-1)] * 4 + [start.reshape(-1)] * 2)
    hi = np.concatenate([end.reshape(-1)] * 4 + [end.reshape(-1)] * 2)
    inside &= (cand >= lo) & (cand <= hi)
    return np.unique(np.clip(cand[inside], 0.0, trajectory.duration))


def validate_trajectory(
    trajectory: Trajectory,
    *,
    max_velocity: ArrayLike,
    max_acceleration: ArrayLike,
    max_jerk: ArrayLike,
    position_limits: ArrayLike | None = None,
    dt: float = 0.01,
    tol: float = 1e-9,
    waypoint_tol: float = 1e-6,
) -> ValidationReport:
    """Return a `ValidationReport` of `trajectory` sampled every `dt` [s] plus its peak times.

    Jerk comes from the trajectory's constant-jerk pieces; waypoints must be passed at
    `waypoint_times` within `waypoint_tol` [rad]. `max_velocity` may be (dof,) only here.
    A trajectory longer than `MAX_SAMPLES` x dt gets a coarser grid (MAX_SAMPLES points; the
    peaks are still checked exactly).
    """
    grid = np.arange(0.0, trajectory.duration, max(dt, trajectory.duration / MAX_SAMPLES))
    t = np.unique(
        np.concatenate(
            [grid, critical_times(trajectory), trajectory.waypoint_times, [trajectory.duration]]
        )
    )
    p, v, a = trajectory.at(t)
    report = validate_samples(
        t,
        p,
        v,
        a,
        max_velocity=max_velocity,
        max_acceleration=max_acceleration,
        max_jerk=max_jerk,
        position_limits=position_limits,
        jerks=trajectory.jerk_at(t),
        tol=tol,
    )
    pw, _, _ = trajectory.at(trajectory.waypoint_times)
    err = np.abs(pw - trajectory.waypoints)
    found = list(report.violations)
    for i, j in np.argwhere(err > waypoint_tol):
        found.append(
            Violation(
                "waypoint",
                int(j) + 1,
                float(trajectory.waypoint_times[i]),
                float(pw[i, j]),
                float(trajectory.waypoints[i, j]),
            )
        )
    worst = dict(report.worst, waypoint=float(err.max()))
    return ValidationReport(tuple(found), worst, report.n_samples)
