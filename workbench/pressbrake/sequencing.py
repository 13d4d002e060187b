"""The bend-sequence and grasp planner of the press-brake cell (SI units: m, rad, s).

Search space: every order of the bends; per bend a grasp from the candidate grid (which also
fixes the part's orientation on the die, `bend_setup`) and a tool station. Cost, compared
lexicographically: regrips, then flips (the part turned over between two bends), then the
estimated cycle time (ram times, moves between placements at the joints' top speed, a fixed
estimate per regrip and per bend for handling).

Best-first search over bend-order prefixes. A prefix carries, for every grasp, the least
cost of doing its bends ending with that grasp (and the grasp before it: regrips are found
by this dynamic programme, not enumerated). Children are scored by the cheap checks of
`bend_eval` (fold feasibility, part against the press at the bend's fractions, back-gauge,
IK and gripper clearance per grasp), evaluated in batches through the batch runner (serial
or Ray); each (bends done, next bend) is evaluated once per search. The heuristic (the ram's
least time per remaining bend) never overestimates, so complete sequences leave the queue in
cost order: ranked. Until the first complete sequence the search dives (deepest prefix
first), so a time limit still returns the best found so far.

Each complete sequence then goes to `verify` (the full cycle: robot motion, bend following,
regrips, transfer, every frame checked; the caller supplies it). The first reason of every
pruned branch is kept.

Where the part rests (the blank stack, the regrip station, the pallet) a grasp counts only
where the robot reaches it collision-free (`robot_free`, the part lying there): the station's
check is made once per set of bends done, in this process.
"""

from __future__ import annotations

import heapq
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.batch import BatchStats, engine_session, run_batches
from workbench.errors import InputError
from workbench.pressbrake.bend_eval import (
    BendEval,
    SweepContext,
    evaluate_batch,
    grasp_label,
    ordered_part,
    reach_where_part_rests,
)
from workbench.pressbrake.grasp import Grasp
from workbench.sheetmetal.folding import fold_state

F64 = NDArray[np.float64]
Progress = Callable[[float, str], None]

REGRIP = 1e6  # cost of a regrip (dominates flips and time)
FLIP = 1e3  # cost of a flip (dominates time)


@dataclass(frozen=True)
class SearchSettings:
    """Named budgets and estimates of the search.

    max_plans: feasible plans to return; width: prefixes expanded per round once the first
    complete sequence is found (their candidates form one batch run); batch_size:
    candidates per batch; regrip_time, handling_time [s]: estimates per regrip and per bend
    (into the die and out) used for ranking before the full cycle is planned;
    max_verify: most complete sequences the expensive stage checks.
    """

    max_plans: int = 3
    width: int = 8
    batch_size: int = 4
    regrip_time: float = 8.0
    handling_time: float = 1.5
    max_verify: int = 12


@dataclass(frozen=True, eq=False)
class SequencePlan:
    """A ranked plan: bend names in order; per bend its grasp, tool station and the part's
    orientation in words; regrips, flips, the cycle time [s] (`estimated` until the full
    cycle is planned) and, once verified, `verified` True."""

    sequence: tuple[str, ...]
    grasps: tuple[Grasp, ...]
    stations: tuple[str, ...]
    orientations: tuple[str, ...]
    regrips: int
    flips: int
    cycle_time: float
    cost: float
    verified: bool = False
    estimated: bool = True
    grasp_ids: tuple[int, ...] = ()  # indices into the search's candidate grasps

    def grasp_labels(self) -> tuple[str, ...]:
        """Return each bend's grasp in words: flange, point [mm], yaw [deg], face."""
        return tuple(grasp_label(g) for g in self.grasps)


@dataclass(frozen=True)
class Rejected:
    """Why the full cycle of a plan fails, and the step (bend index in the plan) whose grasp
    was in use then (None: not one grasp's fault)."""

    reason: str
    step: int | None = None


@dataclass(frozen=True)
class SearchStats:
    """Work done: candidates (bend checks) evaluated, wall time [s], engine, workers, and
    the batch runner's figures summed over rounds."""

    candidates: int
    verified: int
    time: float
    engine: str
    workers: int
    batches: int
    overhead_per_batch: float
    compute: float
    rounds: int
    access: str = ""
    """Ray: who may use the Ray the search ran on (`BatchStats.access`); empty for serial."""

    def describe(self) -> str:
        """Return one line of the figures (and, on Ray, who may use that Ray)."""
        line = (
            f"{self.candidates} bend candidates and {self.verified} full cycles checked in "
            f"{self.time:.1f} s ({self.engine}, {self.workers} worker(s), {self.batches} batches, "
            f"overhead {self.overhead_per_batch * 1e3:.1f} ms per batch)"
        )
        return f"{line}; Ray: {self.access}" if self.access else line


@dataclass(frozen=True, eq=False)
class SearchResult:
    """Ranked feasible plans (best first), the first reason of every pruned branch, the work
    done and a note when a limit stopped the search early."""

    plans: list[SequencePlan]
    rejected: list[tuple[tuple[str, ...], str]]
    stats: SearchStats
    note: str = ""


@dataclass(eq=False)
class _Node:
    prefix: tuple[int, ...]
    cost: F64  # (G,) least cost ending with each grasp
    up: NDArray[np.bool_]  # (G,) top up at the last bend, per grasp
    q1: F64  # (G, dof) joints at the end of the last bend
    prev: NDArray[np.int64]  # (G,) grasp of the parent's last bend
    parent: _Node | None
    evals: BendEval | None = None
    banned: frozenset[tuple[int, int]] = frozenset()  # (step, grasp) the full cycle refused


@dataclass
class _Tally:
    candidates: int = 0
    batches: int = 0
    compute: float = 0.0
    overhead: float = 0.0
    workers: int = 1
    rounds: int = 0
    runs: list[BatchStats] = field(default_factory=list)


def transit_time(q_from: F64, q_to: F64, vmax: F64) -> F64:
    """Return per grasp (G,) the slowest joint's time [s] at top speed from `q_from` to
    `q_to` (G, dof) [rad] (0 where either is unknown): the estimate of a move."""
    moves = np.abs(np.asarray(q_to) - np.asarray(q_from)) / np.asarray(vmax, float)
    known = np.isfinite(moves).all(axis=1)
    return np.where(known, np.max(np.nan_to_num(moves), axis=1), 0.0)  # type: ignore[no-any-return]


def _child(node: _Node, bend: int, e: BendEval, ctx: SweepContext, s: SearchSettings) -> _Node:
    ok = e.grasp_ok
    side = e.grasp_side
    up = np.array([e.sides[int(k)].top_up for k in side], dtype=bool)
    t_bend = np.array([e.sides[int(k)].ram_time for k in side]) + s.handling_time
    G = len(ok)
    transit = transit_time(node.q1, e.q0, ctx.reach.model.max_velocity)
    if node.parent is None and not node.prefix:
        # the first bend: the grasp taken at the blank stack (root cost: home to the stack)
        cost = np.where(ok, node.cost + transit + t_bend, np.inf)
        return _Node((bend,), cost, up, e.q1, np.arange(G), node, e)
    stay = node.cost + FLIP * (node.up != up) + transit
    best_prev = np.full(G, -1)
    regrip = np.full(G, np.inf)
    # a regrip hands the part over at the station (the old grasp) and takes it again (the
    # new one): both must reach the part lying there
    station = np.ones(G, bool) if e.at_station is None else e.at_station
    for prev_up in (True, False):
        mask = (node.up == prev_up) & station
        if not np.any(mask & np.isfinite(node.cost)):
            continue
        cand = np.where(mask, node.cost, np.inf)
        g = int(np.argmin(cand))
        val = cand[g] + REGRIP + s.regrip_time + FLIP * (prev_up != up)
        better = val < regrip
        regrip = np.where(better, val, regrip)
        best_prev = np.where(better, g, best_prev)
    regrip = np.where(station, regrip, np.inf)
    use_stay = stay <= regrip
    cost = np.where(use_stay, stay, regrip) + t_bend
    prev = np.where(use_stay, np.arange(G), best_prev)
    cost = np.where(ok, cost, np.inf)
    return _Node((*node.prefix, bend), cost, up, e.q1, prev, node, e)


def _no_grasp(bend: str, first: bool) -> str:
    """Return why no grasp carries on with `bend` although some make it."""
    if first:
        return (
            f"bend {bend!r}: no grasp that makes it also picks the blank off its stack "
            "(bending.blank) reachable and collision-free"
        )
    return (
        f"bend {bend!r}: no grasp that makes it goes on from the bends before: the same grasp "
        "cannot make it, and no regrip is possible (both grasps must reach the part on the "
        "regrip station, bending.regrip)"
    )


RobotFree = Callable[[F64, "tuple[trimesh.Trimesh, F64] | None"], NDArray[np.bool_]]
"""robot_free(q, lying) (N,): which joint vectors (N, dof) are collision-free, the robot
against itself and the cell and, given `lying` = (mesh, T_world), its links against that part."""


def _free(
    robot_free: RobotFree,
    q: F64,
    ok: NDArray[np.bool_],
    lying: tuple[trimesh.Trimesh, F64] | None,
) -> NDArray[np.bool_]:
    """Return (G,) True where the robot at `q` (G, dof) is collision-free (only `ok` ones
    are checked; the others stay False)."""
    out = np.zeros(len(q), dtype=bool)
    idx = np.flatnonzero(ok)
    if len(idx):
        out[idx] = robot_free(q[idx], lying)
    return out


def _rechain(
    node: _Node,
    banned: frozenset[tuple[int, int]],
    ctx: SweepContext,
    s: SearchSettings,
    finish: Callable[[_Node], None],
) -> _Node | None:
    """Return the complete sequence of `node` scored again without the `banned` (step,
    grasp) pairs, or None when no grasp assignment is left."""
    chain: list[_Node] = []
    n: _Node | None = node
    while n is not None and n.prefix:
        chain.append(n)
        n = n.parent
    assert n is not None
    cur = n
    for depth, link in enumerate(reversed(chain)):
        assert link.evals is not None
        ok = link.evals.grasp_ok.copy()
        for step, g in banned:
            if step == depth:
                ok[g] = False
        cur = _child(cur, link.prefix[-1], replace(link.evals, grasp_ok=ok), ctx, s)
        if not np.isfinite(cur.cost).any():
            return None
    finish(cur)
    if not np.isfinite(cur.cost).any():
        return None
    cur.banned = banned
    return cur


def _plan_of(node: _Node, ctx: SweepContext) -> SequencePlan:
    part = ctx.part()
    g = int(np.argmin(node.cost))
    total = float(node.cost[g])
    chain: list[tuple[_Node, int]] = []
    n: _Node | None = node
    while n is not None and n.prefix:
        chain.append((n, g))
        g = int(n.prev[g])
        n = n.parent
    chain.reverse()
    grasps, stations, orient, ids = [], [], [], []
    regrips = flips = 0
    prev_g: int | None = None
    prev_up: bool | None = None
    for n, gi in chain:
        assert n.evals is not None
        side = n.evals.sides[int(n.evals.grasp_side[gi])]
        grasps.append(ctx.grasps[gi])
        ids.append(gi)
        stations.append(side.station or "")
        which = "child" if int(n.evals.grasp_side[gi]) == 0 else "parent"
        bend = part.bends[n.prefix[-1]]
        front = part.flanges[bend.child if which == "child" else bend.parent].name
        orient.append(
            f"the side of flange {front!r} to the robot, {'top' if side.top_up else 'bottom'} up"
        )
        if prev_g is not None and prev_g != gi:
            regrips += 1
        if prev_up is not None and prev_up != side.top_up:
            flips += 1
        prev_g, prev_up = gi, side.top_up
    estimate = total - REGRIP * regrips - FLIP * flips
    return SequencePlan(
        tuple(part.bends[i].name for i in node.prefix),
        tuple(grasps),
        tuple(stations),
        tuple(orient),
        regrips,
        flips,
        float(estimate),
        total,
        grasp_ids=tuple(ids),
    )


def find_sequences(
    ctx: SweepContext,
    *,
    verify: Callable[[SequencePlan], SequencePlan | Rejected | str] | None = None,
    engine: str = "serial",
    address: str | None = None,
    time_limit: float | None = None,
    progress: Progress | None = None,
    cancel: Callable[[], bool] | None = None,
    settings: SearchSettings | None = None,
    robot_free: RobotFree | None = None,
) -> SearchResult:
    """Return ranked feasible plans of the part in `ctx` (see the module docstring).

    robot_free(q, lying) (`RobotFree`) says which joint vectors are collision-free; the
    grasps at the blank stack and the pallet are checked with it (the part lying there).

    verify(plan) returns the plan with its planned cycle (verified) or the reason the full
    cycle fails; None keeps the cheap stage's verdict. `time_limit` [s] (None: none) stops
    the search and returns what was found, with a note; `cancel()` True stops it too.
    """
    with engine_session(engine, address) as ray_access:
        found = _search(
            ctx, verify, engine, address, time_limit, progress, cancel, settings, robot_free
        )
    return replace(found, stats=replace(found.stats, access=ray_access))


def _search(
    ctx: SweepContext,
    verify: Callable[[SequencePlan], SequencePlan | Rejected | str] | None,
    engine: str,
    address: str | None,
    time_limit: float | None,
    progress: Progress | None,
    cancel: Callable[[], bool] | None,
    settings: SearchSettings | None,
    robot_free: RobotFree | None,
) -> SearchResult:
    s = settings or SearchSettings()
    if time_limit is not None and not (np.isfinite(time_limit) and time_limit > 0):
        raise InputError(f"time_limit: must be > 0 s or None, got {time_limit!r}")
    report = progress or (lambda f, m: None)
    part = ctx.part()
    nb = len(part.bends)
    if nb == 0:
        raise InputError("bending.part: the part has no bends; nothing to sequence")
    if not ctx.grasps:
        raise InputError("grasps: no candidate grasp (every flange is smaller than the inset)")
    G, dof = len(ctx.grasps), ctx.reach.model.dof
    t0 = time.perf_counter()
    deadline = None if time_limit is None else t0 + float(time_limit)
    evals: dict[tuple[tuple[int, ...], int], BendEval] = {}
    tally = _Tally()
    rejected: list[tuple[tuple[str, ...], str]] = []
    plans: list[SequencePlan] = []
    verified = 0
    note = ""
    names = [b.name for b in part.bends]
    ram_floor = (
        ctx.press.ram.open * (1 / ctx.press.ram.approach_speed + 1 / ctx.press.ram.return_speed)
        + s.handling_time
    )
    # Where the part rests: the first grasp must reach the blank, the last the pallet; the
    # moves home -> stack and last bend -> pallet count in the estimate.
    q_home = np.tile(ctx.reach.q, (G, 1))
    at_blank, q_blank = np.ones(G, bool), np.full((G, dof), np.nan)
    if ctx.T_world_blank is not None:
        at_blank, q_blank = reach_where_part_rests(ctx, ctx.T_world_blank, 0)
        if robot_free is not None:
            lying = (fold_state(part, 0, check=False).solid(), ctx.T_world_blank)
            at_blank &= _free(robot_free, q_blank, at_blank, lying)
    at_pallet, q_pallet = np.ones(G, bool), np.full((G, dof), np.nan)
    if ctx.T_world_pallet is not None:
        at_pallet, q_pallet = reach_where_part_rests(ctx, ctx.T_world_pallet, nb)
        if robot_free is not None:
            lying = (fold_state(part, nb, check=False).solid(), ctx.T_world_pallet)
            at_pallet &= _free(robot_free, q_pallet, at_pallet, lying)
    vmax = ctx.reach.model.max_velocity
    station_free: dict[tuple[int, ...], NDArray[np.bool_]] = {}

    def _at_free_station(e: BendEval, done: tuple[int, ...]) -> BendEval:
        """Return `e` with only the grasps the robot takes collision-free at the regrip
        station (the part lying there, folded by `done`) left in its `at_station`."""
        if e.at_station is None or robot_free is None or ctx.T_world_regrip is None:
            return e
        if done not in station_free:
            p = ordered_part(part, done, e.bend)
            reach, q = reach_where_part_rests(ctx, ctx.T_world_regrip, len(done), p)
            lying = (fold_state(p, len(done), check=False).solid(), ctx.T_world_regrip)
            station_free[done] = _free(robot_free, q, reach, lying)
        return replace(e, at_station=e.at_station & station_free[done])

    def _robot_free_at_die(e: BendEval) -> BendEval:
        """Return `e` with the grasps whose robot collides (with itself, the press or the
        cell) in front of the die, at the stop or at the end of the bend refused, naming where."""
        if robot_free is None or e.q_front is None or not e.grasp_ok.any():
            return e
        ok = e.grasp_ok.copy()
        reasons = list(e.grasp_reason)
        name = names[e.bend]
        for q, where in (
            (e.q_front, "in front of the die"),
            (e.q0, "at the stop"),
            (e.q1, "at the end of the bend"),
        ):
            free = _free(robot_free, q, ok, None)
            for i in np.flatnonzero(ok & ~free):
                reasons[i] = (
                    f"bend {name!r}: grasp {grasp_label(ctx.grasps[i])}: the robot collides "
                    f"(with itself, the press or the cell) {where}"
                )
            ok &= free
        return replace(e, grasp_ok=ok, grasp_reason=tuple(reasons))

    def finish(node: _Node) -> None:
        """Add the move to the pallet to a complete sequence (grasps that reach it)."""
        to_pallet = transit_time(node.q1, q_pallet, vmax)
        node.cost = np.where(at_pallet, node.cost + to_pallet, np.inf)

    if not at_blank.any():
        raise InputError(
            "bending.blank: the robot reaches no candidate grasp of the blank on its stack; "
            "move the stack or its pose nearer the robot"
        )
    if not at_pallet.any():
        raise InputError(
            "bending.pallet: the robot reaches no candidate grasp of the finished part on the "
            "pallet; move the pallet nearer the robot"
        )
    root = _Node(
        (),
        np.where(at_blank, transit_time(q_home, q_blank, vmax), np.inf),
        np.ones(G, bool),
        q_blank,
        np.arange(G),
        None,
    )
    counter = 0
    diving = True

    def key(n: _Node) -> tuple[float, ...]:
        f = float(np.min(n.cost)) + ram_floor * (nb - len(n.prefix))
        order = tuple(float(i) for i in n.prefix)
        if diving:
            return (-len(n.prefix), f, *order)
        return (f, -len(n.prefix), *order)

    heap: list[tuple[tuple[float, ...], int, _Node]] = [(key(root), 0, root)]

    def accept(n: _Node) -> bool:
        """Verify complete order `n`; return True when the search is over (enough plans, or
        the budget of full cycles spent)."""
        nonlocal verified, note, counter
        plan = _plan_of(n, ctx)
        if verify is not None:
            if verified >= s.max_verify:
                note += f"stopped after checking {s.max_verify} full cycles (SearchSettings.max_verify). "
                return True
            verified += 1
            report(
                min(0.99, 0.5 + 0.5 * len(plans) / s.max_plans),
                f"checking the full cycle of {' '.join(plan.sequence)}",
            )
            checked = verify(plan)
            if isinstance(checked, (str, Rejected)):
                why = checked if isinstance(checked, Rejected) else Rejected(checked)
                rejected.append((plan.sequence, why.reason))
                if why.step is not None:
                    # the same order with that grasp banned at that step, if any is left
                    ban = n.banned | {(why.step, plan.grasp_ids[why.step])}
                    again = _rechain(n, ban, ctx, s, finish)
                    if again is not None:
                        counter += 1
                        heapq.heappush(heap, (key(again), counter, again))
                return False
            plan = checked
        plans.append(plan)
        return len(plans) >= s.max_plans

    while heap:
        if cancel is not None and cancel():
            note += "cancelled: the plans found so far are returned. "
            break
        if deadline is not None and time.perf_counter() > deadline:
            note += (
                f"stopped at the time limit of {time_limit:g} s: the best plans found so far "
                "are returned; a longer limit may find better ones. "
            )
            deepest = max((h[2] for h in heap), key=lambda n: len(n.prefix), default=None)
            if deepest is not None and len(deepest.prefix) < nb and not plans:
                note += (
                    f"The deepest order reached: {' '.join(names[i] for i in deepest.prefix)} "
                    f"({len(deepest.prefix)} of {nb} bends). "
                )
            if not plans and verify is not None:
                # the best complete order found, checked after the limit: a plan, not nothing
                best = sorted((h for h in heap if len(h[2].prefix) == nb), key=lambda h: h[0])
                for h in best[:1]:
                    note += "The best complete order found was checked after the limit. "
                    accept(h[2])
            break
        # A complete order is taken only from the top of the queue: its cost is exact and no
        # open prefix can end cheaper. While diving, the first one found ends the dive; it
        # goes back into the queue to wait its turn.
        if heap and len(heap[0][2].prefix) == nb:
            n = heapq.heappop(heap)[2]
            if diving:
                diving = False
                counter += 1
                heap.append((key(n), counter, n))
                heap = [(key(h[2]), h[1], h[2]) for h in heap]
                heapq.heapify(heap)
                continue
            if accept(n):
                break
            continue
        width = 1 if diving else s.width
        batch: list[_Node] = []
        while heap and len(batch) < width and len(heap[0][2].prefix) < nb:
            batch.append(heapq.heappop(heap)[2])
        open_nodes = [n for n in batch if len(n.prefix) < nb]
        needed = []
        for n in open_nodes:
            done = tuple(sorted(n.prefix))
            for b in range(nb):
                if b not in n.prefix and (done, b) not in evals and (done, b) not in needed:
                    needed.append((done, b))
        if needed:
            left = None if deadline is None else max(deadline - time.perf_counter(), 1e-3)
            run = run_batches(
                evaluate_batch,
                needed,
                context=ctx,
                engine=engine,
                address=address,
                batch_size=s.batch_size,
                cancel=cancel,
                time_limit=left,
            )
            tally.rounds += 1
            tally.runs.append(run.stats)
            for k, r in zip(needed, run.results, strict=True):
                if r is not None:
                    evals[k] = _at_free_station(_robot_free_at_die(r), k[0])
            tally.candidates += sum(r is not None for r in run.results)
            report(
                min(0.5, 0.5 * len(evals) / max(1, nb * 2 ** (nb - 1))),
                f"{len(evals)} bend candidates checked",
            )
        for n in open_nodes:
            done = tuple(sorted(n.prefix))
            for b in range(nb):
                if b in n.prefix:
                    continue
                e = evals.get((done, b))
                if e is None:
                    continue  # stopped by the time limit or cancel
                branch = tuple(names[i] for i in (*n.prefix, b))
                if not e.feasible:
                    rejected.append((branch, e.reason()))
                    continue
                child = _child(n, b, e, ctx, s)
                if not np.isfinite(child.cost).any():
                    rejected.append((branch, _no_grasp(names[b], not n.prefix)))
                    continue
                if len(child.prefix) == nb:
                    finish(child)
                    if not np.isfinite(child.cost).any():
                        rejected.append(
                            (
                                branch,
                                f"bend {names[b]!r}: no grasp that makes it also puts the part "
                                "on the pallet (bending.pallet) reachable and collision-free",
                            )
                        )
                        continue
                counter += 1
                heapq.heappush(heap, (key(child), counter, child))
    runs = tally.runs
    workers = max((r.workers for r in runs), default=1)
    batches = sum(r.batches for r in runs)
    overhead = sum(r.overhead_per_batch_s * r.batches for r in runs) / batches if batches else 0.0
    stats = SearchStats(
        candidates=tally.candidates,
        verified=verified,
        time=time.perf_counter() - t0,
        engine=engine,
        workers=workers,
        batches=batches,
        overhead_per_batch=overhead,
        compute=sum(r.compute_s for r in runs),
        rounds=tally.rounds,
    )
    # found in order of the estimate; ranked by the planned cycles' times once verified
    plans.sort(key=lambda p: (p.regrips, p.flips, p.cycle_time))
    if not plans:
        note += "no feasible sequence: every branch was pruned (see rejected for the first reasons)"
    report(1.0, "done")
    return SearchResult(plans, rejected, stats, note)
