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


Verify = Callable[[SequencePlan], SequencePlan | Rejected | str]
"""verify(plan): the plan with its planned cycle (verified), or why the full cycle fails."""


def _search(
    ctx: SweepContext,
    verify: Verify | None,
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
    part = ctx.part()
    if len(part.bends) == 0:
        raise InputError("bending.part: the part has no bends; nothing to sequence")
    if not ctx.grasps:
        raise InputError("grasps: no candidate grasp (every flange is smaller than the inset)")
    t0 = time.perf_counter()
    rests = _Rests.of(ctx, robot_free)
    search = _Search(ctx, s, verify, robot_free, rests, progress or (lambda f, m: None))
    search.queue.push_root(rests.root(ctx))
    queue = search.queue
    deadline = None if time_limit is None else t0 + float(time_limit)
    while queue.heap:
        if cancel is not None and cancel():
            search.note += "cancelled: the plans found so far are returned. "
            break
        if deadline is not None and time.perf_counter() > deadline:
            assert time_limit is not None
            search.stop_at_the_time_limit(time_limit)
            break
        # A complete order is taken only from the top of the queue: its cost is exact and no
        # open prefix can end cheaper. While diving, the first one found ends the dive; it
        # goes back into the queue to wait its turn.
        if queue.top_is_complete():
            n = queue.pop()
            if queue.diving:
                queue.end_the_dive(n)
                continue
            if search.accept(n):
                break
            continue
        open_nodes = queue.pop_open(1 if queue.diving else s.width)
        search.evaluate_children(open_nodes, engine, address, cancel, deadline)
        search.expand(open_nodes)
    return search.result(engine, time.perf_counter() - t0)


@dataclass(frozen=True, eq=False)
class _Rests:
    """Where the part rests at the cycle's ends: per grasp (G,), whether the robot takes the
    blank off its stack and puts the finished part on the pallet (reachable and, given
    `robot_free`, collision-free with the part lying there), and its joints there (G, dof)
    (NaN: unknown; all True and NaN where the cell has no stack or pallet)."""

    at_blank: NDArray[np.bool_]
    q_blank: F64
    at_pallet: NDArray[np.bool_]
    q_pallet: F64

    @classmethod
    def of(cls, ctx: SweepContext, robot_free: RobotFree | None) -> _Rests:
        """Return the rests of the part in `ctx`. InputError: no grasp at the stack, or at
        the pallet."""
        part = ctx.part()
        nb = len(part.bends)
        G, dof = len(ctx.grasps), ctx.reach.model.dof
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
        if not at_blank.any():
            raise InputError(
                "bending.blank: the robot reaches no candidate grasp of the blank on its "
                "stack; move the stack or its pose nearer the robot"
            )
        if not at_pallet.any():
            raise InputError(
                "bending.pallet: the robot reaches no candidate grasp of the finished part on "
                "the pallet; move the pallet nearer the robot"
            )
        return cls(at_blank, q_blank, at_pallet, q_pallet)

    def root(self, ctx: SweepContext) -> _Node:
        """Return the search's root: no bend done, each grasp's cost the move from home to
        the blank (the grasps that take it)."""
        G = len(ctx.grasps)
        vmax = ctx.reach.model.max_velocity
        q_home = np.tile(ctx.reach.q, (G, 1))
        cost = np.where(self.at_blank, transit_time(q_home, self.q_blank, vmax), np.inf)
        return _Node((), cost, np.ones(G, bool), self.q_blank, np.arange(G), None)

    def finish(self, node: _Node, vmax: F64) -> None:
        """Add the move to the pallet to a complete sequence (grasps that reach it)."""
        to_pallet = transit_time(node.q1, self.q_pallet, vmax)
        node.cost = np.where(self.at_pallet, node.cost + to_pallet, np.inf)


class _Queue:
    """Open prefixes and complete sequences of `nb` bends, best first: deepest first while
    `diving` (until the first complete sequence), then by least cost plus the heuristic
    (`ram_floor` per remaining bend); ties by depth, then bend order, then arrival."""

    def __init__(self, nb: int, ram_floor: float) -> None:
        self.nb, self.ram_floor = nb, ram_floor
        self.diving = True
        self.counter = 0
        self.heap: list[tuple[tuple[float, ...], int, _Node]] = []

    def key(self, n: _Node) -> tuple[float, ...]:
        """Return the queue's key of `n`."""
        f = float(np.min(n.cost)) + self.ram_floor * (self.nb - len(n.prefix))
        order = tuple(float(i) for i in n.prefix)
        if self.diving:
            return (-len(n.prefix), f, *order)
        return (f, -len(n.prefix), *order)

    def push_root(self, root: _Node) -> None:
        """Start the queue with `root` (arrival 0)."""
        self.heap = [(self.key(root), 0, root)]

    def push(self, n: _Node) -> None:
        """Add `n` (after everything pushed before it among equal keys)."""
        self.counter += 1
        heapq.heappush(self.heap, (self.key(n), self.counter, n))

    def pop(self) -> _Node:
        """Remove and return the first node."""
        return heapq.heappop(self.heap)[2]

    def top_is_complete(self) -> bool:
        """Return whether the first node is a complete sequence."""
        return bool(self.heap) and len(self.heap[0][2].prefix) == self.nb

    def pop_open(self, width: int) -> list[_Node]:
        """Remove and return up to `width` open prefixes from the top (stopping at a
        complete sequence)."""
        batch: list[_Node] = []
        while self.heap and len(batch) < width and len(self.heap[0][2].prefix) < self.nb:
            batch.append(self.pop())
        return [n for n in batch if len(n.prefix) < self.nb]

    def end_the_dive(self, first_complete: _Node) -> None:
        """Stop diving: `first_complete` goes back in, every key is made again by cost."""
        self.diving = False
        self.counter += 1
        self.heap.append((self.key(first_complete), self.counter, first_complete))
        self.heap = [(self.key(h[2]), h[1], h[2]) for h in self.heap]
        heapq.heapify(self.heap)

    def best_complete(self) -> _Node | None:
        """Return the best complete sequence in the queue (None: none)."""
        best = sorted((h for h in self.heap if len(h[2].prefix) == self.nb), key=lambda h: h[0])
        return best[0][2] if best else None

    def deepest(self) -> _Node | None:
        """Return the deepest node in the queue (the first of the deepest; None: empty)."""
        return max((h[2] for h in self.heap), key=lambda n: len(n.prefix), default=None)


class _Search:
    """One search's state: the queue, the bend verdicts evaluated so far (per (bends done,
    next bend)), the work tally, the rejected branches, the plans accepted, the full cycles
    verified and the note."""

    def __init__(
        self,
        ctx: SweepContext,
        settings: SearchSettings,
        verify: Verify | None,
        robot_free: RobotFree | None,
        rests: _Rests,
        report: Progress,
    ) -> None:
        self.ctx, self.s, self.verify, self.robot_free = ctx, settings, verify, robot_free
        self.rests, self.report = rests, report
        self.part = ctx.part()
        self.nb = len(self.part.bends)
        self.names = [b.name for b in self.part.bends]
        ram = ctx.press.ram
        ram_floor = ram.open * (1 / ram.approach_speed + 1 / ram.return_speed)
        self.queue = _Queue(self.nb, ram_floor + settings.handling_time)
        self.evals: dict[tuple[tuple[int, ...], int], BendEval] = {}
        self.station_free: dict[tuple[int, ...], NDArray[np.bool_]] = {}
        self.tally = _Tally()
        self.rejected: list[tuple[tuple[str, ...], str]] = [
            ((), f"grasp {grasp_label(g)}: {why}") for g, why in ctx.refused
        ]
        self.plans: list[SequencePlan] = []
        self.verified = 0
        self.note = ""

    def finish(self, node: _Node) -> None:
        """Add the move to the pallet to a complete sequence (grasps that reach it)."""
        self.rests.finish(node, self.ctx.reach.model.max_velocity)

    def accept(self, n: _Node) -> bool:
        """Verify complete order `n`; return True when the search is over (enough plans, or
        the budget of full cycles spent)."""
        s = self.s
        plan = _plan_of(n, self.ctx)
        if self.verify is not None:
            if self.verified >= s.max_verify:
                self.note += (
                    f"stopped after checking {s.max_verify} full cycles "
                    "(SearchSettings.max_verify). "
                )
                return True
            self.verified += 1
            self.report(
                min(0.99, 0.5 + 0.5 * len(self.plans) / s.max_plans),
                f"checking the full cycle of {' '.join(plan.sequence)}",
            )
            checked = self.verify(plan)
            if isinstance(checked, (str, Rejected)):
                self._refused(
                    n, plan, checked if isinstance(checked, Rejected) else Rejected(checked)
                )
                return False
            plan = checked
        self.plans.append(plan)
        return len(self.plans) >= s.max_plans

    def _refused(self, n: _Node, plan: SequencePlan, why: Rejected) -> None:
        """Record why the full cycle of `n` fails; where one step's grasp is to blame, queue
        the same order with that grasp banned at that step, if any grasp is left."""
        self.rejected.append((plan.sequence, why.reason))
        if why.step is not None:
            ban = n.banned | {(why.step, plan.grasp_ids[why.step])}
            again = _rechain(n, ban, self.ctx, self.s, self.finish)
            if again is not None:
                self.queue.push(again)

    def stop_at_the_time_limit(self, time_limit: float) -> None:
        """Note the stop, the deepest order reached and, with no plan yet, check the best
        complete order found after the limit (a plan, not nothing)."""
        self.note += (
            f"stopped at the time limit of {time_limit:g} s: the best plans found so far "
            "are returned; a longer limit may find better ones. "
        )
        deepest = self.queue.deepest()
        if deepest is not None and len(deepest.prefix) < self.nb and not self.plans:
            self.note += (
                f"The deepest order reached: {' '.join(self.names[i] for i in deepest.prefix)} "
                f"({len(deepest.prefix)} of {self.nb} bends). "
            )
        if not self.plans and self.verify is not None:
            best = self.queue.best_complete()
            if best is not None:
                self.note += "The best complete order found was checked after the limit. "
                self.accept(best)

    def evaluate_children(
        self,
        open_nodes: list[_Node],
        engine: str,
        address: str | None,
        cancel: Callable[[], bool] | None,
        deadline: float | None,
    ) -> None:
        """Evaluate every (bends done, next bend) of the children of `open_nodes` not yet
        evaluated, in one batch run; keep the verdicts with the robot's checks at the die
        and at the regrip station applied."""
        nb = self.nb
        needed = []
        for n in open_nodes:
            done = tuple(sorted(n.prefix))
            for b in range(nb):
                if b not in n.prefix and (done, b) not in self.evals and (done, b) not in needed:
                    needed.append((done, b))
        if not needed:
            return
        left = None if deadline is None else max(deadline - time.perf_counter(), 1e-3)
        run = run_batches(
            evaluate_batch,
            needed,
            context=self.ctx,
            engine=engine,
            address=address,
            batch_size=self.s.batch_size,
            cancel=cancel,
            time_limit=left,
        )
        self.tally.rounds += 1
        self.tally.runs.append(run.stats)
        for k, r in zip(needed, run.results, strict=True):
            if r is not None:
                self.evals[k] = self._at_free_station(self._robot_free_at_die(r), k[0])
        self.tally.candidates += sum(r is not None for r in run.results)
        self.report(
            min(0.5, 0.5 * len(self.evals) / max(1, nb * 2 ** (nb - 1))),
            f"{len(self.evals)} bend candidates checked",
        )

    def _at_free_station(self, e: BendEval, done: tuple[int, ...]) -> BendEval:
        """Return `e` with only the grasps the robot takes collision-free at the regrip
        station (the part lying there, folded by `done`) left in its `at_station`."""
        ctx, robot_free = self.ctx, self.robot_free
        if e.at_station is None or robot_free is None or ctx.T_world_regrip is None:
            return e
        if done not in self.station_free:
            p = ordered_part(self.part, done, e.bend)
            reach, q = reach_where_part_rests(ctx, ctx.T_world_regrip, len(done), p)
            lying = (fold_state(p, len(done), check=False).solid(), ctx.T_world_regrip)
            self.station_free[done] = _free(robot_free, q, reach, lying)
        return replace(e, at_station=e.at_station & self.station_free[done])

    def _robot_free_at_die(self, e: BendEval) -> BendEval:
        """Return `e` with the grasps whose robot collides (with itself, the press or the
        cell) in front of the die, at the stop or at the end of the bend refused, naming where."""
        robot_free = self.robot_free
        if robot_free is None or e.q_front is None or not e.grasp_ok.any():
            return e
        ok = e.grasp_ok.copy()
        reasons = list(e.grasp_reason)
        name = self.names[e.bend]
        for q, where in (
            (e.q_front, "in front of the die"),
            (e.q0, "at the stop"),
            (e.q1, "at the end of the bend"),
        ):
            free = _free(robot_free, q, ok, None)
            for i in np.flatnonzero(ok & ~free):
                reasons[i] = (
                    f"bend {name!r}: grasp {grasp_label(self.ctx.grasps[i])}: the robot collides "
                    f"(with itself, the press or the cell) {where}"
                )
            ok &= free
        return replace(e, grasp_ok=ok, grasp_reason=tuple(reasons))

    def expand(self, open_nodes: list[_Node]) -> None:
        """Queue the children of `open_nodes` that some grasp carries on with (a complete
        one: that also puts the part on the pallet); record why the others are pruned."""
        for n in open_nodes:
            done = tuple(sorted(n.prefix))
            for b in range(self.nb):
                if b in n.prefix:
                    continue
                e = self.evals.get((done, b))
                if e is None:
                    continue  # stopped by the time limit or cancel
                why = self._child_or_why(n, b, e)
                if isinstance(why, str):
                    self.rejected.append((tuple(self.names[i] for i in (*n.prefix, b)), why))
                else:
                    self.queue.push(why)

    def _child_or_why(self, n: _Node, b: int, e: BendEval) -> _Node | str:
        """Return `n` followed by bend `b` (verdict `e`), or why no grasp makes it so."""
        if not e.feasible:
            return e.reason()
        child = _child(n, b, e, self.ctx, self.s)
        if not np.isfinite(child.cost).any():
            return _no_grasp(self.names[b], not n.prefix)
        if len(child.prefix) == self.nb:
            self.finish(child)
            if not np.isfinite(child.cost).any():
                return (
                    f"bend {self.names[b]!r}: no grasp that makes it also puts the part "
                    "on the pallet (bending.pallet) reachable and collision-free"
                )
        return child

    def result(self, engine: str, seconds: float) -> SearchResult:
        """Return the plans ranked, the rejected branches, the work done and the note."""
        runs = self.tally.runs
        batches = sum(r.batches for r in runs)
        overhead = (
            sum(r.overhead_per_batch_s * r.batches for r in runs) / batches if batches else 0.0
        )
        stats = SearchStats(
            candidates=self.tally.candidates,
            verified=self.verified,
            time=seconds,
            engine=engine,
            workers=max((r.workers for r in runs), default=1),
            batches=batches,
            overhead_per_batch=overhead,
            compute=sum(r.compute_s for r in runs),
            rounds=self.tally.rounds,
        )
        # found in order of the estimate; ranked by the planned cycles' times once verified
        self.plans.sort(key=lambda p: (p.regrips, p.flips, p.cycle_time))
        if not self.plans:
            self.note += (
                "no feasible sequence: every branch was pruned (see rejected for the first reasons)"
            )
        self.report(1.0, "done")
        return SearchResult(self.plans, self.rejected, stats, self.note)
