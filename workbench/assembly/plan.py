"""`plan_part_path`: a collision-free straight-segment path for one part among world obstacles."""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import pose_distance
from workbench.assembly.planners.ant import plan_ant
from workbench.assembly.planners.common import check_options
from workbench.assembly.planners.rrt_connect import plan_rrt_connect
from workbench.errors import CollisionError, InputError
from workbench.geometry import check_transform

PLANNERS = ("ant", "rrt_connect")


@dataclass(frozen=True)
class PartPath:
    """A part's path: poses (K, 4, 4) in the world [m], start first, goal last, and planning stats.

    Moving the part straight (lerp + slerp) between consecutive poses never interferes
    (checked every `resolution` [m] of point travel). time_s: planning time [s], without
    building the cells (setup_s); checks: poses checked; nodes: candidates (ant) or tree
    nodes (RRT-Connect); length: translation length of the path [m]; stats (ant): the
    planes whose grid was refined ("refined_planes") and the most halvings ("refine_levels").
    """

    poses: NDArray[np.float64]
    planner: str
    time_s: float
    setup_s: float
    checks: int
    exact_checks: int
    nodes: int
    length: float
    resolution: float
    cell_size: float
    stats: dict[str, int] = field(default_factory=dict)


def plan_part_path(
    start: ArrayLike,
    goal: ArrayLike,
    moving: trimesh.Trimesh,
    obstacles: Sequence[trimesh.Trimesh],
    planner: str = "ant",
    *,
    cell_size: float | None = None,
    checker: InterferenceChecker | None = None,
    **options: object,
) -> PartPath:
    """Return a PartPath taking `moving` (mesh in its frame) from pose `start` to `goal` (4, 4) [m].

    obstacles: meshes in the world frame. planner: "ant" (seed 003's single-ant greedy;
    options step, dis, half_width, bounds) or "rrt_connect" (options seed, max_time,
    max_nodes, range_, bounds, shortcut_iterations). cell_size [m]: side of the
    subdivision cells (default 1/20 of the part's largest extent), also the motion check
    spacing. Raises CollisionError if start or goal interferes (naming the obstacles),
    PlanningError if no path is found, InputError / MeshError on bad input.
    """
    if planner not in PLANNERS:
        raise InputError(f"planner must be one of {PLANNERS}, got {planner!r}")
    S = check_transform(start, "start")
    G = check_transform(goal, "goal")
    t0 = time.perf_counter()
    ch = InterferenceChecker(moving, obstacles, cell_size) if checker is None else checker
    setup = time.perf_counter() - t0
    for name, T in (("start", S), ("goal", G)):
        hit = ch.colliding_obstacles(T)
        if hit:
            raise CollisionError(
                f"{name} pose interferes with obstacles {hit} (indices into `obstacles`); "
                f"move the {name} pose clear of them"
            )
    before = (ch.stats.poses, ch.stats.exact_pairs)
    t1 = time.perf_counter()
    fn = plan_ant if planner == "ant" else plan_rrt_connect
    check_options(planner, fn, options)
    poses_nodes = fn(ch, S, G, **options)  # type: ignore[arg-type]
    poses, nodes = poses_nodes
    dt = time.perf_counter() - t1
    length = float(np.sum(pose_distance(poses[:-1], poses[1:], 0.0)))
    return PartPath(
        poses=poses,
        planner=planner,
        time_s=dt,
        setup_s=setup,
        checks=ch.stats.poses - before[0],
        exact_checks=ch.stats.exact_pairs - before[1],
        nodes=int(nodes),
        length=length,
        resolution=ch.cell_size,
        cell_size=ch.cell_size,
        stats={
            k: int(getattr(poses_nodes, k))
            for k in ("refined_planes", "refine_levels")
            if hasattr(poses_nodes, k)
        },
    )
