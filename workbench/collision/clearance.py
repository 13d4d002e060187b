"""A plan's clearance: the least exact distance over its samples, with its pair, against a margin.

The plan checks (`plan_check.check_motion`) certify that the robot never touches the cell or
itself, at and between the samples. The clearance margin asks more: that no pair of bodies
(a link or the tool against an obstacle, or two links) comes closer than `margin` [m]. This
module measures the least python-fcl distance over the plan's samples and names the pair, so
that a plan closer than the margin is a problem with its pair, distance and time.

It is a branch and bound over (sample, pair): every pair's distance at a sample is at least
the gap between the two bodies' world bounding boxes, and, with a fast engine, at least its
group's least item (spheres or capsules: lower bounds of the group's pairs' distances). fcl's
distance is asked in increasing order of those bounds, until the next bound is no smaller than
the least distance found: the answer equals fcl's distance over every sample and pair
(`tests/collision/test_clearance.py` checks it against that brute force).

Exempt pairs (the contacts a process needs, by name) are not measured; the result lists them.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.collision.engine import CollisionEngine
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.errors import InputError

FloatArray = NDArray[np.float64]
Pair = tuple[str, str]
#: Distances [m] this close to the least are one tie: the clearance names the first sample of
#: a tie (0.1 um, a thousandth of the 0.1 mm a clearance is printed to; fcl's rounding is ~1e-12).
TIE = 1e-7
#: The largest margin [m] a plan may ask for (a clearance of a metre is no margin but a cell).
MAX_MARGIN = 0.5


def check_margin(margin: float) -> float:
    """Return `margin` [m] as a float; InputError naming `margin` unless 0 <= margin <= MAX_MARGIN."""
    m = float(margin)
    if not np.isfinite(m) or not 0.0 <= m <= MAX_MARGIN:
        raise InputError(
            f"margin: {margin!r} m must be a length from 0 to {MAX_MARGIN} m", field="margin"
        )
    return m


def exempt_pairs(pairs: Iterable[Iterable[str]]) -> tuple[Pair, ...]:
    """Return the exempt pairs as sorted name pairs, once each (InputError for a pair not of two)."""
    out: list[Pair] = []
    for p in pairs:
        names = tuple(str(n) for n in p)
        if len(names) != 2 or names[0] == names[1]:
            raise InputError(f"exempt: {names!r} is not a pair of two bodies' names")
        key = (min(names), max(names))
        if key not in out:
            out.append(key)
    return tuple(out)


@dataclass(frozen=True)
class Clearance:
    """The least distance [m] over a plan's samples, its pair and where, against `margin` [m].

    distance: fcl's least surface distance over the samples and the pairs not exempt (0 where
    one touches; inf where no pair was measured). pair: the two bodies' names (None: none).
    time [s] / index: the sample where it is least (None: one configuration, not a plan).
    exempt: the pairs left out by name.
    """

    distance: float
    pair: Pair | None
    time: float | None
    index: int | None
    margin: float = 0.0
    exempt: tuple[Pair, ...] = ()

    @property
    def keeps_margin(self) -> bool:
        """Return True when every measured pair stays at least `margin` apart at every sample."""
        return self.distance >= self.margin

    @property
    def problem(self) -> str | None:
        """Return the margin problem as a sentence naming the pair (mm), or None when kept."""
        if self.keeps_margin or self.pair is None:
            return None
        a, b = self.pair
        return (
            f"{a} comes within {self.distance * 1e3:.1f} mm of {b}{self._at(' at ')},"
            f" closer than the clearance margin {self.margin * 1e3:.1f} mm"
        )

    def _at(self, sep: str) -> str:
        return "" if self.time is None else f"{sep}t = {self.time:.2f} s"

    def describe(self) -> str:
        """Return the clearance as one phrase for a user (mm), exemptions included."""
        if self.pair is None:
            text = "no pair measured"
        else:
            text = (
                f"clearance {self.distance * 1e3:.1f} mm ({self.pair[0]} – {self.pair[1]}"
                f"{self._at(', ')}), margin {self.margin * 1e3:.1f} mm"
            )
        if self.exempt:
            text += "; exempt: " + ", ".join(f"{a} – {b}" for a, b in self.exempt)
        return text


def plan_clearance(
    checker: RobotCollisionChecker,
    times: FloatArray,
    q: FloatArray,
    *,
    margin: float = 0.0,
    exempt: Iterable[Iterable[str]] = (),
    engine: CollisionEngine | None = None,
) -> Clearance:
    """Return the least fcl distance over samples q (N, dof) [rad] at times (N,) [s] and its pair.

    Every pair of `checker.scene.pairs` but the `exempt` ones (by name, either order) is
    measured; `engine` (a fast engine on `checker`) tightens the lower bounds that order
    the search. The answer is exact on the samples (see the module docstring).
    """
    m = check_margin(margin)
    ex = exempt_pairs(exempt)
    qs = np.atleast_2d(np.asarray(q, float))
    t = np.asarray(times, float).reshape(-1)
    if len(t) != len(qs):
        raise InputError(f"times: expected {len(qs)} values [s], got {len(t)}")
    scene = checker.scene
    skip = {frozenset(p) for p in ex}
    pairs = list(scene.pairs)
    keep = np.array([frozenset(p) not in skip for p in pairs], bool)
    if not len(qs) or not keep.any():
        return Clearance(float("inf"), None, None, None, m, ex)
    lower = _lower_bounds(checker, qs, engine)  # (N, P) [m]
    lower[:, ~keep] = np.inf
    order = np.argsort(lower, axis=None, kind="stable")
    best = np.inf
    found: list[tuple[float, int, int]] = []  # (distance, sample, pair) of every one measured
    placed = -1
    for flat in order:
        i, k = divmod(int(flat), len(pairs))
        if not lower[i, k] <= best + TIE:
            break  # every bound left is farther than the least distance found (and its ties)
        if i != placed:
            scene.place(checker.world_poses(qs[i]))
            placed = i
        a, b = pairs[k]
        d = 0.0 if scene.collides(a, b) else scene.distance(a, b)
        found.append((d, i, k))
        best = min(best, d)
    # Ties (a rigid pair at one distance over a stretch of the plan) are named by their first
    # sample, not by whichever fcl's last-bit rounding made least: the time is reproducible.
    i, k = min((i, k) for d, i, k in found if d <= best + TIE)
    return Clearance(float(best), pairs[k], float(t[i]), i, m, ex)


def margin_kept(
    checker: RobotCollisionChecker,
    q: FloatArray,
    *,
    margin: float,
    exempt: Iterable[Iterable[str]] = (),
    engine: CollisionEngine | None = None,
) -> bool:
    """Return ``plan_clearance(...).keeps_margin`` of samples q (N, dof) [rad], measuring less.

    The same bounds, but only the (sample, pair) whose bound is under `margin` are asked of
    fcl (nearest first), and the first closer than `margin` ends it: a search that only needs
    the verdict (a planner's every extension) skips the exact least distance, the same verdict
    (`tests/collision/test_clearance.py` checks it against `plan_clearance`).
    """
    m = check_margin(margin)
    skip = {frozenset(p) for p in exempt_pairs(exempt)}
    qs = np.atleast_2d(np.asarray(q, float))
    scene = checker.scene
    pairs = list(scene.pairs)
    keep = np.array([frozenset(p) not in skip for p in pairs], bool)
    if not len(qs) or not keep.any() or m <= 0.0:
        return True  # nothing measured, or no margin: every distance is >= 0
    lower = _lower_bounds(checker, qs, engine)
    lower[:, ~keep] = np.inf
    flat = lower.ravel()
    near = np.flatnonzero(flat < m)
    placed = -1
    for f in near[np.argsort(flat[near], kind="stable")]:
        i, k = divmod(int(f), len(pairs))
        if i != placed:
            scene.place(checker.world_poses(qs[i]))
            placed = i
        a, b = pairs[k]
        if scene.collides(a, b) or scene.distance(a, b) < m:
            return False
    return True


def _lower_bounds(
    checker: RobotCollisionChecker, qs: FloatArray, engine: CollisionEngine | None
) -> FloatArray:
    """Return (N, P) lower bounds [m] of every pair's distance at every sample."""
    if engine is not None and engine.exact is checker:
        poses = engine.poses(qs)
        lower = np.maximum(engine.aabb_gaps(poses) + engine.margin, 0.0)
        if engine.mode != "exact":
            clr, _ = engine.path_items(qs)
            gmin = np.minimum.reduceat(clr, engine.group_start, axis=1) + engine.margin
            col = {p: k for k, p in enumerate(engine.pair_lever)}
            for g, members in enumerate(engine.group_pairs):
                for p in members:
                    k = col[p]
                    lower[:, k] = np.maximum(lower[:, k], gmin[:, g])
        return lower
    scene = checker.scene
    out = np.empty((len(qs), len(scene.pairs)))
    for i, q in enumerate(qs):
        scene.place(checker.world_poses(q))
        out[i] = [scene.aabb_gap(a, b) for a, b in scene.pairs]
    return out
