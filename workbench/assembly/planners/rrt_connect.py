"""RRT-Connect (Kuffner & LaValle 2000) on the part's pose in SE(3), with path shortcutting.

States are poses; the metric is |Δp| + r·angle (r: the part's radius), a bound on how
far any point of the part moves; motions are straight (lerp + slerp) and validated every
`resolution` [m] of that metric. Extension keeps the last free pose of a blocked motion.
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
    tree: _Tree, T: NDArray, ch: InterferenceChecker, rng_: float, res: float
) -> tuple[int, bool]:
    """Grow `tree` one step toward T; return (new node or -1, whether T was reached)."""
    i = tree.nearest(T, ch.radius)
    target = _steer(tree.T[i], T, ch.radius, rng_)
    new = last_free(ch, tree.T[i], target, res)
    if new is None or pose_distance(new, tree.T[i], ch.radius) < 1e-9:
        return -1, False
    j = tree.add(new, i)
    return j, new is target or bool(pose_distance(new, T, ch.radius) < 1e-9)


def shortcut(
    path: list[NDArray],
    ch: InterferenceChecker,
    res: float,
    rng: np.random.Generator,
    iterations: int = 50,
) -> list[NDArray]:
    """Return the path with random pairs of its poses joined straight where that motion is free."""
    path = list(path)
    for _ in range(iterations):
        if len(path) < 3:
            break
        i, j = sorted(rng.choice(len(path), 2, replace=False))
        if j - i < 2:
            continue
        if motion_free(ch, path[i], path[j], res):
            path = path[: i + 1] + path[j:]
    return path


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
    ta, tb = _Tree(start), _Tree(goal)
    t0 = time.perf_counter()
    while time.perf_counter() - t0 < max_time and ta.n + tb.n < max_nodes:
        q = rng.normal(size=4)
        T = make_transform(wxyz_to_matrix(q / np.linalg.norm(q)), rng.uniform(B[0], B[1]))
        i, _ = _extend(ta, T, checker, step, res)
        if i >= 0:
            target = ta.T[i]
            while True:
                j, reached = _extend(tb, target, checker, step, res)
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
