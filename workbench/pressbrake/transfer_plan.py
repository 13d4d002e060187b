"""The transfer-only bending plan (a cell without a press model): each bend placed on the die
by IK in one arm configuration, and the checked transfer from the press brake to the pallet
(seed 000's scenario).

SI units (m, rad, s). The transfer is a jerk-limited (ruckig) joint trajectory; its frames
are checked: the part by its OBB tree against the cell, the robot under a collision policy.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from workbench.collision.plan_check import CollisionPolicy, check_trajectory
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel
from workbench.kinematics.path_ik import follow_path
from workbench.motion.trajectory import smooth_joint_path
from workbench.pressbrake.die import Die, DiePlacement, die_placements, die_targets
from workbench.pressbrake.grasp import Grasp, T_part_grasp
from workbench.pressbrake.obstacles import Obstacles
from workbench.pressbrake.plan import BendingPlan, first_collision, robot_frames
from workbench.pressbrake.process_contacts import gripper_contacts
from workbench.pressbrake.transfer import (
    Transfer,
    base_flange_poses,
    carried_poses,
    check_part,
    transfer_poses,
    world_tcp,
)
from workbench.sheetmetal.part import SheetMetalPart

F64 = NDArray[np.float64]
Progress = Callable[[float, str], None]


class ArmSetup(Protocol):
    """The robot as the transfer needs it (`RobotSetup` is one): model, base and TCP frames."""

    @property
    def model(self) -> RobotModel: ...
    @property
    def T_world_base(self) -> F64: ...
    @property
    def T_flange_tcp(self) -> F64: ...


def path_joints(
    arm: ArmSetup,
    T_world_tcp: F64,
    names: list[str],
    q_start: F64,
    what: str,
    grasp_flange: str,
) -> tuple[F64, str]:
    """Return joints (N, dof) reaching the TCP poses (N, 4, 4) with one arm configuration,
    and its label; UnreachableError names the pose (`names`) the robot cannot reach."""
    path = follow_path(
        arm.model,
        base_flange_poses(arm.T_world_base, arm.T_flange_tcp, T_world_tcp),
        q_start,
        labels=names,
        what=what,
        cost="total",
        points=T_world_tcp[:, :3, 3],
        hint=f"the grasp is on flange {grasp_flange!r}; move the die or pallet, "
        "change the grasp or the sequence",
    )
    return path.q, path.configuration


def placements(
    arm: ArmSetup, part: SheetMetalPart, die: Die, grasp: Grasp, q_start: F64
) -> tuple[tuple[DiePlacement, ...], str]:
    """Return each bend's die placement with one arm configuration, and its label.

    Raises UnreachableError naming the bend the robot cannot hold on the die.
    """
    T_part, T_tcp, names = die_targets(part, die, grasp)
    q, label = path_joints(arm, T_tcp, names, q_start, "bending.die", grasp.flange)
    return die_placements(part, T_part, T_tcp, q), label


def plan_transfer(
    arm: ArmSetup,
    part: SheetMetalPart,
    grasp: Grasp,
    *,
    die: Die,
    transfer: Transfer,
    frames: int,
    q_start: F64,
    obstacles: Obstacles,
    checker: RobotCollisionChecker,
    policy: CollisionPolicy,
    progress: Progress | None = None,
) -> BendingPlan:
    """Place every bend on the die, then plan and check the transfer to the pallet.

    The transfer is a jerk-limited (ruckig) joint trajectory; `frames` (>= 22) evenly
    timed frames are checked: the part with its OBB tree against the cell's `obstacles`
    (leaf hits on cylinders and meshes confirmed with python-fcl) and the robot's links and
    tool under `policy` (`check_trajectory`; by default spheres + SDF at every frame, what
    it flags confirmed with python-fcl, the motion between frames certified on the
    trajectory). `progress(fraction, message)` reports the stages.
    """
    report = progress or (lambda f, m: None)
    model = arm.model
    report(0.0, "placing each bend line on the die")
    placed, label = placements(arm, part, die, grasp, q_start)
    report(0.25, "planning the transfer")
    T_tcp, names = transfer_poses(transfer, die, placed[-1], part, grasp)
    q_way, _ = path_joints(arm, T_tcp, names, placed[-1].q, "bending transfer", grasp.flange)
    traj = smooth_joint_path(
        q_way,
        model.max_velocity,
        model.max_acceleration,
        model.max_jerk,
        position_limits=model.limits,
        exact_stop=[0, len(q_way) - 1],
    )
    F = frames
    times = np.linspace(0.0, traj.duration, F)
    q = traj.at(times)[0]
    T_world_grasp, T_world_part = carried_poses(
        world_tcp(model, arm.T_world_base, arm.T_flange_tcp, q), part, grasp
    )
    report(0.4, f"checking {F} frames with the OBB tree")
    tree = part.fold(len(part.bends)).obb_tree(grasp.flange)
    rep = check_part(tree, obstacles, T_world_grasp)
    report(0.7, "checking the robot against the cell")
    # The checker holds the robot's links and tool, not the part: the tool and the part it
    # grips are never a pair, and the part's own checks are the tree's above. The gripper
    # takes the part off the die and puts it on the pallet: those contacts are exempt from
    # the clearance margin.
    policy = policy.exempting(gripper_contacts(checker, [q_way[0], q_way[-1]]))
    path = check_trajectory(
        traj,
        times,
        q,
        checker,
        policy,
        progress=lambda f, m: report(0.7 + 0.25 * f, m),
    )
    robot_hit, robot_between = robot_frames(path, F)
    first = first_collision(
        times,
        rep,
        robot_hit,
        path,
        [f.name for f in part.flanges],
        obstacles.names,
        lambda f: checker.check(q[f], distance=False).colliding,
    )
    plan = BendingPlan(
        placements=placed,
        configuration=label,
        trajectory=traj,
        times=times,
        joints=q,
        T_world_grasp=T_world_grasp,
        T_world_part=T_world_part,
        part_report=rep,
        part_colliding=rep.collides,
        robot_colliding=robot_hit,
        first_collision=first,
        obstacle_names=obstacles.names,
        robot_report=path,
        robot_between=robot_between,
        T_tcp_part=invert_transform(T_part_grasp(part, grasp, len(part.bends))),
    )
    report(1.0, "done")
    return plan
