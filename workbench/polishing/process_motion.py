"""The robot's motion along a polishing path: IK in one configuration, per-segment joint
speeds from the feed, jerk-limited timing and the program of moves (SI: m, rad, s).

Each segment's joint speed is the one that moves the TCP at the feed (joint change times
feed over TCP distance), clipped to the robot's speed limits; the motion stops exactly at
the first point, at the first process point and at the last point.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.geometry.transforms import invert_transform
from workbench.kinematics import RobotModel
from workbench.motion import Move, Program, Trajectory, smooth_joint_path
from workbench.polishing.robot_path import solve_path_ik

F64 = NDArray[np.float64]
#: Blending zone [m] between the process moves (the first and last stop exactly).
ZONE = 0.5e-3
#: Speed of the joint move to the first point (fraction of the robot's joint speeds).
APPROACH_SPEED = 0.5


@dataclass(frozen=True)
class ProcessMotion:
    """The joints (N, n) [rad] of the path in one arm `configuration`, their jerk-limited
    `trajectory` and the `program` (a joint move to the first point, then one linear move per
    point at the feed)."""

    q: F64
    configuration: str
    trajectory: Trajectory
    program: Program

    def sample_dt(self, dt: float | None = None) -> float:
        """Return the sample period [s]: `dt`, or by default at most ~600 samples (>= 20 ms)."""
        return dt if dt is not None else max(0.02, self.trajectory.duration / 600)

    @property
    def validate_dt(self) -> float:
        """Return the period [s] of the limit check: ~5000 steps, at least 10 ms."""
        return max(0.01, self.trajectory.duration / 5000)


def segment_speeds(q: F64, tcp: F64, feed: float, max_velocity: F64) -> F64:
    """Return the joint speeds (N-1, n) [rad/s] that move the TCP points `tcp` (N, 3) [m] at
    `feed` [m/s] between joints `q` (N, n), within [1e-3, 1] x `max_velocity` (n,)."""
    vmax = np.asarray(max_velocity, float)
    ds = np.maximum(np.linalg.norm(np.diff(tcp, axis=0), axis=1), 1e-9)
    dq = np.abs(np.diff(q, axis=0))
    return np.clip(dq * (feed / ds)[:, None], 1e-3 * vmax, vmax)


def plan_process_motion(
    robot: RobotModel,
    T_world_tcp: F64,
    T_world_base: F64,
    T_flange_tcp: F64,
    q_near: F64,
    feed: float,
    *,
    n_lead: int,
    labels: list[str] | None = None,
) -> ProcessMotion:
    """Return the `ProcessMotion` through the world TCP poses `T_world_tcp` (N, 4, 4) [m].

    The robot stands at `T_world_base` with the tool at `T_flange_tcp`; `q_near` (n,) [rad]
    picks the arm configuration; `feed` [m/s] is the TCP speed along the path; the first
    `n_lead` points are the lead-in (the motion stops exactly at the first process point);
    `labels` name the points in errors (`solve_path_ik`)."""
    T_base_tcp = invert_transform(T_world_base) @ T_world_tcp
    T_base_flange = T_base_tcp @ invert_transform(T_flange_tcp)
    q, config = solve_path_ik(robot, T_base_flange, q_near, labels=labels)
    seg_v = segment_speeds(q, T_world_tcp[:, :3, 3], feed, robot.max_velocity)
    traj = smooth_joint_path(
        q,
        seg_v,
        robot.max_acceleration,
        robot.max_jerk,
        position_limits=robot.limits,
        exact_stop=[0, n_lead, len(q) - 1],
    )
    last = len(T_base_tcp) - 2
    moves = [Move.joint(q[0], speed=APPROACH_SPEED, name="approach")]
    moves += [
        Move.linear(T, speed=feed, zone=0.0 if i in (0, last) else ZONE)
        for i, T in enumerate(T_base_tcp[1:])
    ]
    return ProcessMotion(q, config, traj, Program("polish", tuple(moves)))
