"""RRT-Connect (Kuffner & LaValle 2000) in a robot's joint space, with shortcutting.

The planner knows nothing of what is moved or what it must not touch: a `JointSpace` says
which configurations and straight joint motions are valid and how far apart two
configurations are (a bound on how far any checked point moves, [m]). The assembly's
`CarrySpace` (a robot carrying one part) and the press-brake cycle's transit space are two.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import CollisionError, InputError, PlanningError

FloatArray = NDArray[np.float64]

#: Least time [s] between two progress reports of a search (each also checks a time limit).
PROGRESS_S = 0.25


class JointSpace(Protocol):
    """What the planner asks of a space: joints `dof`, `limits` (dof, 2) [rad], the travel
    bound `distance` [m] (broadcasting over rows of qa), validity of one configuration
    (`valid`, `explain`: what touches, in words) and of a straight motion (`motion_free`)."""

    dof: int
    limits: FloatArray

    def distance(self, qa: ArrayLike, qb: ArrayLike) -> FloatArray: ...

    def valid(self, q: ArrayLike) -> bool: ...

    def explain(self, q: ArrayLike) -> str: ...

    def motion_free(self, qa: ArrayLike, qb: ArrayLike) -> bool: ...


def bisection_order(n: int) -> NDArray[np.int64]:
    """Return 0..n-1 coarse to fine: the last, the middle, the quarters, ... (each once)."""
    order = [n - 1]
    seen = {n - 1}
    step = n
    while step > 1:
        step = (step + 1) // 2
        for i in range(step - 1, n, step):
            if i not in seen:
                seen.add(i)
                order.append(i)
    order += [i for i in range(n) if i not in seen]
    return np.asarray(order, dtype=np.int64)


class _Tree:
    def __init__(self, root: FloatArray) -> None:
        self.q = np.empty((64, len(root)))
        self.parent = np.empty(64, dtype=np.int64)
        self.n = 0
        self.add(root, -1)

    def add(self, q: FloatArray, parent: int) -> int:
        if self.n == len(self.q):
            self.q = np.concatenate([self.q, np.empty_like(self.q)])
            self.parent = np.concatenate([self.parent, np.empty_like(self.parent)])
        self.q[self.n], self.parent[self.n] = q, parent
        self.n += 1
        return self.n - 1

    def branch(self, i: int) -> list[FloatArray]:
        out = []
        while i >= 0:
            out.append(self.q[i].copy())
            i = int(self.parent[i])
        return out


_TRAPPED, _ADVANCED, _REACHED = 0, 1, 2


def _extend(tree: _Tree, q: FloatArray, space: JointSpace, step: float) -> tuple[int, int]:
    """Grow `tree` one step of at most `step` [m] toward q; return (status, new node)."""
    d = space.distance(tree.q[: tree.n], q)
    i = int(np.argmin(d))
    di = float(d[i])
    if di < 1e-12:
        return _REACHED, i
    target = q if di <= step else tree.q[i] + (q - tree.q[i]) * (step / di)
    if not space.motion_free(tree.q[i], target):
        return _TRAPPED, -1
    j = tree.add(target, i)
    return (_REACHED if di <= step else _ADVANCED), j


def shortcut_joints(
    path: list[FloatArray], space: JointSpace, rng: np.random.Generator, iterations: int = 50
) -> list[FloatArray]:
    """Return the joint path with random pairs of its configurations joined straight where free."""
    path = list(path)
    for _ in range(iterations):
        if len(path) < 3:
            break
        i, j = sorted(rng.choice(len(path), 2, replace=False))
        if j - i >= 2 and space.motion_free(path[i], path[j]):
            path = path[: i + 1] + path[j:]
    return path


def plan_joint_rrt_connect(
    space: JointSpace,
    q_start: ArrayLike,
    q_goal: ArrayLike,
    *,
    seed: int = 0,
    max_time: float = 10.0,
    max_nodes: int = 20000,
    range_: float | None = None,
    shortcut_iterations: int = 50,
    progress: Callable[[float, str], None] | None = None,
) -> tuple[FloatArray, int]:
    """Return (joints (K, dof) [rad] from q_start to q_goal, tree nodes) by RRT-Connect.

    seed: rng seed; max_time [s]; range_: extension step [m] of the travel bound Σ|Δq|·w
    (default 1/10 of the bound across the joint limits); samples are uniform within the
    joint limits. Raises CollisionError if an end is not valid (saying what touches),
    PlanningError if no path is found in time. `progress(fraction of max_nodes, message)` is
    called at the start and then at most every `PROGRESS_S` while the trees grow: a caller's
    time limit or cancel raising there ends the search (`workbench.plan_limit`).
    """
    qs, qg = (np.asarray(q, float).reshape(-1) for q in (q_start, q_goal))
    for name, q in (("q_start", qs), ("q_goal", qg)):
        if q.shape != (space.dof,) or not np.all(np.isfinite(q)):
            raise InputError(f"{name} must be {space.dof} finite joint values [rad], got {q}")
        if not space.valid(q):
            # No joint values: only the caller knows the controller's convention.
            raise CollisionError(
                f"the {name.split('_')[1]} configuration is not valid: {space.explain(q)}; move"
                f" the {name.split('_')[1]} pose or the grasp"
            )
    lo, hi = space.limits[:, 0], space.limits[:, 1]
    step = 0.1 * float(space.distance(lo, hi)) if range_ is None else float(range_)
    if not (np.isfinite(step) and step > 0):
        raise InputError(f"range_ must be > 0 m, got {range_!r}")
    rng = np.random.default_rng(seed)
    if space.motion_free(qs, qg):
        return np.stack([qs, qg]), 2
    ta, tb = _Tree(qs), _Tree(qg)
    t0 = shown = time.perf_counter()
    report = progress or (lambda f, m: None)
    report(0.0, "joint-space RRT-Connect")
    while (now := time.perf_counter()) - t0 < max_time and ta.n + tb.n < max_nodes:
        if now - shown >= PROGRESS_S:
            shown = now
            report((ta.n + tb.n) / max_nodes, f"joint-space RRT-Connect, {ta.n + tb.n} nodes")
        q = rng.uniform(lo, hi)
        status, i = _extend(ta, q, space, step)
        if status != _TRAPPED:
            target = ta.q[i].copy()
            while True:
                status2, j = _extend(tb, target, space, step)
                if status2 != _ADVANCED:
                    break
            if status2 == _REACHED:
                path = ta.branch(i)[::-1] + tb.branch(j)[1:]
                if not np.array_equal(path[0], qs):
                    path = path[::-1]
                path = shortcut_joints(path, space, rng, shortcut_iterations)
                return np.asarray(path), ta.n + tb.n
        ta, tb = tb, ta
    raise PlanningError(
        f"joint-space RRT-Connect found no path within max_time={max_time:g} s / "
        f"max_nodes={max_nodes} ({ta.n + tb.n} nodes grown); raise max_time, or free the "
        "robot's way (its links, tool and the carried part are all checked)"
    )
