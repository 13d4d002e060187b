"""Planning the project's robot program: moves -> jerk-limited trajectory -> limits and collisions."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from workbench.collision import PathReport, RobotCollisionChecker
from workbench.collision.engine import EnginePathReport
from workbench.errors import InputError, UnreachableError
from workbench.geometry.transforms import invert_transform
from workbench.motion import (
    Move,
    Program,
    Trajectory,
    ValidationReport,
    plan_program,
    time_program,
    validate_trajectory,
)
from workbench.motion.programs import csv_text, json_text, to_krl, to_ls, to_rapid, to_urscript
from workbench.motion.validation import AccelerationBound, interval_acceleration_bound
from workbench.project.models import ProgramSpec
from workbench.service.convert import DEG, MM, pose_to_matrix
from workbench.service.robot_setup import RobotSetup

EXPORT_FORMATS = {
    "rapid": ".mod",
    "krl": ".src",
    "ls": ".ls",
    "urscript": ".script",
    "csv": ".csv",
    "json": ".json",
}
Progress = Callable[[float, str], None]


@dataclass(frozen=True)
class MotionPlan:
    """A planned program: the trajectory, its samples, and what the checks found.

    Samples are every `dt` [s]: `times` (N,), `positions`/`velocities`/`accelerations` (N, dof)
    [rad, rad/s, rad/s^2], `tcp_speed` (N,) [m/s]; `colliding` (N,) marks samples in collision
    and samples whose interval to the next one collides or could not be certified free
    (treated as colliding: the plan promises nothing it has not proven). `collision_report` is an
    `EnginePathReport` (its `message` states the guarantee between samples or the first
    failure); its `colliding_indices` are exactly the samples the dense exact check flags.
    """

    program: Program
    trajectory: Trajectory
    times: NDArray[np.float64] = field(repr=False)
    positions: NDArray[np.float64] = field(repr=False)
    velocities: NDArray[np.float64] = field(repr=False)
    accelerations: NDArray[np.float64] = field(repr=False)
    tcp_speed: NDArray[np.float64] = field(repr=False)
    colliding: NDArray[np.bool_] = field(repr=False)
    limits_report: ValidationReport
    collision_report: PathReport

    @property
    def cycle_time(self) -> float:
        """Return the program's duration [s]."""
        return float(self.trajectory.duration)

    @property
    def ok(self) -> bool:
        """Return True when every sample is within limits and free of collisions."""
        return self.limits_report.ok and self.collision_report.collision_free

    def summary(self) -> str:
        """Return a one-paragraph human summary."""
        lines = [f"cycle time {self.cycle_time:.3f} s, {len(self.program.moves)} moves"]
        lines.append(
            "within joint limits"
            if self.limits_report.ok
            else f"{len(self.limits_report.violations)} limit violation(s)"
        )
        rep_ = self.collision_report
        if isinstance(rep_, EnginePathReport):
            lines.append(rep_.message)
        elif rep_.collision_free:
            lines.append("collision-free at every sample")
        else:
            first = self.collision_report.first_index
            rep = self.collision_report.first_report
            pairs = ", ".join(f"{a}–{b}" for a, b in rep.colliding) if rep else ""
            lines.append(f"first collision at t = {self.times[first]:.3f} s ({pairs})")
        return "; ".join(lines)


def build_program(spec: ProgramSpec, setup: RobotSetup, q_start: NDArray[np.float64]) -> Program:
    """Return the motion `Program` of a project program (poses in the robot base frame, SI)."""
    if not spec.moves:
        raise InputError("program.moves: the program has no moves; add at least one")
    model = setup.model
    T_base_world = invert_transform(setup.T_world_base)
    T_tcp_flange = invert_transform(setup.T_flange_tcp)
    moves = []
    q_prev = q_start
    for i, mv in enumerate(spec.moves):
        where = f"program.moves[{i}]" + (f" ({mv.name})" if mv.name else "")
        zone = mv.zone * MM
        if mv.joints is not None:
            q = np.asarray(mv.joints, float) * DEG
            if q.shape != (model.dof,):
                raise InputError(
                    f"{where}.joints: expected {model.dof} values [deg], got {len(mv.joints)}"
                )
            lo, hi = model.limits[:, 0], model.limits[:, 1]
            bad = np.flatnonzero((q < lo) | (q > hi))
            if bad.size:
                j = int(bad[0])
                raise InputError(
                    f"{where}.joints[{j}]: {mv.joints[j]} deg is outside"
                    f" [{lo[j] / DEG:.1f}, {hi[j] / DEG:.1f}] deg"
                )
            moves.append(Move.joint(q, speed=mv.speed / 100.0, zone=zone, name=mv.name))
            q_prev = q
            continue
        assert mv.pose is not None
        T_base_tcp = T_base_world @ pose_to_matrix(mv.pose)
        if mv.type == "linear":
            moves.append(Move.linear(T_base_tcp, speed=mv.speed * MM, zone=zone, name=mv.name))
            continue
        try:
            sols = np.asarray(model.ik(T_base_tcp @ T_tcp_flange, q_near=q_prev), float)
        except UnreachableError as exc:
            raise UnreachableError(f"{where}.pose: {exc}") from None
        if len(sols) == 0:
            raise UnreachableError(f"{where}.pose: no IK solution within the joint limits")
        q_prev = sols[0]
        moves.append(Move.joint(q_prev, speed=mv.speed / 100.0, zone=zone, name=mv.name))
    return Program(spec.name, tuple(moves))


def plan_motion(
    spec: ProgramSpec,
    setup: RobotSetup,
    checker: RobotCollisionChecker,
    q_start: NDArray[np.float64],
    *,
    dt: float = 0.01,
    progress: Progress | None = None,
) -> MotionPlan:
    """Return the `MotionPlan` of `spec`: IK through the moves, ruckig timing, then the checks."""
    report = progress or (lambda f, msg: None)
    model = setup.model
    report(0.0, "moves through IK")
    program = build_program(spec, setup, q_start)
    path = plan_program(
        model, program, q_start, model.max_velocity, T_flange_tcp=setup.T_flange_tcp
    )
    report(0.2, "jerk-limited timing")
    traj = time_program(path, model.max_acceleration, model.max_jerk, position_limits=model.limits)
    plan = plan_from_trajectory(
        program, traj, setup, checker, dt=dt, progress=lambda f, m: report(0.3 + 0.7 * f, m)
    )
    report(1.0, "done")
    return plan


def plan_from_trajectory(
    program: Program,
    trajectory: Trajectory,
    setup: RobotSetup,
    checker: RobotCollisionChecker,
    *,
    dt: float,
    validate_dt: float = 0.01,
    progress: Progress | None = None,
) -> MotionPlan:
    """Return the `MotionPlan` of a timed program: limits checked every `validate_dt` [s] and at
    the trajectory's peaks, samples every `dt` [s] with TCP speed, collisions checked at and
    between the samples.

    The check (`check_trajectory`) runs the spheres engine over all samples at once, confirms
    what it flags with python-fcl and certifies the motion between samples; where the fast
    mode cannot apply every sample is checked exactly and the report says why."""
    model = setup.model
    limits = validate_trajectory(
        trajectory,
        max_velocity=model.max_velocity,
        max_acceleration=model.max_acceleration,
        max_jerk=model.max_jerk,
        position_limits=model.limits,
        dt=validate_dt,
    )
    times, q, qd, qdd = trajectory.sample(dt)
    tcp = (setup.T_world_base @ model.fk(q) @ setup.T_flange_tcp)[:, :3, 3]
    tcp_speed = np.r_[np.linalg.norm(np.diff(tcp, axis=0), axis=1) / np.diff(times), 0.0]
    path_report = check_trajectory(trajectory, times, q, checker, progress=progress)
    colliding = np.zeros(len(times), bool)
    colliding[list(path_report.colliding_indices)] = True
    colliding[list(path_report.between_indices)] = True
    return MotionPlan(
        program, trajectory, times, q, qd, qdd, tcp_speed, colliding, limits, path_report
    )


def check_trajectory(
    trajectory: Trajectory,
    times: NDArray[np.float64],
    q: NDArray[np.float64],
    checker: RobotCollisionChecker,
    *,
    progress: Progress | None = None,
) -> EnginePathReport:
    """Return the collision report of a trajectory sampled at `times` [s] as q (N, dof) [rad].

    Fast mode: the shared spheres engine (`shared_engine`), bisecting between samples on the
    real motion (`trajectory.at`) with the exact acceleration bound of each interval
    (`interval_acceleration_bound`). Fallback: every sample
    checked exactly with python-fcl, nothing certified between them (`fallback` says why).
    """
    return check_motion(
        times,
        q,
        checker,
        sampler=lambda t: trajectory.at(t)[0],
        acceleration=interval_acceleration_bound(trajectory),
        progress=progress,
    )


def check_motion(
    times: NDArray[np.float64],
    q: NDArray[np.float64],
    checker: RobotCollisionChecker,
    *,
    sampler: Callable[[NDArray[np.float64]], NDArray[np.float64]],
    acceleration: NDArray[np.float64] | AccelerationBound,
    progress: Progress | None = None,
) -> EnginePathReport:
    """Return the collision report of a motion sampled at `times` [s] as q (N, dof) [rad].

    sampler(times (M,) [s]) -> (M, dof) [rad] gives the real motion between samples;
    acceleration (dof,) [rad/s^2] bounds |q''| over it, or bound(t0, t1) -> (M, dof) bounds it
    over each interval (the motion must be C1: the chord
    deviation bound ``acceleration * h**2 / 8`` needs a continuous velocity). Fast mode and
    fallback as in `check_trajectory`.
    """
    from workbench.service.collision_engine import shared_engine

    report = progress or (lambda f, m: None)
    engine, why = shared_engine(checker, progress=lambda f, m: report(0.2 * f, m))
    if engine is not None:
        return engine.check_path(
            q,
            times,
            sampler=sampler,
            acceleration=acceleration,
            progress=lambda f, m: report(0.2 + 0.8 * f, m),
        )
    dense = checker.check_path(q, progress=lambda f, m: report(0.2 + 0.8 * f, m))
    hits = dense.colliding_indices
    extra: dict[str, object] = {}
    if hits:
        rep = dense.first_report
        a, b = rep.colliding[0] if rep is not None else (None, None)
        extra = {
            "first_time": float(times[hits[0]]),
            "first_q": q[hits[0]],
            "link": a,
            "obstacle": b,
        }
    return EnginePathReport(
        collision_free=dense.collision_free,
        first_index=dense.first_index,
        first_report=dense.first_report,
        min_distance=dense.min_distance,
        samples=dense.samples,
        colliding_indices=hits,
        mode="exact",
        evaluated=len(q),
        certified=False,
        fallback=why,
        **extra,  # type: ignore[arg-type]
    )


def export_text(plan: MotionPlan, fmt: str) -> str:
    """Return the plan exported as `fmt` (rapid, krl, ls, urscript, csv or json)."""
    if fmt not in EXPORT_FORMATS:
        raise InputError(f"format: {fmt!r} is not one of {', '.join(EXPORT_FORMATS)}")
    if fmt == "csv":
        return csv_text(plan.times, plan.positions)
    if fmt == "json":
        return json_text(plan.times, plan.positions)
    post = {"rapid": to_rapid, "krl": to_krl, "ls": to_ls, "urscript": to_urscript}[fmt]
    return str(post(plan.program))
