"""A task of the sequence: approach, pick, carry, place, retreat and home, timed jerk-limited (ruckig).

The robot makes a joint move to the approach pose (back along the TCP z from the grasp), a
straight approach to the grasp, carries the part along its planned path, makes a straight
retreat from the place, and goes back home: the arm leaves the shared workspace to the
others. Exact stops at the approach pose, the pick, the place and the end of the retreat.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.part import AssemblyPart
from workbench.assembly.part_moves import PartPlan, Progress
from workbench.assembly.workcell import Workcell
from workbench.errors import InputError, UnreachableError
from workbench.geometry.transforms import make_transform
from workbench.motion import Trajectory, smooth_joint_path
from workbench.motion.moves import LINE_ANGLE_STEP, LINE_STEP, line_poses

#: Plans the part's move: (part, q_start [rad] where the approach ended or None, progress) -> PartPlan.
MovePlanner = Callable[[str, NDArray[np.float64] | None, Progress], PartPlan]


@dataclass(frozen=True, eq=False)
class TaskPlan:
    """One part move of the sequence, timed: robot trajectory from `t0` [s]; held from t_pick to t_place."""

    part: str
    robot: str
    t0: float
    t_pick: float
    t_place: float
    trajectory: Trajectory
    part_plan: PartPlan

    @property
    def t1(self) -> float:
        """Return the end time [s] of the task."""
        return self.t0 + float(self.trajectory.duration)


def tcp_line(T0: NDArray[np.float64], T1: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return poses (n, 4, 4) from T0 to T1 (both included) along the straight line, sampled as
    the motion planner samples a linear move (`motion.moves.line_poses` every `LINE_STEP` and
    `LINE_ANGLE_STEP`): the task's approach and retreat, planned again as the program's linear
    moves, pass the same waypoints and take the same time."""
    return np.concatenate([T0[None], line_poses(T0, T1, LINE_STEP, LINE_ANGLE_STEP)])


def time_waypoints(
    arm: AssemblyArm,
    waypoints: NDArray[np.float64],
    speed: float,
    exact_stop: list[int],
    labels: list[str] | None = None,
) -> Trajectory:
    """Return the jerk-limited trajectory through joint `waypoints` at `speed` (fraction of the
    limits); `labels` name each waypoint's stage in a PlanningError."""
    model = arm.setup.model
    return smooth_joint_path(
        waypoints,
        np.asarray(model.max_velocity) * speed,
        np.asarray(model.max_acceleration) * speed,
        np.asarray(model.max_jerk) * speed,
        position_limits=model.limits,
        exact_stop=exact_stop,
        labels=labels,
    )


def plan_task(
    what: str,
    part: AssemblyPart,
    arm: AssemblyArm,
    approach: float,
    retreat: float,
    q_now: NDArray[np.float64],
    t0: float,
    speed: float,
    *,
    joint_space: bool,
    plan_move: MovePlanner,
    report: Progress,
) -> TaskPlan:
    """Return the timed task of `arm` moving `part`, starting at joints q_now [rad] at time t0 [s].

    approach, retreat [m]: distances back along the TCP z before the pick and after the
    place; speed: fraction of the arm's joint velocity, acceleration and jerk limits.
    joint_space: the move is planned in joint space (it starts where the approach ends and
    the retreat starts where it ends, so the three share the arm configuration at pick and
    place); else the arm follows approach, carried path and retreat by IK in one
    configuration. what: the task, for messages. report: the task's progress (0..1).
    Raises UnreachableError naming the task.
    """

    def sub(f: float, m: str) -> None:
        report(0.8 * f, m)

    pick = part.start @ part.T_part_tcp
    place = part.goal @ part.T_part_tcp
    back = make_transform(np.eye(3), [0.0, 0.0, -approach])
    up = make_transform(np.eye(3), [0.0, 0.0, -retreat])
    to_pick = tcp_line(pick @ back, pick)
    from_place = tcp_line(place, place @ up)
    if joint_space:
        ik_a = arm.follow(to_pick, q_now, f"{what} approach")
        pp = plan_move(part.name, ik_a.q[-1], sub)
        assert pp.joints is not None
        ik_r = arm.follow(from_place, pp.joints[-1], f"{what} retreat")
        if np.abs(ik_r.q[0] - pp.joints[-1]).max() > 1e-6:
            raise UnreachableError(
                f"{what} retreat: the straight retreat from the goal needs another arm "
                "configuration than the planned one; shorten the retreat or move the goal"
            )
        q_task = np.concatenate([ik_a.q, pp.joints[1:], ik_r.q[1:]])
        i_pick = len(to_pick) - 1
        i_place = i_pick + len(pp.joints) - 1
    else:
        pp = plan_move(part.name, None, sub)
        carried = pp.samples @ part.T_part_tcp
        tcp = np.concatenate([to_pick, carried[1:], from_place[1:]])
        q_task = arm.follow(tcp, q_now, what).q
        i_pick = len(to_pick) - 1
        i_place = i_pick + len(carried) - 1
    waypoints = np.concatenate([q_now[None], q_task, arm.q_home[None]])
    report(0.85, f"{part.name}: jerk-limited timing")
    n = len(waypoints)
    stages = [
        (2, "to the approach"),
        (i_pick + 2, "approach"),
        (i_place + 2, "carry"),
        (n - 1, "retreat"),
        (n, "home"),
    ]
    head = f"{what} (robot {arm.name})"
    labels = [f"{head}: the start"]
    labels += [f"{head}: " + next(s for e, s in stages if k < e) for k in range(1, n)]
    stops = [0, 1, i_pick + 1, i_place + 1, n - 2, n - 1]
    traj = time_waypoints(arm, waypoints, speed, stops, labels)
    wt = traj.waypoint_times
    return TaskPlan(
        part=part.name,
        robot=arm.name,
        t0=t0,
        t_pick=t0 + float(wt[i_pick + 1]),
        t_place=t0 + float(wt[i_place + 1]),
        trajectory=traj,
        part_plan=pp,
    )


def plan_tasks(
    cell: Workcell,
    sequence: Sequence[tuple[str, float, float]],
    speed: float,
    *,
    joint_space: bool,
    plan_move: MovePlanner,
    report: Progress,
) -> list[TaskPlan]:
    """Return the timed tasks of a sequence in `cell`, one after the other from t = 0 [s].

    sequence: (part, approach [m], retreat [m]) in order; InputError naming a part no arm
    carries. Each arm starts from its home joints and is back home after each task.
    Options as for `plan_task`; report: the sequence's progress (0..1).
    """
    for name, _, _ in sequence:
        if cell.part(name).robot is None:
            raise InputError(
                f"{cell.where(name)}.robot: part {name!r} is in the sequence but no robot "
                f"carries it; name one of {list(cell.arms)}"
            )
    q_now = {n: a.q_home.copy() for n, a in cell.arms.items()}
    tasks: list[TaskPlan] = []
    for k, (name, approach, retreat) in enumerate(sequence):
        part = cell.part(name)
        assert part.robot is not None
        arm = cell.arms[part.robot]

        def sub(f: float, m: str, k: int = k) -> None:
            report((k + f) / len(sequence), m)

        task = plan_task(
            f"task {k + 1} ({part.name})",
            part,
            arm,
            approach,
            retreat,
            q_now[arm.name],
            tasks[-1].t1 if tasks else 0.0,
            speed,
            joint_space=joint_space,
            plan_move=plan_move,
            report=sub,
        )
        tasks.append(task)
        q_now[arm.name] = arm.q_home.copy()
    return tasks
