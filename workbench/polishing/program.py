"""The robot program of a polishing motion: the planned path as the fewest linear moves that keep
it within a chordal tolerance, with the planned joints and times, the force offset in the targets
and the force in comments (SI: m, rad, s, N).

The plan (`process_motion`) times one joint waypoint per path point (a spiral of 1,221 points on
the example panel). A controller needs far fewer moves: `thin_path` keeps the fewest points such
that every planned TCP point between two kept ones lies within `CHORD_TOLERANCE` of the straight
line the controller moves on, and the tool axis within `ANGLE_TOLERANCE` of the interpolated one;
the exact stops of the plan (first point, first process point, last point) are always kept.
Each kept target carries the planned joints there (never re-solved), its TCP pose in the
workpiece's work object and its arm configuration; each move its planned duration (the time
between the trajectory's waypoints), so the moves add up to the plan's cycle time.

Force: the plan's targets are the commanded points, moved D = F/k into the surface along the tool
axis (`toolpath.force_offset`, seed 004: F = 20 N, k = 5000 N/m, D = 4 mm), so a controller
without force control presses with F only through a compliant tool of spring rate k; comments at
the top and at the first process point state F, k and D, and the program's `contact`
(`ContactForce`) makes every post without force control say so plainly in its header. The
moves from the first to the last process point carry the force F (`MoveInstr.force`): RAPID
writes them as ABB's Force Control pressing (FCCalib, FCPress1LStart, FCPressL, FCPressEnd on
the first lead-out move; `motion.programs.rapid`), where F along the tool's z replaces the
offset (see docs/programs.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel
from workbench.motion.program import Move, Program
from workbench.motion.programs.controller_program import (
    Comment,
    ContactForce,
    Instruction,
    MotionLimits,
    MoveInstr,
    RobotProgram,
    Target,
    ToolData,
    WorkObject,
)
from workbench.motion.programs.from_plan import planner_durations
from workbench.motion.trajectory import DUPLICATE_TOL, Trajectory
from workbench.polishing.process_motion import APPROACH_SPEED
from workbench.polishing.toolpath import force_offset

F64 = NDArray[np.float64]

#: Largest distance [m] of a planned TCP point from the linear move that replaces it (0.05 mm).
CHORD_TOLERANCE = 0.05e-3
#: Largest angle [rad] between a planned tool axis and the one the linear move interpolates (0.5 deg).
ANGLE_TOLERANCE = np.radians(0.5)
#: The work object of the program: the workpiece frame.
WOBJ = "workpiece"
#: Largest blend radius [m] between the linear moves (less at sharper turns: `corner_zones`).
BLEND_ZONE = 2e-3
#: The blend radii [m] used (a corner gets the largest not above its own, at least the first).
BLEND_LEVELS = (0.1e-3, 0.2e-3, 0.5e-3, 1e-3, 2e-3)


class _Contact(Protocol):
    @property
    def stiffness(self) -> float: ...


class ProcessSettings(Protocol):
    """What the program needs of the process (the project's `PolishingSI` is one): `force` [N],
    `feed` [m/s], `control.stiffness` [N/m]."""

    @property
    def force(self) -> float: ...
    @property
    def feed(self) -> float: ...
    @property
    def control(self) -> _Contact: ...


def _segment_ok(P: F64, Z: F64, i: int, j: int, tol: float, angle_tol: float) -> bool:
    """Return True when points i+1..j-1 lie within `tol` of segment P[i]P[j] and their axes within
    `angle_tol` of the axis interpolated by arc position."""
    if j - i < 2:
        return True
    a, b, p = P[i], P[j], P[i + 1 : j]
    d = b - a
    L2 = float(d @ d)
    s = np.clip(((p - a) @ d) / L2, 0.0, 1.0) if L2 > 0 else np.zeros(len(p))
    if np.any(np.linalg.norm(p - (a + s[:, None] * d), axis=1) > tol):
        return False
    z = (1.0 - s)[:, None] * Z[i] + s[:, None] * Z[j]
    z /= np.maximum(np.linalg.norm(z, axis=1), 1e-12)[:, None]
    cos = np.clip(np.sum(z * Z[i + 1 : j], axis=1), -1.0, 1.0)
    return bool(np.all(np.arccos(cos) <= angle_tol))


def thin_path(
    points: F64,
    axes: F64,
    keep: list[int] | tuple[int, ...] = (),
    *,
    tol: float = CHORD_TOLERANCE,
    angle_tol: float = ANGLE_TOLERANCE,
) -> NDArray[np.int64]:
    """Return the indices (K,) of the points (N, 3) [m] kept as linear-move targets: greedily the
    farthest next point whose chord keeps every point between within `tol` [m] and its tool axis
    (`axes` (N, 3), unit) within `angle_tol` [rad]; the first, last and `keep` indices always."""
    P, Z = np.asarray(points, float), np.asarray(axes, float)
    n = len(P)
    if n == 0:
        raise InputError("the polishing path has no points")
    if not (np.isfinite(tol) and tol > 0 and np.isfinite(angle_tol) and angle_tol > 0):
        raise InputError(
            f"chordal tolerance {tol!r} m and angle tolerance {angle_tol!r} rad must be > 0"
        )
    forced = sorted({0, n - 1, *(int(k) for k in keep if 0 <= k < n)})
    out = [0]
    for lo, hi in zip(forced[:-1], forced[1:], strict=True):
        i = lo
        while i < hi:
            j = i + 1
            while j < hi and _segment_ok(P, Z, i, j + 1, tol, angle_tol):
                j += 1
            out.append(j)
            i = j
    return np.array(out, np.int64)


def approach_time(
    model: RobotModel, q_start: F64 | None, q_end: F64, T_flange_tcp: F64 | None = None
) -> float:
    """Return the time [s] of the joint move from `q_start` to `q_end` at `APPROACH_SPEED` of
    the joints' maximum speed, as the motion planner times it (`planner_durations`: ruckig,
    stop to stop); 0 for a move shorter than the trajectory's `DUPLICATE_TOL` (none to make)."""
    if q_start is None or np.max(np.abs(np.asarray(q_start, float) - q_end)) < DUPLICATE_TOL:
        return 0.0
    prog = Program("approach", (Move.joint(q_end, speed=APPROACH_SPEED),))
    T = np.eye(4) if T_flange_tcp is None else T_flange_tcp
    return float(planner_durations(model, prog, np.asarray(q_start, float), T)[0])


def corner_zones(P: F64, tol: float, largest: float = BLEND_ZONE) -> F64:
    """Return the blend radius [m] at each interior point of the polyline P (K, 3) [m] (K - 2,):
    `largest`, or less where the corner turns so much that the blend would leave it by more
    than `tol` (a quadratic blend of radius r at a turn of angle a passes r sin(a/2) / 2 from
    the corner, so r <= 2 tol / sin(a/2)), rounded down to `BLEND_LEVELS` (at least the
    first: a sharper corner may be left by more than `tol`)."""
    u = np.diff(P, axis=0)
    u /= np.maximum(np.linalg.norm(u, axis=1), 1e-12)[:, None]
    turn = np.arccos(np.clip(np.sum(u[:-1] * u[1:], axis=1), -1.0, 1.0))
    s = np.sin(turn / 2.0)
    r = np.minimum(largest, 2.0 * tol / np.maximum(s, 1e-12))
    # a few radii only (NACHI has 7 accuracy levels): the largest level not above r
    levels = np.array(BLEND_LEVELS)
    return levels[np.maximum(np.searchsorted(levels, r * (1.0 + 1e-9), side="right") - 1, 0)]


def _calibrated_speed(
    model: RobotModel, moves: list[Move], q0: F64, T_flange_tcp: F64, planned: float, feed: float
) -> float:
    """Return the TCP speed [m/s] at which the motion planner takes the `planned` time [s] for
    the linear `moves` (stated at `feed`) from joints `q0`: the feed, scaled by the planned
    over the planner's time (their waypoints differ: the plan's path points, the planner's
    samples along the moves), so the program planned again takes the plan's cycle time."""
    took = float(planner_durations(model, Program("polish", tuple(moves)), q0, T_flange_tcp).sum())
    return feed * took / planned if planned > 0 else feed


def polishing_program(
    trajectory: Trajectory,
    model: RobotModel,
    tool: ToolData,
    T_world_base: F64,
    T_world_workpiece: F64,
    process: NDArray[np.bool_],
    settings: ProcessSettings,
    q_start: F64 | None = None,
    *,
    name: str = "polish",
    robot: str = "robot",
    limits: MotionLimits | None = None,
    tol: float = CHORD_TOLERANCE,
    angle_tol: float = ANGLE_TOLERANCE,
) -> RobotProgram:
    """Return the polishing `RobotProgram` of the planned `trajectory` (one waypoint per path point).

    `process` (N,) marks the process points (the rest: lead-in and lead-out); `settings` give
    the force [N], the contact stiffness [N/m] (comments: the offset D = F/k is already in the
    planned targets) and the feed [m/s] (comment); the work object is the workpiece frame
    `T_world_workpiece` (4, 4) [m], the robot stands at `T_world_base`. The joint move to the
    first point starts at `q_start` (dof,) [rad] (default: there already); the plan does not
    time it, so it is timed here (`approach_time`) and is the one move beyond the plan's cycle
    time. Then linear moves to the points `thin_path` keeps, each with the planned joints and
    its duration from the trajectory, all at one TCP speed: the feed, calibrated so that the
    motion planner takes the plan's time for them (`_calibrated_speed`); exact stops where the
    plan stops (its `stop_indices`: the first point, the first process point, the last point),
    elsewhere blends of `corner_zones` (at most `BLEND_ZONE`, within `tol` of the corner: the
    program's path stays within 2 `tol` of the planned points).
    """
    path = _planned_path(trajectory, model, tool, T_world_base, T_world_workpiece, process)
    kept = thin_path(
        path.T_base_tcp[:, :3, 3],
        path.T_base_tcp[:, :3, 2],
        (path.first, path.last_in),
        tol=tol,
        angle_tol=angle_tol,
    )
    approach = MoveInstr(
        "joint",
        path.target(model, 0, "approach"),
        APPROACH_SPEED,
        0.0,
        tool.name,
        WOBJ,
        approach_time(model, q_start, path.q[0], tool.T_flange_tcp),
    )
    zones = _zones(trajectory, path, kept, tol)
    lim = limits or MotionLimits()
    speed, planned = _path_speed(model, tool, path, kept, zones, settings.feed, lim)
    ins: list[Instruction] = [
        *_comments(path, kept, settings, speed, planned, tol, angle_tol),
        approach,
    ]
    ins += _path_moves(model, tool, path, kept, zones, speed, settings)
    return RobotProgram(
        name,
        (tool,),
        (WorkObject(WOBJ, path.T_base_wobj),),
        tuple(ins),
        model.convention,
        model.dof,
        robot,
        lim,
        contact=ContactForce(settings.force, settings.control.stiffness),
    )


@dataclass(frozen=True)
class _Path:
    """The planned path as the program sees it: joints (N, dof) [rad], waypoint times (N,) [s],
    TCP poses (N, 4, 4) [m, base], the work object's frame, the first and last process points."""

    q: F64
    wt: F64
    T_base_tcp: F64
    T_base_wobj: F64
    first: int
    last_in: int

    def target(self, model: RobotModel, i: int, label: str) -> Target:
        """Return point `i` as a target: planned joints, TCP in the work object, configuration."""
        T_wobj_tcp = invert_transform(self.T_base_wobj) @ self.T_base_tcp[i]
        return Target.planned(label, self.q[i], model, T_wobj_tcp)


def _planned_path(
    trajectory: Trajectory,
    model: RobotModel,
    tool: ToolData,
    T_world_base: F64,
    T_world_workpiece: F64,
    process: NDArray[np.bool_],
) -> _Path:
    """Return the planned path: one point per waypoint, its process points checked."""
    q = np.asarray(trajectory.waypoints, float)
    process = np.asarray(process, bool)
    if process.shape != (len(q),):
        raise InputError(f"process: {process.shape} flags for {len(q)} planned points")
    T_base_wobj = invert_transform(np.asarray(T_world_base, float)) @ np.asarray(
        T_world_workpiece, float
    )
    return _Path(
        q,
        np.asarray(trajectory.waypoint_times, float),
        model.fk(q) @ tool.T_flange_tcp,
        T_base_wobj,
        int(np.argmax(process)) if process.any() else 0,
        int(np.flatnonzero(process)[-1]) if process.any() else len(q) - 1,
    )


def _zones(trajectory: Trajectory, path: _Path, kept: NDArray[np.intp], tol: float) -> F64:
    """Return the blend radius [m] at every kept point: exact stops where the plan stops."""
    stops = {int(i) for i in trajectory.stop_indices} | {0, len(path.q) - 1}
    zones = np.concatenate([[0.0], corner_zones(path.T_base_tcp[kept, :3, 3], tol), [0.0]])
    zones[[k for k, b in enumerate(kept) if int(b) in stops]] = 0.0
    return zones


def _path_speed(
    model: RobotModel,
    tool: ToolData,
    path: _Path,
    kept: NDArray[np.intp],
    zones: F64,
    feed: float,
    limits: MotionLimits,
) -> tuple[float, float]:
    """Return the one TCP speed [m/s] of the linear moves (the feed calibrated to the plan's
    time, within the robot's limit) and the planned time [s] of those moves."""
    lin = [
        Move.linear(path.T_base_tcp[b], speed=feed, zone=float(zones[k]))
        for k, b in enumerate(kept)
    ][1:]
    planned = float(path.wt[kept[-1]] - path.wt[kept[0]])
    speed = float(
        np.clip(
            _calibrated_speed(model, lin, path.q[kept[0]], tool.T_flange_tcp, planned, feed),
            1e-4,
            limits.max_tcp_speed,
        )
    )
    return speed, planned


def _comments(
    path: _Path,
    kept: NDArray[np.intp],
    settings: ProcessSettings,
    speed: float,
    planned: float,
    tol: float,
    angle_tol: float,
) -> list[Instruction]:
    """Return the program's head comments: the force and its offset, the path, the speed."""
    force, stiffness, feed = settings.force, settings.control.stiffness, settings.feed
    D = force_offset(force, stiffness)
    return [
        Comment(
            f"polishing: contact force F = {force:g} N through the contact stiffness k = {stiffness:g} N/m:"
            f" process targets offset D = F/k = {D * 1e3:.3f} mm into the surface along the tool axis"
        ),
        Comment(
            f"path: {len(path.q)} planned points as {len(kept) - 1} linear moves within"
            f" {tol * 1e3:g} mm (chord) and {np.degrees(angle_tol):g} deg (tool axis); feed {feed * 1e3:g} mm/s"
        ),
        Comment(
            f"TCP speed {speed * 1e3:.2f} mm/s: the feed {feed * 1e3:g} mm/s, scaled so that the"
            f" moves take the planned {planned:.2f} s"
        ),
    ]


def _path_moves(
    model: RobotModel,
    tool: ToolData,
    path: _Path,
    kept: NDArray[np.intp],
    zones: F64,
    speed: float,
    settings: ProcessSettings,
) -> list[Instruction]:
    """Return the linear moves to the kept points, each with its planned duration, and the
    comments where the process starts and the lead-out begins."""
    D = force_offset(settings.force, settings.control.stiffness)
    first, last_in, n = path.first, path.last_in, len(path.q)
    ins: list[Instruction] = []
    for k, (a, b) in enumerate(zip(kept[:-1], kept[1:], strict=True)):
        dt = float(path.wt[b] - path.wt[a])
        if dt <= 0:
            raise InputError(
                f"point {b}: the planned trajectory reaches it in {dt!r} s; replan the motion"
            )
        if b == first:
            ins.append(
                Comment(
                    f"process: press with F = {settings.force:g} N (offset D = {D * 1e3:.3f} mm)"
                )
            )
        kind = "lead_in" if b < first else ("lead_out" if b > last_in else "p")
        ins.append(
            MoveInstr(
                "linear",
                path.target(model, int(b), f"{kind}{b}"),
                speed,
                float(zones[k + 1]),
                tool.name,
                WOBJ,
                dt,
                force=settings.force if kind == "p" else 0.0,  # into contact .. the last point
            )
        )
        if b == last_in and b != n - 1:
            ins.append(Comment("lead-out: off the surface, no contact force"))
    return ins
