"""The press-brake cycle's free moves, routed around the press and the cell (SI units).

Between stations (the stack, the die, the regrip station, the pallet, via home) and
between two bends the cycle moves the robot straight in joint space. Turned end for end
in front of the die, a 300 mm part swings through the punch; swung home from the regrip
station, an arm can fold into itself. Each such move (a waypoint marked `free`) is
checked as the cycle's final check sees it: the robot (links and tool) against the cell,
the press and itself under the collision policy, certified between samples, and kept the
policy's clearance margin away from them at every `TRANSIT_RESOLUTION`; the part it
carries (its OBB tree, `press_check.frame_hits`) against the open press and the cell,
every `TRANSIT_RESOLUTION` of its travel. A blocked move is planned again by RRT-Connect
in joint space (`motion.joint_rrt`, seeded, bounded by `TRANSIT_NODES` tree nodes so the
same cycle gives the same detour on every machine), shortcut, and its via configurations
become waypoints of the cycle (`DETOUR_STEP` apart, so the blended trajectory keeps to
the planned polyline). Where no detour is found the move stays straight and the cycle's
check reports what it hits; `TransitReport` says which moves were rerouted or not.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision.clearance import margin_kept
from workbench.collision.motion_bound import JointLevers
from workbench.collision.plan_check import CollisionPolicy, check_motion, shared_engine
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.errors import CollisionError, PlanLimitError, PlanningError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel
from workbench.motion.joint_rrt import plan_joint_rrt_connect
from workbench.pressbrake.cycle_path import CyclePath, Phase, Waypoint
from workbench.pressbrake.obstacles import Obstacles
from workbench.pressbrake.press_check import PartHit, frame_hits
from workbench.sheetmetal.folding import FoldedState

F64 = NDArray[np.float64]

#: Largest travel [m] of a point of the carried part between two checks along a move.
TRANSIT_RESOLUTION = 0.005
#: Tree nodes RRT-Connect may grow for one blocked move (a count, not a time: the same
#: detour on every machine); past it the move stays straight and the check reports it.
TRANSIT_NODES = 3000
#: Seed of the detours' random samples.
TRANSIT_SEED = 0
#: Largest joint change [rad] between two via waypoints of a detour.
DETOUR_STEP = 0.1


@dataclass(frozen=True)
class Carried:
    """What the robot carries on a move: the part folded as `state` at the TCP pose
    `T_part_tcp` (4, 4) [m] in the part frame, among `obstacles` (the open press, the cell)."""

    state: FoldedState
    T_part_tcp: F64
    obstacles: Obstacles


class TransitSpace:
    """Valid configurations and straight joint moves of the robot, carrying a part or not
    (a `motion.joint_rrt.JointSpace`)."""

    def __init__(
        self,
        model: RobotModel,
        T_world_base: F64,
        T_flange_tcp: F64,
        checker: RobotCollisionChecker,
        policy: CollisionPolicy,
        carried: Carried | None,
    ) -> None:
        self.model, self.checker, self.policy, self.carried = model, checker, policy, carried
        self.dof = int(model.dof)
        self.limits: F64 = np.asarray(model.limits, float)
        self.T_world_base = np.asarray(T_world_base, float)
        lev = JointLevers(model)
        moving = [b.solid.mesh for b in checker.scene.moving.values()]
        robot = np.stack(
            [
                lev.levers(min(i, self.dof), m.vertices)
                for i, m in enumerate(moving)
                if m is not None
            ]
        ).max(axis=0)
        self.T_flange_part = None
        self.part_lever = np.zeros(self.dof)
        if carried is not None:
            self.T_flange_part = np.asarray(T_flange_tcp, float) @ invert_transform(
                carried.T_part_tcp
            )
            pts = carried.state.solid().vertices
            pf = pts @ self.T_flange_part[:3, :3].T + self.T_flange_part[:3, 3]
            self.part_lever = lev.levers(self.dof, pf)
        self.weights = np.maximum(robot, self.part_lever)

    def distance(self, qa: ArrayLike, qb: ArrayLike) -> F64:
        """Return Σ_j |Δq_j|·w_j [m]: a bound on how far any point of robot or part moves."""
        return np.abs(np.asarray(qb, float) - np.asarray(qa, float)) @ self.weights

    def _in_limits(self, q: F64) -> bool:
        return bool(np.all(q >= self.limits[:, 0] - 1e-9) and np.all(q <= self.limits[:, 1] + 1e-9))

    def _part_hits(self, q: F64) -> list[tuple[int, int, int]]:
        c = self.carried
        if c is None or self.T_flange_part is None:
            return []
        T = self.T_world_base @ self.model.fk(q) @ self.T_flange_part
        return frame_hits(c.state, T, c.obstacles)

    def _robot_free(self, q: F64) -> bool:
        n = len(q)
        rep = check_motion(
            np.arange(n, dtype=float),
            q,
            self.checker,
            self.policy,
            sampler=lambda t: _lerp(q, t),
            acceleration=np.zeros(self.dof),
            clearance=False,
        )
        if not rep.collision_free:
            return False
        # The search keeps the margin: only its verdict, fcl asked only where a bound is
        # under it (the least distance itself, `plan_clearance`, cost 70 % of the search).
        eng, _ = shared_engine(self.checker, self.policy)
        p = self.policy
        return margin_kept(self.checker, q, margin=p.margin, exempt=p.exempt, engine=eng)

    def valid(self, q: ArrayLike) -> bool:
        """Return True if q (dof,) [rad] is within the limits, nothing touches and the robot
        keeps the policy's clearance margin."""
        qa = np.asarray(q, float)
        return self._in_limits(qa) and not self._part_hits(qa[None]) and self._robot_free(qa[None])

    def explain(self, q: ArrayLike) -> str:
        """Return what touches what at q (dof,) [rad], or "" where nothing does."""
        qa = np.asarray(q, float)
        out = [] if self._in_limits(qa) else ["joint limits exceeded"]
        if self._part_hits(qa[None]):
            out.append("the carried part touches the press or the cell")
        rep = self.checker.check(qa, distance=False)
        out += [f"{a} hits {b}" for a, b in rep.colliding]
        return "; ".join(out)

    def motion_free(self, qa: ArrayLike, qb: ArrayLike) -> bool:
        """Return True if the straight joint move qa -> qb is free (part and robot)."""
        a, b = np.asarray(qa, float), np.asarray(qb, float)
        n = max(1, int(np.ceil(float(np.abs(b - a) @ self.part_lever) / TRANSIT_RESOLUTION)))
        u = np.linspace(0.0, 1.0, n + 1)[:, None]
        q = a + u * (b - a)
        if self._part_hits(q[1:]):
            return False
        # The engine certifies contact between the samples; the margin is kept at them.
        return self._robot_free(q)


def _lerp(q: F64, t: F64) -> F64:
    """Return the piecewise straight joint path through q (N, dof) at parameters t (index)."""
    t = np.clip(np.asarray(t, float), 0.0, len(q) - 1)
    i = np.minimum(np.floor(t).astype(int), len(q) - 2)
    f = (t - i)[:, None]
    return q[i] * (1 - f) + q[i + 1] * f  # type: ignore[no-any-return]


@dataclass(frozen=True)
class TransitReport:
    """Which free moves were rerouted (their target waypoints' labels, with the vias added)
    and which were blocked with no detour found (label, why)."""

    rerouted: tuple[tuple[str, int], ...] = ()
    blocked: tuple[tuple[str, str], ...] = ()

    def describe(self) -> str:
        """Return the report in words ("" when every free move was straight and free)."""
        parts = [f"{label}: around in {n} vias" for label, n in self.rerouted]
        parts += [f"{label}: no detour ({why})" for label, why in self.blocked]
        return "; ".join(parts)


def route_transits(
    path: CyclePath,
    q: F64,
    space_of: Callable[[int], TransitSpace],
    fk_tcp: Callable[[F64], F64],
    progress: Callable[[float, str], None] | None = None,
) -> tuple[CyclePath, F64, TransitReport]:
    """Return the cycle's path and joints (N, dof) with every blocked free move replaced by
    a detour (via waypoints inserted before its target) and the report.

    space_of(k): the space of a move within phase k of `path` (what the robot carries, among
    which obstacles; the caller keeps one per phase: a detour keeps the phases' order); fk_tcp(q (dof,)) -> the TCP pose (4, 4) in the world.
    progress(fraction, message): called for each move and while a detour is searched (a time
    limit or cancel raising there ends the routing, `workbench.plan_limit`).
    """
    wps = list(path.waypoints)
    rows = [q[0]]
    new_index = [0]
    rerouted: list[tuple[str, int]] = []
    blocked: list[tuple[str, str]] = []
    out_wps = [wps[0]]
    report = progress or (lambda f, m: None)
    for i in range(1, len(wps)):
        w = wps[i]
        report((i - 1) / len(wps), f"the move to {w.label}")
        if w.free and np.any(np.abs(q[i] - q[i - 1]) > 1e-9):
            space = space_of(_phase_of(path.phases, i))
            if not space.motion_free(q[i - 1], q[i]):
                try:
                    via, _ = plan_joint_rrt_connect(
                        space,
                        q[i - 1],
                        q[i],
                        seed=TRANSIT_SEED,
                        max_time=np.inf,
                        max_nodes=TRANSIT_NODES,
                        progress=_detour_progress(
                            report, (i - 1) / len(wps), 1 / len(wps), w.label
                        ),
                    )
                except PlanLimitError:
                    raise  # the plan's time limit or cancel: not a move without a detour
                except (CollisionError, PlanningError) as exc:
                    blocked.append((w.label, str(exc)))
                else:
                    dense = _densify(via, DETOUR_STEP)[1:-1]
                    for j, qv in enumerate(dense):
                        out_wps.append(Waypoint(fk_tcp(qv), f"{w.label} (around {j + 1})"))
                        rows.append(qv)
                    rerouted.append((w.label, len(dense)))
        out_wps.append(w)
        rows.append(q[i])
        new_index.append(len(out_wps) - 1)
    if not rerouted:
        return path, q, TransitReport((), tuple(blocked))
    phases = tuple(
        replace(ph, start=new_index[ph.start], end=new_index[ph.end]) for ph in path.phases
    )
    new_path = replace(path, waypoints=tuple(out_wps), phases=phases)
    return new_path, np.asarray(rows), TransitReport(tuple(rerouted), tuple(blocked))


def carried_hits_between(
    times: F64,
    q: F64,
    sample: Callable[[F64], F64],
    phase_of_frame: NDArray[np.int64],
    space_of_phase: Callable[[int], TransitSpace | None],
) -> dict[int, PartHit]:
    """Return the carried part's first hit between frames n and n+1, by n, where any.

    times (F,) [s], q (F, dof) [rad]: the checked frames; sample(t (M,)) -> joints (M, dof)
    on the trajectory; phase_of_frame (F,); space_of_phase(k) -> the space of phase k where
    the robot carries the part there, else None. Between two frames of one carrying phase the
    part is sampled on the trajectory every `TRANSIT_RESOLUTION` of its travel (bounded by the
    joints' change times the part's levers), so a frame spacing in time does not step over
    a table the part grazes at speed.
    """
    out: dict[int, PartHit] = {}
    for k in np.unique(phase_of_frame):
        space = space_of_phase(int(k))
        if space is None or space.carried is None or space.T_flange_part is None:
            continue
        idx = np.flatnonzero((phase_of_frame[:-1] == k) & (phase_of_frame[1:] == k))
        travel = np.abs(q[idx + 1] - q[idx]) @ space.part_lever
        m = np.ceil(travel / TRANSIT_RESOLUTION).astype(int)
        keep = m > 1
        if not keep.any():
            continue
        owner = np.repeat(idx[keep], m[keep] - 1)
        u = np.concatenate([np.arange(1, j) / j for j in m[keep]])
        t = times[owner] + u * (times[owner + 1] - times[owner])
        T = space.T_world_base @ space.model.fk(sample(t)) @ space.T_flange_part
        names = [f.name for f in space.carried.state.part.flanges]
        obs = space.carried.obstacles.names
        at: dict[int, list[tuple[int, int]]] = {}
        for f, fl, o in frame_hits(space.carried.state, T, space.carried.obstacles):
            at.setdefault(f, []).append((fl, o))
        for f in sorted(at):
            n = int(owner[f])
            if n not in out:
                out[n] = PartHit(
                    n,
                    tuple(dict.fromkeys(names[fl] for fl, _ in at[f])),
                    tuple(obs[o] for _, o in at[f]),
                )
    return out


def _detour_progress(
    report: Callable[[float, str], None], at: float, share: float, label: str
) -> Callable[[float, str], None]:
    """Return the progress of a detour's search: `share` of the routing from `at`."""
    return lambda f, m: report(at + share * f, f"a detour to {label} ({m})")


def _phase_of(phases: tuple[Phase, ...], i: int) -> int:
    """Return the phase the move into waypoint i belongs to (the last that spans it)."""
    best = 0
    for k, ph in enumerate(phases):
        if ph.start <= i - 1 and i <= ph.end:
            best = k
    return best


def _densify(q: F64, step: float) -> F64:
    """Return the joint polyline q (K, dof) with points added so no joint changes more than
    `step` [rad] between two; the given points kept."""
    out = [q[0]]
    for a, b in zip(q[:-1], q[1:], strict=True):
        n = max(1, int(np.ceil(float(np.abs(b - a).max()) / step)))
        out += [a + (b - a) * (j / n) for j in range(1, n + 1)]
    return np.asarray(out)
