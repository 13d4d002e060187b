"""RRT-Connect (Kuffner & LaValle 2000) on the part's pose in SE(3), with path shortcutting.

States are poses; motions are straight (lerp + slerp) and validated every `resolution` [m]
of |Δp| + r·angle (r: the part's radius, a bound on how far any point of the part moves).
The trees' nearest node and step use |Δp| + range·angle (one step turns at most 1 rad).
Extension keeps the last free pose of a blocked motion. Solutions are shortened by
`shortcut`: far-to-near vertex joins (batched), random point-to-point joins, joins again.
"""

from __future__ import annotations

import time

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import interpolate, motion_samples, pose_distance
from workbench.assembly.planners.common import last_free, motion_free, retreat, scene_bounds
from workbench.errors import InputError, PlanningError
from workbench.geometry.transforms import make_transform, wxyz_to_matrix


class _Tree:
    def __init__(self, root: NDArray) -> None:
        self.T = np.empty((64, 4, 4))
        self.parent = np.empty(64, dtype=int)
        self.n = 0
        self.add(root, -1)

    def add(self, T: NDArray, parent: int) -> int:
        if self.n == len(self.T):
            self.T = np.concatenate([self.T, np.empty_like(self.T)])
            self.parent = np.concatenate([self.parent, np.empty_like(self.parent)])
        self.T[self.n], self.parent[self.n] = T, parent
        self.n += 1
        return self.n - 1

    def nearest(self, T: NDArray, radius: float) -> int:
        return int(np.argmin(pose_distance(self.T[: self.n], T, radius)))

    def branch(self, i: int) -> list[NDArray]:
        out = []
        while i >= 0:
            out.append(self.T[i])
            i = int(self.parent[i])
        return out


def _steer(a: NDArray, b: NDArray, radius: float, rng_: float) -> NDArray:
    d = float(pose_distance(a, b, radius))
    return b if d <= rng_ else interpolate(a, b, [rng_ / d])[0]


def _extend(
    tree: _Tree, T: NDArray, ch: InterferenceChecker, rng_: float, res: float, metric: float
) -> tuple[int, bool]:
    """Grow `tree` one step toward T; return (new node or -1, whether T was reached).

    metric [m]: the rotation weight of the tree's distance |Δp| + metric·angle (nearest
    node, step length); motions are still checked every `res` of the part's own metric.
    """
    i = tree.nearest(T, metric)
    target = _steer(tree.T[i], T, metric, rng_)
    new = last_free(ch, tree.T[i], target, res)
    if new is None or pose_distance(new, tree.T[i], ch.radius) < 1e-9:
        return -1, False
    j = tree.add(new, i)
    return j, new is target or bool(pose_distance(new, T, metric) < 1e-9)


def reduce_vertices(path: list[NDArray], ch: InterferenceChecker, res: float) -> list[NDArray]:
    """Return the path with each vertex joined straight to the farthest later vertex it can reach.

    Deterministic, far to near: from each kept vertex, the motions to every later vertex
    (farthest first) go through one batched check (`first_free_group`: the AABB stage on
    all their samples at once, then each motion in order up to its first hit) and the
    first free one is taken; the next vertex is always reachable (a path segment).
    """
    out = [path[0]]
    i = 0
    while i < len(path) - 1:
        cand = list(range(len(path) - 1, i + 1, -1))  # farthest first; i + 1 is a segment
        j = i + 1
        if cand:
            S = [motion_samples(path[i], path[k], ch.radius, res) for k in cand]
            g = ch.first_free_group(np.concatenate(S), [len(x) for x in S], cells=False)
            if g >= 0:
                j = cand[g]
        out.append(path[j])
        i = j
    return out


def _point_at(path: list[NDArray], cum: NDArray, s: float, radius: float) -> tuple[int, NDArray]:
    """Return (segment index k, pose) at arc length s along the path (cum: lengths at vertices)."""
    k = min(max(int(np.searchsorted(cum, s, side="right")) - 1, 0), len(path) - 2)
    seg = cum[k + 1] - cum[k]
    u = 0.0 if seg <= 0 else min(max((s - cum[k]) / seg, 0.0), 1.0)
    return k, interpolate(path[k], path[k + 1], [u])[0]


def shortcut(
    path: list[NDArray],
    ch: InterferenceChecker,
    res: float,
    rng: np.random.Generator,
    iterations: int = 50,
) -> list[NDArray]:
    """Return the path shortened where straight motions are free (the ends kept).

    1. `reduce_vertices` (deterministic, far to near, batched motion checks);
    2. `iterations` random shortcuts between two points anywhere on the path (by arc
       length in the |Δp| + r·angle metric, at least two segments apart or on different
       segments), taken where the straight motion between them is free and shorter;
    3. `reduce_vertices` again over the new vertices.
    Every motion of the result is checked as `motion_free` checks it (its own samples at
    `res`), pieces of old segments included.
    """
    path = list(path)
    if len(path) < 3:
        return path
    path = reduce_vertices(path, ch, res)
    r = ch.radius
    for _ in range(iterations):
        if len(path) < 3:
            break
        P = np.asarray(path)
        seg = pose_distance(P[:-1], P[1:], r)
        cum = np.concatenate([[0.0], np.cumsum(seg)])
        a, b = np.sort(rng.uniform(0.0, cum[-1], 2))
        ka, A = _point_at(path, cum, float(a), r)
        kb, B = _point_at(path, cum, float(b), r)
        if kb <= ka:  # the same segment: straight already
            continue
        if float(pose_distance(A, B, r)) >= float(b - a) - 1e-9:
            continue
        # The new pieces path[ka] -> A and B -> path[kb + 1] lie on old segments but are
        # sampled afresh: all three motions in one batched check.
        S = [
            motion_samples(path[ka], A, r, res),
            motion_samples(A, B, r, res),
            motion_samples(B, path[kb + 1], r, res),
        ]
        if ch.first_interference(np.concatenate(S), cells=False) < 0:
            path = path[: ka + 1] + [A, B] + path[kb + 1 :]
    return reduce_vertices(path, ch, res)


def plan_rrt_connect(
    checker: InterferenceChecker,
    start: NDArray[np.float64],
    goal: NDArray[np.float64],
    *,
    seed: int = 0,
    max_time: float = 10.0,
    max_nodes: int = 20000,
    range_: float | None = None,
    resolution: float | None = None,
    bounds: NDArray[np.float64] | None = None,
    shortcut_iterations: int = 50,
) -> tuple[NDArray[np.float64], int]:
    """Return (poses (K, 4, 4) from start to goal, tree nodes) by RRT-Connect in SE(3).

    seed: rng seed; max_time [s]; range_: extension step in the |Δp| + r·angle metric [m]
    (default 1/10 of the bounds' diagonal); resolution: motion check spacing [m]
    (default the cell size); bounds (2, 3): position sampling box [m].
    """
    res = checker.cell_size if resolution is None else float(resolution)
    B = scene_bounds(checker, start, goal) if bounds is None else np.asarray(bounds, float)
    step = 0.1 * float(np.linalg.norm(B[1] - B[0])) if range_ is None else float(range_)
    if not step > 0:
        raise InputError(f"range_ must be > 0 m, got {range_!r}")
    rng = np.random.default_rng(seed)
    # A part seated in a hole is withdrawn first, as in the ant planner (common.retreat).
    a = retreat(checker, start, goal[:3, 3], res)
    b = retreat(checker, goal, start[:3, 3] if a is None else a[:3, 3], res)
    head = [start] if a is None else [start, a]
    tail = [goal] if b is None else [b, goal]
    start, goal = head[-1], tail[0]
    if motion_free(checker, start, goal, res):
        return np.asarray(head + tail), 2
    # The tree's metric weighs rotation by the step (one step turns the part by at most
    # 1 rad) rather than by the part's radius, with which a step could turn it by
    # range / radius (~4 rad on the window scenes): random turns at every step kept a tree
    # from sliding through a window and sent it round the wall (paths 1.5-1.7x OMPL's).
    metric = max(checker.radius, step)
    ta, tb = _Tree(start), _Tree(goal)
    t0 = time.perf_counter()
    while time.perf_counter() - t0 < max_time and ta.n + tb.n < max_nodes:
        q = rng.normal(size=4)
        T = make_transform(wxyz_to_matrix(q / np.linalg.norm(q)), rng.uniform(B[0], B[1]))
        i, _ = _extend(ta, T, checker, step, res, metric)
        if i >= 0:
            target = ta.T[i]
            while True:
                j, reached = _extend(tb, target, checker, step, res, metric)
                if j < 0:
                    break
                if reached:
                    path = ta.branch(i)[::-1] + tb.branch(j)[1:]
                    if not np.array_equal(path[0], start):
                        path = path[::-1]
                    path = shortcut(path, checker, res, rng, shortcut_iterations)
                    return np.asarray(head[:-1] + path + tail[1:]), ta.n + tb.n
        ta, tb = tb, ta
    raise PlanningError(
        f"RRT-Connect found no path within max_time={max_time:g} s / max_nodes={max_nodes} "
        f"({ta.n + tb.n} nodes grown); raise max_time or check that the goal is reachable"
    )


def check_path(checker: InterferenceChecker, poses: NDArray, resolution: float) -> int:
    """Return the index of the first interfering sample along the path, or -1 if it is free."""
    S = np.concatenate(
        [poses[:1]]
        + [
            motion_samples(poses[i], poses[i + 1], checker.radius, resolution)
            for i in range(len(poses) - 1)
        ]
    )
    return checker.first_interference(S)
