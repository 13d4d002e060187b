"""The cheap checks of one bend in a sequence search: given the bends already made, can the
next bend be made, with which grasps, at which tool station (SI units: m, rad, s).

A candidate is (bends done, next bend). Its folded states do not depend on the order of the
bends done, so a search over orders evaluates each candidate once. Per side of the bend
(which side faces the robot; the grasp's flange decides it, `bend_setup`), in this order,
the first failure is the reason:

1. the tool station: the first station whose die is as long as the bend line and whose
   punch covers it (short by at most `PUNCH_SHORTFALL` at each end) and where the part
   clears the press and the cell at every checked fraction of the bend (`press_check`);
2. the back-gauge: a stop within its axes at the placement (`bend_setup.gauge_stop`);
Per grasp on that side: inverse kinematics in the search's one arm configuration at the
bend's following fractions and at every IK waypoint of the straight moves onto the die and
out of it (lifted, then pulled back; as `cycle_path` moves them), the joints' speed while
following, and the gripper's and the arm's boxes clear of the press as the robot sees it
(ram stroke, dies, frame, back-gauge reach).

Everything here is a pure function of a picklable `SweepContext` and the candidate keys, so
the batch runner (`workbench.batch`) can send it to Ray workers.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.collision.shapes import Solid
from workbench.errors import InputError
from workbench.geometry.obb import OBB, obb_overlap
from workbench.kinematics.ik_report import branch_name
from workbench.kinematics.model import RobotModel
from workbench.pressbrake.airbend import apex_depth
from workbench.pressbrake.bend_setup import (
    PressObstacles,
    bend_pose,
    contact_zone,
    gauge_stop,
    in_child_side,
    merge_obstacles,
    part_points,
    robot_obstacles,
)
from workbench.pressbrake.cycle_path import LINE_STEP, clear_of_tools, follow_fractions
from workbench.pressbrake.grasp import Grasp, T_flange_grasp
from workbench.pressbrake.obstacles import Obstacles, cell_obstacles
from workbench.pressbrake.press import PressBrake, Station, ram_time
from workbench.pressbrake.press_check import check_states
from workbench.sheetmetal.folding import FoldedState, fold_state
from workbench.sheetmetal.part import SheetMetalPart

F64 = NDArray[np.float64]
Body = tuple[str, Solid, F64]

#: How much shorter than the bend line a punch may be at each end [m] (box bending: the
#: walls already bent stand at the line's ends; the punch fits between them).
PUNCH_SHORTFALL = 0.006
#: Fractions of each bend checked by the cheap stage (the full cycle checks every frame).
FRACTIONS = (0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0)


def home_branch(model: RobotModel, q: F64) -> int | None:
    """Return the `ik_batch` branch (arm configuration) of joints `q` (dof,) [rad]: the cycle
    and the search keep it (None: a numeric model, or `q` on no branch)."""
    if not model.is_analytic:
        return None
    q = np.asarray(q, float)
    sol, valid = model.ik_batch(model.fk(q)[None])  # type: ignore[attr-defined]
    err = np.where(valid[0], np.nan_to_num(np.abs(sol[0] - q), nan=np.inf).max(axis=1), np.inf)
    return int(np.argmin(err)) if np.isfinite(err).any() else None


@dataclass(frozen=True, eq=False)
class Reach:
    """The robot as the search needs it: model, base and TCP frames (4, 4) [m], the arm
    configuration's IK branch (`ik_batch` index; -1 for a numeric model: any solution), its
    label, the gripper's box in the TCP frame (None: no tool body) and the home joints."""

    model: RobotModel
    T_world_base: F64
    T_flange_tcp: F64
    branch: int
    configuration: str
    tool_box: OBB | None
    q: F64  # (dof,) [rad] the joints the cycle starts from (home)
    link_boxes: OBB | None = None  # (L,) each link's box in its own frame (base first)

    @classmethod
    def of(
        cls,
        model: RobotModel,
        T_world_base: F64,
        T_flange_tcp: F64,
        q: F64,
        tool_mesh: trimesh.Trimesh | None,
        link_meshes: list[trimesh.Trimesh] | None = None,
    ) -> Reach:
        """Return the reach of a robot whose arm configuration is that of joints `q` (dof,)
        [rad]; the gripper's box is the tool mesh's bounding box in the TCP frame."""
        q = np.asarray(q, float)
        branch = -1
        if model.is_analytic:
            sol, valid = model.ik_batch(model.fk(q)[None])  # type: ignore[attr-defined]
            err = np.where(
                valid[0], np.nan_to_num(np.abs(sol[0] - q), nan=np.inf).max(axis=1), np.inf
            )
            if np.isfinite(err).any():
                branch = int(np.argmin(err))
        box = None
        if tool_mesh is not None and len(tool_mesh.vertices):
            v = np.asarray(tool_mesh.vertices, float)
            T_tcp_flange = np.linalg.inv(T_flange_tcp)
            box = OBB.from_points(v @ T_tcp_flange[:3, :3].T + T_tcp_flange[:3, 3])
        links = None
        if link_meshes:
            boxes = [OBB.from_points(np.asarray(m.vertices, float)) for m in link_meshes]
            links = OBB(
                np.array([b.center for b in boxes]),
                np.array([b.rotation for b in boxes]),
                np.array([b.half_extents for b in boxes]),
            )
        return cls(model, T_world_base, T_flange_tcp, branch, branch_name(model, q), box, q, links)


@dataclass(frozen=True, eq=False)
class SweepContext:
    """What every candidate evaluation reads: the part (its SI spec), the press, the cell's
    colliding objects (world) other than the press, the robot and the grasp candidates."""

    part_spec: Any  # PartSI or the plain dict of `SheetMetalPart.from_spec`
    press: PressBrake
    cell: tuple[Body, ...]
    reach: Reach
    grasps: tuple[Grasp, ...]
    fractions: tuple[float, ...] = FRACTIONS
    key: str = field(default="", compare=False)
    T_world_blank: F64 | None = None  # the flat blank on its stack (None: not checked)
    T_world_pallet: F64 | None = None  # the finished part on the pallet (None: not checked)
    lift: float = 0.0  # [m] approach height at the stack and the pallet
    approach: F64 | None = None  # (3,) [m] die frame: the pose before the stop, and after
    T_world_regrip: F64 | None = None  # the part's pose on the regrip station (None: no check)
    refused: tuple[tuple[Grasp, str], ...] = ()  # grid candidates set apart by their footprint

    def part(self) -> SheetMetalPart:
        """Return the part (built once per process and context)."""
        return _cached(self, "part", lambda: SheetMetalPart.from_spec(self.part_spec, check=False))

    def cell_bodies(self) -> list[Body]:
        """Return the cell's colliding objects (world frame)."""
        return list(self.cell)

    def press_obstacles(self) -> PressObstacles:
        """Return the press's obstacles for the part (built once per process and context)."""
        return _cached(self, "press_obstacles", lambda: PressObstacles(self.press))

    def cell_obstacles(self) -> Obstacles:
        """Return the cell's colliding objects as obstacles (built once)."""
        return _cached(self, "cell_obstacles", lambda: cell_obstacles(self.cell_bodies()))

    def flange_grasps(self) -> F64:
        """Return every candidate's TCP in its flange's frame (G, 4, 4) [m] (built once)."""

        def build() -> F64:
            part = self.part()
            return np.array([T_flange_grasp(part, g) for g in self.grasps]).reshape(-1, 4, 4)

        # keyed by the grasps too: a context copied with other grasps keeps its key
        grasps = hash(
            tuple(
                (g.flange, None if g.offset is None else tuple(g.offset), g.yaw, g.face)
                for g in self.grasps
            )
        )
        return _cached(self, f"flange_grasps {grasps}", build)  # type: ignore[no-any-return]

    def robot_press(self) -> OBB:
        """Return the press's bodies as the robot sees them, as world boxes (M,)."""
        return _cached(
            self, "robot_press", lambda: cell_obstacles(robot_obstacles(self.press)).boxes
        )


_CACHE: dict[tuple[str, str], Any] = {}


def _cached(ctx: SweepContext, what: str, build: Any) -> Any:
    key = (ctx.key or str(id(ctx)), what)
    if key not in _CACHE:
        if len(_CACHE) > 64:
            _CACHE.clear()
        _CACHE[key] = build()
    return _CACHE[key]


def ordered_part(part: SheetMetalPart, done: Sequence[int], bend: int) -> SheetMetalPart:
    """Return `part` with its bends reordered: `done` (indices into part.bends), then `bend`,
    then the rest; its fold step len(done) is the state before `bend`."""
    rest = [i for i in range(len(part.bends)) if i not in done and i != bend]
    order = [*done, bend, *rest]
    return SheetMetalPart(
        part.thickness, list(part.flanges), [part.bends[i] for i in order], check=False
    )


@dataclass(frozen=True)
class SideEval:
    """One side of a bend facing the robot: feasible or the first `reason`; the `station`,
    back-gauge stop, final apex depth [m], the ram's time for the bend [s] and whether the
    part shows its top (base +z) upwards."""

    ok: bool
    reason: str | None
    station: str | None = None
    stop_x: float = np.nan
    depth: float = np.nan
    ram_time: float = np.nan
    top_up: bool = True


@dataclass(frozen=True, eq=False)
class BendEval:
    """The cheap verdict of bend `bend` (index into the part's bends) after bends `done`.

    `sides[0]`: the child's side facing the robot, `sides[1]`: the parent's. Per grasp
    candidate: `grasp_ok` (G,), its first `grasp_reason`, and the joints (G, dof) [rad] at
    the placement (`q0`), at the end of the bend (`q1`) and in front of the die before it
    (`q_front`), NaN where not reachable.
    """

    done: tuple[int, ...]
    bend: int
    problem: str | None
    sides: tuple[SideEval, SideEval]
    grasp_side: NDArray[np.int64]
    grasp_ok: NDArray[np.bool_]
    grasp_reason: tuple[str | None, ...]
    q0: F64
    q1: F64
    at_station: NDArray[np.bool_] | None = None  # (G,) reachable at the regrip station before it
    q_front: F64 | None = None

    @property
    def feasible(self) -> bool:
        """Return whether any grasp can make the bend."""
        return bool(self.grasp_ok.any())

    def reason(self) -> str:
        """Return why no grasp makes the bend: its most common first reason, with how many
        grasps it stopped and one of them."""
        if self.problem:
            return self.problem
        found = [r for r in self.grasp_reason if r]
        if not found:
            return "feasible"
        kinds = [_kind(r) for r in found]
        top = max(dict.fromkeys(kinds), key=kinds.count)
        example = found[kinds.index(top)]
        if kinds.count(top) == len(found) and len(found) == 1:
            return example
        return f"{example} (and so {kinds.count(top) - 1} more of the {len(found)} grasps)"


def fitting_station(press: PressBrake, length: float) -> str:
    """Return the first station whose tools fit a bend line `length` [m] long."""
    fits = _stations(press, length)
    if not fits:
        raise InputError(
            f"{press.where}.stations: no station fits a {length * 1e3:.0f} mm bend line (die at "
            f"least as long, punch at most {2 * PUNCH_SHORTFALL * 1e3:g} mm shorter)"
        )
    return fits[0].name


def _stations(press: PressBrake, length: float) -> list[Station]:
    return [
        s
        for s in press.stations
        if s.die_length >= length - 1e-9 and s.punch_length >= length - 2 * PUNCH_SHORTFALL - 1e-9
    ]


def _side(
    ctx: SweepContext,
    part: SheetMetalPart,
    k: int,
    flange: int,
    bend_name: str,
    states: list[FoldedState],
) -> tuple[SideEval, list[F64]]:
    """Return the side's verdict and the part's poses T_die_part at `ctx.fractions`."""
    press = ctx.press
    grasp = Grasp(part.flanges[flange].name)
    length = float(part.bend_lengths[k])
    stations = _stations(press, length)
    if not stations:
        return SideEval(
            False,
            f"bend {bend_name!r}: no tool station fits its {length * 1e3:.0f} mm bend line "
            f"(die at least as long, punch at most {2 * PUNCH_SHORTFALL * 1e3:g} mm shorter; "
            f"{press.where}.stations)",
        ), []
    tried: list[tuple[str, str]] = []
    cell, scene = ctx.cell_obstacles(), ctx.press_obstacles()
    cut = contact_zone(float(part.bend_allowances[k]), part.thickness, press.tolerance)
    pts = part_points(states[0])
    for station in stations:
        poses = [bend_pose(s, k, grasp, press, station) for s in states]
        stop = gauge_stop(
            (poses[0].T_die_part @ np.c_[pts, np.ones(len(pts))].T).T[:, :3], press, station
        )
        if stop.problem is not None:
            tried.append((station.name, stop.problem))
            continue
        obstacles = [merge_obstacles(scene.at(station, p.punch_z, cut, stop), cell) for p in poses]
        T = np.array([press.T_world_die @ p.T_die_part for p in poses])
        hits = check_states(states, T, obstacles)
        bad = [i for i, h in enumerate(hits) if h is not None]
        if bad:
            i = bad[0]
            hit = hits[i]
            assert hit is not None
            angle = np.degrees(states[i].angles[k])
            at = f"at {angle:.0f}° (of {np.degrees(part.bends[k].angle):.0f}°)"
            tried.append((station.name, f"{hit.describe()} {at}"))
            continue
        top_up = bool(T[0][2, 2] > 0)
        return SideEval(
            True,
            None,
            station.name,
            stop.x,
            poses[-1].depth,
            ram_time(press, poses[-1].depth),
            top_up,
        ), [p.T_die_part for p in poses]
    if len(press.stations) == 1:
        return SideEval(False, f"bend {bend_name!r}: {tried[0][1]}"), []
    why = "; ".join(f"at station {n!r} {w}" for n, w in tried)
    return SideEval(False, f"bend {bend_name!r}: {why}"), []


def reach_where_part_rests(
    ctx: SweepContext, T_world_part: F64, step: int, part: SheetMetalPart | None = None
) -> tuple[NDArray[np.bool_], F64]:
    """Return (G,) whether the robot reaches each grasp of the part lying at `T_world_part`
    (4, 4) [m] folded `step` bends of `part`'s sequence (default: the context's part) and
    `lift` above it, and the joints (G, dof) [rad] at the grasp (NaN where not)."""
    part = ctx.part() if part is None else part
    state = fold_state(part, step, check=False)
    flanges = np.array([part.flange_index(g.flange) for g in ctx.grasps], dtype=np.int64)
    tcp = T_world_part @ state.T_part_flange[flanges] @ ctx.flange_grasps()
    up = tcp.copy()
    up[:, 2, 3] += ctx.lift
    ok, q = _reach(ctx, np.concatenate([tcp, up]))
    both = ok[: len(tcp)] & ok[len(tcp) :]
    return both, np.where(both[:, None], q[: len(tcp)], np.nan)


def _reach(ctx: SweepContext, T_world_tcp: F64) -> tuple[NDArray[np.bool_], F64]:
    """Return (reachable (N,), joints (N, dof)) of TCP poses (N, 4, 4) in the configuration."""
    r = ctx.reach
    T_base_flange = np.linalg.inv(r.T_world_base) @ T_world_tcp @ np.linalg.inv(r.T_flange_tcp)
    n, dof = len(T_base_flange), r.model.dof
    q = np.full((n, dof), np.nan)
    if r.model.is_analytic and r.branch >= 0:
        sol, valid = r.model.ik_batch(T_base_flange)  # type: ignore[attr-defined]
        ok = valid[:, r.branch]
        q[ok] = sol[ok, r.branch]
        return ok, q
    ok = np.zeros(n, dtype=bool)
    for i, T in enumerate(T_base_flange):
        s = r.model.ik(T)
        if len(s):
            ok[i], q[i] = True, s[0]
    return ok, q


def evaluate(ctx: SweepContext, done: tuple[int, ...], bend: int) -> BendEval:
    """Return the cheap verdict of making bend `bend` after the bends `done`."""
    base = ctx.part()
    name = base.bends[bend].name
    part = ordered_part(base, done, bend)
    k = len(done)
    G = len(ctx.grasps)
    nan_q = np.full((G, ctx.reach.model.dof), np.nan)
    try:
        fold_state(part, k + 1)
    except InputError as exc:
        said = exc.detail if exc.field == "bend sequence" else str(exc)
        return _not_foldable(done, bend, f"bend {name!r}: {said}", nan_q)
    states = [fold_state(part, k, f, check=False) for f in ctx.fractions]
    sides = [
        _side(ctx, part, k, flange, name, states)[0]
        for flange in (part.bends[k].child, part.bends[k].parent)
    ]
    gflange = np.array([part.flange_index(g.flange) for g in ctx.grasps], dtype=np.int64)
    gside = np.array([0 if in_child_side(part, k, f) else 1 for f in gflange], dtype=np.int64)
    ok = np.zeros(G, bool)
    reasons: list[str | None] = [None] * G
    q0, q1, q_front = nan_q.copy(), nan_q.copy(), nan_q.copy()
    for s in (0, 1):
        idx = np.flatnonzero(gside == s)
        if not len(idx):
            continue
        if not sides[s].ok:
            for i in idx:
                reasons[i] = sides[s].reason
            continue
        sweep = _follow_sweep(ctx, part, k, s, sides[s], gflange[idx], idx)
        for m, i in enumerate(idx):
            reasons[i] = _grasp_problem(ctx, sweep, m, f"bend {name!r}", k)
            if reasons[i] is None:
                ok[i], q0[i], q1[i], q_front[i] = (
                    True,
                    sweep.q_f[0, m],
                    sweep.q_f[-1][m],
                    sweep.q_in_front[m],
                )
    station_ok = None
    if ctx.T_world_regrip is not None:
        station_ok = reach_where_part_rests(ctx, ctx.T_world_regrip, k, part)[0]
    return BendEval(
        done,
        bend,
        None,
        (sides[0], sides[1]),
        gside,
        ok,
        tuple(reasons),
        q0,
        q1,
        station_ok,
        q_front,
    )


def _not_foldable(done: tuple[int, ...], bend: int, problem: str, nan_q: F64) -> BendEval:
    """Return the verdict of a bend the part cannot fold next: `problem` for every grasp."""
    side = SideEval(False, problem)
    G = len(nan_q)
    return BendEval(
        done,
        bend,
        problem,
        (side, side),
        np.zeros(G, np.int64),
        np.zeros(G, bool),
        (problem,) * G,
        nan_q,
        nan_q.copy(),
    )


@dataclass(frozen=True, eq=False)
class _FollowSweep:
    """The robot following one side's flange through the bend, for the n grasps on that side
    (column m: the m-th of them): the grasps; the fold states at the following fractions
    (nf); reachable (nf, n) and joints (nf, n, dof) [rad] along the bend; joints in front of
    the die (n, dof); whether every pose of the straight moves onto the die and out of it is
    reachable (n,); the highest ratio of joint speed to top speed while following (n,); the
    gripper's box against the press at the stop, then at the end of the bend (2n,); the arm's
    boxes against the press along the bend (nf, n) and on the moves onto and out of the die
    (n,)."""

    grasps: tuple[Grasp, ...]
    states: list[FoldedState]
    reach_f: NDArray[np.bool_]
    q_f: F64
    q_in_front: F64
    reach_onto: NDArray[np.bool_]
    reach_out: NDArray[np.bool_]
    speed: F64
    tool_hits: NDArray[np.bool_]
    arm_hits: NDArray[np.bool_]
    arm_onto: NDArray[np.bool_]
    arm_out: NDArray[np.bool_]


def _follow_sweep(
    ctx: SweepContext,
    part: SheetMetalPart,
    k: int,
    s: int,
    side: SideEval,
    flanges: NDArray[np.int64],
    idx: NDArray[np.intp],
) -> _FollowSweep:
    """Return the IK and the press checks of the grasps `idx` (their flanges `flanges`) on
    side `s` (0: the child's, 1: the parent's) of bend `k` of `part`, at the cycle's
    following fractions (the robot keeps pace) and on the straight moves near the die."""
    dof = ctx.reach.model.dof
    follow = [fold_state(part, k, f, check=False) for f in follow_fractions()]
    rep = Grasp(part.flanges[(part.bends[k].child, part.bends[k].parent)[s]].name)
    station = ctx.press.station(side.station or "")
    along = [bend_pose(st, k, rep, ctx.press, station).T_die_part for st in follow]
    nf = len(follow)
    # (nf, n, 4, 4): die pose at each fraction x the gripped flange x the grasp on it
    T_wp = ctx.press.T_world_die @ np.array(along)  # (nf, 4, 4) world <- part
    T_pf = np.array([st.T_part_flange[flanges] for st in follow])  # (nf, n, 4, 4)
    tcp_f = (T_wp[:, None] @ T_pf @ ctx.flange_grasps()[idx][None]).reshape(-1, 4, 4)
    n = len(idx)
    tcp = np.concatenate([tcp_f[:n], tcp_f[-n:]])  # at the stop, at the end of the bend
    # the moves in and out of the die: in front of the stop, and lifted out and pulled
    # back after the bend (the cycle's waypoints; `cycle_path`)
    pts = [part_points(follow[j]) for j in (0, -1)]
    pts_die = tuple(
        (along[j] @ np.c_[p, np.ones(len(p))].T).T[:, :3] for j, p in zip((0, -1), pts, strict=True)
    )
    onto, out = _aside(ctx, tcp[:n], tcp[n:], side.depth, pts_die)  # type: ignore[arg-type]
    reach, q = _reach(ctx, np.concatenate([tcp_f, onto.reshape(-1, 4, 4), out.reshape(-1, 4, 4)]))
    q_f = q[: nf * n].reshape(nf, n, dof)
    k0 = nf * n + onto.shape[0] * n
    depth = [
        float(
            apex_depth(
                st.angles[k],
                st.radii[k],
                part.thickness,
                ctx.press.die.v_opening,
                ctx.press.die.shoulder_radius,
            )
        )
        for st in follow
    ]
    robot_press = ctx.robot_press()
    arm_aside = _links_hit(ctx, q[nf * n :], robot_press).reshape(-1, n)
    return _FollowSweep(
        grasps=tuple(ctx.grasps[i] for i in idx),
        states=follow,
        reach_f=reach[: nf * n].reshape(nf, n),
        q_f=q_f,
        q_in_front=q[k0 - n : k0],  # onto's last row: in front of the die
        reach_onto=np.all(reach[nf * n : k0].reshape(-1, n), axis=0),
        reach_out=np.all(reach[k0:].reshape(-1, n), axis=0),
        speed=_following_speed(ctx, q_f, depth),
        tool_hits=_tool_hits(ctx, tcp, robot_press),
        arm_hits=_links_hit(ctx, q_f.reshape(-1, dof), robot_press).reshape(nf, n),
        arm_onto=np.any(arm_aside[: k0 // n - nf], axis=0),
        arm_out=np.any(arm_aside[k0 // n - nf :], axis=0),
    )


def _grasp_problem(ctx: SweepContext, sweep: _FollowSweep, m: int, bend: str, k: int) -> str | None:
    """Return the first reason the m-th grasp of `sweep` cannot make bend `k` (named `bend`:
    "bend 'A'"), or None when it can: reach along the bend, then near the die, the
    following speed, the gripper, the arm along the bend, then near the die."""
    label = grasp_label(sweep.grasps[m])
    n = len(sweep.grasps)
    where_unreachable = None
    if not sweep.reach_f[:, m].all():
        j = int(np.argmin(sweep.reach_f[:, m]))
        where_unreachable = (
            "at the die" if j == 0 else f"at {_degrees_at(sweep, j, k)}° of the bend"
        )
    elif not sweep.reach_onto[m]:
        where_unreachable = "on the way onto the die"
    elif not sweep.reach_out[m]:
        where_unreachable = "on the way out of the die (lifted, then pulled back)"
    if where_unreachable is not None:
        return (
            f"{bend}: grasp {label} unreachable {where_unreachable} in the arm configuration "
            f"{ctx.reach.configuration}"
        )
    if sweep.speed[m] > 1.0:
        return (
            f"{bend}: grasp {label}: following the flange needs {sweep.speed[m]:.1f}x a "
            "joint's top speed (a wrist near its singularity, or the grasp too far out)"
        )
    if sweep.tool_hits[m] or sweep.tool_hits[n + m]:
        when = "at the die" if sweep.tool_hits[m] else "at the end of the bend"
        return f"{bend}: grasp {label}: the gripper hits the press {when}"
    if sweep.arm_hits[:, m].any():
        j = int(np.argmax(sweep.arm_hits[:, m]))
        return (
            f"{bend}: grasp {label}: the arm hits the press at {_degrees_at(sweep, j, k)}° "
            "of the bend"
        )
    if sweep.arm_onto[m] or sweep.arm_out[m]:
        when = "onto the die" if sweep.arm_onto[m] else "out of the die (lifted, pulled back)"
        return f"{bend}: grasp {label}: the arm hits the press on the way {when}"
    return None


def _degrees_at(sweep: _FollowSweep, j: int, k: int) -> str:
    """Return bend k's angle at the sweep's j-th following fraction [deg], as the reasons
    write it."""
    return f"{np.degrees(sweep.states[j].angles[k]):.0f}"


def _following_speed(ctx: SweepContext, q: F64, depth: list[float]) -> F64:
    """Return per grasp (N,) the highest ratio of joint speed to top speed while following
    the flange between the search's fractions (q (F, N, dof) [rad]) at the ram's pace."""
    if len(depth) < 2:
        return np.zeros(q.shape[1])
    dt = np.maximum(np.diff(np.asarray(depth)) / ctx.press.ram.bending_speed, 1e-6)
    dq = np.abs(np.diff(q, axis=0)) / dt[:, None, None]
    ratio = dq / np.asarray(ctx.reach.model.max_velocity, float)
    return np.nan_to_num(ratio, nan=np.inf).max(axis=(0, 2))  # type: ignore[no-any-return]


def _aside(
    ctx: SweepContext, at_stop: F64, at_end: F64, depth: float, points: tuple[F64, F64]
) -> tuple[F64, F64]:
    """Return the TCP poses of the straight moves near the die, as `cycle_path` moves them
    (every `LINE_STEP` or less, ends included): onto the die from in front of it (the
    approach offset in the die frame, its y far enough for the whole part,
    `cycle_path.clear_of_tools`, from the part's points (P, 3) in the die frame at the stop
    and at the end) and, after the bend, lifted out by its z plus the depth, then pulled back
    by its y. Returns (onto (K0, N, 4, 4), out (K1, N, 4, 4))."""
    if ctx.approach is None:
        return at_stop[None], at_end[None]
    R = ctx.press.T_world_die[:3, :3]
    a0 = clear_of_tools(ctx.approach, points[0])
    a1 = clear_of_tools(ctx.approach, points[1])
    onto = _line_poses(at_stop, R @ a0)
    lift = _line_poses(at_end, R @ np.array([0.0, 0.0, a1[2] + depth]))
    back = _line_poses(lift[-1], R @ np.array([0.0, a1[1], 0.0]))
    return onto, np.concatenate([lift, back[1:]])


def _line_poses(T: F64, offset: F64) -> F64:
    """Return poses (K, N, 4, 4) from `T` (N, 4, 4) to `T` moved by `offset` (3,) [m], the
    orientation kept, every `LINE_STEP` or less, both ends included."""
    k = max(1, int(np.ceil(float(np.linalg.norm(offset)) / LINE_STEP)))
    out = np.repeat(T[None], k + 1, axis=0)
    out[:, :, :3, 3] += np.linspace(0.0, 1.0, k + 1)[:, None, None] * offset
    return out


def _links_hit(ctx: SweepContext, q: F64, press_boxes: OBB) -> NDArray[np.bool_]:
    """Return (N,) whether any link's box at joints q (N, dof) meets the press's boxes (the
    base excepted: it stands where it stands). Conservative: a link's box holds the link."""
    boxes = ctx.reach.link_boxes
    n = len(q)
    out = np.zeros(n, dtype=bool)
    ok = np.isfinite(q).all(axis=1)
    if boxes is None or not ok.any():
        return out
    T = ctx.reach.T_world_base @ ctx.reach.model.link_transforms(q[ok])  # (K, L, 4, 4)
    R = T[:, 1:, :3, :3]
    placed = OBB(
        np.einsum("klij,lj->kli", R, boxes.center[1:]) + T[:, 1:, :3, 3],
        R @ boxes.rotation[1:],
        np.broadcast_to(boxes.half_extents[1:], R.shape[:2] + (3,)),
    )
    hit = obb_overlap(placed.reshape(*R.shape[:2], 1), press_boxes.reshape(1, 1, -1))
    out[ok] = np.asarray(hit).any(axis=(1, 2))
    return out


def _tool_hits(ctx: SweepContext, T_world_tcp: F64, press_boxes: OBB) -> NDArray[np.bool_]:
    """Return (N,) whether the gripper's box at each TCP pose (N, 4, 4) meets the press."""
    box = ctx.reach.tool_box
    if box is None or not len(T_world_tcp):
        return np.zeros(len(T_world_tcp), dtype=bool)
    R = T_world_tcp[:, :3, :3]
    placed = OBB(
        np.einsum("nij,j->ni", R, box.center) + T_world_tcp[:, :3, 3],
        R @ box.rotation,
        np.broadcast_to(box.half_extents, (len(R), 3)),
    )
    hit = obb_overlap(placed.reshape(len(R), 1), press_boxes.reshape(1, -1))
    return np.asarray(np.asarray(hit).any(axis=1), dtype=bool)


def _kind(reason: str) -> str:
    """Return a grasp's reason without the grasp and the numbers (to count alike ones)."""
    import re

    text = re.sub(r"grasp '[^']*' at [^,]*, yaw [-0-9]+°(, bottom face)?:?", "grasp", reason)
    return re.sub(r"[-0-9.]+", "#", text)


def grasp_label(g: Grasp) -> str:
    """Return a short name of a grasp: flange, point [mm], yaw [deg] and face."""
    off = (
        "centroid" if g.offset is None else f"({g.offset[0] * 1e3:.0f}, {g.offset[1] * 1e3:.0f}) mm"
    )
    face = "" if getattr(g, "face", 1) > 0 else ", bottom face"
    return f"'{g.flange}' at {off}, yaw {np.degrees(g.yaw):.0f}°{face}"


def evaluate_batch(ctx: SweepContext, keys: list[tuple[tuple[int, ...], int]]) -> list[BendEval]:
    """Return `evaluate` of every (done, bend) key: the batch runner's unit of work."""
    return [evaluate(ctx, done, bend) for done, bend in keys]


__all__ = [
    "FRACTIONS",
    "PUNCH_SHORTFALL",
    "BendEval",
    "Reach",
    "SideEval",
    "SweepContext",
    "evaluate",
    "evaluate_batch",
    "grasp_label",
    "ordered_part",
    "ram_time",
]
