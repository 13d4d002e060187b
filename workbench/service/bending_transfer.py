"""The transfer-only bending plan of `Workbench.bending` (a project without a press model):
each bend placed on the die by IK in one arm configuration, and the checked transfer from
the press brake to the pallet (seed 000's scenario). Orchestration of `workbench.sheetmetal`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from workbench.collision import check_trajectory
from workbench.kinematics import follow_path
from workbench.motion import smooth_joint_path
from workbench.pressbrake.die import DiePlacement, die_placements, die_targets
from workbench.pressbrake.plan import BendingPlan, first_collision, robot_frames
from workbench.pressbrake.transfer import base_flange_poses, carried_poses, check_part

if TYPE_CHECKING:
    from workbench.service.bending import BendingService

Progress = Callable[[float, str], None]


def _ik(
    svc: BendingService,
    T_world_tcp: NDArray[np.float64],
    names: list[str],
    q_start: NDArray[np.float64],
    what: str,
) -> tuple[NDArray[np.float64], str]:
    """Return joints (N, dof) reaching the TCP poses (N, 4, 4) with one arm configuration."""
    setup = svc.wb.setup
    path = follow_path(
        svc.wb.robot,
        base_flange_poses(setup.T_world_base, setup.T_flange_tcp, T_world_tcp),
        q_start,
        labels=names,
        what=what,
        cost="total",
        points=T_world_tcp[:, :3, 3],
        hint=f"the grasp is on flange {svc.grasp_flange!r}; move the die or pallet, "
        "change the grasp or the sequence",
    )
    return path.q, path.configuration


def placements(svc: BendingService) -> tuple[tuple[DiePlacement, ...], str]:
    """Return each bend's die placement with one arm configuration, and its label.

    Raises UnreachableError naming the bend the robot cannot hold on the die.
    """
    part = svc.part
    T_part, T_tcp, names = die_targets(part, svc.si().die, svc.grasp)
    q, label = _ik(svc, T_tcp, names, svc.wb.joints, "bending.die")
    return die_placements(part, T_part, T_tcp, q), label


def plan_transfer(svc: BendingService, progress: Progress | None = None) -> BendingPlan:
    """Place every bend on the die, then plan and check the transfer to the pallet.

    The transfer is a jerk-limited (ruckig) joint trajectory; `frames` (>= 22) evenly
    timed frames are checked: the part with its OBB tree against the cell (leaf hits on
    cylinders and meshes confirmed with python-fcl) and the robot's links and tool under
    the project's collision policy (`check_trajectory` with `wb.collision_policy`; by
    default spheres + SDF at every frame, what it flags confirmed with python-fcl, the
    motion between frames certified on the trajectory). `progress(fraction, message)`
    reports the stages.
    """
    report = progress or (lambda f, m: None)
    model, part, grasp = svc.wb.robot, svc.part, svc.grasp
    report(0.0, "placing each bend line on the die")
    placed, label = placements(svc)
    report(0.25, "planning the transfer")
    T_tcp, names = svc.transfer_poses(placed[-1])
    q_way, _ = _ik(svc, T_tcp, names, placed[-1].q, "bending transfer")
    traj = smooth_joint_path(
        q_way,
        model.max_velocity,
        model.max_acceleration,
        model.max_jerk,
        position_limits=model.limits,
        exact_stop=[0, len(q_way) - 1],
    )
    F = svc.si().frames
    times = np.linspace(0.0, traj.duration, F)
    q = traj.at(times)[0]
    T_world_grasp, T_world_part = carried_poses(svc.world_tcp(q), part, grasp)
    report(0.4, f"checking {F} frames with the OBB tree")
    obst = svc.obstacles()
    rep = check_part(svc.tree(), obst, T_world_grasp)
    report(0.7, "checking the robot against the cell")
    # The checker holds the robot's links and tool, not the part: the tool and the part it
    # grips are never a pair, and the part's own checks are the tree's above.
    checker = svc.wb.checker
    path = check_trajectory(
        traj,
        times,
        q,
        checker,
        svc.wb.collision_policy,
        progress=lambda f, m: report(0.7 + 0.25 * f, m),
    )
    robot_hit, robot_between = robot_frames(path, F)
    first = first_collision(
        times,
        rep,
        robot_hit,
        path,
        [f.name for f in part.flanges],
        obst.names,
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
        obstacle_names=obst.names,
        robot_report=path,
        robot_between=robot_between,
    )
    report(1.0, "done")
    return plan
