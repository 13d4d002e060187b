"""One part's move from its start to its goal: the planned path, dense poses and the carrying robot's joints.

Pose planners ("ant", "rrt_connect") plan the part's pose; the robot that carries it then
follows by inverse kinematics in one arm configuration. The joint-space planner
("joint_rrt_connect") plans the carrying robot's joints, robot and part checked together.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import path_samples, pose_distance
from workbench.assembly.part import AssemblyPart
from workbench.assembly.plan import PartPath, plan_part_path
from workbench.assembly.planners.joint_rrt import CarrySpace, plan_carried_path
from workbench.assembly.workcell import Workcell
from workbench.errors import CollisionError, InputError, PlanningError, UnreachableError

Progress = Callable[[float, str], None]
#: Planners for a part move: the part's pose (seed 003's single ant, RRT-Connect in SE(3)), or
#: the carrying robot's joints (RRT-Connect in joint space, robot and part checked).
PLANNER_CHOICES = ("ant", "rrt_connect", "joint_rrt_connect")
#: Spacing [m] of the TCP samples handed to the motion module along approach, carry, retreat.
PATH_SPACING = 0.02


@dataclass(frozen=True, eq=False)
class PartPlan:
    """A planned part move: the planner's key poses, dense part poses, and the carrying robot's joints.

    `path.poses` (K, 4, 4) are the key points; `samples` (M, 4, 4) the part's poses every
    PATH_SPACING [m] of motion along them; `joints` (M, dof) [rad] the carrying robot's
    joints at those samples (None when no robot carries the part).
    """

    part: str
    robot: str | None
    path: PartPath
    samples: NDArray[np.float64]
    joints: NDArray[np.float64] | None
    branch: int

    @property
    def key_points(self) -> NDArray[np.float64]:
        """Return the key poses (K, 4, 4) [m] of the part from start to goal."""
        return self.path.poses


def check_ends(
    checker: InterferenceChecker, part: AssemblyPart, obstacles: Sequence[str], where: str
) -> None:
    """Raise CollisionError naming the obstacles the part touches at its start or goal pose.

    obstacles: the names of the checker's obstacles; where: the part's field, for messages.
    """
    for which, T in (("start", part.start), ("goal", part.goal)):
        hit = checker.colliding_obstacles(T)
        if hit:
            raise CollisionError(
                f"{where}.{which}: part {part.name!r} at its {which} pose interferes with "
                f"{[obstacles[k] for k in hit]}; move the {which} clear of them"
            )


def plan_pose_move(
    part: AssemblyPart,
    arm: AssemblyArm | None,
    checker: InterferenceChecker,
    planner: str,
    options: dict[str, Any],
    where: str,
    report: Progress,
) -> PartPlan:
    """Return the PartPlan of a pose planner; the carrying `arm` (if any) follows from its home.

    UnreachableError naming `where` when the arm cannot follow in one configuration.
    """
    path = plan_part_path(part.start, part.goal, part.mesh, [], planner, checker=checker, **options)
    samples = path_samples(path.poses, checker.radius, PATH_SPACING)
    joints: NDArray[np.float64] | None = None
    branch = -1
    if arm is not None:
        report(0.7, f"{part.name}: {arm.name} follows by inverse kinematics")
        ik = arm.follow(samples @ part.T_part_tcp, arm.q_home, f"{where} ({part.name}) path")
        joints, branch = ik.q, ik.branch
    return PartPlan(part.name, None if arm is None else arm.name, path, samples, joints, branch)


def plan_joint_move(
    space: CarrySpace,
    part: AssemblyPart,
    arm: AssemblyArm,
    options: dict[str, Any],
    q_start: ArrayLike | None,
    where: str,
) -> PartPlan:
    """Return the PartPlan of the joint-space planner in `space`, from `q_start` (default: near home).

    Waypoints for the motion module along each straight joint segment, about every
    PATH_SPACING of the part's motion (|Δp| + 0.1 m·angle, measured on 16 sub-steps), as
    the pose planners' samples; the timed motion is checked again afterwards.
    """
    try:
        path = plan_carried_path(
            space, part.start, part.goal, arm.q_home, q_start=q_start, **options
        )
    except (CollisionError, UnreachableError, PlanningError) as exc:
        # PlanningError too: a flip on a withdrawal (`carry_ik`) is one since `follow_path`.
        raise exc.within(f"{where} ({part.name}) carried by {arm.name}") from exc
    assert path.joints is not None
    K = path.joints
    dense = [K[:1]]
    u = np.linspace(0.0, 1.0, 17)[:, None]
    for a, b in zip(K[:-1], K[1:], strict=True):
        P = space.part_poses(a + u * (b - a))
        travel = float(np.sum(pose_distance(P[:-1], P[1:], 0.1)))
        n = max(1, int(np.ceil(travel / PATH_SPACING)))
        dense.append(a + (np.arange(1, n + 1) / n)[:, None] * (b - a))
    joints = np.concatenate(dense)
    return PartPlan(part.name, arm.name, path, space.part_poses(joints), joints, path.branch)


def plan_move(
    cell: Workcell,
    name: str,
    planner: str,
    options: dict[str, Any],
    *,
    cell_size: float | None = None,
    q_start: ArrayLike | None = None,
    report: Progress | None = None,
) -> PartPlan:
    """Return the PartPlan of part `name` of `cell` from its start to its goal, with its robot's joints.

    planner: one of PLANNER_CHOICES: "ant" and "rrt_connect" plan the part's pose and the
    robot follows by IK; "joint_rrt_connect" plans the carrying robot's joints (options
    seed, max_time, max_nodes, range_, shortcut_iterations, resolution, robot_resolution
    [m]) from `q_start` [rad] (default: the IK solution nearest the robot's home at the
    part's start). cell_size [m]: as `Workcell.cell_size`. Raises CollisionError when the
    start or goal interferes (naming the obstacles or the robot's bodies), PlanningError
    when no path is found (or, in joint space, the robot's withdrawal flips), UnreachableError
    when the carrying robot cannot follow in one configuration or the start or goal is out of
    its reach; each naming the part's field, except a pose planner's PlanningError.
    """
    report = report or (lambda f, m: None)
    part = cell.part(name)
    if planner not in PLANNER_CHOICES:
        raise InputError(f"planner must be one of {PLANNER_CHOICES}, got {planner!r}")
    report(0.05, f"{name}: subdividing into cells")
    ch = cell.checker(name, cell_size)
    where = cell.where(name)
    check_ends(ch, part, [n for n, _ in cell.obstacles_for(name)], where)
    report(0.3, f"{name}: planning ({planner})")
    if planner == "joint_rrt_connect":
        opts = dict(options)
        opts.setdefault("progress", lambda f, m: report(0.3 + 0.4 * f, f"{name}: {m}"))
        space = cell.carry_space(
            name,
            cell_size,
            resolution=opts.pop("resolution", None),
            robot_resolution=opts.pop("robot_resolution", None),
        )
        assert part.robot is not None  # carry_space refused a part without one
        plan = plan_joint_move(space, part, cell.arms[part.robot], opts, q_start, where)
        done = f"{len(plan.path.poses)} key points (joint space)"
    else:
        arm = None if part.robot is None else cell.arms[part.robot]
        plan = plan_pose_move(part, arm, ch, planner, options, where, report)
        done = f"{len(plan.path.poses)} key points"
    report(1.0, f"{name}: {done}")
    return plan
