"""Planning the project's robot program: moves -> jerk-limited trajectory -> limits and collisions."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from workbench.collision import CollisionPolicy, RobotCollisionChecker, plan_check
from workbench.collision.engine import EnginePathReport
from workbench.errors import InputError
from workbench.kinematics.dh_chain import joint_vector
from workbench.motion import (
    JointPath,
    Program,
    SampledMotion,
    Trajectory,
    ValidationReport,
    plan_program,
    time_program,
    validate_trajectory,
)
from workbench.motion.program import motion_program, program_start
from workbench.motion.programs.controller_program import (
    MotionLimits,
    RobotProgram,
    ToolData,
    WorkObject,
)
from workbench.motion.programs.from_plan import robot_program as _robot_program
from workbench.motion.programs.from_plan import wait_holds, wait_summary
from workbench.project.models import ProgramSI, Project
from workbench.project.program_io import program_items
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
    `colliding_indices` are exactly the samples the dense exact check flags. `path` (the
    joint waypoints) and `items` (the program's moves and actions) are what `robot_program`
    needs; plans of other workflows leave them empty.
    """

    program: Program
    trajectory: Trajectory
    samples: SampledMotion = field(repr=False)
    limits_report: ValidationReport
    collision_report: EnginePathReport
    path: JointPath | None = field(default=None, repr=False)
    items: tuple = field(default=(), repr=False)

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
        """Return True when every sample is within limits and free of collisions, and the robot
        keeps the clearance margin (`EnginePathReport.keeps_margin`)."""
        rep = self.collision_report
        return self.limits_report.ok and rep.collision_free and rep.keeps_margin

    def summary(self) -> str:
        """Return a one-paragraph human summary."""
        head = f"cycle time {self.cycle_time:.3f} s"
        waits = wait_summary(self.items, self.path) if self.path is not None else ""
        lines = [head + (f" ({waits})" if waits else "") + f", {len(self.program.moves)} moves"]
        lines.append(
            "within joint limits"
            if self.limits_report.ok
            else f"{len(self.limits_report.violations)} limit violation(s)"
        )
        lines.append(self.collision_report.message)
        return "; ".join(lines)


def build_program(
    spec: ProgramSI, setup: RobotSetup, q_start: NDArray[np.float64], items: tuple[Any, ...] = ()
) -> Program:
    """Return the motion `Program` of a project program (`from_plan.motion_program`): `items`
    are its moves and actions (default: the moves of `spec`)."""
    seq: tuple[Any, ...] = items or tuple(spec.moves)
    return motion_program(
        spec.name, seq, setup.model, setup.T_world_base, setup.T_flange_tcp, q_start
    )


def plan_project(
    project: Project,
    setup: RobotSetup,
    checker: RobotCollisionChecker,
    *,
    policy: CollisionPolicy,
    dt: float = 0.01,
    progress: Progress | None = None,
) -> MotionPlan:
    """Return the `MotionPlan` of the project's program (its moves and actions) from its start
    joints (`program.start`; absent: its first move's target, `program_start`, a pose solved
    near the robot's joints as the file stores them), never from the robot's current joints; InputError when there is no program or `dt` [s] is bad."""
    section = project.program
    if section is None:
        raise InputError("program: the project has no program; add a 'program' with moves")
    convention = setup.model.convention  # the file's controller joints -> the model's
    spec = section.to_si(convention)
    if not (np.isfinite(dt) and 0 < dt <= 0.1):
        raise InputError(f"dt: {dt!r} s must be in (0, 0.1]")
    items = program_items(project, convention)
    q_start = (
        program_start(items, setup.model, setup.T_world_base, setup.T_flange_tcp, setup.q0)
        if spec.start is None
        else joint_vector(spec.start, setup.model.dof, "program.start")
    )
    return plan_motion(
        spec, setup, checker, q_start, policy=policy, dt=dt, progress=progress, items=items
    )


def plan_motion(
    spec: ProgramSI,
    setup: RobotSetup,
    checker: RobotCollisionChecker,
    q_start: NDArray[np.float64],
    *,
    policy: CollisionPolicy,
    dt: float = 0.01,
    progress: Progress | None = None,
    items: tuple[Any, ...] = (),
) -> MotionPlan:
    """Return the `MotionPlan` of `spec`: IK through the moves, ruckig timing, then the checks
    (collisions under `policy`). `items`: the program's moves and actions (default: its moves)."""
    report = progress or (lambda f, msg: None)
    model = setup.model
    report(0.0, "moves through IK")
    items = items or tuple(spec.moves)
    program = build_program(spec, setup, q_start, items)
    path = plan_program(
        model, program, q_start, model.max_velocity, T_flange_tcp=setup.T_flange_tcp
    )
    report(0.2, "jerk-limited timing")
    traj = time_program(
        path, model.max_acceleration, model.max_jerk, position_limits=model.limits, program=program
    ).with_holds(wait_holds(items, path))  # the program's waits, held at their stops
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
    return replace(plan, path=path, items=tuple(items))


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


def robot_program(
    plan: MotionPlan,
    setup: RobotSetup,
    *,
    tool: ToolData,
    work_objects: tuple[WorkObject, ...],
    limits: MotionLimits,
    robot: str,
) -> RobotProgram:
    """Return the `RobotProgram` of a Motion plan (`from_plan.robot_program`)."""
    if plan.path is None:
        raise InputError(
            "this plan has no program moves to write (it was not planned from a program)"
        )
    return _robot_program(
        plan.items,
        plan.program,
        plan.path,
        plan.trajectory,
        setup.model,
        tool=tool,
        work_objects=work_objects,
        T_world_base=setup.T_world_base,
        limits=limits,
        robot=robot,
    )
