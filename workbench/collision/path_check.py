"""A joint path certified between samples: fast conservative items first, exact pairs where flagged.

The engine (any mode) gives, per configuration, clearance lower bounds of "items" (a sphere
or capsule against the cell, a sphere pair of a self-collision pair), each belonging to a
"group" of exact body pairs (a body against every obstacle, or one self pair). A group is
*flagged* at a configuration when one of its items has clearance <= 0; only then are its
exact pairs (python-fcl collide plus containment) evaluated. The fast items never miss a
contact, so a configuration collides exactly iff one of its flagged groups' pairs collides:
the per-sample verdict equals the dense exact check of every pair.

Between two samples a, b (both free), an item with levers L (dof,) [m/rad] is safe when
``c_a + c_b > |q_b - q_a| @ L + 2 * dev @ L`` (its clearance changes by at most |dq| @ L,
and the real motion is within dev of the straight joint segment); for a flagged group the
exact surface distances of its pairs are used instead of the items. Intervals that cannot
be certified are bisected; a midpoint whose flagged pairs collide exactly is a collision
between samples.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from workbench.collision.path_oracle import Pair, PathNode, PathOracle, PathOutcome, chord_bound
from workbench.collision.thin_matmul import thin_matmul

FloatArray = NDArray[np.float64]
Sampler = Callable[[FloatArray], FloatArray]
# (t0 (M,), t1 (M,)) [s] -> (M, dof) [rad/s^2]: a bound of |q''| over each interval.
AccelerationBound = Callable[[FloatArray, FloatArray], FloatArray]
#: Slack [rad] added to the chord deviation a·h²/8: that bound holds for a C1 motion, and a
#: timed trajectory's pieces meet with position jumps of up to ~7e-9 rad (ruckig's rounding).
PIECE_JUMP = 1e-7
# From this bisection depth on, a group whose fast items keep failing is settled with exact
# distances (one fcl distance per pair) rather than more midpoints.
PROMOTE_DEPTH = 1
# At most this many (interval, group) clearance bounds are settled with fcl for the report.
REFINE = 256
# An anchor (a configuration with fcl's distance d) serves nearby configurations while its
# lever bound stays >= RENEW * d.
RENEW = 0.8
# A lower bound that says nothing [m] (finite: chord bounds stay free of inf - inf).
NO_BOUND = -1e9
#: The finest subdivision: an interval between samples is halved at most this many times
#: (down to 1/4096 of it, 2.4 us of a 10 ms step) before it is reported "not certified at the
#: finest subdivision" (`EnginePathReport.uncertified_indices`), i.e. treated as touching.
MAX_DEPTH = 12
# An interval of the path: (start node, end node, bisection depth, index of its sample interval).
Interval = tuple[PathNode, PathNode, int, int]


class PathCertifier:
    """Certify a sampled joint path with an engine's items, confirming flagged groups exactly."""

    def __init__(self, oracle: PathOracle) -> None:
        self.o = oracle
        # The node whose poses the exact checker holds, kept by reference: an id() would be
        # reused by a new node once the placed one is dropped, and its poses never placed.
        self._placed: PathNode | None = None
        self.exact_pairs = 0
        # Per pair, configurations with an exact distance: the distance at any q is at least
        # d - |q - q_anchor| @ lever (the lever bound along the straight joint segment).
        self.anchors: dict[Pair, tuple[FloatArray, FloatArray]] = {}
        # Exact pairs in `aabb_gaps` column order (the order of `pair_lever`).
        self.pair_index = {p: k for k, p in enumerate(oracle.pair_lever)}
        self.plev = np.stack(list(oracle.pair_lever.values()))
        self.pairs = list(oracle.pair_lever)
        self.group_cols = [
            np.array([self.pair_index[p] for p in g], np.int64) for g in oracle.group_pairs
        ]
        self.group_member = np.zeros((len(self.group_cols), len(self.pairs)), np.int64)
        for g, cols in enumerate(self.group_cols):
            self.group_member[g, cols] = 1

    def _nodes(self, t: FloatArray, q: FloatArray) -> list[PathNode]:
        clr, lev = self.o.path_items(q)
        gmin = np.minimum.reduceat(clr, self.o.group_start, axis=1)
        # One item per group between samples: its least clearance with the largest lever of its
        # items (each item changes by at most |dq| @ its lever, so their minimum by at most
        # |dq| @ the largest). A little looser than item by item, and (G,) rather than (I,)
        # columns (about 1000 sphere pairs of the self pairs on the MZ07).
        self.lev = np.maximum.reduceat(lev, self.o.group_start, axis=0)
        inside = self.o.contained(q)
        T = self.o.poses(q)
        gaps = self.o.aabb_gaps(T)
        # Exact confirmation of what the fast items could not rule out: the pairs of flagged
        # groups whose bounding boxes touch (apart boxes cannot touch) and whose pair table
        # (a lower bound of the surfaces' distance) does not keep them apart, and the held pairs.
        flagged = ((gmin <= 0.0).astype(np.int64) @ self.group_member > 0) & ~(
            gaps + self.o.margin > 0.0
        )
        tab = self.o.table_bounds(q, flagged)
        flagged &= ~(tab + self.o.margin > 0.0)
        nodes = [
            PathNode(float(t[i]), q[i], gmin[i], gmin[i], T[i], gaps[i], tab[i])
            for i in range(len(q))
        ]
        for i, j in zip(*np.nonzero(flagged), strict=True):
            node, p = nodes[i], self.pairs[j]
            if self._anchored(node, p) + self.o.margin > 0.0:
                continue  # an anchor keeps it apart
            self._place(node)
            self.exact_pairs += 1
            if self.o.pair_collides(p):
                node.hits += (p,)
            else:
                self._lower(node, p, 2)  # an anchor for the configurations nearby
        for i, k in zip(*np.nonzero(inside), strict=True):
            node, p = nodes[i], self.o.always_pairs[k]
            if p in node.hits:
                continue
            self._place(node)
            self.exact_pairs += 1
            if self.o.pair_collides(p):
                node.hits += (p,)
        return nodes

    def _tabs(self, ends: list[PathNode], want: NDArray[np.bool_]) -> FloatArray:
        """Return (W, P) table bounds at the interval ends, looking up the wanted ones not yet known."""
        tab = np.array([n.tab for n in ends])
        miss = want & np.isnan(tab)
        rows = np.flatnonzero(miss.any(axis=1))
        if rows.size:
            got = self.o.table_bounds(np.array([ends[k].q for k in rows]), miss[rows])
            for k, r in enumerate(rows):
                m = miss[r]
                ends[r].tab[m] = got[k, m]
            tab = np.array([n.tab for n in ends])
        return np.where(np.isnan(tab), NO_BOUND, tab)

    def _place(self, node: PathNode) -> None:
        if self._placed is not node:
            self.o.place(node.poses)
            self._placed = node

    def _anchored(self, node: PathNode, pair: Pair) -> float:
        """Return the anchors' bound at node where it keeps RENEW of the anchor's distance, else -inf.

        Renewing anchors before their bound decays to 0 keeps the reported clearance within
        about 1 - RENEW of fcl's distance.
        """
        if pair not in self.anchors:
            return -np.inf
        qa, d = self.anchors[pair]
        b = d - np.abs(qa - node.q) @ self.o.pair_lever[pair]
        k = int(np.argmax(b))
        return float(b[k]) if b[k] >= RENEW * d[k] else -np.inf

    def _lower(self, node: PathNode, pair: Pair, tier: int) -> float:
        """Return a lower bound [m] of the pair's distance (less the margin) at node.

        tier 0: the gap between bounding boxes; 1: the best anchor's lever bound; 2: fcl's
        distance (which becomes an anchor).
        """
        if tier == 0:
            return float(node.gaps[self.pair_index[pair]])
        key = (pair, tier)
        if key in node.dist:
            return node.dist[key]
        if tier == 1:
            if pair not in self.anchors:
                return -np.inf
            qa, da = self.anchors[pair]
            return float(np.max(da - np.abs(qa - node.q) @ self.o.pair_lever[pair]))
        self._place(node)
        self.exact_pairs += 1
        value = self.o.pair_distance(pair)
        qa, da = self.anchors.get(pair, (np.zeros((0, len(node.q))), np.zeros(0)))
        self.anchors[pair] = (np.vstack([qa, node.q]), np.append(da, value))
        node.dist[key] = value
        return value

    def run(
        self,
        q: FloatArray,
        t: FloatArray,
        *,
        sampler: Sampler | None,
        acceleration: FloatArray | AccelerationBound | None,
        deviation: FloatArray,
        max_depth: int = MAX_DEPTH,
        progress: Callable[[float, str], None] | None = None,
    ) -> PathOutcome:
        """Return the outcome for samples q (N, dof) [rad] at times t (N,) [s].

        sampler(times) -> q gives the real motion at bisection midpoints; with `acceleration`
        (dof,) [rad/s^2] bounding |q''| the deviation from the chord of an interval of length
        h is ``acceleration * h**2 / 8``; `acceleration` may also be a function
        (t0, t1) -> (M, dof) bounding |q''| on each interval (tighter where the motion is
        smooth than one bound for the whole path). Without a sampler, midpoints lie on the chord and
        `deviation` (dof,) [rad] is used for every interval.

        Every interval between samples is settled on its own: certified free, or found
        colliding at a midpoint, or halved `max_depth` times without being certified (an event
        without pairs: its clearance is below what the finest subdivision resolves). There is
        no budget shared across the path: the work per interval does not depend on the
        path's length, so neither does the cost per sample.
        """
        report = progress or (lambda _f, _m: None)
        report(0.0, f"fast check of {len(q)} samples")
        nodes = self._nodes(t, q)
        lev = self.lev  # the samples' group levers (midpoints' `_nodes` replace self.lev)
        sample_hits = {i: n.hits for i, n in enumerate(nodes) if n.hits}
        flagged = int(sum(bool(np.any(n.gmin <= 0.0)) for n in nodes))
        report(0.3, f"{flagged} flagged samples confirmed exactly; certifying between samples")
        evaluated = len(nodes)
        events: list[tuple[float, int, FloatArray, tuple[Pair, ...]]] = []
        work: list[Interval] = [
            (nodes[i], nodes[i + 1], 0, i)
            for i in range(len(nodes) - 1)
            if not nodes[i].hits and not nodes[i + 1].hits
        ]
        if len(nodes) == 1 and not nodes[0].hits:
            work = [(nodes[0], nodes[0], 0, 0)]  # one configuration: its clearance only
        # Certified intervals: per group the clearance bound, and whether it is fcl's.
        cert: list[tuple[Any, FloatArray, NDArray[np.bool_], FloatArray, FloatArray]] = []
        while work:
            safe, glo, dq, dev = self._bound_round(work, lev, acceleration, deviation)
            bisect = [w for w, ok in zip(work, safe, strict=True) if not ok]
            cert += [
                (work[k], glo[k], np.zeros(glo.shape[1], bool), dq[k], dev[k])
                for k in np.flatnonzero(safe)
            ]
            work = self._bisect(bisect, sampler, max_depth, events)
            evaluated += sum(1 for w in bisect if w[2] < max_depth)
            level = min(w[2] for w in work) if work else max_depth
            report(
                0.3 + 0.6 * level / max(max_depth, 1),
                f"{evaluated} configurations checked ({len(work)} intervals at subdivision {level})",
            )
        clearance = self._tighten(cert) if cert and not events and not sample_hits else np.inf
        events.sort(key=lambda e: e[0])
        return PathOutcome(
            sample_hits, flagged, events, float(clearance), evaluated, self.exact_pairs
        )

    def _bound_round(
        self,
        work: list[Interval],
        lev: FloatArray,
        acceleration: FloatArray | AccelerationBound | None,
        deviation: FloatArray,
    ) -> tuple[NDArray[np.bool_], FloatArray, FloatArray, FloatArray]:
        """Return, per interval of `work`: whether it is certified free, its clearance bound
        per group (W, G) [m], its joint travel |dq| (W, dof) and deviation bound (W, dof) [rad].

        A group's bound is its fast item's chord bound, or for an exact group (flagged at an
        end, or failing from PROMOTE_DEPTH on) the least bound of its exact pairs."""
        a = np.array([w[0].clr for w in work])
        b = np.array([w[1].clr for w in work])
        dq = np.array([np.abs(w[1].q - w[0].q) for w in work])
        dev = _deviation(work, dq, acceleration, deviation)
        travel, tube = thin_matmul(dq, lev.T), thin_matmul(dev, lev.T)
        group_lo = chord_bound(a, b, travel) - tube
        group_fail = ~(group_lo > 0.0)
        ga = np.array([w[0].gmin for w in work])
        gb = np.array([w[1].gmin for w in work])
        depth = np.array([w[2] for w in work])
        exact = (ga <= 0.0) | (gb <= 0.0) | (group_fail & (depth >= PROMOTE_DEPTH)[:, None])
        fast_fail = np.any(group_fail & ~exact, axis=1)
        pb = self._pair_bounds(work, exact, fast_fail, dq, dev)
        safe = ~fast_fail & np.all(pb > 0.0, axis=1)
        glo = np.where(exact, np.inf, group_lo)
        for g, cols in enumerate(self.group_cols):
            if len(cols) == 0:
                continue
            glo[:, g] = np.where(exact[:, g], pb[:, cols].min(axis=1), glo[:, g])
        return safe, glo, dq, dev

    def _pair_bounds(
        self,
        work: list[Interval],
        exact: NDArray[np.bool_],
        fast_fail: NDArray[np.bool_],
        dq: FloatArray,
        dev: FloatArray,
    ) -> FloatArray:
        """Return the exact pairs' clearance bounds (W, P) [m] over the intervals (inf for the
        pairs of no exact group, and where the interval's fast items fail): box gaps first,
        then pair tables, anchors and fcl only where those fail; an interval stops at its
        first failing pair (it is bisected anyway)."""
        # Exact pairs of the exact groups, tier 0 (box gaps) for all at once.
        pa = np.array([w[0].gaps for w in work])
        pb = np.array([w[1].gaps for w in work])
        ptravel, ptube = thin_matmul(dq, self.plev.T), thin_matmul(dev, self.plev.T)
        pair_lo = chord_bound(pa, pb, ptravel) - ptube  # (W, P)
        pairs_in = (exact.astype(np.int64) @ self.group_member > 0) & ~fast_fail[:, None]
        # Pair tables: lower bounds of the distance at both ends, the same chord bound.
        want = pairs_in & ~(pair_lo > 0.0)
        ta = self._tabs([w[0] for w in work], want)
        tb = self._tabs([w[1] for w in work], want)
        pair_lo = np.where(want, np.maximum(pair_lo, chord_bound(ta, tb, ptravel) - ptube), pair_lo)
        pb = np.where(pairs_in, pair_lo, np.inf)
        failed: set[int] = set()
        for k, j in zip(*np.nonzero(pairs_in & ~(pair_lo > 0.0)), strict=True):
            if k in failed:
                continue  # bisected anyway
            pb[k, j] = self._pair_interval(
                work[k], self.pairs[j], ptravel[k, j], ptube[k, j], pair_lo[k, j]
            )
            if not pb[k, j] > 0.0:
                failed.add(int(k))
        return pb

    def _bisect(
        self,
        bisect: list[Interval],
        sampler: Sampler | None,
        max_depth: int,
        events: list[tuple[float, int, FloatArray, tuple[Pair, ...]]],
    ) -> list[Interval]:
        """Return the halves of the intervals not certified; add to `events` the ones at
        `max_depth` (not certified at the finest subdivision) and the colliding midpoints."""
        for w in bisect:
            if w[2] >= max_depth:  # not certified at the finest subdivision: reported as such
                tm = (w[0].t + w[1].t) / 2
                events.append((tm, w[3], (w[0].q + w[1].q) / 2, ()))
        bisect = [w for w in bisect if w[2] < max_depth]
        work: list[Interval] = []
        if not bisect:
            return work
        t_mid = np.array([(w[0].t + w[1].t) / 2 for w in bisect])
        qm = (
            sampler(t_mid)
            if sampler is not None
            else np.array([(w[0].q + w[1].q) / 2 for w in bisect])
        )
        mids = self._nodes(t_mid, qm)
        for w, m in zip(bisect, mids, strict=True):
            if m.hits:
                events.append((m.t, w[3], m.q, m.hits))
                continue
            work.append((w[0], m, w[2] + 1, w[3]))
            work.append((m, w[1], w[2] + 1, w[3]))
        return work

    def _pair_interval(
        self, w: Any, pair: Pair, travel: float, tube: float, lo: float, *, fcl: bool = False
    ) -> float:
        """Return the pair's clearance bound [m] over interval w, at least `lo` (box gaps).

        Anchors' bounds next (cheap); fcl's distances only when the bound is still <= 0, or
        when `fcl` asks for the tight bound.
        """
        for tier in (1, 2):
            if tier == 2 and lo > 0.0 and not fcl:
                break
            da = self._lower(w[0], pair, tier)
            db = self._lower(w[1], pair, tier)
            if np.isfinite(da) and np.isfinite(db):
                lo = max(
                    lo, float(chord_bound(np.array(da), np.array(db), np.array(travel))) - tube
                )
        return lo

    def _tighten(
        self, cert: list[tuple[Any, FloatArray, NDArray[np.bool_], FloatArray, FloatArray]]
    ) -> float:
        """Return the path's clearance bound [m], settling the smallest bounds with fcl.

        Every interval's group bound is valid. The smallest is settled with fcl distances of
        its group's pairs at the interval's ends; those become anchors, whose lever bounds
        then raise that group's bound on every interval (the larger bound is kept); pairs whose
        box-gap bound on that interval is above the others' fcl bound are not asked. Stops when
        the smallest bound left is fcl's, or after `REFINE` rounds.
        """
        B = np.array([c[1] for c in cert])
        tight = np.zeros(B.shape, bool)
        qa = np.array([c[0][0].q for c in cert])
        qb = np.array([c[0][1].q for c in cert])
        dq = np.array([c[3] for c in cert])
        dev = np.array([c[4] for c in cert])
        ga = np.array([c[0][0].gaps for c in cert])
        gb = np.array([c[0][1].gaps for c in cert])
        best = np.inf  # the smallest fcl-settled bound so far: rows above it cannot matter
        for _ in range(REFINE):
            k, g = np.unravel_index(int(np.argmin(B)), B.shape)
            if tight[k, g] or not np.isfinite(B[k, g]):
                break
            w = cert[k][0]
            rows = np.flatnonzero((B[:, g] < best) | (np.arange(len(B)) == k))
            kr = int(np.searchsorted(rows, k))
            cols = self.group_cols[g]
            # Box-gap bounds of the group's pairs on these rows: a pair whose gap bound on
            # row k is above the group's fcl bound there cannot be its least; no fcl for it.
            L = self.plev[cols]
            gap_lo = chord_bound(ga[rows][:, cols], gb[rows][:, cols], thin_matmul(dq[rows], L.T))
            gap_lo = gap_lo - thin_matmul(dev[rows], L.T)
            lo = np.full(len(rows), np.inf)
            for c in np.argsort(gap_lo[kr], kind="stable"):
                if gap_lo[kr, c] >= lo[kr]:
                    lo = np.minimum(lo, gap_lo[:, c])
                    continue
                pair = self.pairs[cols[c]]
                # The interval's ends as anchors (every anchor gives a valid bound).
                anchor_q = np.stack([w[0].q, w[1].q])
                anchor_d = np.array([self._lower(w[0], pair, 2), self._lower(w[1], pair, 2)])
                Lp = L[c]
                da = np.max(anchor_d[None] - np.abs(qa[rows, None] - anchor_q[None]) @ Lp, axis=1)
                db = np.max(anchor_d[None] - np.abs(qb[rows, None] - anchor_q[None]) @ Lp, axis=1)
                Lc = Lp[:, None]
                pair_lo = chord_bound(da, db, thin_matmul(dq[rows], Lc)[:, 0])
                pair_lo = pair_lo - thin_matmul(dev[rows], Lc)[:, 0]
                lo = np.minimum(lo, np.maximum(pair_lo, gap_lo[:, c]))
            B[rows, g] = np.maximum(B[rows, g], lo)
            tight[k, g] = True
            best = min(best, float(B[k, g]))
        return float(B.min())


def _deviation(
    work: list[Interval],
    dq: FloatArray,
    acceleration: FloatArray | AccelerationBound | None,
    deviation: FloatArray,
) -> FloatArray:
    """Return each interval's bound (W, dof) [rad] of the motion's deviation from its chord:
    acceleration * h**2 / 8 plus PIECE_JUMP with an acceleration bound, else `deviation`."""
    h = np.array([w[1].t - w[0].t for w in work])
    if callable(acceleration):
        t0 = np.array([w[0].t for w in work])
        acc = np.abs(np.asarray(acceleration(t0, t0 + h), float))
        return acc * (h[:, None] ** 2) / 8.0 + PIECE_JUMP
    if acceleration is not None:
        return acceleration[None] * (h[:, None] ** 2) / 8.0 + PIECE_JUMP
    return np.broadcast_to(deviation, dq.shape)
