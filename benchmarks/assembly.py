"""Assembly planning benchmark: single-ant vs our RRT-Connect vs OMPL's RRT-Connect (same checker).

Run: python benchmarks/assembly.py [--no-ompl] [--example-only]
Prints, on generated scenes of growing clutter, success rate, median planning time and
median path length per planner; the example scene's per-part times; and the
interference-check time of the cell stage against python-fcl on the same pairs.
"""

from __future__ import annotations

import time

import fcl
import numpy as np
import trimesh

from workbench.assembly import InterferenceChecker, plan_part_path
from workbench.assembly.example_scene import example_scene, plate_mesh, screw_mesh
from workbench.assembly.motion import pose_distance
from workbench.assembly.planners.common import retreat, scene_bounds
from workbench.errors import PlanningError
from workbench.geometry.transforms import (
    make_transform,
    matrix_to_wxyz,
    rpy_to_matrix,
    wxyz_to_matrix,
)

try:
    from ompl import base as ob
    from ompl import geometric as og
    from ompl import util as ou

    ou.setLogLevel(ou.LogLevel.LOG_WARN)
    ou.RNG.setSeed(1)  # once: OMPL refuses a new seed after sampling started

    HAVE_OMPL = True
except Exception as exc:  # pragma: no cover
    HAVE_OMPL = False
    OMPL_WHY = repr(exc)


def ompl_rrt_connect(ch: InterferenceChecker, start, goal, max_time=10.0, seed=0):
    """Return (poses, seconds) from OMPL's RRT-Connect + simplifier with our checker, or (None, s)."""
    res = ch.cell_size
    t0 = time.perf_counter()
    a = retreat(ch, start, goal[:3, 3], res)
    b = retreat(ch, goal, (start if a is None else a)[:3, 3], res)
    s_T = start if a is None else a
    g_T = goal if b is None else b
    B = scene_bounds(ch, start, goal)
    space = ob.SE3StateSpace()
    bounds = ob.RealVectorBounds(3)
    for i in range(3):
        bounds.setLow(i, float(B[0, i]))
        bounds.setHigh(i, float(B[1, i]))
    space.setBounds(bounds)
    ss = og.SimpleSetup(space)

    def to_T(st):
        r = st.rotation()
        return make_transform(
            wxyz_to_matrix([r.w, r.x, r.y, r.z]), [st.getX(), st.getY(), st.getZ()]
        )

    # The same check our planners use for their motions (AABB, then exact).
    ss.setStateValidityChecker(lambda st: ch.first_interference(to_T(st)[None], cells=False) < 0)
    space.setLongestValidSegmentFraction(res / space.getMaximumExtent())

    def to_state(T):
        st = space.allocState()
        st.setXYZ(*map(float, T[:3, 3]))
        q = matrix_to_wxyz(T[:3, :3])
        r = st.rotation()
        r.w, r.x, r.y, r.z = map(float, q)
        return st

    ss.setStartAndGoalStates(to_state(s_T), to_state(g_T))
    planner = og.RRTConnect(ss.getSpaceInformation())
    planner.setRange(0.1 * float(np.linalg.norm(B[1] - B[0])))
    ss.setPlanner(planner)
    ok = ss.solve(max_time)
    if not ok or not ss.haveExactSolutionPath():
        return None, time.perf_counter() - t0
    ss.simplifySolution()
    path = ss.getSolutionPath()
    poses = (
        [start]
        + ([a] if a is not None else [])
        + [to_T(path.getState(i)) for i in range(path.getStateCount())]
    )
    poses += ([b] if b is not None else []) + [goal]
    return np.asarray(poses), time.perf_counter() - t0


def clutter_scene(n_obstacles: int, seed: int):
    """Return (part, obstacles, start, goal): a 5 cm cube crossing a 1 m box of random blocks."""
    rng = np.random.default_rng(seed)
    part = trimesh.creation.box([0.05, 0.05, 0.05])
    start = make_transform(np.eye(3), [-0.5, 0.0, 0.0])
    goal = make_transform(rpy_to_matrix([0.0, 0.0, np.pi / 2]), [0.5, 0.0, 0.0])
    obstacles = [trimesh.creation.box([0.6, 0.6, 0.02]).apply_translation([0, 0, -0.35])]
    while len(obstacles) < n_obstacles + 1:
        c = rng.uniform([-0.35, -0.25, -0.25], [0.35, 0.25, 0.25])
        obstacles.append(trimesh.creation.box(rng.uniform(0.04, 0.18, 3)).apply_translation(c))
    return part, obstacles, start, goal


def _length(P):
    return float(np.sum(pose_distance(P[:-1], P[1:], 0.0)))


def main() -> None:
    import argparse

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--no-ompl", action="store_true", help="skip OMPL (slow) while iterating")
    ap.add_argument("--example-only", action="store_true", help="only the example scene")
    ap.add_argument("--repeat", type=int, default=1, help="example scene runs (median over all)")
    args = ap.parse_args()
    use_ompl = HAVE_OMPL and not args.no_ompl
    planners = ["ant", "rrt_connect"] + (["ompl_rrt_connect"] if use_ompl else [])
    if not HAVE_OMPL:
        print(f"OMPL not importable: {OMPL_WHY}")
    if not args.example_only:
        _generated(planners, use_ompl)
    _example(planners, use_ompl, args.repeat)
    if not args.example_only:
        _cells_vs_fcl()


def _generated(planners: list[str], use_ompl: bool) -> None:
    print("== generated scenes: success / median time [ms] / median length [m] (8 seeds each)")
    print(f"{'obstacles':>9} " + " ".join(f"{p:>28}" for p in planners) + "   ours/ompl time")
    for n in (0, 4, 8, 16):
        row, med = [], {}
        for pl in planners:
            ok, ts, ls = 0, [], []
            for seed in range(8):
                part, obs, s, g = clutter_scene(n, seed)
                ch = InterferenceChecker(part, obs, 0.01)
                if ch.colliding_obstacles(s) or ch.colliding_obstacles(g):
                    continue
                t0 = time.perf_counter()
                try:
                    if pl == "ompl_rrt_connect":
                        P, _ = ompl_rrt_connect(ch, s, g, max_time=5.0, seed=seed)
                    else:
                        P = plan_part_path(
                            s,
                            g,
                            part,
                            obs,
                            pl,
                            checker=ch,
                            **({"seed": seed, "max_time": 5.0} if pl == "rrt_connect" else {}),
                        ).poses
                except PlanningError:
                    P = None
                ts.append(time.perf_counter() - t0)
                if P is not None:
                    ok += 1
                    ls.append(_length(P))
            med[pl] = float(np.median(ts)) * 1e3
            row.append(
                f"{ok}/{len(ts)} {med[pl]:8.1f} {np.median(ls) if ls else float('nan'):6.3f}"
            )
        ratio = med["rrt_connect"] / med["ompl_rrt_connect"] if use_ompl else float("nan")
        print(f"{n:>9} " + " ".join(f"{r:>28}" for r in row) + f"   {ratio:6.2f}")


def _example(planners: list[str], use_ompl: bool, repeat: int) -> None:
    print(
        "== example scene (seed 003 Fig. 11): planning time [ms] per part (checker built "
        f"beforehand; ours: median of {repeat} runs)"
    )
    sc = example_scene()
    times = {p: [] for p in planners}
    for i, part in enumerate(sc.parts):
        ch = InterferenceChecker(part.mesh, sc.obstacles_for(i))
        line = f"{part.name:>8}"
        for pl in planners:
            runs = []
            # OMPL takes seconds per part: it runs once; ours `repeat` times (median).
            for _ in range(1 if pl == "ompl_rrt_connect" else repeat):
                t0 = time.perf_counter()
                if pl == "ompl_rrt_connect":
                    P, _ = ompl_rrt_connect(ch, part.start, part.goal)
                else:
                    P = plan_part_path(part.start, part.goal, part.mesh, [], pl, checker=ch).poses
                runs.append((time.perf_counter() - t0) * 1e3)
            dt = float(np.median(runs))
            times[pl].append(dt)
            line += f"  {pl} {dt:7.1f} ({'ok' if P is not None else 'fail'})"
        print(line)
    print("median: " + ", ".join(f"{p} {np.median(v):.1f} ms" for p, v in times.items()))
    if use_ompl:
        print(
            f"ours/ompl median ratio: {np.median(times['rrt_connect']) / np.median(times['ompl_rrt_connect']):.2f}"
        )


def _cells_vs_fcl() -> None:
    sc = example_scene()
    print(
        "== interference check: cell stage vs python-fcl on the same pairs (screw near plate hole)"
    )
    plate_world = plate_mesh().apply_transform(sc.parts[1].goal)
    rng = np.random.default_rng(0)
    T = np.repeat(sc.parts[2].goal[None], 400, axis=0)
    T[:, :3, 3] += rng.normal(0, [0.003, 0.003, 0.006], (400, 3))
    T[:, :3, :3] = rpy_to_matrix(rng.normal(0, 0.05, (400, 3)))
    for c in (0.004, 0.002, 0.001):
        ch = InterferenceChecker(screw_mesh(), [plate_world], c, obstacle_cell_size=c)
        t0 = time.perf_counter()
        cells = ch.cell_stage_pair(T, 0)
        t_cells = (time.perf_counter() - t0) / len(T)
        t0 = time.perf_counter()
        exact = np.array([ch.exact_pair(t, 0) for t in T])
        t_ex = (time.perf_counter() - t0) / len(T)
        t0 = time.perf_counter()
        for t in T:
            ch.moving.fcl_obj.setTransform(fcl.Transform(t[:3, :3], t[:3, 3]))
            fcl.collide(
                ch.moving.fcl_obj,
                ch.obstacles[0].fcl_obj,
                fcl.CollisionRequest(),
                fcl.CollisionResult(),
            )
        t_fcl = (time.perf_counter() - t0) / len(T)
        missed = int(np.sum(exact & ~cells))
        fp = float(np.mean(cells[~exact])) if np.any(~exact) else float("nan")
        print(
            f"cell {c * 1e3:.0f} mm: cell stage {t_cells * 1e6:7.1f} us/pose (batched), "
            f"fcl collide {t_fcl * 1e6:6.1f} us/pose, exact (fcl+containment) {t_ex * 1e6:6.1f} us/pose, "
            f"cells/fcl {t_cells / t_fcl:5.2f}; missed {missed}, false-positive rate {fp:.2f}"
        )


if __name__ == "__main__":
    main()
