"""Planning the project's robot program: moves -> jerk-limited trajectory -> limits and collisions."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from workbench.collision import CollisionPolicy, RobotCollisionChecker, plan_check
from workbench.collision.engine import EnginePathReport
from workbench.errors import InputError, UnreachableError
from workbench.geometry.transforms import invert_transform
from workbench.motion import (
    Move,
    Program,
    SampledMotion,
    Trajectory,
    ValidationReport,
    plan_program,
    time_program,
    validate_trajectory,
)
from workbench.motion.programs import export
from workbench.project.models import ProgramSI
from workbench.project.units import to_deg
from workbench.service.robot_setup import RobotSetup

Progress = Callable[[float, str], None]


@dataclass(frozen=True)
class MotionPlan:
    """A planned program: the trajectory, its samples, and what the checks found.

    `samples` (a `SampledMotion`) every `dt` [s]: times (N,), joints/velocities/accelerations
    (N, dof) [rad, rad/s, rad/s^2], TCP positions (N, 3) [m] (world) and `tcp_speed` (N,)
    [m/s]; `colliding` (N,) marks samples in collision and samples whose interval to the
    next one collides or could not be certified free (treated as colliding: the plan
    promises nothing it has not proven). `collision_report` is an `EnginePathReport` (its
    `message` states the guarantee between samples or the first failure); its
    `colliding_indices` are exactly the samples the dense exact check flags.
    """

    program: Program
    trajectory: Trajectory
    samples: SampledMotion = field(repr=False)
    limits_report: ValidationReport
    collision_report: EnginePathReport

    @property
    def times(self) -> NDArray[np.float64]:
        """Return the sample times (N,) [s]."""
        return self.samples.times

    @property
    def positions(self) -> NDArray[np.float64]:
        """Return the sampled joints (N, dof) [rad]."""
        return self.samples.joints

    @property
    def velocities(self) -> NDArray[np.float64]:
        """Return the sampled joint velocities (N, dof) [rad/s]."""
        return self.samples.velocity

    @property
    def accelerations(self) -> NDArray[np.float64]:
        """Return the sampled joint accelerations (N, dof) [rad/s^2]."""
        return self.samples.acceleration

    @property
    def tcp_speed(self) -> NDArray[np.float64]:
        """Return the TCP speed (N,) [m/s] (`SampledMotion.tcp_speed`: central differences)."""
        return self.samples.tcp_speed

    @property
    def colliding(self) -> NDArray[np.bool_]:
        """Return (N,) samples in collision or not certified free up to the next."""
        return self.samples.colliding

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
        lines.append(self.collision_report.message)
        return "; ".join(lines)


def build_program(spec: ProgramSI, setup: RobotSetup, q_start: NDArray[np.float64]) -> Program:
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
        if mv.joints is not None:
            q = mv.joints
            if q.shape != (model.dof,):
                raise InputError(f"{where}.joints: expected {model.dof} values [deg], got {len(q)}")
            lo, hi = model.limits[:, 0], model.limits[:, 1]
            bad = np.flatnonzero((q < lo) | (q > hi))
            if bad.size:
                j = int(bad[0])
                conv = model.convention  # the file's values are the controller's
                qc, lim = conv.to_controller(q), conv.limits_to_controller(model.limits)
                raise InputError(
                    f"{where}.joints[{j}]: {to_deg(qc[j]):g} deg is outside"
                    f" [{to_deg(lim[j, 0]):.1f}, {to_deg(lim[j, 1]):.1f}] deg"
                )
            moves.append(Move.joint(q, speed=mv.speed, zone=mv.zone, name=mv.name))
            q_prev = q
            continue
        assert mv.T_world_tcp is not None
        T_base_tcp = T_base_world @ mv.T_world_tcp
        if mv.type == "linear":
            moves.append(Move.linear(T_base_tcp, speed=mv.speed, zone=mv.zone, name=mv.name))
            continue
        try:
            sols = np.asarray(model.ik(T_base_tcp @ T_tcp_flange, q_near=q_prev), float)
        except UnreachableError as exc:
            raise UnreachableError(f"{where}.pose: {exc}") from None
        if len(sols) == 0:
            raise UnreachableError(f"{where}.pose: no IK solution within the joint limits")
        q_prev = sols[0]
        moves.append(Move.joint(q_prev, speed=mv.speed, zone=mv.zone, name=mv.name))
    return Program(spec.name, tuple(moves))


def plan_motion(
    spec: ProgramSI,
    setup: RobotSetup,
    checker: RobotCollisionChecker,
    q_start: NDArray[np.float64],
    *,
    policy: CollisionPolicy,
    dt: float = 0.01,
    progress: Progress | None = None,
) -> MotionPlan:
    """Return the `MotionPlan` of `spec`: IK through the moves, ruckig timing, then the checks
    (collisions under `policy`)."""
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
        program,
        traj,
        setup,
        checker,
        policy=policy,
        dt=dt,
        progress=lambda f, m: report(0.3 + 0.7 * f, m),
    )
    report(1.0, "done")
    return plan


def plan_from_trajectory(
    program: Program,
    trajectory: Trajectory,
    setup: RobotSetup,
    checker: RobotCollisionChecker,
    *,
    policy: CollisionPolicy,
    dt: float,
    validate_dt: float = 0.01,
    progress: Progress | None = None,
) -> MotionPlan:
    """Return the `MotionPlan` of a timed program: limits checked every `validate_dt` [s] and at
    the trajectory's peaks, samples every `dt` [s] with TCP speed, collisions checked at and
    between the samples.

    The check (`workbench.collision.check_trajectory` under `policy`, the project's
    `Workbench.collision_policy`) runs the fast engine over all samples at once, confirms
    what it flags with python-fcl and certifies the motion between samples; in the exact mode,
    or where the fast mode cannot apply, every sample is checked exactly and the report says
    why."""
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
    path_report = plan_check.check_trajectory(
        trajectory, times, q, checker, policy, progress=progress
    )
    colliding = np.zeros(len(times), bool)
    colliding[list(path_report.colliding_indices)] = True
    colliding[list(path_report.between_indices)] = True
    samples = SampledMotion(times, q, qd, qdd, tcp, colliding, name=program.name)
    return MotionPlan(program, trajectory, samples, limits, path_report)


def export_text(plan: MotionPlan, fmt: str) -> str:
    """Return the plan exported as `fmt` (rapid, krl, ls, urscript, csv or json)."""
    return export(fmt, plan.program, plan.times, plan.positions)
