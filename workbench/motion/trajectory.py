"""Jerk-limited joint trajectories through waypoints, chained from ruckig state-to-state segments.

ruckig's community edition solves one state-to-state problem at a time (its
``intermediate_positions`` would call a cloud service), so the path is split into one
segment per pair of consecutive waypoints. The motion flows through intermediate
waypoints: each waypoint gets a velocity along the chord of its two segments (zero for a
joint that reverses there, at exact stops and at the ends), scaled to the velocity limits
and lowered by a forward and a backward pass to what every joint can reach from, and brake
to, its neighbours' speeds within part of the segments between them; one ruckig call per
segment then times it. Every
segment is checked (``validate_input``, the ``Result``, no overshoot beyond the box of its
two waypoints); a segment that fails is re-solved with a stop at its end waypoint, then at
its start waypoint (re-solving the previous segment).

Each segment's ruckig ``Trajectory`` is kept; for fast evaluation the profiles are also
flattened into one table of constant-jerk pieces per joint (`at` is exact, vectorised).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np
import ruckig
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, PlanningError
from workbench.motion.limits import check_limits, check_position_limits, check_waypoints
from workbench.motion.speed_bounds import max_speed_change

# Slack for "no overshoot beyond the waypoint box": ruckig's own position error is ~1e-12.
_BOX_TOL = 1e-10
# Consecutive waypoints closer than this (every joint) are merged into one [rad]: a shorter
# segment is below ruckig's precision (a 1e-5 mm linear move gives ~1e-8 rad, whose
# jerk-limited profile overshoots its waypoints), and 1e-7 rad moves a point 1 m out 0.1 um.
DUPLICATE_TOL = 1e-7
REACH_FRACTION = 0.45
"""Share of a segment's length within which each joint must be able to change its speed
between the segment's two waypoint speeds (the rest is slack that lets the joints share
the segment time the slowest one sets). At 1 the speeds sit on the edge of reachability,
so joints moving a little must dip their speed and ruckig's synchronised profile
overshoots; 0.45 was the fastest on benchmarks/motion.py's sets (0.3-0.5 within 5 %).
"""
MAX_SAMPLES = 200_000
"""Most samples of one trajectory (`Trajectory.sample`): its duration / dt (33 minutes at the
plans' 0.01 s; about 40 MB of joints, rates and accelerations, and some 30 s of collision
checks on this 2-core machine). A longer one is refused before it is sampled, with the estimate."""

# Why ruckig refused a segment, by its result code (the Python binding knows only some of
# them by name: the others arrive as "ValueError: -101 is not a valid Result").
RUCKIG_CAUSES = {
    -1: "ruckig failed (an unclassified error)",
    -100: "ruckig refused the input (a limit or state it cannot use)",
    -101: (
        "the segment would last longer than ruckig can time (about 7,600 s): the speed, "
        "acceleration or jerk limits are too small for its distance"
    ),
    -102: "the segment would leave ruckig's position limits",
    -104: "a velocity, acceleration or jerk limit is zero",
    -110: (
        "ruckig found no duration for the segment: its limits (speed, acceleration, jerk) and "
        "its length differ by too many orders of magnitude"
    ),
    -111: "ruckig could not synchronise the joints of the segment",
}


def ruckig_cause(code: int) -> str:
    """Return the cause of ruckig result `code` in words (its number for an unknown one)."""
    return RUCKIG_CAUSES.get(int(code), f"ruckig returned error {int(code)}")


def sample_count(duration: float, dt: float, what: str = "the trajectory") -> int:
    """Return how many samples `duration` [s] every `dt` [s] takes (end included).

    Raises PlanningError with the estimate when it is over `MAX_SAMPLES`."""
    n = int(np.floor(duration / dt + 1e-9)) + 2
    if n > MAX_SAMPLES:
        raise PlanningError(
            f"{what} lasts {duration:.4g} s: {n:,} samples every {dt:g} s, above the budget of "
            f"{MAX_SAMPLES:,} (workbench.motion.trajectory.MAX_SAMPLES); raise the speeds, "
            "accelerations or jerks, shorten the motion, or sample it less often"
        )
    return n


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
        sample_count(self.duration, step)
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

    def with_holds(self, holds: Sequence[tuple[int, float]]) -> Trajectory:
        """Return the trajectory holding still `seconds` [s] at each (waypoint index, seconds)
        of `holds`: the program's waits at an exact stop (a dwell, a gripper's settle time).

        The waypoint must be a stop (`stop_indices`): InputError naming it otherwise. Later
        waypoints, segments and pieces move later by the holds before them.
        """
        out = self
        for idx, seconds in sorted(holds, key=lambda h: -self.waypoint_times[h[0]]):
            if seconds <= 0.0:
                continue
            if idx not in self.stop_indices:
                raise InputError(
                    f"waypoint {idx}: a wait needs an exact stop there (the robot is moving)"
                )
            out = out._hold(float(self.waypoint_times[idx]), idx, float(seconds))
        return out

    def _hold(self, t: float, idx: int, seconds: float) -> Trajectory:
        pos = self.at([t])[0][0]
        dof = self.dof
        # (dof, P): pieces that start at or after the stop move later (the stop is a boundary)
        later = self.piece_start >= t - 1e-12
        start = np.where(later, self.piece_start + seconds, self.piece_start)
        # the still piece goes in front of each joint's first later piece
        cols = [np.searchsorted(start[j], t + seconds * 0.5) for j in range(dof)]

        def insert(a: NDArray[np.float64], value: NDArray[np.float64]) -> NDArray[np.float64]:
            rows = [np.insert(a[j], cols[j], value[j]) for j in range(dof)]
            return np.stack(rows)

        zero = np.zeros(dof)
        wp_t = self.waypoint_times.copy()
        wp_t[np.arange(len(wp_t)) > idx] += seconds
        seg_t = np.where(
            self.segment_start_times >= t - 1e-12,
            self.segment_start_times + seconds,
            self.segment_start_times,
        )
        return Trajectory(
            duration=self.duration + seconds,
            waypoint_times=wp_t,
            waypoints=self.waypoints,
            segments=self.segments,
            segment_start_times=seg_t,
            stop_indices=self.stop_indices,
            dt=self.dt,
            piece_start=insert(start, np.full(dof, t)),
            piece_p=insert(self.piece_p, pos),
            piece_v=insert(self.piece_v, zero),
            piece_a=insert(self.piece_a, zero),
            piece_j=insert(self.piece_j, zero),
        )


def _flow_velocities(
    q: NDArray[np.float64],
    vmax: NDArray[np.float64],
    amax: NDArray[np.float64],
    jmax: NDArray[np.float64],
    stops: NDArray[np.bool_],
) -> NDArray[np.float64]:
    """Return waypoint velocities (N, dof): along the path, zero at reversals, stops and ends.

    Direction: the chord (q[i+1] - q[i-1]) over the two segments' times at full speed
    (max over joints of distance / velocity limit), which lies between the two segments'
    own velocities joint by joint, so every joint's share of the motion stays consistent
    with the segment time the slowest joint sets; a joint whose two segments move in
    opposite directions (or not at all) gets zero. Speed: the direction scaled as a whole
    to the velocity limits of both segments, then lowered, as a whole per waypoint, by a
    forward and a backward pass until every joint can reach its speed from the previous
    waypoint's and brake to the next one's within `REACH_FRACTION` of the segment between
    them (closed-form jerk-limited bound, `max_speed_change`). No segment time is needed,
    so one ruckig call per segment follows.
    """
    d = np.diff(q, axis=0)
    dist = np.abs(d)
    cruise = np.max(dist / vmax, axis=1)
    # a joint that moves less than DUPLICATE_TOL over a segment stands still there: the sign
    # of IK noise (1e-16 on a joint held at 0 along a line) must not decide its flow
    still = dist < DUPLICATE_TOL
    same = (np.sign(d[:-1]) == np.sign(d[1:])) & ~still[:-1] & ~still[1:]
    chord = np.where(same, (q[2:] - q[:-2]) / (cruise[:-1] + cruise[1:])[:, None], 0.0)
    # A hair below the limit: ruckig's validate_input rejects a velocity equal to the
    # limit after rounding (seen with per-segment limits from linear moves).
    cap = np.minimum(vmax[:-1], vmax[1:]) * (1.0 - 1e-9)
    mag = np.abs(chord)
    with np.errstate(divide="ignore"):
        scale = np.min(np.where(mag > 0.0, cap / mag, np.inf), axis=1, keepdims=True)
    w = np.zeros_like(q)  # each waypoint's speed per joint at full scale
    w[1:-1] = mag * np.where(np.isfinite(scale), scale, 0.0)
    sigma = np.zeros(q.shape[0])  # the scale of each waypoint, in [0, 1]
    sigma[1:-1] = 1.0
    sigma[stops | ~np.any(w > 0.0, axis=1)] = 0.0
    _reach_passes(sigma, w, dist * REACH_FRACTION, amax, jmax)
    v = np.sign(np.concatenate([d[:1], d])) * w * sigma[:, None]
    v[0] = v[-1] = 0.0
    return v


def _reach_passes(
    sigma: NDArray[np.float64],
    w: NDArray[np.float64],
    dist: NDArray[np.float64],
    amax: NDArray[np.float64],
    jmax: NDArray[np.float64],
) -> None:
    """Lower `sigma` (N,) in place: waypoint i's speeds sigma[i] * w[i] (N, dof) reachable from
    waypoint i-1's and brakeable to waypoint i+1's within `dist` (N-1, dof), joint by joint
    (`max_speed_change`).

    Jacobi rounds of both neighbour constraints, vectorised over waypoints (faster here than
    sequential passes: numpy's per-call cost dominates 6-element arrays); a constraint
    travels one waypoint per round, so N rounds always suffice, typically far fewer. The
    bound is a heuristic (ruckig checks each segment), so rounds stop once no scale drops
    by more than 0.1 %."""
    moving = w > 0.0
    inv = 1.0 / np.where(moving, w, 1.0)
    for _ in range(w.shape[0]):
        s = sigma[:, None] * w
        fwd = max_speed_change(s[:-1], dist, amax, jmax) * inv[1:]
        bwd = max_speed_change(s[1:], dist, amax, jmax) * inv[:-1]
        new = sigma.copy()
        new[1:] = np.minimum(new[1:], np.min(np.where(moving[1:], fwd, np.inf), axis=1))
        new[:-1] = np.minimum(new[:-1], np.min(np.where(moving[:-1], bwd, np.inf), axis=1))
        done = np.all(new >= sigma * (1.0 - 1e-3))
        sigma[:] = new
        if done:
            break


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
        except ValueError as exc:  # a result code the binding has no name for
            code = str(exc).split(" ", 1)[0]
            if not code.lstrip("-").isdigit():
                raise
            return None, ruckig_cause(int(code))
        if result not in (ruckig.Result.Working, ruckig.Result.Finished):
            return None, ruckig_cause(int(result.value))
        if not np.isfinite(traj.duration):
            return None, "ruckig returned a non-finite duration"
        lo, hi = np.minimum(q0, q1), np.maximum(q0, q1)
        tol = _BOX_TOL * np.maximum(1.0, np.abs(hi))
        for j, b in enumerate(traj.position_extrema):
            if b.min < lo[j] - tol[j] or b.max > hi[j] + tol[j]:
                return None, (
                    f"joint {j + 1} would overshoot its waypoints ({lo[j]:.10g}..{hi[j]:.10g};"
                    f" the motion reaches {b.min:.10g}..{b.max:.10g}): the segment is too short "
                    f"({hi[j] - lo[j]:.3g}) for the joint to stop on its waypoint within its "
                    "acceleration and jerk limits"
                )
        return traj, ""


def _solve_chain(
    q: NDArray[np.float64],
    v: NDArray[np.float64],
    vmax_seg: NDArray[np.float64],
    solver: _SegmentSolver,
    names: list[str] | None = None,
) -> tuple[list[ruckig.Trajectory], NDArray[np.float64]]:
    """Return per-segment trajectories and the waypoint velocities finally used.

    `names` (one per segment) name each segment in the PlanningError of one that fails."""
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
            where = f"segment {k} (waypoint {k} -> {k + 1})"
            if names is not None:
                where = f"{names[k]}, {where}"
            raise PlanningError(
                f"{where} has no jerk-limited solution even from rest to rest: {why}"
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
    labels: Sequence[str] | None = None,
) -> Trajectory:
    """Return a jerk-limited `Trajectory` through joint `waypoints` (N, dof) [rad].

    Limits are per joint, (dof,): velocity [rad/s], acceleration [rad/s^2], jerk [rad/s^3];
    `max_velocity` may also be (N-1, dof), one row per segment. `position_limits` (dof, 2)
    [rad] is checked against the waypoints; since no segment overshoots the box of its two
    waypoints, the whole motion stays within them. `exact_stop` lists waypoint indices
    where the robot comes to rest. `dt` [s] is the default period of `Trajectory.sample`.
    Consecutive waypoints equal within 1e-9 rad are merged (they share a waypoint time).

    `labels` (N,) name what each waypoint belongs to (e.g. "move 2 (pick)"): a segment that
    cannot be solved is named by its end waypoint's label, with the cause.

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
    names = None
    if labels is not None:
        if len(labels) != n_in:
            raise InputError(f"labels: expected {n_in} (one per waypoint), got {len(labels)}")
        names = [str(labels[i]) for i in np.flatnonzero(keep)[1:]]  # each segment's end
    vmax_seg = np.broadcast_to(vmax_in, (n_in - 1, dof))[moved]
    stops = np.zeros(q.shape[0], bool)
    np.logical_or.at(stops, group, stops_in)

    solver = _SegmentSolver(dof, amax, jmax)
    v = _flow_velocities(q, vmax_seg, amax, jmax, stops)
    segs, v_used = _solve_chain(q, v, vmax_seg, solver, names)
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
