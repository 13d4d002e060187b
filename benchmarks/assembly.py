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
from workbench.assembly.planners.common import motion_free, retreat, scene_bounds
from workbench.assembly.planners.rrt_connect import check_path, plan_rrt_connect, shortcut
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
    """Return (poses, seconds, straight) from OMPL's RRT-Connect with our planner's pieces.

    The same as `plan_rrt_connect` around the tree: the same retreat at seated ends, the same
    straight-move check first (`straight` True when that answered), the same motion
    validator (`motion_free`: every sample of a motion in one batched check, OMPL's
    ``MotionValidator`` subclassed as its docs describe for a custom motion check,
    ompl.kavrakilab.org/classompl_1_1base_1_1MotionValidator.html), the same position
    bounds and extension range (1/10 of the bounds' diagonal) and the same shortcutting of
    the raw solution (`shortcut`, 50 iterations, same seed). OMPL's ``simplifySolution()``
    is not used: with a Python state checker it calls back per state (85-93 % of a solve).
    """
    res = ch.cell_size
    t0 = time.perf_counter()
    a = retreat(ch, start, goal[:3, 3], res)
    b = retreat(ch, goal, (start if a is None else a)[:3, 3], res)
    head = [start] if a is None else [start, a]
    tail = [goal] if b is None else [b, goal]
    s_T, g_T = head[-1], tail[0]
    if motion_free(ch, s_T, g_T, res):
        return np.asarray(head + tail), time.perf_counter() - t0, True
    B = scene_bounds(ch, start, goal)
    space = ob.SE3StateSpace()
    bounds = ob.RealVectorBounds(3)
    for i in range(3):
        bounds.setLow(i, float(B[0, i]))
        bounds.setHigh(i, float(B[1, i]))
    space.setBounds(bounds)
    ss = og.SimpleSetup(space)
    si = ss.getSpaceInformation()

    def to_T(st):
        r = st.rotation()
        return make_transform(
            wxyz_to_matrix([r.w, r.x, r.y, r.z]), [st.getX(), st.getY(), st.getZ()]
        )

    class BatchedMotion(ob.MotionValidator):
        def checkMotion(self, s1, s2):  # noqa: N802 - OMPL's name
            return motion_free(ch, to_T(s1), to_T(s2), res)

    validator = BatchedMotion(si)
    si.setMotionValidator(validator)
    ss.setStateValidityChecker(lambda st: ch.first_interference(to_T(st)[None], cells=False) < 0)

    def to_state(T):
        st = space.allocState()
        st.setXYZ(*map(float, T[:3, 3]))
        q = matrix_to_wxyz(T[:3, :3])
        r = st.rotation()
        r.w, r.x, r.y, r.z = map(float, q)
        return st

    ss.setStartAndGoalStates(to_state(s_T), to_state(g_T))
    planner = og.RRTConnect(si)
    planner.setRange(0.1 * float(np.linalg.norm(B[1] - B[0])))
    ss.setPlanner(planner)
    ok = ss.solve(max_time)
    if not ok or not ss.haveExactSolutionPath():
        return None, time.perf_counter() - t0, False
    path = ss.getSolutionPath()
    raw = [to_T(path.getState(i)) for i in range(path.getStateCount())]
    raw = shortcut(raw, ch, res, np.random.default_rng(seed), 50)
    poses = head[:-1] + raw + tail[1:]
    return np.asarray(poses), time.perf_counter() - t0, False


def ours_rrt_connect(ch: InterferenceChecker, start, goal, max_time=10.0, seed=0):
    """Return (poses or None, seconds, straight) from our RRT-Connect, as `ompl_rrt_connect`."""
    t0 = time.perf_counter()
    try:
        P, nodes = plan_rrt_connect(ch, start, goal, seed=seed, max_time=max_time)
    except PlanningError:
        return None, time.perf_counter() - t0, False
    return P, time.perf_counter() - t0, nodes == 2


def window_scene(factor: float, seed: int):
    """Return (part, obstacles, start, goal): a 5 cm cube through a square window in a wall.

    The window's side is `factor` x the cube's edge, at a random place in a 1 m x 1 m wall
    (2 cm thick, at x = 0); start and goal 0.3 m either side, offset from the window so the
    straight move hits the wall; random orientations at both ends.
    """
    rng = np.random.default_rng(seed)
    edge = 0.05
    w = factor * edge
    yc, zc = rng.uniform(-0.25, 0.25, 2)
    part = trimesh.creation.box([edge] * 3)
    wall = []
    for lo, hi in (((-0.5, -0.5), (yc - w / 2, 0.5)), ((yc + w / 2, -0.5), (0.5, 0.5))):
        wall.append(_slab(lo, hi))
    wall.append(_slab((yc - w / 2, -0.5), (yc + w / 2, zc - w / 2)))
    wall.append(_slab((yc - w / 2, zc + w / 2), (yc + w / 2, 0.5)))
    off = rng.uniform(0.15, 0.3, 2) * rng.choice([-1, 1], 2)
    rpy = rng.uniform(-np.pi, np.pi, (2, 3))
    start = make_transform(rpy_to_matrix(rpy[0]), [-0.3, yc + off[0], zc + off[1]])
    off2 = np.abs(rng.uniform(0.15, 0.3, 2)) * np.sign(off)  # same side: the line hits the wall
    goal = make_transform(rpy_to_matrix(rpy[1]), [0.3, yc + off2[0], zc + off2[1]])
    return part, wall, start, goal


def _slab(lo, hi) -> trimesh.Trimesh:
    """A wall piece at x = 0 (2 cm thick) over y in [lo0, hi0], z in [lo1, hi1] [m]."""
    size = [0.02, hi[0] - lo[0], hi[1] - lo[1]]
    centre = [0.0, (hi[0] + lo[0]) / 2, (hi[1] + lo[1]) / 2]
    return trimesh.creation.box(size).apply_translation(centre)


def _rrt_vs_ompl(scenes: str, make, params, seeds: int, max_time: float) -> None:
    """Print ours vs OMPL's RRT-Connect on scenes make(param, seed), same checker per scene."""
    print(
        f"== {scenes}: RRT-Connect, ours vs OMPL's (same retreat, straight-move check, batched"
        f" motion validator, shortcutting); {seeds} seeds, max {max_time:g} s"
    )
    print(
        f"{'scene':>12} {'planner':>6}  solved  straight  time median [ms] (min-max)   length median [m]"
    )
    for param in params:
        res = {"ours": [], "ompl": []}
        for seed in range(seeds):
            part, obs, s, g = make(param, seed)
            ch = InterferenceChecker(part, obs, 0.01)
            if ch.colliding_obstacles(s) or ch.colliding_obstacles(g):
                continue
            for name, fn in (("ours", ours_rrt_connect), ("ompl", ompl_rrt_connect)):
                P, dt, straight = fn(ch, s, g, max_time=max_time, seed=seed)
                if P is not None:
                    assert check_path(ch, P, ch.cell_size) < 0, f"{name}: path interferes"
                res[name].append(
                    (P is not None, dt, straight, _length(P) if P is not None else np.nan)
                )
        med = {}
        for name, rows in res.items():
            ok = [r for r in rows if r[0]]
            ts = np.array([r[1] for r in rows]) * 1e3
            ls = np.array([r[3] for r in ok])
            med[name] = (float(np.median(ts)), float(np.median(ls)) if len(ls) else np.nan)
            print(
                f"{param:>12} {name:>6}  {len(ok):>2}/{len(rows):<2}   {sum(r[2] for r in rows):>2}"
                f"        {med[name][0]:8.1f} ({ts.min():7.1f}-{ts.max():7.1f})        {med[name][1]:6.3f}"
            )
        print(
            f"{'':>12} ours/ompl: time {med['ours'][0] / med['ompl'][0]:.2f}, length"
            f" {med['ours'][1] / med['ompl'][1]:.2f}"
        )


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
    ap.add_argument("--repeat", type=int, default=5, help="example scene runs (median over all)")
    ap.add_argument("--seeds", type=int, default=8, help="seeds per generated scene")
    ap.add_argument("--windows-only", action="store_true", help="only RRT-Connect vs OMPL, windows")
    args = ap.parse_args()
    if args.windows_only:
        _rrt_vs_ompl(
            "window scenes (window side / cube edge)",
            window_scene,
            (3.0, 2.0, 1.5),
            args.seeds,
            10.0,
        )
        return
    use_ompl = HAVE_OMPL and not args.no_ompl
    if not HAVE_OMPL:
        print(f"OMPL not importable: {OMPL_WHY}")
    if not args.example_only:
        _generated(["ant", "rrt_connect"], args.seeds)
        if use_ompl:
            _rrt_vs_ompl("clutter scenes (obstacles)", clutter_scene, (4, 16), args.seeds, 5.0)
            _rrt_vs_ompl(
                "window scenes (window side / cube edge)",
                window_scene,
                (3.0, 2.0, 1.5),
                args.seeds,
                10.0,
            )
    if not args.example_only:
        _narrow_passages(args.seeds)
    _example(use_ompl, args.repeat)
    _ant_cold_warm()
    if not args.example_only:
        _cells_vs_fcl()


def _narrow_passages(seeds: int) -> None:
    """Ant and RRT-Connect through a window that fills the bounds (no way round the wall).

    The scene of tests/assembly/planners/test_ant.py: a 5 cm box, fixed orientation, the
    window's centre and the end offsets varied by seed; the planners check every 1 mm.
    """
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "assembly" / "planners"))
    from test_ant import BOUNDS, EDGE, RES, window_scene  # noqa: PLC0415

    print(
        "== narrow passages (window side / box edge, wall fills the bounds): solved, median"
        f" time [ms], median length [m], planes refined (ant); {seeds} seeds"
    )
    for factor in (3.0, 2.6, 1.5, 1.08, 0.9):
        line = f"{factor:>6.2f}"
        for pl in ("ant", "rrt_connect"):
            ok, ts, ls, refined = 0, [], [], 0
            for seed in range(seeds):
                yc, zc = np.random.default_rng(seed).uniform(-0.1, 0.1, 2)
                part, wall, s, g = window_scene(factor * EDGE, yc, zc)
                ch = InterferenceChecker(part, wall, 0.005)
                opts = {"seed": seed, "max_time": 10.0} if pl == "rrt_connect" else {}
                t0 = time.perf_counter()
                try:
                    r = plan_part_path(
                        s, g, part, wall, pl, checker=ch, bounds=BOUNDS, resolution=RES, **opts
                    )
                    ok += 1
                    ls.append(r.length)
                    refined += r.stats.get("refined_planes", 0) > 0
                except PlanningError:
                    pass
                ts.append(time.perf_counter() - t0)
            med_l = f"{np.median(ls):6.3f}" if ls else "     -"
            extra = f" refined {refined}" if pl == "ant" else ""
            line += f"  {pl} {ok}/{seeds} {1e3 * np.median(ts):8.1f} {med_l}{extra}"
        print(line)


def _generated(planners: list[str], seeds: int) -> None:
    print(f"== clutter scenes: success / median time [ms] / median length [m] ({seeds} seeds each)")
    print(f"{'obstacles':>9} " + " ".join(f"{p:>28}" for p in planners))
    for n in (0, 4, 8, 16):
        row = []
        for pl in planners:
            ok, ts, ls = 0, [], []
            for seed in range(seeds):
                part, obs, s, g = clutter_scene(n, seed)
                ch = InterferenceChecker(part, obs, 0.01)
                if ch.colliding_obstacles(s) or ch.colliding_obstacles(g):
                    continue
                t0 = time.perf_counter()
                try:
                    opts = {"seed": seed, "max_time": 5.0} if pl == "rrt_connect" else {}
                    P = plan_part_path(s, g, part, obs, pl, checker=ch, **opts).poses
                except PlanningError:
                    P = None
                ts.append(time.perf_counter() - t0)
                if P is not None:
                    ok += 1
                    ls.append(_length(P))
            med = float(np.median(ts)) * 1e3
            row.append(f"{ok}/{len(ts)} {med:8.1f} {np.median(ls) if ls else float('nan'):6.3f}")
        print(f"{n:>9} " + " ".join(f"{r:>28}" for r in row))


def _example(use_ompl: bool, repeat: int) -> None:
    print(
        "== example scene (seed 003 Fig. 11): planning time [ms] per part, checker built "
        f"beforehand; median of {repeat} runs; (s) = the straight move answered"
    )
    sc = example_scene()
    times: dict[str, list[float]] = {"ant": [], "rrt_connect": []}
    if use_ompl:
        times["ompl_rrt_connect"] = []
    straight = dict.fromkeys(times, 0)
    for i, part in enumerate(sc.parts):
        ch = InterferenceChecker(part.mesh, sc.obstacles_for(i))
        line = f"{part.name:>8}"
        for pl in times:
            runs, st = [], False
            for _ in range(repeat):
                if pl == "ant":
                    t0 = time.perf_counter()
                    P = plan_part_path(
                        part.start, part.goal, part.mesh, [], "ant", checker=ch
                    ).poses
                    dt = time.perf_counter() - t0
                else:
                    fn = ompl_rrt_connect if pl == "ompl_rrt_connect" else ours_rrt_connect
                    P, dt, st = fn(ch, part.start, part.goal)
                runs.append(dt * 1e3)
            times[pl].append(float(np.median(runs)))
            straight[pl] += st
            line += f"  {pl} {times[pl][-1]:7.1f}{' (s)' if st else '    '}"
        print(line)
    print("median: " + ", ".join(f"{p} {np.median(v):.1f} ms" for p, v in times.items()))
    print(
        "straight-move answers: "
        + ", ".join(f"{p} {n}/{len(sc.parts)}" for p, n in straight.items() if p != "ant")
        + " (the example scene needs no tree: its RRT figures compare the straight-move check)"
    )


def _ant_cold_warm() -> None:
    """The ant planner on the example scene with its checker build: fresh process, then warm."""
    import json
    import os
    import subprocess
    import sys
    import tempfile

    code = (
        "import json, time\n"
        "t0 = time.perf_counter()\n"
        "from workbench.assembly import InterferenceChecker, plan_part_path\n"
        "from workbench.assembly.example_scene import example_scene\n"
        "t_import = time.perf_counter() - t0\n"
        "out = {'import': t_import, 'runs': []}\n"
        "for _ in range(2):\n"
        "    sc = example_scene()\n"
        "    build = plan = 0.0\n"
        "    for i, part in enumerate(sc.parts):\n"
        "        t = time.perf_counter()\n"
        "        ch = InterferenceChecker(part.mesh, sc.obstacles_for(i))\n"
        "        build += time.perf_counter() - t\n"
        "        t = time.perf_counter()\n"
        "        plan_part_path(part.start, part.goal, part.mesh, [], 'ant', checker=ch)\n"
        "        plan += time.perf_counter() - t\n"
        "    out['runs'].append((build, plan, len(sc.parts)))\n"
        "print(json.dumps(out))\n"
    )
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, WORKBENCH_CACHE=cache)
        res = subprocess.run(
            [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
        )
    out = json.loads(res.stdout.strip().splitlines()[-1])
    (cb, cp, n), (wb_, wp, _) = out["runs"]
    print(
        f"== ant planner on the example scene ({n} parts), checker build included: fresh process,"
        f" empty cache (WORKBENCH_CACHE a new folder), import {out['import']:.2f} s"
    )
    print(
        f"  cold: checker builds {cb * 1e3:7.1f} ms + plans {cp * 1e3:6.1f} ms = {(cb + cp) * 1e3:7.1f} ms"
        f" ({(cb + cp) / n * 1e3:6.1f} ms per part)"
    )
    print(
        f"  warm (same process, again): builds {wb_ * 1e3:7.1f} ms + plans {wp * 1e3:6.1f} ms ="
        f" {(wb_ + wp) * 1e3:7.1f} ms ({(wb_ + wp) / n * 1e3:6.1f} ms per part)"
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
