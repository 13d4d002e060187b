"""The single-ant greedy planner of seed 003 (Sec. 5.2, Table 4).

1. B: the feasible region (obstacle bounds and the end poses, grown by the part's size).
2. D = |e - s|; the dominant axis is the one with the largest |e - s| component; cutting
   planes are perpendicular to it.
3. The straight line s -> e is split into `step` segments; on each of the step - 1
   cutting planes a grid of spacing `dis` is laid around the node; grid points are sorted
   by (distance to the previous path point) + (distance to the goal).
4. The first grid point whose straight motion from the previous point is free of
   interference is taken. Orientation is slerped from s to e by the plane's fraction.

Additions to the seed (documented in docs/assembly.md): the projections of the goal and
of the previous point onto the plane are candidates too (so a part can line up with a
hole), and a part seated in a hole at the start or goal is first withdrawn along a
free axis (see `common.retreat`), as the seed's straight splitting cannot leave a hole
sideways.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import interpolate, motion_samples
from workbench.assembly.planners.common import retreat, scene_bounds
from workbench.errors import InputError, PlanningError

_AXES = "xyz"


def plan_ant(
    checker: InterferenceChecker,
    start: NDArray[np.float64],
    goal: NDArray[np.float64],
    *,
    step: int = 20,
    dis: float | None = None,
    half_width: float | None = None,
    resolution: float | None = None,
    bounds: NDArray[np.float64] | None = None,
) -> tuple[NDArray[np.float64], int]:
    """Return (poses (K, 4, 4) from start to goal, candidates tried) by the single-ant greedy.

    step: number of segments (>= 1); dis: grid spacing on each plane [m] (default: the
    larger of 2 cell sizes and half_width / 25); half_width: grid half size [m] (default
    D/2 + the part's radius); resolution: motion check spacing [m] (default cell size).
    """
    if not isinstance(step, int | np.integer) or step < 1:
        raise InputError(f"step must be an integer >= 1, got {step!r}")
    res = checker.cell_size if resolution is None else float(resolution)
    head: list[NDArray] = [start]
    tail: list[NDArray] = [goal]
    a = retreat(checker, start, goal[:3, 3], res)
    if a is not None:
        head.append(a)
    b = retreat(checker, goal, head[-1][:3, 3], res)
    if b is not None:
        tail.insert(0, b)
    s, e = head[-1], tail[0]
    delta = e[:3, 3] - s[:3, 3]
    D = float(np.linalg.norm(delta))
    ax = int(np.argmax(np.abs(delta)))
    u_ax, v_ax = [i for i in range(3) if i != ax]
    hw = D / 2.0 + checker.radius if half_width is None else float(half_width)
    spacing = max(2.0 * checker.cell_size, hw / 25.0) if dis is None else float(dis)
    if not spacing > 0:
        raise InputError(f"dis must be a grid spacing > 0 m, got {dis!r}")
    B = scene_bounds(checker, start, goal) if bounds is None else np.asarray(bounds, float)
    n = int(np.floor(hw / spacing))
    g = np.arange(-n, n + 1) * spacing
    gu, gv = (x.ravel() for x in np.meshgrid(g, g, indexing="ij"))
    nodes = interpolate(s, e, np.arange(1, step) / step) if step > 1 else np.zeros((0, 4, 4))
    path = list(head)
    tried = 0
    # Fast path: when the straight line through the nodes is free, every plane's first
    # candidate (the node itself: it lies on the segment previous -> goal) is taken.
    straight = np.concatenate([nodes, e[None]])
    S = np.concatenate(
        [
            motion_samples(a_, b_, checker.radius, res)
            for a_, b_ in zip(np.concatenate([s[None], nodes]), straight, strict=True)
        ]
    )
    if checker.first_interference(S) < 0:
        nodes = nodes[:0]
        path.extend(straight[:-1])
        tried += len(straight)
    for i, node in enumerate(nodes):
        prev = path[-1]
        c = np.repeat(node[:3, 3][None], len(gu) + 2, axis=0)
        c[: len(gu), u_ax] += gu
        c[: len(gu), v_ax] += gv
        for j, q in enumerate((e[:3, 3], prev[:3, 3])):  # projections onto the plane
            c[len(gu) + j, [u_ax, v_ax]] = q[[u_ax, v_ax]]
        c = c[np.all((c >= B[0]) & (c <= B[1]), axis=1)]
        cost = np.linalg.norm(c - prev[:3, 3], axis=1) + np.linalg.norm(c - e[:3, 3], axis=1)
        order = np.argsort(cost, kind="stable")
        last_plane = i == len(nodes) - 1
        chosen = None
        for k in order:
            tried += 1
            T = node.copy()
            T[:3, 3] = c[k]
            if checker.first_interference(motion_samples(prev, T, checker.radius, res)) >= 0:
                continue
            if (
                last_plane
                and checker.first_interference(motion_samples(T, e, checker.radius, res)) >= 0
            ):
                continue
            chosen = T
            break
        if chosen is None:
            raise PlanningError(
                f"single-ant planner: no interference-free grid point on cutting plane "
                f"{i + 1} of {step - 1} ({_AXES[ax]} = {node[ax, 3]:.4f} m, {len(c)} points, "
                f"dis = {spacing:g} m); try a larger step, a smaller dis or planner='rrt_connect'"
            )
        path.append(chosen)
    if step == 1:
        tried += 1
        if checker.first_interference(motion_samples(s, e, checker.radius, res)) >= 0:
            raise PlanningError(
                "single-ant planner: the straight move with step=1 interferes; use step > 1"
            )
    for T in tail:
        if (
            T is tail[0]
            or checker.first_interference(motion_samples(path[-1], T, checker.radius, res)) < 0
        ):
            path.append(T)
        else:
            raise PlanningError(
                "single-ant planner: the final insertion move into the goal interferes"
            )
    return np.asarray(path), tried
