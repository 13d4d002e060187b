"""Jerk-limited joint trajectories through waypoints, chained from ruckig state-to-state segments.

ruckig's community edition solves one state-to-state problem at a time (its
``intermediate_positions`` would call a cloud service), so the path is split into one
segment per pair of consecutive waypoints. The motion flows through intermediate
waypoints: each joint gets a waypoint velocity from the slopes of its neighbouring
segments (zero at direction reversals, at exact stops and at the ends), bounded by what
the joint can reach from rest and brake to rest within its neighbouring segments. Every
segment is checked (``validate_input``, the ``Result``, no overshoot beyond the box of its
two waypoints); a segment that fails is re-solved with a stop at its end waypoint, then at
its start waypoint (re-solving the previous segment).

Each segment's ruckig ``Trajectory`` is kept; for fast evaluation the profiles are also
flattened into one table of constant-jerk pieces per joint (`at` is exact, vectorised).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np
import ruckig
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, PlanningError
from workbench.motion.limits import check_limits, check_position_limits, check_waypoints
from workbench.motion.speed_bounds import max_speed_change, rest_to_rest_time

# Slack for "no overshoot beyond the waypoint box": ruckig's own position error is ~1e-12.
_BOX_TOL = 1e-10
# Consecutive waypoints closer than this (every joint) are merged into one.
DUPLICATE_TOL = 1e-9
# Refinement passes of the waypoint velocities: at most this many, while each gains > 1 %.
MAX_PASSES = 4
PASS_GAIN = 0.01


@dataclass(frozen=True, eq=False)
class Trajectory:
    """A jerk-limited joint trajectory: times in s, positions in rad (or m for linear axes).

    `waypoint_times[i]` is when input waypoint i is passed (merged duplicates share a time).
    `segments` are the ruckig trajectories, one per (merged) waypoint pair, starting at
    `segment_start_times`. `piece_start` (dof, P) and `piece_p/v/a/j` (dof, P) describe
    the same motion as constant-jerk pieces (pieces may have zero length).
    """

    duration: float
    waypoint_times: NDArray[np.float64]
    waypoints: NDArray[np.float64]
    segments: tuple[ruckig.Trajectory, ...] = field(repr=False)
    segment_start_times: NDArray[np.float64] = field(repr=False)
    stop_indices: tuple[int, ...] = ()
    dt: float = 0.004
    piece_start: NDArray[np.float64] = field(repr=False, default_factory=lambda: np.zeros((0, 0)))
    piece_p: NDArray[np.float64] = field(repr=False, default_factory=lambda: np.zeros((0, 0)))
    piece_v: NDArray[np.float64] = field(repr=False, default_factory=lambda: np.zeros((0, 0)))
    piece_a: NDArray[np.float64] = field(repr=False, default_factory=lambda: np.zeros((0, 0)))
    piece_j: NDArray[np.float64] = field(repr=False, default_factory=lambda: np.zeros((0, 0)))

    @property
    def dof(self) -> int:
        """Return the number of joints."""
        return int(self.waypoints.shape[1])

    def at(
        self, times: ArrayLike
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """Return (positions, velocities, accelerations), each (len(times), dof), at `times` [s].

        Times are clamped to [0, duration] (the robot rests before and after).
        """
        t = np.clip(np.atleast_1d(np.asarray(times, dtype=float)), 0.0, self.duration)
        if t.ndim != 1:
            t = t.reshape(-1)
        n, dof = t.shape[0], self.dof
        pos, vel, acc = np.empty((n, dof)), np.empty((n, dof)), np.empty((n, dof))
        for j in range(dof):
            k = np.searchsorted(self.piece_start[j], t, side="right") - 1
            k = np.clip(k, 0, self.piece_start.shape[1] - 1)
            h = t - self.piece_start[j, k]
            p0, v0, a0, jj = (
                self.piece_p[j, k],
                self.piece_v[j, k],
                self.piece_a[j, k],
                self.piece_j[j, k],
            )
            pos[:, j] = p0 + h * (v0 + h * (a0 / 2.0 + h * jj / 6.0))
            vel[:, j] = v0 + h * (a0 + h * jj / 2.0)
            acc[:, j] = a0 + h * jj
        return pos, vel, acc

    def sample(
        self, dt: float | None = None
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """Return (times [s], positions, velocities, accelerations) every `dt` s, end included.

        `dt` defaults to the trajectory's `dt`; the last sample is at `duration` exactly.
        """
        step = self.dt if dt is None else float(dt)
        if not np.isfinite(step) or step <= 0.0:
            raise InputError(f"dt must be a positive number of seconds, got {dt!r}")
        n = int(np.floor(self.duration / step + 1e-9))
        times = np.arange(n + 1, dtype=np.float64) * float(step)
        if times[-1] < self.duration - 1e-12:
            times = np.append(times, self.duration)
        else:
            times[-1] = self.duration
        p, v, a = self.at(times)
        return times, p, v, a

    def jerk_at(self, times: ArrayLike) -> NDArray[np.float64]:
        """Return jerks (len(times), dof) [rad/s^3] at `times` [s] (piecewise constant)."""
        t = np.clip(np.atleast_1d(np.asarray(times, dtype=float)).reshape(-1), 0.0, self.duration)
        out = np.empty((t.shape[0], self.dof))
        for j in range(self.dof):
            k = np.clip(np.searchsorted(self.piece_start[j], t, side="right") - 1, 0, None)
            out[:, j] = self.piece_j[j, k]
        return out


def _flow_velocities(
    q: NDArray[np.float64],
    seg_time: NDArray[np.float64],
    vmax: NDArray[np.float64],
    amax: NDArray[np.float64],
    jmax: NDArray[np.float64],
    stops: NDArray[np.bool_],
) -> NDArray[np.float64]:
    """Return waypoint velocities (N, dof): along the path tangent, zero at reversals and stops.

    The tangent (q[i+1] - q[i-1]) / (T[i-1] + T[i]) is scaled down as a whole to the
    velocity limits; then, per joint, a forward and a backward pass keep each speed
    reachable from, and brakeable to, its neighbours' within the segment between them.
    """
    d = np.diff(q, axis=0)
    same = (np.sign(d[:-1]) == np.sign(d[1:])) & (d[:-1] != 0.0)
    tangent = (q[2:] - q[:-2]) / (seg_time[:-1] + seg_time[1:])[:, None]
    mag = np.where(same, np.abs(tangent), 0.0)
    # A hair below the limit: ruckig's validate_input rejects a velocity equal to the
    # limit after rounding (seen with per-segment limits from linear moves).
    cap = np.minimum(vmax[:-1], vmax[1:]) * (1.0 - 1e-9)
    with np.errstate(divide="ignore"):
        scale = np.min(np.where(mag > 0.0, cap / mag, np.inf), axis=1, keepdims=True)
    speed = np.zeros_like(q)
    speed[1:-1] = mag * np.minimum(1.0, scale)
    speed[stops] = 0.0
    # Fixed point of both neighbour constraints, vectorised over waypoints; a constraint
    # travels one waypoint per round, so N rounds always suffice.
    dist = np.abs(d)
    for _ in range(q.shape[0]):
        new = speed.copy()
        new[1:] = np.minimum(new[1:], max_speed_change(speed[:-1], dist, amax, jmax))
        new[:-1] = np.minimum(new[:-1], max_speed_change(speed[1:], dist, amax, jmax))
        if np.array_equal(new, speed):
            break
        speed = new
    v = np.zeros_like(q)
    v[1:-1] = np.sign(d[1:]) * speed[1:-1]
    return v


class _SegmentSolver:
    """Solves one waypoint-to-waypoint segment with ruckig and checks it."""

    def __init__(self, dof: int, amax: NDArray[np.float64], jmax: NDArray[np.float64]) -> None:
        self.otg = ruckig.Ruckig(dof)
        self.inp = ruckig.InputParameter(dof)
        self.inp.max_acceleration = amax.tolist()
        self.inp.max_jerk = jmax.tolist()
        self.inp.current_acceleration = [0.0] * dof
        self.inp.target_acceleration = [0.0] * dof
        self.dof = dof

    def solve(
        self,
        q0: NDArray[np.float64],
        v0: NDArray[np.float64],
        q1: NDArray[np.float64],
        v1: NDArray[np.float64],
        vmax: NDArray[np.float64],
    ) -> tuple[ruckig.Trajectory | None, str]:
        """Return (trajectory, "") or (None, reason)."""
        inp = self.inp
        inp.current_position, inp.current_velocity = q0.tolist(), v0.tolist()
        inp.target_position, inp.target_velocity = q1.tolist(), v1.tolist()
        inp.max_velocity = vmax.tolist()
        try:
            if not self.otg.validate_input(inp, True, True):
                return None, "ruckig rejected the input"
            traj = ruckig.Trajectory(self.dof)
            result = self.otg.calculate(inp, traj)
        except (RuntimeError, ruckig.RuckigError) as exc:  # validate_input raises on bad input
            return None, f"ruckig error: {exc}"
        if result not in (ruckig.Result.Working, ruckig.Result.Finished):
            return None, f"ruckig returned {result.name}"
        if not np.isfinite(traj.duration):
            return None, "ruckig returned a non-finite duration"
        lo, hi = np.minimum(q0, q1), np.maximum(q0, q1)
        tol = _BOX_TOL * np.maximum(1.0, np.abs(hi))
        for j, b in enumerate(traj.position_extrema):
            if b.min < lo[j] - tol[j] or b.max > hi[j] + tol[j]:
                return None, f"joint {j + 1} overshoots its waypoints ({b.min:.6g}..{b.max:.6g})"
        return traj, ""


def _solve_chain(
    q: NDArray[np.float64],
    v: NDArray[np.float64],
    vmax_seg: NDArray[np.float64],
    solver: _SegmentSolver,
) -> tuple[list[ruckig.Trajectory], NDArray[np.float64]]:
    """Return per-segment trajectories and the waypoint velocities finally used."""
    v = v.copy()
    n_seg = q.shape[0] - 1
    segs: list[ruckig.Trajectory | None] = [None] * n_seg
    k = 0
    while k < n_seg:
        traj, why = solver.solve(q[k], v[k], q[k + 1], v[k + 1], vmax_seg[k])
        if traj is not None:
            segs[k] = traj
            k += 1
        elif np.any(v[k + 1] != 0.0):
            v[k + 1] = 0.0  # stop at the end waypoint and retry
        elif np.any(v[k] != 0.0):
            v[k] = 0.0  # stop at the start waypoint: the previous segment must end at rest
            k -= 1
        else:
            raise PlanningError(
                f"segment {k} (waypoint {k} -> {k + 1}) has no jerk-limited solution even "
                f"from rest to rest: {why}"
            )
    return [s for s in segs if s is not None], v


def _piece_table(
    segs: list[ruckig.Trajectory], starts: NDArray[np.float64], dof: int
) -> tuple[NDArray[np.float64], ...]:
    """Return (start, p, v, a, j) arrays (dof, 9 * n_seg): brake (2) + profile (7) pieces."""
    profs = [prof for seg in segs for prof in seg.profiles[0]]
    brakes = [prof.brake for prof in profs]
    n = len(profs)
    t0 = np.repeat(starts, dof)[:, None]
    b_dur = np.array([b.duration for b in brakes])[:, None]
    b_t = np.array([b.t for b in brakes], float).reshape(n, -1)
    p_t = np.array([prof.t for prof in profs], float).reshape(n, 7)
    start = np.concatenate(
        [
            t0,
            t0 + b_t[:, :1],
            t0 + b_dur + np.concatenate([np.zeros((n, 1)), np.cumsum(p_t, axis=1)[:, :-1]], axis=1),
        ],
        axis=1,
    )
    cols = [start]
    for name in ("p", "v", "a", "j"):
        b_x = np.array([getattr(b, name) for b in brakes], float).reshape(n, -1)[:, :2]
        p_x = np.array([getattr(prof, name) for prof in profs], float).reshape(n, -1)[:, :7]
        cols.append(np.concatenate([b_x, p_x], axis=1))
    # rows are (segment, joint); reorder to (joint, segment * 9 pieces)
    return tuple(c.reshape(len(segs), dof, 9).transpose(1, 0, 2).reshape(dof, -1) for c in cols)


def smooth_joint_path(
    waypoints: ArrayLike,
    max_velocity: ArrayLike,
    max_acceleration: ArrayLike,
    max_jerk: ArrayLike,
    *,
    position_limits: ArrayLike | None = None,
    exact_stop: Iterable[int] | None = None,
    dt: float = 0.004,
) -> Trajectory:
    """Return a jerk-limited `Trajectory` through joint `waypoints` (N, dof) [rad].

    Limits are per joint, (dof,): velocity [rad/s], acceleration [rad/s^2], jerk [rad/s^3];
    `max_velocity` may also be (N-1, dof), one row per segment. `position_limits` (dof, 2)
    [rad] is checked against the waypoints; since no segment overshoots the box of its two
    waypoints, the whole motion stays within them. `exact_stop` lists waypoint indices
    where the robot comes to rest. `dt` [s] is the default period of `Trajectory.sample`.
    Consecutive waypoints equal within 1e-9 rad are merged (they share a waypoint time).

    Raises InputError on bad input and PlanningError naming a segment that cannot be solved.
    """
    q_in = check_waypoints(waypoints)
    n_in, dof = q_in.shape
    vmax_in = check_limits("max_velocity", max_velocity, dof, n_segments=n_in - 1)
    amax = check_limits("max_acceleration", max_acceleration, dof)
    jmax = check_limits("max_jerk", max_jerk, dof)
    if position_limits is not None:
        check_position_limits(position_limits, q_in)
    if not np.isfinite(dt) or dt <= 0.0:
        raise InputError(f"dt must be a positive number of seconds, got {dt!r}")
    stops_in = np.zeros(n_in, bool)
    for i in exact_stop or ():
        if not (-n_in <= int(i) < n_in):
            raise InputError(f"exact_stop index {i} is outside 0..{n_in - 1}")
        stops_in[int(i)] = True

    # Merge duplicates: keep[i] says waypoint i starts a new position.
    moved = np.any(np.abs(np.diff(q_in, axis=0)) > DUPLICATE_TOL, axis=1)
    keep = np.concatenate([[True], moved])
    group = np.cumsum(keep) - 1  # merged index of each input waypoint
    if group[-1] == 0:
        raise InputError(
            f"waypoints: all {n_in} waypoints are the same position; give at least two distinct ones"
        )
    q = q_in[keep]
    vmax_seg = np.broadcast_to(vmax_in, (n_in - 1, dof))[moved]
    stops = np.zeros(q.shape[0], bool)
    np.logical_or.at(stops, group, stops_in)

    solver = _SegmentSolver(dof, amax, jmax)
    # Segment times start at stop-and-go values and are refined from the solved durations
    # (the tangent velocities depend on them) while the total keeps shrinking.
    d = np.abs(np.diff(q, axis=0))
    seg_time = np.max(rest_to_rest_time(d, vmax_seg, amax, jmax), axis=1)
    best: tuple[float, list[ruckig.Trajectory], NDArray[np.float64]] | None = None
    for _ in range(MAX_PASSES):
        v = _flow_velocities(q, seg_time, vmax_seg, amax, jmax, stops)
        segs, v_used = _solve_chain(q, v, vmax_seg, solver)
        durations = np.array([s.duration for s in segs])
        total = float(durations.sum())
        if best is not None and total > best[0] * (1.0 - PASS_GAIN):
            if total < best[0]:
                best = (total, segs, v_used)
            break
        best = (total, segs, v_used)
        seg_time = np.maximum(durations, 1e-9)
    assert best is not None
    _, segs, v_used = best
    durations = np.array([s.duration for s in segs])
    starts = np.concatenate([[0.0], np.cumsum(durations)])
    table = _piece_table(segs, starts[:-1], dof)
    at_rest = np.all(v_used == 0.0, axis=1)
    stop_idx = tuple(int(i) for i in np.flatnonzero(at_rest[group]))
    return Trajectory(
        duration=float(starts[-1]),
        waypoint_times=starts[group],
        waypoints=q_in,
        segments=tuple(segs),
        segment_start_times=starts[:-1],
        stop_indices=stop_idx,
        dt=float(dt),
        piece_start=table[0],
        piece_p=table[1],
        piece_v=table[2],
        piece_a=table[3],
        piece_j=table[4],
    )
