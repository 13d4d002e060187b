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

Narrow passages: a cutting plane with no free grid point has its grid refined (spacing
halved, the points already tried left out) down to `min_dis` (default: the larger of
dis / 2**`REFINE_HALVINGS` and half a cell) before the planner gives up; the result says on
how many planes and how far (`AntPath.refined_planes`, `AntPath.refine_levels`), and the
error names the plane and the finest spacing tried.

Speed without changing the result: a plane's candidates are decided in vectorised
batches (their motions share one rotation, so they are sampled together and the AABB
stage clears them in one call), taking the first free one in cost order as the seed's
one-by-one loop would; motions are checked AABB -> exact (`cells=False`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import (
    interpolate,
    pose_distance,
    rotation_angle,
    slerp,
    unit_quaternion,
)
from workbench.assembly.planners.common import retreat, scene_bounds
from workbench.errors import InputError, PlanningError
from workbench.geometry.transforms import make_transform, wxyz_to_matrix

_AXES = "xyz"
MAX_PLANE_POINTS = 250_000
"""Most grid points on one cutting plane ((2 half width / dis + 1)²), refused before the search."""
MAX_LINE_SAMPLES = 2_000_000
"""Most poses of the straight move's check (its length / resolution), refused before it."""
REFINE_HALVINGS = 3
"""How many times a cutting plane's grid spacing may be halved when the plane has no free
point (the default `min_dis` is dis / 2**REFINE_HALVINGS, at least half a cell)."""


class AntPath(tuple):
    """(poses (K, 4, 4), candidates tried), as `plan_ant` returns, with what refinement did:
    refined_planes: planes whose grid was refined; refine_levels: most halvings on one."""

    refined_planes: int = 0
    refine_levels: int = 0


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
    min_dis: float | None = None,
) -> AntPath:
    """Return (poses (K, 4, 4) from start to goal, candidates tried) by the single-ant greedy.

    step: number of segments (>= 1); dis: grid spacing on each plane [m] (default: the
    larger of 2 cell sizes and half_width / 25); half_width: grid half size [m] (default
    D/2 + the part's radius); resolution: motion check spacing [m] (default cell size);
    min_dis: the finest spacing a plane without a free point is refined to [m] (default
    the larger of dis / 2**REFINE_HALVINGS and half a cell; min_dis >= dis: no refinement).
    start and goal must be free of interference (`plan_part_path` checks them first).
    """
    if not isinstance(step, int | np.integer) or step < 1:
        raise InputError(f"step must be an integer >= 1, got {step!r}")
    res = checker.cell_size if resolution is None else float(resolution)
    head, tail = _retreats(checker, start, goal, res)
    s, e = head[-1], tail[0]
    grid = _grid(checker, s, e, dis, half_width, min_dis, res, step)
    B = scene_bounds(checker, start, goal) if bounds is None else np.asarray(bounds, float)
    nodes = interpolate(s, e, np.arange(1, step) / step) if step > 1 else np.zeros((0, 4, 4))
    path = list(head)
    tried = 0
    # Fast path: when the straight line through the nodes is free, every plane's first
    # candidate (the node itself: it lies on the segment previous -> goal) is taken.
    if _straight_line_free(checker, s, e, step, res):
        path.extend(nodes)
        nodes = nodes[:0]
        tried += step
    elif step == 1:
        raise PlanningError(
            "single-ant planner: the straight move with step=1 interferes; use step > 1"
        )
    refined_planes = refine_levels = 0
    for i, node in enumerate(nodes):
        point, level, n_tried = _plane_point(checker, grid, B, path, len(head), i, node, e)
        tried += n_tried
        if level:
            refined_planes += 1
            refine_levels = max(refine_levels, level)
        T = node.copy()
        T[:3, 3] = point
        path.append(T)
    # The moves start -> a and b -> goal are the retreats, which `retreat` checked sample
    # by sample (b -> goal as goal -> b: the same samples, with the goal itself checked
    # by plan_part_path instead of b).
    path.extend(tail)
    out = AntPath((np.asarray(path), tried))
    out.refined_planes, out.refine_levels = refined_planes, refine_levels
    return out


def _retreats(
    checker: InterferenceChecker, start: NDArray, goal: NDArray, res: float
) -> tuple[list[NDArray], list[NDArray]]:
    """Return the path's head [start, (withdrawn from start)] and tail [(withdrawn from the
    goal), goal]: a part seated in a hole first leaves it along a free axis (`retreat`)."""
    head: list[NDArray] = [start]
    tail: list[NDArray] = [goal]
    a = retreat(checker, start, goal[:3, 3], res)
    if a is not None:
        head.append(a)
    b = retreat(checker, goal, head[-1][:3, 3], res)
    if b is not None:
        tail.insert(0, b)
    return head, tail


@dataclass(frozen=True)
class _Grid:
    """The cutting planes' grids: normal axis `ax` (the dominant axis of e - s), in-plane axes
    u_ax, v_ax, half width `hw`, spacing and the finest refined spacing [m], the motion
    check spacing `res` [m] and the number of segments `step`."""

    ax: int
    u_ax: int
    v_ax: int
    hw: float
    spacing: float
    finest: float
    res: float
    step: int


def _grid(
    checker: InterferenceChecker,
    s: NDArray,
    e: NDArray,
    dis: float | None,
    half_width: float | None,
    min_dis: float | None,
    res: float,
    step: int,
) -> _Grid:
    """Return the `_Grid` of the planes between s and e (defaults as `plan_ant` says);
    InputError for a spacing <= 0 or a plane of more than MAX_PLANE_POINTS points."""
    delta = e[:3, 3] - s[:3, 3]
    D = float(np.linalg.norm(delta))
    ax = int(np.argmax(np.abs(delta)))
    u_ax, v_ax = [i for i in range(3) if i != ax]
    hw = D / 2.0 + checker.radius if half_width is None else float(half_width)
    spacing = max(2.0 * checker.cell_size, hw / 25.0) if dis is None else float(dis)
    if not spacing > 0:
        raise InputError(f"dis must be a grid spacing > 0 m, got {dis!r}")
    finest = (
        max(spacing / 2**REFINE_HALVINGS, checker.cell_size / 2.0)
        if min_dis is None
        else float(min_dis)
    )
    if not finest > 0:
        raise InputError(f"min_dis must be a grid spacing > 0 m, got {min_dis!r}")
    n = int(np.floor(hw / spacing))
    if (2 * n + 1) ** 2 > MAX_PLANE_POINTS:
        raise InputError(
            f"dis = {spacing:g} m lays {(2 * n + 1) ** 2:.3g} grid points on each cutting plane "
            f"(half width {hw:g} m), above the budget of {MAX_PLANE_POINTS:,} "
            f"(workbench.assembly.planners.ant.MAX_PLANE_POINTS); use dis >= "
            f"{2 * hw / (MAX_PLANE_POINTS**0.5 - 1):.2g} m"
        )
    return _Grid(ax, u_ax, v_ax, hw, spacing, finest, res, step)


def _straight_line_free(
    checker: InterferenceChecker, s: NDArray, e: NDArray, step: int, res: float
) -> bool:
    """Return whether the straight move s -> e is free, sampled as the `step` segments' moves
    would be (lerp and slerp restricted to a sub-interval are the same motion, so one call
    makes them all); InputError above MAX_LINE_SAMPLES poses."""
    n_seg = max(1, int(np.ceil(float(pose_distance(s, e, checker.radius)) / (step * res))))
    if step * n_seg > MAX_LINE_SAMPLES:
        raise InputError(
            f"the straight move ({float(pose_distance(s, e, checker.radius)):.3g} m) checked every"
            f" {res:g} m takes {step * n_seg:.3g} poses, above the budget of {MAX_LINE_SAMPLES:,}"
            " (workbench.assembly.planners.ant.MAX_LINE_SAMPLES); move the start and goal closer"
            " or use a coarser cell_size"
        )
    u = (np.arange(step)[:, None] + np.arange(1, n_seg + 1)[None] / n_seg).ravel() / step
    return bool(checker.first_interference(interpolate(s, e, u), cells=False) < 0)


def _plane_point(
    checker: InterferenceChecker,
    grid: _Grid,
    B: NDArray,
    path: list[NDArray],
    n_head: int,
    i: int,
    node: NDArray,
    e: NDArray,
) -> tuple[NDArray, int, int]:
    """Return (the position (3,) taken on cutting plane i, its refinement level, candidates
    tried): the first free grid point from path[-1] within bounds B (2, 3) [m], the grid
    refined while none is free.

    May line up path[-1] (replaced in `path`) in front of the point; PlanningError naming
    the plane and the finest spacing tried when no point is free."""
    prev = path[-1]
    last = i == grid.step - 2
    level, dis_l, n_pts, tried = 0, grid.spacing, 0, 0
    while True:
        c = _plane_candidates(node, prev, e, grid.u_ax, grid.v_ax, grid.hw, dis_l, B, level > 0)
        n_pts += len(c)
        k, n_tried = _first_free(checker, prev, node[:3, :3], c, e if last else None, grid.res)
        tried += n_tried
        if k < 0 and i > 0 and len(path) > n_head:
            # Line up: move the previous plane's point in front of a free point of this
            # plane (same plane coordinates), so the part enters the passage straight.
            k, n_tried, lined = _line_up(
                checker, path[-2], prev, node, c, grid.ax, last, e, grid.res
            )
            tried += n_tried
            if k >= 0:
                path[-1] = lined
        nxt = dis_l / 2.0
        if (
            k >= 0
            or nxt < grid.finest * (1.0 - 1e-9)
            or (2 * int(np.floor(grid.hw / nxt)) + 1) ** 2 > MAX_PLANE_POINTS
        ):
            break
        level, dis_l = level + 1, nxt
    if k < 0:
        how = (
            f"refined down to dis = {dis_l:g} m (min_dis = {grid.finest:g} m)"
            if level
            else f"dis = {grid.spacing:g} m, not refined (min_dis = {grid.finest:g} m)"
        )
        raise PlanningError(
            f"single-ant planner: no interference-free grid point on cutting plane "
            f"{i + 1} of {grid.step - 1} ({_AXES[grid.ax]} = {node[grid.ax, 3]:.4f} m, "
            f"{n_pts} points, {how}); the passage there is narrower than the part can take on "
            "this greedy path: try a larger step, a smaller min_dis or planner='rrt_connect'"
        )
    return c[k], level, tried


def _line_up(
    checker: InterferenceChecker,
    before: NDArray,
    prev: NDArray,
    node: NDArray,
    c: NDArray,
    ax: int,
    last: bool,
    goal: NDArray,
    res: float,
) -> tuple[int, int, NDArray]:
    """Return (k, candidates tried, the previous plane's new pose) for the first c[k] that the
    part reaches as before -> (prev's plane, lined up with c[k]) -> c[k] (-> goal if `last`),
    every motion free; k = -1 if none."""
    r = checker.radius
    b0, size = 0, 4
    while b0 < len(c):
        cb = c[b0 : b0 + size]
        lined = cb.copy()
        lined[:, ax] = prev[ax, 3]
        parts = [
            _fan(before[:3, :3], before[:3, 3], prev[:3, :3], lined, r, res),
            _fan(prev[:3, :3], lined, node[:3, :3], cb, r, res),
        ]
        if last:
            parts.append(_fan(node[:3, :3], cb, goal[:3, :3], goal[:3, 3], r, res))
        gid = np.concatenate([np.repeat(np.arange(len(cb)), n) for _, n in parts])
        S = np.concatenate([S for S, _ in parts])[np.argsort(gid, kind="stable")]
        g = checker.first_free_group(S, sum(n for _, n in parts), cells=False)
        if g >= 0:
            T = prev.copy()
            T[:3, 3] = lined[g]
            return b0 + g, b0 + g + 1, T
        b0 += len(cb)
        size *= 4
    return -1, len(c), prev


def _plane_candidates(
    node: NDArray,
    prev: NDArray,
    goal: NDArray,
    u_ax: int,
    v_ax: int,
    hw: float,
    dis: float,
    B: NDArray,
    refined: bool,
) -> NDArray:
    """Return a plane's candidate positions (M, 3) in cost order: the grid of spacing `dis`
    around `node` and the projections of the goal and of `prev`, within bounds B.

    `refined`: the grid of spacing 2 * dis was tried already; leave its points (both grid
    indices even) and the projections out."""
    n = int(np.floor(hw / dis))
    idx = np.arange(-n, n + 1)
    iu, iv = (x.ravel() for x in np.meshgrid(idx, idx, indexing="ij"))
    if refined:
        new = (iu % 2 != 0) | (iv % 2 != 0)
        iu, iv = iu[new], iv[new]
    c = np.repeat(node[:3, 3][None], len(iu) + (0 if refined else 2), axis=0)
    c[: len(iu), u_ax] += iu * dis
    c[: len(iu), v_ax] += iv * dis
    if not refined:
        for j, q in enumerate((goal[:3, 3], prev[:3, 3])):  # projections onto the plane
            c[len(iu) + j, [u_ax, v_ax]] = q[[u_ax, v_ax]]
    c = c[np.all((c >= B[0]) & (c <= B[1]), axis=1)]
    cost = np.linalg.norm(c - prev[:3, 3], axis=1) + np.linalg.norm(c - goal[:3, 3], axis=1)
    return c[np.argsort(cost, kind="stable")]


def _fan(
    R0: NDArray, P0: NDArray, R1: NDArray, P1: NDArray, radius: float, res: float
) -> tuple[NDArray, NDArray]:
    """Return (samples (M, 4, 4), per-motion counts (K,)) of straight motions (R0, P0[k]) -> (R1, P1[k]).

    The motions share their rotations, so one slerp serves all; each is sampled like
    `motion_samples` (start excluded, end included, points at most `res` [m] apart).
    """
    P0, P1 = np.broadcast_arrays(np.atleast_2d(P0), np.atleast_2d(P1))
    d = np.linalg.norm(P1 - P0, axis=1) + radius * float(rotation_angle(R0, R1))
    n = np.maximum(1, np.ceil(d / res).astype(np.int64))
    k = np.repeat(np.arange(len(n)), n)
    u = (np.arange(len(k)) - np.repeat(np.cumsum(n) - n, n) + 1) / n[k]
    R = wxyz_to_matrix(slerp(unit_quaternion(R0), unit_quaternion(R1), u))
    return make_transform(R, P0[k] + u[:, None] * (P1 - P0)[k]), n


def _first_free(
    checker: InterferenceChecker,
    prev: NDArray,
    R: NDArray,
    c: NDArray,
    goal: NDArray | None,
    res: float,
) -> tuple[int, int]:
    """Return (index of the first position c[k] whose pose (R, c[k]) prev reaches freely, or -1; candidates tried).

    With `goal`, the move on to it must be free too. Candidates go in batches of growing
    size (the first is often free), each batch's motions sampled and cleared by the AABB
    stage in one vectorised call.
    """
    r = checker.radius
    b0, size = 0, 4
    while b0 < len(c):
        cb = c[b0 : b0 + size]
        S, n = _fan(prev[:3, :3], prev[:3, 3], R, cb, r, res)
        if goal is not None:
            S2, n2 = _fan(R, cb, goal[:3, :3], goal[:3, 3], r, res)
            # Each candidate's group: its move in, then its move on to the goal.
            gid = np.concatenate(
                [np.repeat(np.arange(len(cb)), n), np.repeat(np.arange(len(cb)), n2)]
            )
            S = np.concatenate([S, S2])[np.argsort(gid, kind="stable")]
            n = n + n2
        g = checker.first_free_group(S, n, cells=False)
        if g >= 0:
            return b0 + g, b0 + g + 1
        b0 += len(cb)
        size *= 4
    return -1, len(c)
