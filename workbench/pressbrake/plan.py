"""A bending plan: die placements, the checked transfer, its first collision and its summary.

SI units (m, rad, s). The part is checked by its OBB tree, the robot (links and tool, not
the part it holds) under a collision policy (`workbench.collision.check_trajectory`);
`first_collision` picks the earliest failure of the two.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision.engine import EnginePathReport
from workbench.motion import SampledMotion, Trajectory
from workbench.pressbrake.die import DiePlacement
from workbench.sheetmetal.obbtree import FramesReport

if TYPE_CHECKING:
    from workbench.motion.programs.controller_program import ProgramSettings, RobotProgram
    from workbench.pressbrake.program import BendingCell, RobotAt

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class FirstCollision:
    """The first colliding transfer frame: what hit what (part flanges or robot bodies).

    `between`: the robot collides (or could not be certified free: no bodies named) between
    frame `frame` and the next, at `time` [s]; the frames themselves are free.
    """

    frame: int
    time: float  # [s]
    kind: str  # "part" or "robot"
    flanges: tuple[str, ...]
    obstacles: tuple[str, ...]
    between: bool = False

    def describe(self) -> str:
        """Return one line naming the frame, the flange(s) or robot body and the obstacle(s)."""
        what = (
            f"flange {', '.join(repr(f) for f in self.flanges)}"
            if self.kind == "part"
            else f"robot {', '.join(self.flanges)}"
        )
        where = (
            f"between frames {self.frame + 1} and {self.frame + 2}"
            if self.between
            else f"frame {self.frame + 1}"
        )
        if self.between and not self.flanges:
            return (
                f"{where} (t = {self.time:.3f} s): robot clearance below what the check"
                " resolves; treat it as touching"
            )
        return (
            f"{where} (t = {self.time:.3f} s): {what} hits "
            f"{', '.join(repr(o) for o in self.obstacles)}"
        )


def robot_frames(path: EnginePathReport, n: int) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """Return (colliding, between) (n,) of the frames from the robot's path report."""
    hit, between = np.zeros(n, dtype=bool), np.zeros(n, dtype=bool)
    hit[list(path.colliding_indices)] = True
    between[list(path.between_indices)] = True
    return hit, between


def first_collision(
    times: NDArray[np.float64],
    part_report: FramesReport,
    robot_hit: NDArray[np.bool_],
    path: EnginePathReport,
    flange_names: Sequence[str],
    obstacle_names: Sequence[str],
    robot_pairs: Callable[[int], Sequence[tuple[str, str]]],
) -> FirstCollision | None:
    """Return the transfer's earliest failure, or None when every frame and interval is free.

    A robot failure between two free frames wins when it comes before every hit frame; else
    the first hit frame: the part's flanges and obstacles when the part hits there, else the
    robot's colliding pairs at that frame (`robot_pairs(frame)`: (body, obstacle) names).
    """
    hit_frames = np.flatnonzero(part_report.collides | robot_hit)
    if path.between and path.first_index is not None and path.first_time is not None:
        if not len(hit_frames) or path.first_time < times[hit_frames[0]]:
            return FirstCollision(
                path.first_index,
                float(path.first_time),
                "robot",
                (path.link,) if path.link else (),
                (path.obstacle,) if path.obstacle else (),
                between=True,
            )
    if not len(hit_frames):
        return None
    f0 = int(hit_frames[0])
    if part_report.collides[f0]:
        fr = part_report.frame(f0)
        return FirstCollision(
            f0,
            float(times[f0]),
            "part",
            tuple(flange_names[i] for i in fr.hit_flanges),
            tuple(obstacle_names[i] for i in fr.hit_obstacles),
        )
    pairs = robot_pairs(f0)
    return FirstCollision(
        f0, float(times[f0]), "robot", tuple(a for a, _ in pairs), tuple(b for _, b in pairs)
    )


@dataclass(frozen=True, eq=False)
class BendingPlan:
    """Die placements for every bend, and the checked transfer from the press brake to the pallet.

    Per transfer frame (F,): `times` [s], `joints` (F, dof) [rad], `T_world_grasp` (F, 4, 4)
    [m] of the gripped flange and `T_world_part` of the part. The part is checked by its OBB
    tree (`part_report`); the robot (links and tool, not the part it holds) under the
    plan's collision policy: `robot_colliding` is the exact verdict of each frame,
    `robot_between` (F,) marks frames whose interval to the next collides (or could not be
    certified), and `robot_report` (an `EnginePathReport`) states the guarantee between
    frames (none in the exact mode) or the first failure.
    """

    placements: tuple[DiePlacement, ...]
    configuration: str
    trajectory: Trajectory = field(repr=False)
    times: NDArray[np.float64]
    joints: NDArray[np.float64]
    T_world_grasp: NDArray[np.float64]
    T_world_part: NDArray[np.float64]
    part_report: FramesReport
    part_colliding: NDArray[np.bool_]
    robot_colliding: NDArray[np.bool_]
    first_collision: FirstCollision | None
    obstacle_names: tuple[str, ...]
    robot_report: EnginePathReport | None = None
    robot_between: NDArray[np.bool_] | None = None
    T_tcp_part: NDArray[np.float64] | None = None  # (4, 4) [m] the part held, in the TCP frame

    @property
    def tree_tests(self) -> NDArray[np.int64]:
        """Return the OBB tests (F,) of the tree's check at each frame."""
        return self.part_report.n_obb_tests

    @property
    def colliding(self) -> NDArray[np.bool_]:
        """Return (F,) frames where the part or the robot collides (at the frame or up to the next)."""
        out = self.part_colliding | self.robot_colliding
        return out if self.robot_between is None else out | self.robot_between

    @property
    def ok(self) -> bool:
        """Return True when every transfer frame is collision-free and the robot keeps the
        clearance margin (`EnginePathReport.keeps_margin`)."""
        robot = self.robot_report
        return self.first_collision is None and (robot is None or robot.keeps_margin)

    def nearest_frame(self, t: float) -> int:
        """Return the index of the checked frame nearest time `t` [s]."""
        return int(np.argmin(np.abs(self.times - t)))

    def frame_at(self, t: ArrayLike) -> NDArray[np.intp]:
        """Return, per time (N,) [s], the index of the last checked frame at or before it."""
        k = np.searchsorted(self.times, t, side="right") - 1
        return np.clip(k, 0, len(self.times) - 1)

    @property
    def duration(self) -> float:
        """Return the transfer's duration [s]."""
        return float(self.trajectory.duration)

    @property
    def first_problem_time(self) -> float | None:
        """Return the time [s] of the first collision's frame (None: free)."""
        first = self.first_collision
        return None if first is None else float(self.times[first.frame])

    @property
    def grasp_frames(self) -> NDArray[np.float64]:
        """Return the gripped flange's poses (F, 4, 4) [m] (the tree's root at each frame)."""
        return self.T_world_grasp

    def part_pose_at(
        self, t: float, world_tcp: Callable[[NDArray[np.float64]], NDArray[np.float64]]
    ) -> NDArray[np.float64]:
        """Return T_world_part (4, 4) [m] of the part held at time `t` [s] of the transfer
        (a plan without `T_tcp_part`: at the last checked frame before t)."""
        if self.T_tcp_part is None:
            return self.T_world_part[int(self.frame_at(t))]  # type: ignore[no-any-return]
        q = self.trajectory.at([t])[0][0]
        return world_tcp(q) @ self.T_tcp_part  # type: ignore[no-any-return]

    def part_step_at(self, t: float) -> float:
        """Return how far the part is folded at time `t` [s]: all bends done (the transfer)."""
        return float(len(self.placements))

    def press_poses_at(self, t: float, press: object) -> dict[str, NDArray[np.float64]]:
        """Return no press poses: the transfer moves no press."""
        return {}

    def tree_check_at(self, t: float) -> tuple[tuple[int, ...], tuple[int, ...]]:
        """Return the OBB tree's (tested, hit) nodes at the frame nearest time `t` [s]."""
        rep = self.part_report.frame(self.nearest_frame(t))
        return rep.nodes_tested, rep.nodes_hit

    def playback(
        self, world_tcp: Callable[[NDArray[np.float64]], NDArray[np.float64]], dt: float = 0.02
    ) -> SampledMotion:
        """Return the transfer sampled every `dt` [s] for the timeline (`playback`)."""
        return playback(self, world_tcp, dt)

    def robot_program(
        self, robot_at: RobotAt, cell: BendingCell, settings: ProgramSettings, q_start: F64
    ) -> RobotProgram:
        """Return the plan as a robot program (`pressbrake.program.bending_program`)."""
        from workbench.pressbrake.program import bending_program  # it imports this module

        return bending_program(self, robot_at, cell, settings, q_start)

    def summary(self) -> str:
        """Return a short human summary (markdown)."""
        head = (
            f"{len(self.placements)} bends placed on the die ({self.configuration}); transfer "
            f"{self.trajectory.duration:.2f} s, {len(self.times)} frames checked."
        )
        robot = f" Robot: {self.robot_report.message}." if self.robot_report is not None else ""
        if self.first_collision is None:
            ok = self.robot_report is None or self.robot_report.keeps_margin
            return head + (" Collision-free." if ok else " Closer than the margin.") + robot
        return head + f" First collision: {self.first_collision.describe()}." + robot


def playback(
    plan: BendingPlan,
    world_tcp: Callable[[NDArray[np.float64]], NDArray[np.float64]],
    dt: float = 0.02,
) -> SampledMotion:
    """Return the transfer sampled every `dt` [s] for the timeline, frames' verdicts carried over.

    `world_tcp(q)` gives the TCP's world poses (N, 4, 4) [m] at joints (N, dof).
    """
    t, p, v, a = plan.trajectory.sample(dt)
    colliding = plan.colliding[plan.frame_at(t)]
    return SampledMotion(t, p, v, a, world_tcp(p), colliding, name="bending transfer")
