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

Speed without changing the result: a plane's candidates are decided in vectorised
batches (their motions share one rotation, so they are sampled together and the AABB
stage clears them in one call), taking the first free one in cost order as the seed's
one-by-one loop would; motions are checked AABB -> exact (`cells=False`).
"""

from __future__ import annotations

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
    start and goal must be free of interference (`plan_part_path` checks them first).
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
    # The segments' samples are the whole line's at the same fractions (lerp and slerp
    # restricted to a sub-interval are the same motion), so one call makes them all.
    n_seg = max(1, int(np.ceil(float(pose_distance(s, e, checker.radius)) / (step * res))))
    u = (np.arange(step)[:, None] + np.arange(1, n_seg + 1)[None] / n_seg).ravel() / step
    if checker.first_interference(interpolate(s, e, u), cells=False) < 0:
        path.extend(nodes)
        nodes = nodes[:0]
        tried += step
    elif step == 1:
        raise PlanningError(
            "single-ant planner: the straight move with step=1 interferes; use step > 1"
        )
    for i, node in enumerate(nodes):
        prev = path[-1]
        c = np.repeat(node[:3, 3][None], len(gu) + 2, axis=0)
        c[: len(gu), u_ax] += gu
        c[: len(gu), v_ax] += gv
        for j, q in enumerate((e[:3, 3], prev[:3, 3])):  # projections onto the plane
            c[len(gu) + j, [u_ax, v_ax]] = q[[u_ax, v_ax]]
        c = c[np.all((c >= B[0]) & (c <= B[1]), axis=1)]
        cost = np.linalg.norm(c - prev[:3, 3], axis=1) + np.linalg.norm(c - e[:3, 3], axis=1)
        c = c[np.argsort(cost, kind="stable")]
        k, n_tried = _first_free(
            checker, prev, node[:3, :3], c, e if i == len(nodes) - 1 else None, res
        )
        tried += n_tried
        if k < 0:
            raise PlanningError(
                f"single-ant planner: no interference-free grid point on cutting plane "
                f"{i + 1} of {step - 1} ({_AXES[ax]} = {node[ax, 3]:.4f} m, {len(c)} points, "
                f"dis = {spacing:g} m); try a larger step, a smaller dis or planner='rrt_connect'"
            )
        T = node.copy()
        T[:3, 3] = c[k]
        path.append(T)
    # The moves start -> a and b -> goal are the retreats, which `retreat` checked sample
    # by sample (b -> goal as goal -> b: the same samples, with the goal itself checked
    # by plan_part_path instead of b).
    path.extend(tail)
    return np.asarray(path), tried


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
