"""The planned press-brake cycle: joints, a jerk-limited trajectory, and every frame checked.

SI units (m, rad, s). From `cycle_path`'s waypoints: inverse kinematics of every TCP pose in
one arm configuration (`follow_path`), one jerk-limited trajectory (ruckig) through them with
exact stops where the gripper or the press works, holding still for their times; each
bend-following segment is slowed per joint so it lasts at least the ram's time for it (the
robot keeps pace with the press; where the robot cannot, the plan says which joint).

Checked, frame by frame (every `frame_dt` and at every waypoint):
- the part (its OBB tree, `press_check`) against the press at that instant (punch height,
  back-gauge fingers) and the cell, carried, bent or resting;
- the robot (links and tool) against the cell and the press under the collision policy
  (spheres + SDF, confirmed with python-fcl, certified between frames);
- the robot's links against the part when it rests (blank stack, regrip station, pallet).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.collision.engine import EnginePathReport
from workbench.collision.fcl_checker import CollisionScene
from workbench.collision.plan_check import CollisionPolicy, check_trajectory
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.collision.shapes import Solid
from workbench.errors import PlanningError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel
from workbench.kinematics.path_ik import follow_path
from workbench.motion.sampled import SampledMotion
from workbench.motion.trajectory import Trajectory, sample_count, smooth_joint_path
from workbench.pressbrake.bend_eval import home_branch
from workbench.pressbrake.bend_setup import (
    Body,
    PressObstacles,
    bend_pose,
    contact_zone,
    merge_obstacles,
    press_poses,
)
from workbench.pressbrake.cycle_path import (
    CycleCell,
    CyclePath,
    CycleStep,
    Phase,
    T_part_tcp,
    cycle_path,
)
from workbench.pressbrake.die import DiePlacement
from workbench.pressbrake.obstacles import Obstacles, cell_obstacles
from workbench.pressbrake.press_check import PartHit, check_states
from workbench.pressbrake.press_signals import PressEvent, press_events
from workbench.pressbrake.process_contacts import HANDLING, gripper_contacts
from workbench.pressbrake.transit import (
    Carried,
    TransitReport,
    TransitSpace,
    carried_hits_between,
    route_transits,
)
from workbench.sheetmetal.folding import FoldedState, fold_state
from workbench.sheetmetal.part import SheetMetalPart

if TYPE_CHECKING:
    from workbench.motion.programs.controller_program import ProgramSettings, RobotProgram
    from workbench.pressbrake.press import PressBrake
    from workbench.pressbrake.program import RobotAt

F64 = NDArray[np.float64]
Progress = Callable[[float, str], None]


@dataclass(frozen=True, eq=False)
class CycleFrames:
    """Per checked frame (F,): the following robot's TCP distance [m] from the grasp on the
    part the press holds (0 outside bends), time [s], joints (F, dof), the part's fold step, its pose
    T_world_part (F, 4, 4) [m], the punch tip's height [m] over the die's top, the
    back-gauge setting (index into the path's stops, -1 none), the phase index, and the
    part's first collision (None: free)."""

    follow_error: F64
    times: F64
    joints: F64
    step: F64
    T_world_part: F64
    punch_z: F64
    stop: NDArray[np.int64]
    phase: NDArray[np.int64]
    part_hits: tuple[PartHit | None, ...]
    robot_part_hits: tuple[str | None, ...]


@dataclass(frozen=True, eq=False)
class BendingCycle:
    """A planned cycle: its path, joints at the waypoints (N, dof) [rad], the configuration,
    the trajectory, the checked frames and the robot's report; `first_problem` names the
    first collision (time, what hits what) or is None when the whole cycle is free."""

    part: SheetMetalPart
    steps: tuple[CycleStep, ...]
    path: CyclePath = field(repr=False)
    q: F64
    configuration: str
    trajectory: Trajectory = field(repr=False)
    frames: CycleFrames = field(repr=False)
    robot_report: EnginePathReport
    first_problem: str | None
    first_step: int | None = None  # the step (bend) whose grasp was in use at the problem
    transits: TransitReport = TransitReport()  # the moves between stations sent around

    @property
    def times(self) -> F64:
        """Return the checked frames' times (F,) [s] (the samples a csv/json export writes)."""
        return self.frames.times

    @property
    def joints(self) -> F64:
        """Return the joints (F, dof) [rad] at the checked frames."""
        return self.frames.joints

    @property
    def cycle_time(self) -> float:
        """Return the cycle's duration [s], holds included."""
        return float(self.trajectory.duration)

    @property
    def ok(self) -> bool:
        """Return whether the whole cycle is collision-free."""
        return self.first_problem is None

    @property
    def regrips(self) -> int:
        """Return how many times the part is handed to the regrip station."""
        return sum(
            1 for w in self.path.waypoints if w.label == "put the part on the regrip station"
        )

    def frame_at(self, t: ArrayLike) -> NDArray[np.intp]:
        """Return, per time [s], the index of the last checked frame at or before it."""
        k = np.searchsorted(self.frames.times, np.asarray(t, float), side="right") - 1
        return np.clip(k, 0, len(self.frames.times) - 1)  # type: ignore[no-any-return]

    @property
    def colliding(self) -> NDArray[np.bool_]:
        """Return (F,) frames where the part or the robot collides (or is not certified up to
        the next frame)."""
        out = np.array([h is not None for h in self.frames.part_hits], dtype=bool)
        out |= np.array([h is not None for h in self.frames.robot_part_hits], dtype=bool)
        out[list(self.robot_report.colliding_indices)] = True
        out[list(self.robot_report.between_indices)] = True
        return out

    def playback(self, world_tcp: Callable[[F64], F64], dt: float = 0.02) -> SampledMotion:
        """Return the cycle sampled every `dt` [s] for the timeline, the frames' verdicts
        carried over; `world_tcp(q)` gives TCP world poses (N, 4, 4) at joints (N, dof)."""
        t, p, v, a = self.trajectory.sample(dt)
        return SampledMotion(
            t, p, v, a, world_tcp(p), self.colliding[self.frame_at(t)], name="bending cycle"
        )

    @property
    def duration(self) -> float:
        """Return the cycle's duration [s] (`cycle_time`)."""
        return self.cycle_time

    @property
    def first_problem_time(self) -> float | None:
        """Return the time [s] of the first colliding frame (None: free)."""
        hits = np.flatnonzero(self.colliding)
        return float(self.frames.times[hits[0]]) if len(hits) else None

    @property
    def grasp_frames(self) -> None:
        """Return None: the cycle checks the part per state, not by one tree at the grasp."""
        return None

    def part_pose_at(self, t: float, world_tcp: Callable[[F64], F64] | None = None) -> F64:
        """Return T_world_part (4, 4) [m] at the last checked frame at or before time `t` [s]
        (`world_tcp` unused: the frames hold the part's pose)."""
        return self.frames.T_world_part[int(self.frame_at(t))]  # type: ignore[no-any-return]

    def part_step_at(self, t: float) -> float:
        """Return how far the part is folded at time `t` [s] (bends done, fractions partway)."""
        return float(self.frames.step[int(self.frame_at(t))])

    def press_poses_at(self, t: float, press: PressBrake | None) -> dict[str, F64]:
        """Return the world poses (4, 4) [m] of `press`'s moving bodies at time `t` [s], by
        their display names (`bend_setup.press_poses`)."""
        assert press is not None, "a cycle is planned with a press"
        n = int(self.frame_at(t))
        k = int(self.frames.stop[n])
        stop = self.path.stops[k] if k >= 0 else None
        return press_poses(press, float(self.frames.punch_z[n]), stop)

    def tree_check_at(self, t: float) -> None:
        """Return None: no single OBB tree checks the part through the cycle."""
        return None

    def robot_program(
        self, robot_at: RobotAt, cell: object, settings: ProgramSettings, q_start: F64
    ) -> RobotProgram:
        """Return the cycle as a robot program (`pressbrake.cycle_program.cycle_program`;
        `cell` unused: the cycle holds its stations)."""
        from workbench.pressbrake.cycle_program import cycle_program  # it imports this module

        return cycle_program(self, robot_at, settings, q_start)

    def waypoint_times(self) -> F64:
        """Return when the robot reaches each waypoint [s] (arrival, before its hold)."""
        return self.trajectory.waypoint_times  # type: ignore[no-any-return]

    def press_events(self) -> list[PressEvent]:
        """Return the plan's timeline of the press's signals: start, clamped, the following,
        top dead centre (`press_signals.press_events`), the order the program waits in."""
        return press_events(self)

    def summary(self) -> str:
        """Return a short human summary (markdown)."""
        head = (
            f"{len(self.steps)} bends ({' '.join(s.bend for s in self.steps)}), "
            f"{self.regrips} regrip(s), cycle {self.cycle_time:.1f} s, "
            f"{len(self.frames.times)} frames checked ({self.configuration})."
        )
        tail = f" Robot: {self.robot_report.message}."
        if self.transits.describe():
            tail += f" Detours: {self.transits.describe()}."
        if self.first_problem is None:
            return head + " Collision-free." + tail
        return head + f" First problem: {self.first_problem}." + tail


def _segment_speeds(q: F64, path: CyclePath, vmax: F64, labels: list[str]) -> F64:
    """Return per-segment velocity limits (N-1, dof): the robot's, or for a bend-following
    segment the joints' top speeds times the one fraction at which the slowest keeps the
    ram's pace, in the programs' 1 % steps (`following_fraction`; PlanningError above 100 %)."""
    out = np.tile(vmax, (len(q) - 1, 1))
    for i, w in enumerate(path.waypoints[1:]):
        if w.bend_time <= 0.0:
            continue
        need = np.abs(q[i + 1] - q[i]) / w.bend_time
        if np.any(need > vmax * (1 + 1e-9)):
            j = int(np.argmax(need / vmax))
            raise PlanningError(
                f"{labels[i + 1]}: following the flange needs joint {j + 1} at "
                f"{np.degrees(need[j]):.0f} deg/s, above its {np.degrees(vmax[j]):.0f} deg/s; "
                "lower the press's bending speed or grip farther from the bend line"
            )
        out[i] = vmax * following_fraction(q[i], q[i + 1], w.bend_time, vmax)
    return out


def following_fraction(q_a: F64, q_b: F64, seconds: float, vmax: F64) -> float:
    """Return the joint-speed fraction of a bend-following move from q_a to q_b (dof,) [rad]
    that lasts about `seconds` [s], the ram's time for it: the slowest joint's share of its
    top speed `vmax` [rad/s], rounded up to the 1 % steps the programs state (KRL's and
    FANUC's percentages), so plan and program move alike; at least 1 %, at most 100 %."""
    need = float(np.max(np.abs(np.asarray(q_b) - np.asarray(q_a)) / (seconds * vmax)))
    return float(np.clip(np.ceil(need * 100.0 - 1e-9) / 100.0, 0.01, 1.0))


def cycle_joints(
    model: RobotModel,
    T_world_base: F64,
    T_flange_tcp: F64,
    path: CyclePath,
    q_home: F64,
    branch: int | None = None,
) -> tuple[F64, str]:
    """Return joints at every waypoint (N, dof) and the configuration label (`branch`: the
    arm configuration's IK branch to keep; None: the one nearest home); the home waypoints
    take the home arm and the wrist carried between its neighbours (`_carry_the_wrist`)."""
    idx = [i for i, w in enumerate(path.waypoints) if w.T_world_tcp is not None]
    T = np.array([path.waypoints[i].T_world_tcp for i in idx])
    T_bf = invert_transform(T_world_base) @ T @ invert_transform(T_flange_tcp)
    labels = [w.label for w in path.waypoints]
    ik = follow_path(
        model,
        T_bf,
        q_home,
        labels=[labels[i] for i in idx],
        what="bending cycle",
        cost="total",
        points=T[:, :3, 3],
        hint="move the press, stack, station or pallet, or change the grasps",
        branch=branch,
    )
    q = np.tile(np.asarray(q_home, float), (len(path.waypoints), 1))
    q[idx] = ik.q
    _carry_the_wrist(q, idx)
    return q, ik.configuration


def cycle_trajectory(model: RobotModel, path: CyclePath, q: F64) -> Trajectory:
    """Return the jerk-limited trajectory through the waypoints' joints q (N, dof) [rad]:
    exact stops and holds where the path says, bend-following moves at the ram's pace."""
    labels = [w.label for w in path.waypoints]
    vmax = np.asarray(model.max_velocity, float)
    speeds = _segment_speeds(q, path, vmax, labels)
    stops = [i for i, w in enumerate(path.waypoints) if w.stop]
    traj = smooth_joint_path(
        q,
        speeds,
        model.max_acceleration,
        model.max_jerk,
        position_limits=model.limits,
        exact_stop=stops,
        labels=labels,
    )
    holds = [(i, w.hold) for i, w in enumerate(path.waypoints) if w.hold > 0]
    return traj.with_holds(holds)


#: The arm's joints (the first three) that a move via home takes to the home joints; the wrist
#: joints after them go halfway between the poses before and after (`_carry_the_wrist`).
ARM_JOINTS = 3


def _carry_the_wrist(q: F64, idx: list[int]) -> None:
    """Set the wrist at each via-home waypoint (rows of `q` (N, dof) not in `idx`, the IK
    waypoints) halfway between the wrists of the IK waypoints before and after it, in place.

    Via home the arm swings home but the wrist does not unwind to home's and back: a part
    held out on the gripper would otherwise sweep round (a wrist turned 340 deg and back
    swung a 300 mm part through the press). A robot without a wrist (dof <= 3) keeps home."""
    if q.shape[1] <= ARM_JOINTS or not idx:
        return
    known = np.asarray(idx)  # ascending
    for i in np.setdiff1d(np.arange(len(q)), known):
        k = int(np.searchsorted(known, i))
        if 0 < k < len(known):
            q[i, ARM_JOINTS:] = 0.5 * (q[known[k - 1], ARM_JOINTS:] + q[known[k], ARM_JOINTS:])


@dataclass(eq=False)
class _PressScene:
    """Obstacles of the part per press state (the press's moved with the ram, the cell's)."""

    part: SheetMetalPart
    path: CyclePath
    cell: CycleCell
    others: Obstacles
    press: PressObstacles

    @property
    def open_z(self) -> float:
        """Return the punch tip's height [m] over the die's top with the ram open."""
        return self.cell.press.ram.open + self.part.thickness

    def at(self, station: str, punch_z: float, stop: int, bend: int) -> Obstacles:
        press = self.cell.press
        ba = float(self.part.bend_allowances[max(bend, 0)])
        cut = contact_zone(ba, self.part.thickness, press.tolerance) if bend >= 0 else 0.0
        gs = self.path.stops[stop] if stop >= 0 else None
        return merge_obstacles(self.press.at(press.station(station), punch_z, cut, gs), self.others)


def _frame_times(traj: Trajectory, dt: float) -> F64:
    sample_count(traj.duration, dt, "the bending cycle")  # the budget, before the frames
    grid = np.arange(0.0, traj.duration, dt)
    marks = np.asarray(traj.waypoint_times, float)
    return np.unique(np.concatenate([grid, marks, [traj.duration]]))


def waypoint_joints(
    part: SheetMetalPart,
    steps: list[CycleStep],
    cell: CycleCell,
    robot: tuple[RobotModel, F64, F64],
) -> tuple[CyclePath, F64, str]:
    """Return the cycle's path, the joints (N, dof) [rad] at its waypoints and the
    configuration's label: the cycle's own inverse kinematics (the home branch, one
    configuration throughout) of `robot` (model, T_world_base, T_flange_tcp), before any
    detour. UnreachableError names the first waypoint the robot cannot reach."""
    model, T_world_base, T_flange_tcp = robot
    path = cycle_path(part, steps, cell)
    branch = home_branch(model, cell.q_home)
    q_wp, label = cycle_joints(model, T_world_base, T_flange_tcp, path, cell.q_home, branch)
    return path, q_wp, label


def die_placements(
    part: SheetMetalPart, path: CyclePath, q_wp: F64, T_world_die: F64
) -> tuple[DiePlacement, ...]:
    """Return each bend of the cycle `path` against its back-gauge stop, as `check_cycle`
    plans it: the step's grasp and station, the joints `q_wp` (N, dof) [rad] at the stop."""
    starts = {ph.bend: ph.start for ph in path.phases if ph.kind == "bend"}
    out = []
    for k, b in enumerate(part.bends):
        i = starts[k]  # the stop: where the bend's phase starts
        T_tcp = path.waypoints[i].T_world_tcp
        assert T_tcp is not None  # a stop at the die is a pose, never home
        T_part = T_world_die @ path.bend_poses[k][0].T_die_part
        out.append(DiePlacement(b.name, k, T_part, T_tcp, q_wp[i]))
    return tuple(out)


def check_cycle(
    part: SheetMetalPart,
    steps: list[CycleStep],
    cell: CycleCell,
    *,
    model: RobotModel,
    T_world_base: F64,
    T_flange_tcp: F64,
    checker: RobotCollisionChecker,
    policy: CollisionPolicy,
    cell_bodies: list[Body],
    progress: Progress | None = None,
) -> BendingCycle:
    """Return the planned and checked cycle of `part` (bends in sequence order) with `steps`.

    `cell_bodies`: the cell's colliding objects other than the press (world frame), for the
    part's checks; `checker` holds the robot against the cell and the press.
    """
    report = progress or (lambda f, m: None)
    report(0.0, "building the cycle's waypoints and their inverse kinematics")
    path, q_wp, label = waypoint_joints(part, steps, cell, (model, T_world_base, T_flange_tcp))
    # The gripper's contacts where it handles the part are exempt from the clearance margin.
    handling = [q_wp[i] for i, w in enumerate(path.waypoints) if w.action in HANDLING]
    policy = policy.exempting(gripper_contacts(checker, handling))
    scene = _PressScene(part, path, cell, cell_obstacles(cell_bodies), PressObstacles(cell.press))
    report(0.1, "checking the moves between stations (detours where one is blocked)")
    spaces = _TransitSpaces(
        part, steps, path, scene, model, T_world_base, T_flange_tcp, checker, policy
    )
    path, q_wp, transits = route_transits(
        path,
        q_wp,
        spaces.of_phase,
        lambda q: T_world_base @ model.fk(q) @ T_flange_tcp,
        lambda f, m: report(0.1 + 0.1 * f, f"checking the moves between stations: {m}"),
    )
    spaces.path = path  # the same phases, in the same order, with the detours' waypoints
    report(0.2, "the jerk-limited trajectory")
    traj = cycle_trajectory(model, path, q_wp)
    times = _frame_times(traj, cell.frame_dt)
    q = traj.at(times)[0]
    from workbench.pressbrake.transfer import world_tcp

    T_tcp = world_tcp(model, T_world_base, T_flange_tcp, q)
    report(0.3, f"checking the part in {len(times)} frames")
    wp_times = _WaypointTimes.of(traj, path)
    frame_ctx = _FrameContext(part, steps, cell, path, scene, wp_times, q_wp, _FoldCache(part))
    part_frames = _part_frames(frame_ctx, times, q, T_tcp)
    report(0.35, f"checking the part against the press and the cell in {len(times)} frames")
    hits = _part_hits(part_frames, times, q, traj, path, spaces, report)
    report(0.55, "checking the robot against the part where it rests")
    robot_part = _robot_vs_resting_part(
        checker, path, part_frames.phase, q, part_frames.T_world_part, part_frames.states
    )
    report(0.6, "checking the robot against the cell and the press")
    robot = check_trajectory(
        traj, times, q, checker, policy, progress=lambda f, m: report(0.6 + 0.38 * f, m)
    )
    frames = part_frames.cycle_frames(times, q, hits, robot_part)
    first = _first_problem(path, frames, robot)
    report(1.0, "done")
    return BendingCycle(
        part,
        tuple(steps),
        path,
        q_wp,
        label,
        traj,
        frames,
        robot,
        None if first is None else first[1],
        None if first is None else _step_at(path, steps, frames, first[0]),
        transits,
    )


class _TransitSpaces:
    """The transit space of each phase of the cycle, built once (the routing and the check
    between frames share it; a detour keeps the phases' order). `path`: the cycle's path,
    updated once the detours are in."""

    def __init__(
        self,
        part: SheetMetalPart,
        steps: list[CycleStep],
        path: CyclePath,
        scene: _PressScene,
        model: RobotModel,
        T_world_base: F64,
        T_flange_tcp: F64,
        checker: RobotCollisionChecker,
        policy: CollisionPolicy,
    ) -> None:
        self.part, self.steps, self.path, self.scene = part, steps, path, scene
        self.robot = (model, T_world_base, T_flange_tcp, checker, policy)
        self.spaces: dict[int, TransitSpace] = {}

    def of_phase(self, k: int) -> TransitSpace:
        """Return the transit space of phase k (the part carried in it, if any)."""
        if k in self.spaces:
            return self.spaces[k]
        phase = self.path.phases[k]
        carried = None
        if phase.kind == "carried":
            step = self.steps[min(int(phase.step), len(self.steps) - 1)]
            carried = Carried(
                fold_state(self.part, phase.step, check=False),
                T_part_tcp(self.part, phase.grasp or step.grasp, phase.step),
                self.scene.at(
                    phase.station or step.station,
                    self.scene.open_z,
                    _last_stop(self.path, phase),
                    -1,
                ),
            )
        self.spaces[k] = TransitSpace(*self.robot, carried)
        return self.spaces[k]


@dataclass(frozen=True)
class _WaypointTimes:
    """When the robot reaches each waypoint (`arrive`) and leaves it after its hold
    (`leave`) [s]: the hold at waypoint i lasts [arrive[i], leave[i]]."""

    arrive: F64
    leave: F64

    @classmethod
    def of(cls, traj: Trajectory, path: CyclePath) -> _WaypointTimes:
        """Return the waypoints' times of `traj` (with_holds already moved later waypoints'
        times by the holds before them)."""
        arrive = np.asarray(traj.waypoint_times, float)
        leave = np.array(
            [traj.waypoint_times[i] + path.waypoints[i].hold for i in range(len(arrive))]
        )
        return cls(arrive, leave)


@dataclass(frozen=True, eq=False)
class _PartFrames:
    """Per checked frame (F,): the part's fold state, its pose T_world_part (F, 4, 4) [m],
    fold step, the punch tip's height [m], the back-gauge setting (-1: none yet), the phase
    index, the obstacles it is checked against, and the following robot's TCP distance [m]
    from its grasp (0 outside a followed bend)."""

    states: list[FoldedState]
    T_world_part: F64
    step: F64
    punch_z: F64
    stop: NDArray[np.int64]
    phase: NDArray[np.int64]
    obstacles: list[Obstacles]
    follow_error: F64

    def cycle_frames(
        self,
        times: F64,
        q: F64,
        part_hits: list[PartHit | None],
        robot_part_hits: list[str | None],
    ) -> CycleFrames:
        """Return the checked frames at `times` (F,) [s], joints `q` (F, dof) [rad], with the
        part's collisions and the robot's links touching the resting part."""
        return CycleFrames(
            self.follow_error,
            times,
            q,
            self.step,
            self.T_world_part,
            self.punch_z,
            self.stop,
            self.phase,
            tuple(part_hits),
            tuple(robot_part_hits),
        )


def _part_hits(
    part_frames: _PartFrames,
    times: F64,
    q: F64,
    traj: Trajectory,
    path: CyclePath,
    spaces: _TransitSpaces,
    report: Progress,
) -> list[PartHit | None]:
    """Return, per frame, the part's first collision (None: free): at the frame, or, carried,
    on the way to the next frame; `report` each batch of frames checked."""
    n = len(times)
    hits = check_states(
        part_frames.states,
        part_frames.T_world_part,
        part_frames.obstacles,
        progress=lambda k: report(0.35 + 0.15 * k / n, f"the part checked in {k} of {n} frames"),
    )
    report(0.5, "the carried part between frames")
    between = carried_hits_between(
        times,
        q,
        lambda t: traj.at(t)[0],
        part_frames.phase,
        lambda k: spaces.of_phase(k) if path.phases[k].kind == "carried" else None,
    )
    for n, hit in between.items():
        hits[n] = hits[n] or hit
    return hits


class _FoldCache:
    """The part's fold states by fold step (rounded to 1e-9), each built once."""

    def __init__(self, part: SheetMetalPart) -> None:
        self.part = part
        self.states: dict[float, FoldedState] = {}

    def __call__(self, step: float) -> FoldedState:
        key = round(step, 9)
        if key not in self.states:
            self.states[key] = fold_state(self.part, step, check=False)
        return self.states[key]


@dataclass(frozen=True, eq=False)
class _FrameContext:
    """What every frame's part check reads: the part, the steps, the cell, the routed path,
    the press scene, the waypoints' times, the joints at the waypoints (N, dof) [rad] and
    the fold states."""

    part: SheetMetalPart
    steps: list[CycleStep]
    cell: CycleCell
    path: CyclePath
    scene: _PressScene
    wp_times: _WaypointTimes
    q_wp: F64
    fold: _FoldCache


def _part_frames(ctx: _FrameContext, times: F64, q: F64, T_tcp: F64) -> _PartFrames:
    """Return where the part is, how far it is folded and what it meets at each frame
    `times` (F,) [s] of the robot at joints `q` (F, dof) (TCP poses `T_tcp` (F, 4, 4))."""
    n_frames = len(times)
    out = _PartFrames(
        [],
        np.zeros((n_frames, 4, 4)),
        np.zeros(n_frames),
        np.zeros(n_frames),
        np.full(n_frames, -1),
        np.zeros(n_frames, dtype=np.int64),
        [],
        np.zeros(n_frames),
    )
    steps, path = ctx.steps, ctx.path
    last_stop = -1
    for n, t in enumerate(times):
        phase_index = _phase_at(path.phases, ctx.wp_times.arrive, ctx.wp_times.leave, t)
        phase = path.phases[phase_index]
        stop = _stop_of(path, phase)
        if stop >= 0:
            last_stop = stop
        station = phase.station or steps[max(0, min(int(phase.step), len(steps) - 1))].station
        step, punch_z = _fold_and_punch(ctx, phase, station, t, q[n])
        state = ctx.fold(step)
        out.states.append(state)
        out.T_world_part[n] = _part_pose(ctx, phase, station, step, state, T_tcp[n])
        if phase.kind == "bend" and not phase.pressed:
            grasp = steps[phase.bend].grasp
            T_grip = out.T_world_part[n] @ T_part_tcp(ctx.part, grasp, step, state)
            out.follow_error[n] = float(np.linalg.norm(T_grip[:3, 3] - T_tcp[n][:3, 3]))
        out.step[n] = step
        out.punch_z[n] = punch_z
        out.stop[n] = last_stop
        out.phase[n] = phase_index
        bend = phase.bend if phase.kind == "bend" else -1
        out.obstacles.append(ctx.scene.at(station, punch_z, last_stop, bend))
    return out


def _fold_and_punch(
    ctx: _FrameContext, phase: Phase, station: str, t: float, q_t: F64
) -> tuple[float, float]:
    """Return the part's fold step and the punch tip's height [m] over the die's top at
    time t [s] in `phase` (the robot at `q_t`): the ram open outside bends; in a bend, how
    far it has gone."""
    part, press = ctx.part, ctx.cell.press
    if phase.kind != "bend":
        return phase.step, ctx.scene.open_z
    k = phase.bend
    arrive, leave = ctx.wp_times.arrive, ctx.wp_times.leave
    fraction = _bend_fraction(ctx.path, phase, arrive, leave, t, q_t, ctx.q_wp)
    step = k + fraction
    grasp = ctx.steps[k].grasp
    depth = bend_pose(ctx.fold(step), k, grasp, press, press.station(station)).depth
    punch_z = part.thickness - depth
    if fraction <= 0.0 and _in_first_hold(phase, arrive, leave, t):
        punch_z = part.thickness  # the ram closes onto the sheet during this hold
    return step, punch_z


def _part_pose(
    ctx: _FrameContext, phase: Phase, station: str, step: float, state: FoldedState, T_tcp: F64
) -> F64:
    """Return the part's pose T_world_part (4, 4) [m] at fold `step` in `phase`: where it
    rests, where the punch and die hold it in a bend (the following robot is checked for
    how far its TCP strays from the grasp, `follow_error`), else where the robot's TCP
    `T_tcp` carries it."""
    if phase.kind == "rest":
        assert phase.T_world_part is not None
        return phase.T_world_part
    steps = ctx.steps
    if phase.kind == "bend":
        press = ctx.cell.press
        k = phase.bend
        on_die = bend_pose(state, k, steps[k].grasp, press, press.station(station))
        return press.T_world_die @ on_die.T_die_part  # type: ignore[no-any-return]
    grasp = phase.grasp or steps[min(int(np.floor(step + 1e-9)), len(steps) - 1)].grasp
    part_tcp = T_part_tcp(ctx.part, grasp, step, state)
    return T_tcp @ invert_transform(part_tcp)  # type: ignore[no-any-return]


def _step_at(path: CyclePath, steps: list[CycleStep], frames: CycleFrames, t: float) -> int:
    """Return the step (bend) whose grasp is in use at time t [s]."""
    n = int(np.searchsorted(frames.times, t, side="right")) - 1
    phase = path.phases[int(frames.phase[max(n, 0)])]
    return int(phase.bend) if phase.kind == "bend" else _grasp_step(phase, steps)


def _phase_at(phases: tuple[Phase, ...], arrive: F64, leave: F64, t: float) -> int:
    """Return the phase running at time t: the last one whose start waypoint was reached."""
    best = 0
    for i, ph in enumerate(phases):
        if arrive[ph.start] - 1e-9 <= t and (t <= arrive[ph.end] + 1e-9 or i == len(phases) - 1):
            best = i
            # a phase starting at a waypoint owns the hold there (the gripper acts)
    return best


def _in_first_hold(ph: Phase, arrive: F64, leave: F64, t: float) -> bool:
    return bool(arrive[ph.start] - 1e-9 <= t <= leave[ph.start] + 1e-9)


def _bend_fraction(
    path: CyclePath, ph: Phase, arrive: F64, leave: F64, t: float, q_t: F64, q_wp: F64
) -> float:
    """Return how far the bend has gone at time t: by the robot's progress along its
    following segment (the press keeps pace with the robot: the joints' share of the way
    from one following waypoint to the next), or by the ram's time when the press holds
    the part alone."""
    fr = path.fractions
    if ph.pressed:
        # the press bends while the robot stands back: the hold of the waypoint after the stop
        i_back = ph.start + 1
        t_a, t_b = arrive[i_back], leave[i_back]
        return float(np.clip((t - t_a) / max(t_b - t_a, 1e-9), 0.0, 1.0))
    if t <= leave[ph.start]:
        return 0.0
    idx = ph.start + np.arange(len(fr))
    k = int(np.clip(np.searchsorted(arrive[idx[1:]], t, side="right"), 0, len(fr) - 2))
    a, b = q_wp[idx[k]], q_wp[idx[k + 1]]
    span = float(np.linalg.norm(b - a))
    share = 1.0 if span < 1e-12 else float(np.clip(np.dot(q_t - a, b - a) / span**2, 0.0, 1.0))
    return float(fr[k] + share * (fr[k + 1] - fr[k]))


def _grasp_step(ph: Phase, steps: list[CycleStep]) -> int:
    """Return the step whose grasp is in use in phase `ph`: on the way to the regrip station
    the part is still held by an earlier step's grasp than its fold step's."""
    k = min(int(ph.step), len(steps) - 1)
    if ph.grasp is not None:
        for j in range(k, -1, -1):
            if steps[j].grasp is ph.grasp:
                return j
    return k


def _last_stop(path: CyclePath, ph: Phase) -> int:
    """Return the back-gauge setting during phase `ph`: its own, else the last one set by a
    phase before it (-1: none yet)."""
    out = -1
    for other in path.phases:
        if other.start > ph.start:
            break
        k = _stop_of(path, other)
        out = k if k >= 0 else out
        if other is ph:
            break
    return out


def _stop_of(path: CyclePath, ph: Phase) -> int:
    if ph.stop is None:
        return -1
    for i, s in enumerate(path.stops):
        if s is ph.stop:
            return i
    return -1


def _robot_vs_resting_part(
    checker: RobotCollisionChecker,
    path: CyclePath,
    phase_idx: NDArray[np.int64],
    q: F64,
    T_part: F64,
    states: list[FoldedState],
) -> list[str | None]:
    """Return, per frame, the robot link that touches the resting part (None: free). The tool
    is left out: it touches the part where it grips it."""
    out: list[str | None] = [None] * len(q)
    scenes: dict[int, PartScene] = {}
    for n in range(len(q)):
        ph = path.phases[int(phase_idx[n])]
        if ph.kind != "rest":
            continue
        k = int(phase_idx[n])
        if k not in scenes:
            scenes[k] = PartScene(checker, states[n].solid(), T_part[n])
        out[n] = scenes[k].link_hit(q[n])
    return out


class PartScene:
    """The robot's links (the tool left out: it touches the part where it grips it) against
    a part resting at a pose: `link_hit(q)` names the first link that touches it."""

    def __init__(self, checker: RobotCollisionChecker, mesh: trimesh.Trimesh, T_world: F64) -> None:
        self.checker = checker
        links = [b.solid for name, b in checker.scene.moving.items() if name != "tool"]
        self.scene = CollisionScene(links, [(Solid("part", "mesh", mesh=mesh), T_world)])

    def link_hit(self, q: F64) -> str | None:
        """Return the first link touching the part at joints `q` (dof,) [rad], or None."""
        poses = {k: v for k, v in self.checker.world_poses(q).items() if k != "tool"}
        rep = self.scene.check(poses, distance=False)
        return rep.colliding[0][0] if rep.colliding else None


#: How far [m] the following robot's TCP may stray from the grasp on the part the press
#: holds (the gripper's compliance); more is a problem of the plan.
FOLLOW_TOLERANCE = 0.002


def _first_problem(
    path: CyclePath, frames: CycleFrames, robot: EnginePathReport
) -> tuple[float, str] | None:
    """Return the earliest failure (time [s], in words), or None."""
    cands: list[tuple[float, str]] = []
    lag = np.flatnonzero(frames.follow_error > FOLLOW_TOLERANCE)
    if len(lag):
        n = int(lag[0])
        ph = path.phases[int(frames.phase[n])]
        cands.append(
            (
                float(frames.times[n]),
                f"t = {frames.times[n]:.2f} s ({ph.label}): the robot strays "
                f"{frames.follow_error[n] * 1e3:.1f} mm from the flange it follows (more than "
                f"FOLLOW_TOLERANCE {FOLLOW_TOLERANCE * 1e3:g} mm); more following waypoints "
                "or a slower bend",
            )
        )
    for n, h in enumerate(frames.part_hits):
        if h is not None:
            ph = path.phases[int(frames.phase[n])]
            cands.append(
                (
                    float(frames.times[n]),
                    f"t = {frames.times[n]:.2f} s ({ph.label}): {h.describe()}",
                )
            )
            break
    for n, link in enumerate(frames.robot_part_hits):
        if link is not None:
            cands.append(
                (
                    float(frames.times[n]),
                    f"t = {frames.times[n]:.2f} s: robot {link} hits the resting part",
                )
            )
            break
    if not robot.collision_free and robot.first_time is not None:
        what = (
            f"robot {robot.link} hits {robot.obstacle!r}"
            if robot.link
            else "robot clearance unresolved"
        )
        cands.append((float(robot.first_time), f"t = {robot.first_time:.2f} s: {what}"))
    near = robot.nearest
    if near is not None and near.problem is not None and near.time is not None:
        cands.append((near.time, f"t = {near.time:.2f} s: {near.problem}"))
    if not cands:
        return None
    return min(cands)
