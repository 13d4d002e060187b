"""Bending sweep: the cheap stage of the sequence search, serial against Ray, and its
part-against-press check against python-fcl.

On every example project whose `bending` section has a press (others are skipped, saying so):

1. Candidates per second of the cheap stage (`bend_eval.evaluate_batch`, one candidate = one
   (bends done, next bend) key), the same fixed list of keys through
   `run_batches(..., engine="serial" | "ray", batch_size=B)` inside `engine_session`, so Ray's
   start-up is timed on its own and not mixed into the rates. Results compared item by item
   between the engines (`grasp_ok`, `problem`, `grasp_reason`; q0/q1 bitwise reported).
   Per run: `BatchStats.overhead_per_batch_s` and that overhead as a share of one batch's
   compute time (the issue's bound: under 10 %).
2. Ray's start-up and its overhead per task on its own (a no-op over the same context).
3. The part-against-press check of the candidates (`press_check.check_states` on the folded
   states at `ctx.fractions`, placed by `bend_setup.bend_pose`, among `PressObstacles.at(...)`
   and the cell, exactly the calls `bend_eval._side` makes) against python-fcl asked the same
   question on the same states and obstacles: flange boxes against the non-tool obstacles,
   the folded part's exact solid against the tools. fcl objects built outside the timed loop,
   moved with `setTransform(fcl.Transform(R, t))`, fcl's DynamicAABBTreeCollisionManager, a
   first-hit callback. Verdicts asserted equal per state.

Run: PYTHONPATH=$PWD python benchmarks/bending_sweep.py
     [--items 8] [--batch-sizes 1,2,4,8] [--repeat 30] [--projects a.json,b.json]
"""

# ruff: noqa: E402  (the BLAS thread setting below must come before numpy is imported)
from __future__ import annotations

import os

# One BLAS thread in this process, as Ray gives its workers (OMP_NUM_THREADS=1): otherwise the
# serial baseline's numpy runs OpenBLAS threads whose busy-wait fights the machine's other
# load (measured: the four keys 9.2-11.5 s serial with the default, 6.5-7.7 s with one thread)
# and the serial/Ray ratio would mix that in. Set before numpy is imported.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse
import itertools
import math
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import fcl
import numpy as np
import trimesh

from workbench import Workbench, WorkbenchError
from workbench.batch import BatchRun, engine_session, run_batches
from workbench.collision.shapes import bvh_model
from workbench.geometry.transforms import make_transform
from workbench.pressbrake import bend_eval
from workbench.pressbrake.bend_eval import BendEval, SweepContext, evaluate_batch
from workbench.pressbrake.bend_setup import (
    bend_pose,
    contact_zone,
    gauge_stop,
    merge_obstacles,
    part_points,
)
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.obstacles import Obstacles
from workbench.pressbrake.press_check import check_states, is_tool
from workbench.service.bending_process import sweep_context
from workbench.sheetmetal.folding import FoldedState, fold_state

ROOT = Path(__file__).resolve().parents[1]
PROJECTS = ("projects/u_channel_cell.json", "projects/bending_cell.json")

Key = tuple[tuple[int, ...], int]


def load() -> str:
    return " ".join(Path("/proc/loadavg").read_text().split()[:3])


# ---------------------------------------------------------------------------------------------
# 1 + 2: the cheap stage through the batch runner, serial and Ray


def all_keys(n_bends: int) -> list[Key]:
    """Every (bends done, next bend) key of a part, in the search's order: fewer bends done
    first, done sets in lexicographic order, next bend ascending (`sequencing._search` keys
    a candidate by the sorted bends done)."""
    return [
        (done, b)
        for r in range(n_bends)
        for done in itertools.combinations(range(n_bends), r)
        for b in range(n_bends)
        if b not in done
    ]


def _noop_batch(ctx: SweepContext, keys: list[Key]) -> list[int]:
    """A batch that does nothing with the same context: Ray's bare per-task overhead."""
    return [0] * len(keys)


def same_results(a: list[BendEval | None], b: list[BendEval | None]) -> tuple[bool, bool]:
    """Return (grasp_ok, problem and grasp_reason equal per item; q0/q1 bitwise equal)."""
    verdicts = joints = True
    for x, y in zip(a, b, strict=True):
        assert x is not None and y is not None, "an item was not evaluated"
        verdicts &= (
            x.done == y.done
            and x.bend == y.bend
            and x.problem == y.problem
            and np.array_equal(x.grasp_ok, y.grasp_ok)
            and x.grasp_reason == y.grasp_reason
        )
        joints &= np.array_equal(x.q0, y.q0, equal_nan=True) and np.array_equal(
            x.q1, y.q1, equal_nan=True
        )
    return verdicts, joints


def _row(label: str, run: BatchRun[Any], serial_rate: float | None) -> str:
    s = run.stats
    rate = s.items / s.wall_s
    per_batch = s.compute_s / s.batches
    share = 100.0 * s.overhead_per_batch_s / per_batch if per_batch > 0 else math.inf
    speed = f"{rate / serial_rate:6.2f}x" if serial_rate else f"{'-':>7s}"
    ok = "yes" if share < 10.0 else "NO"
    return (
        f"  {label:7s} {s.workers:2d} {s.batches:4d} {s.wall_s:8.2f} {rate:8.3f} {speed}"
        f" {s.compute_s:9.2f} {per_batch:9.3f} {s.overhead_per_batch_s * 1e3:11.1f}"
        f" {share:7.2f} %  {ok}"
    )


def sweep(ctx: SweepContext, keys: list[Key], n_items: int, sizes: list[int]) -> None:
    """Print candidates per second, serial vs Ray, per batch size, and Ray's overheads."""
    items = (keys * math.ceil(n_items / len(keys)))[:n_items]
    print(
        f"cheap stage: {len(keys)} distinct (done, next) keys, {len(ctx.grasps)} grasps each; "
        f"{len(items)} items = the keys in order, repeated"
    )

    # warm this process's context caches (part, press and cell obstacles, the robot's view of
    # the press), as the Ray warm-up below warms the workers'
    ctx.part(), ctx.press_obstacles(), ctx.cell_obstacles(), ctx.robot_press()
    head = (
        f"  {'engine':7s} {'w':>2s} {'bat':>4s} {'wall s':>8s} {'cand/s':>8s} {'vs ser':>7s}"
        f" {'compute s':>9s} {'s/batch':>9s} {'ovh ms/bat':>11s} {'ovh/batch':>9s}  <10%"
    )
    # serial, one candidate per batch: the reference results, and each key's time (from the
    # progress calls). Its batch size changes nothing but the loop's granularity.
    stamps = [time.perf_counter()]
    print(f"serial (load {load()})")
    print(head)
    serial = run_batches(
        evaluate_batch,
        items,
        context=ctx,
        engine="serial",
        batch_size=1,
        progress=lambda f, m: stamps.append(time.perf_counter()),
    )
    print(_row("B=1", serial, None))
    base = serial.results
    rate_s = serial.stats.items / serial.stats.wall_s
    dts = np.diff(stamps)
    for i, k in enumerate(keys):
        e = base[i]
        assert e is not None
        times = ", ".join(f"{dts[j]:.2f}" for j in range(i, len(items), len(keys)))
        print(
            f"    key done={k[0]!s:8s} next={k[1]}: {times} s; feasible grasps "
            f"{int(e.grasp_ok.sum()):4d}" + (f"; problem: {e.problem}" if e.problem else "")
        )
    v, _ = same_results([base[i % len(keys)] for i in range(len(items))], base)
    assert v, "serial: a repeated key gave a different result"
    cheap = keys[int(np.argmin(dts[: len(keys)]))]
    runs: dict[int, BatchRun[Any]] = {}

    t0 = time.perf_counter()
    with engine_session("ray"):
        startup = time.perf_counter() - t0
        import ray

        print(
            f"ray: engine_session start-up {startup:.2f} s (embedded local Ray, "
            f"{int(ray.cluster_resources().get('CPU', 0))} CPUs; load {load()})"
        )
        warm = run_batches(evaluate_batch, [cheap] * 4, context=ctx, engine="ray", batch_size=1)
        print(
            f"  warm-up (workers' first tasks: imports, context caches), 4 x key {cheap}: "
            f"wall {warm.stats.wall_s:.2f} s, compute {warm.stats.compute_s:.2f} s, overhead "
            f"{warm.stats.overhead_per_batch_s * 1e3:.0f} ms per batch"
        )
        noop = run_batches(_noop_batch, [cheap] * 64, context=ctx, engine="ray", batch_size=1)
        s = noop.stats
        print(
            f"  bare Ray overhead per task (no-op fn, same {ctx_size(ctx) / 1e3:.0f} kB context, "
            f"{s.batches} tasks of 1 item in {s.wall_s:.2f} s on {s.workers} workers): "
            f"{s.overhead_per_batch_s * 1e3:.1f} ms"
        )
        print(head)
        for b in sizes:
            run = run_batches(evaluate_batch, items, context=ctx, engine="ray", batch_size=b)
            runs[b] = run
            verdicts, joints = same_results(base, run.results)
            assert verdicts, f"ray B={b}: results differ from serial"
            print(
                _row(f"B={b}", run, rate_s)
                + f"  same as serial: {'yes' if verdicts else 'NO'}"
                + ("" if joints else " (q0/q1 not bitwise equal)")
                + f"; compute {run.stats.compute_s / serial.stats.compute_s:.2f}x serial's"
            )
        shut = time.perf_counter()
    print(f"  ray shutdown {time.perf_counter() - shut:.2f} s; load {load()}")
    meeting = [
        b
        for b in sizes
        if (st := runs[b].stats).overhead_per_batch_s < 0.1 * st.compute_s / st.batches
    ]
    best = max(sizes, key=lambda b: runs[b].stats.items / runs[b].stats.wall_s)
    rate_b = runs[best].stats.items / runs[best].stats.wall_s
    print(
        f"  overhead < 10 % of a batch's compute: batch sizes {meeting or 'none'}; smallest "
        f"{min(meeting) if meeting else '-'}; fastest Ray run B={best} at {rate_b:.3f} cand/s "
        f"({rate_b / rate_s:.2f}x serial)"
    )
    print(
        "  (overhead per batch = (wall x min(workers, batches) - compute) / batches: it counts a "
        "worker idle at the tail, waiting for the other's last batch, as overhead)"
    )


def ctx_size(ctx: SweepContext) -> int:
    import pickle

    return len(pickle.dumps(ctx))


# ---------------------------------------------------------------------------------------------
# 3: the part against the press, OBB tree (check_states) vs python-fcl


@dataclass
class Call:
    """One `check_states` call of `bend_eval._side`: a candidate's side at one station."""

    key: Key
    side: str
    states: list[FoldedState]
    T: np.ndarray  # (S, 4, 4) T_world_part
    obstacles: list[Obstacles]


def side_calls(ctx: SweepContext, keys: list[Key]) -> list[Call]:
    """Return the check_states calls `evaluate` makes for `keys` (same states, poses and
    obstacles as `bend_eval._side`: stations in order, the next one only after a hit)."""
    base, press = ctx.part(), ctx.press
    scene, cell = ctx.press_obstacles(), ctx.cell_obstacles()
    calls: list[Call] = []
    for done, bend in keys:
        part = bend_eval.ordered_part(base, done, bend)
        k = len(done)
        try:
            fold_state(part, k + 1)
        except WorkbenchError:
            continue  # evaluate stops before the press check
        states = [fold_state(part, k, f, check=False) for f in ctx.fractions]
        cut = contact_zone(float(part.bend_allowances[k]), part.thickness, press.tolerance)
        pts = part_points(states[0])
        for side, flange in (("child", part.bends[k].child), ("parent", part.bends[k].parent)):
            grasp = Grasp(part.flanges[flange].name)
            for station in bend_eval._stations(press, float(part.bend_lengths[k])):
                poses = [bend_pose(s, k, grasp, press, station) for s in states]
                P = (poses[0].T_die_part @ np.c_[pts, np.ones(len(pts))].T).T[:, :3]
                stop = gauge_stop(P, press, station)
                if stop.problem is not None:
                    continue
                obstacles = [
                    merge_obstacles(scene.at(station, p.punch_z, cut, stop), cell) for p in poses
                ]
                T = np.array([press.T_world_die @ p.T_die_part for p in poses])
                calls.append(Call((done, bend), side, states, T, obstacles))
                if not any(h is not None for h in check_states(states, T, obstacles)):
                    break
    return calls


def first_hit(o1: fcl.CollisionObject, o2: fcl.CollisionObject, cdata: fcl.CollisionData) -> bool:
    """Broadphase callback that stops at the first contact. (python-fcl's
    defaultCollisionCallback stops only once len(contacts) > num_max_contacts, i.e. after the
    second colliding pair with num_max_contacts=1.)"""
    if cdata.done:
        return True
    fcl.collide(o1, o2, cdata.request, cdata.result)
    cdata.done = cdata.result.is_collision
    return cdata.done


def _obstacle_object(obs: Obstacles, j: int, geoms: dict[Any, Any]) -> fcl.CollisionObject:
    """An fcl object of obstacle j where the state puts it; geometry shared (built once)."""
    e = obs.exact[j]
    if e is None:
        h = tuple(np.round(2.0 * obs.boxes.half_extents[j], 12))
        if ("box", h) not in geoms:
            geoms["box", h] = fcl.Box(*h)
        g = geoms["box", h]
        R, t = obs.boxes.rotation[j], obs.boxes.center[j]
    else:
        g = e.geometry  # the press's BVH / cylinder, built once by PressObstacles
        R, t = e.T_world[:3, :3], e.T_world[:3, 3]
    return fcl.CollisionObject(g, fcl.Transform(np.ascontiguousarray(R), np.ascontiguousarray(t)))


def _pose(obs: Obstacles, j: int) -> tuple[np.ndarray, np.ndarray]:
    e = obs.exact[j]
    if e is None:
        R, t = obs.boxes.rotation[j], obs.boxes.center[j]
        return np.ascontiguousarray(R), np.ascontiguousarray(t)
    return np.ascontiguousarray(e.T_world[:3, :3]), np.ascontiguousarray(e.T_world[:3, 3])


def _manager(objs: list[fcl.CollisionObject]) -> fcl.DynamicAABBTreeCollisionManager:
    m = fcl.DynamicAABBTreeCollisionManager()
    m.registerObjects(objs)
    m.setup()
    return m


@dataclass
class PartFcl:
    """One folded state's part for fcl: flange boxes as one BVH, the exact solid as one BVH,
    and the flange boxes as fcl.Box objects in their own manager; all in the part frame."""

    boxes: fcl.CollisionObject
    solid: fcl.CollisionObject
    flange_objs: list[fcl.CollisionObject]
    flange_local: np.ndarray  # (K, 4, 4) T_part_box
    flange_mgr: fcl.DynamicAABBTreeCollisionManager


def part_fcl(state: FoldedState) -> PartFcl:
    tree = state.obb_tree(0)  # the tree check_states uses; its leaves are the flange boxes
    leaves = tree.boxes[tree.leaves]
    T_pf = state.T_part_flange[0]
    local = np.array(
        [
            T_pf @ make_transform(leaves.rotation[i], leaves.center[i])
            for i in range(len(leaves.center))
        ]
    )
    mesh: Any = trimesh.util.concatenate(
        [
            trimesh.creation.box(2 * leaves.half_extents[i], transform=local[i])
            for i in range(len(local))
        ]
    )
    solid = state.solid()
    objs = [fcl.CollisionObject(fcl.Box(*(2 * h))) for h in leaves.half_extents]
    return PartFcl(
        fcl.CollisionObject(bvh_model(mesh.vertices, mesh.faces)),
        fcl.CollisionObject(bvh_model(solid.vertices, solid.faces)),
        objs,
        local,
        _manager(objs),
    )


def press_check(ctx: SweepContext, keys: list[Key], repeat: int) -> None:
    """Print check_states against python-fcl on the candidates' states and obstacles."""
    calls = side_calls(ctx, keys)
    n_states = sum(len(c.states) for c in calls)
    obs0 = calls[0].obstacles[0]
    tools = [n for n in obs0.names if is_tool(n)]
    print(
        f"part vs press: {len(keys)} candidates -> {len(calls)} check_states calls (side x "
        f"station), {n_states} states; {len(obs0.names)} obstacles per state ({len(tools)} "
        f"tool pieces: {', '.join(dict.fromkeys(tools))}; the rest boxes: frame, beam, cell)"
    )

    # ours: check_states exactly as _side calls it (trees and solid BVHs cached on the states
    # by a first call, as fcl's objects are built before its loop)
    ours_verdicts = [h is not None for c in calls for h in check_states(c.states, c.T, c.obstacles)]

    def ours() -> list[bool]:
        return [h is not None for c in calls for h in check_states(c.states, c.T, c.obstacles)]

    # fcl: objects built once, out of the timed loop
    req = fcl.CollisionRequest(num_max_contacts=1)
    geoms: dict[Any, Any] = {}
    parts = [[part_fcl(s) for s in c.states] for c in calls]
    Rt = [
        [(np.ascontiguousarray(T[:3, :3]), np.ascontiguousarray(T[:3, 3])) for T in c.T]
        for c in calls
    ]
    tool_idx = [j for j, n in enumerate(obs0.names) if is_tool(n)]
    other_idx = [j for j, n in enumerate(obs0.names) if not is_tool(n)]
    for c in calls:  # same obstacle list in every state (names, order)
        assert all(o.names == obs0.names for o in c.obstacles)

    # (A) obstacles placed where each state has them (as check_states receives them): two
    #     managers per state, built before the loop
    placed = [
        [
            (
                _manager([_obstacle_object(o, j, geoms) for j in other_idx]),
                _manager([_obstacle_object(o, j, geoms) for j in tool_idx]),
            )
            for o in c.obstacles
        ]
        for c in calls
    ]

    def fcl_part_bvh(mgrs: list[list[tuple[Any, Any]]], prepare: Any = None) -> list[bool]:
        out = []
        for ci in range(len(calls)):
            for si in range(len(Rt[ci])):
                if prepare is not None:
                    prepare(ci, si)
                R, t = Rt[ci][si]
                tf = fcl.Transform(R, t)
                p = parts[ci][si]
                other, tool = mgrs[ci][si]
                p.boxes.setTransform(tf)
                cd = fcl.CollisionData(request=req)
                other.collide(p.boxes, cd, first_hit)
                if not cd.result.is_collision:
                    p.solid.setTransform(tf)
                    cd = fcl.CollisionData(request=req)
                    tool.collide(p.solid, cd, first_hit)
                out.append(bool(cd.result.is_collision))
        return out

    # (B) the obstacles of a candidate side built once and moved: per state the pieces that
    #     move (punch and beam with the ram) get setTransform from their matrices, then
    #     the managers' update()
    moved_objs = []
    moves: list[list[list[tuple[Any, np.ndarray, np.ndarray, bool]]]] = []
    for c in calls:
        o0 = c.obstacles[0]
        objs = {j: _obstacle_object(o0, j, geoms) for j in range(len(o0.names))}
        mo = _manager([objs[j] for j in other_idx]), _manager([objs[j] for j in tool_idx])
        moved_objs.append([mo] * len(c.obstacles))
        per_state = []
        n = len(c.obstacles)
        for si in range(n):
            prev, cur = c.obstacles[(si - 1) % n], c.obstacles[si]
            m = []
            for j in range(len(cur.names)):
                R, t = _pose(cur, j)
                R0, t0 = _pose(prev, j)
                if not (np.array_equal(R, R0) and np.array_equal(t, t0)):
                    m.append((objs[j], R, t, j in tool_idx))
            per_state.append(m)
        moves.append(per_state)
    n_moving = sum(len(m) for per in moves for m in per) / n_states

    def move(ci: int, si: int) -> None:
        other_moved = tool_moved = False
        for obj, R, t, tool in moves[ci][si]:
            obj.setTransform(fcl.Transform(R, t))
            tool_moved |= tool
            other_moved |= not tool
        other, tool_m = moved_objs[ci][si]
        if other_moved:
            other.update()
        if tool_moved:
            tool_m.update()

    # (C) as (A), the flange boxes as fcl.Box primitives in a manager (solid boxes, exactly
    #     the tree's leaves) against the non-tool manager
    def fcl_flange_boxes() -> list[bool]:
        out = []
        for ci in range(len(calls)):
            for si in range(len(Rt[ci])):
                T = calls[ci].T[si]
                p = parts[ci][si]
                other, tool = placed[ci][si]
                W = T @ p.flange_local
                for k, obj in enumerate(p.flange_objs):
                    obj.setTransform(fcl.Transform(W[k, :3, :3], W[k, :3, 3]))
                p.flange_mgr.update()
                cd = fcl.CollisionData(request=req)
                p.flange_mgr.collide(other, cd, first_hit)
                if not cd.result.is_collision:
                    R, t = Rt[ci][si]
                    p.solid.setTransform(fcl.Transform(R, t))
                    cd = fcl.CollisionData(request=req)
                    tool.collide(p.solid, cd, first_hit)
                out.append(bool(cd.result.is_collision))
        return out

    # (D) as (A) without a broadphase: the part's BVHs against each obstacle in turn (the
    #     state's objects built before the loop), stopping at the first contact
    placed_lists = [
        [
            (
                [_obstacle_object(o, j, geoms) for j in other_idx],
                [_obstacle_object(o, j, geoms) for j in tool_idx],
            )
            for o in c.obstacles
        ]
        for c in calls
    ]

    def fcl_each() -> list[bool]:
        out = []
        for ci in range(len(calls)):
            for si in range(len(Rt[ci])):
                R, t = Rt[ci][si]
                tf = fcl.Transform(R, t)
                p = parts[ci][si]
                other, tool = placed_lists[ci][si]
                p.boxes.setTransform(tf)
                hit = any(fcl.collide(p.boxes, o, req) > 0 for o in other)
                if not hit:
                    p.solid.setTransform(tf)
                    hit = any(fcl.collide(p.solid, o, req) > 0 for o in tool)
                out.append(hit)
        return out

    peers = {
        "fcl (A) part BVHs vs obstacles placed per state": lambda: fcl_part_bvh(placed),
        "fcl (B) part BVHs, obstacles moved (setTransform)": lambda: fcl_part_bvh(moved_objs, move),
        "fcl (C) flange fcl.Box manager + solid BVH": fcl_flange_boxes,
        "fcl (D) part BVHs vs each obstacle, no broadphase": fcl_each,
    }
    verdicts = {name: fn() for name, fn in peers.items()}
    verdicts["fcl (B) part BVHs, obstacles moved (setTransform)"] = peers[
        "fcl (B) part BVHs, obstacles moved (setTransform)"
    ]()  # second pass: starts from the last state's poses, as in the timed loop
    for name, v in verdicts.items():
        assert v == ours_verdicts, (
            f"{name}: verdicts differ from check_states: {v} vs {ours_verdicts}"
        )
    print(
        f"  verdicts per state (all equal, asserted): {sum(ours_verdicts)} of {n_states} states "
        f"collide; {', '.join(f'{c.key[0]}->{c.key[1]} {c.side}: {[int(h) for h in ours_verdicts[i * 4 : i * 4 + 4]]}' for i, c in enumerate(calls))}"
    )
    print(f"  (B) moves {n_moving:.1f} obstacle pieces per state on average")

    def tree_alone() -> tuple[int, int]:
        """The broad phase of check_states only (for where the time goes): its leaf hits,
        and those on non-box obstacles (each confirmed by `obstacles.confirm_exact`)."""
        n = n_exact = 0
        for c in calls:
            for state, T, obs in zip(c.states, c.T, c.obstacles, strict=True):
                tree = state.obb_tree(0)
                hits = tree.collide_frames(obs.boxes, (T @ state.T_part_flange[0])[None]).hits
                n += len(hits)
                n_exact += sum(obs.exact[int(o)] is not None for _, _, o in hits)
        return n, n_exact

    leaf_hits, exact_hits = tree_alone()
    tree_label = "(info) ours' OBB tree alone, no exact confirmation"
    # every variant once per round, rounds repeated: load drift hits all alike
    fns = {
        "ours: check_states (OBB tree, tool hits on the exact solid)": ours,
        **peers,
        tree_label: tree_alone,
    }
    times: dict[str, list[float]] = {name: [] for name in fns}
    for fn in fns.values():
        fn()  # warm-up
    for _ in range(repeat):
        for name, fn in fns.items():
            t_start = time.perf_counter()
            fn()
            times[name].append(time.perf_counter() - t_start)
    rows = [(name, min(ts), float(np.median(ts))) for name, ts in times.items()]
    t_ours = rows[0][1]
    print(
        f"  us per candidate state, best / median of {repeat} rounds, variants interleaved "
        f"(load {load()})"
    )
    for i, (name, b, med) in enumerate(rows):
        ratio = f"   peer/ours {b / t_ours:.2f}x" if i else ""
        print(f"  {name:55s} {b / n_states * 1e6:8.1f} / {med / n_states * 1e6:8.1f}{ratio}")
    print(
        f"  (the tree finds {leaf_hits / n_states:.1f} (flange box, obstacle) hits per state, "
        f"{exact_hits / n_states:.1f} of them on non-box obstacles (the die's and punch's "
        "meshes), each confirmed by `obstacles.confirm_exact` (fcl box vs mesh, then a winding "
        "number) before a surviving tool hit goes to the exact solid)"
    )
    fastest = min(rows[1:-1], key=lambda r: r[1])
    print(
        f"  fastest peer: {fastest[0]} {fastest[1] / n_states * 1e6:.1f} us/state; ours "
        f"{t_ours / n_states * 1e6:.1f} us/state: peer/ours {fastest[1] / t_ours:.2f}x"
    )

    build_costs(ctx, calls)


def build_costs(ctx: SweepContext, calls: list[Call]) -> None:
    """Print what a sweep pays per new folded state before either check runs (each candidate
    folds its own states): not in the timed rows, where both sides' objects are prebuilt."""
    fresh = []
    for c in calls:
        part = bend_eval.ordered_part(ctx.part(), c.key[0], c.key[1])
        fresh += [fold_state(part, len(c.key[0]), f, check=False) for f in ctx.fractions]
    t0 = time.perf_counter()
    for state in fresh:
        state.obb_tree(0)
    t1 = time.perf_counter()
    meshes = [state.solid() for state in fresh]
    t2 = time.perf_counter()
    for mesh in meshes:
        bvh_model(mesh.vertices, mesh.faces)
    t3 = time.perf_counter()
    n = len(fresh)
    tris = [len(mesh.faces) for mesh in meshes]
    print(
        f"  per new state (not in the rows above): OBB tree build {(t1 - t0) / n * 1e6:.0f} us, "
        f"exact solid mesh {(t2 - t1) / n * 1e6:.0f} us, fcl BVH of the solid "
        f"{(t3 - t2) / n * 1e6:.0f} us ({min(tris)}-{max(tris)} triangles)"
    )


# ---------------------------------------------------------------------------------------------


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--items", type=int, default=8, help="candidates per batch run")
    ap.add_argument("--batch-sizes", default="1,2,4,8")
    ap.add_argument("--repeat", type=int, default=30, help="best of N for the press check")
    ap.add_argument("--projects", default=",".join(PROJECTS))
    ap.add_argument("--skip-sweep", action="store_true", help="only the press check")
    args = ap.parse_args()
    sizes = [int(b) for b in args.batch_sizes.split(",")]
    start = time.perf_counter()
    print(
        f"load average {load()}; OPENBLAS_NUM_THREADS={os.environ['OPENBLAS_NUM_THREADS']} "
        f"OMP_NUM_THREADS={os.environ['OMP_NUM_THREADS']} (Ray workers inherit them)"
    )
    for rel in args.projects.split(","):
        wb = Workbench.open(ROOT / rel)
        try:
            press = wb.bending.si().press
        except WorkbenchError as exc:
            print(f"\n== {rel}: skipped ({exc})")
            continue
        if press is None:
            print(f"\n== {rel}: skipped (no bending.press)")
            continue
        t = time.perf_counter()
        ctx = sweep_context(wb.bending)
        part = ctx.part()
        print(
            f"\n== {rel}: part {len(part.flanges)} flanges, {len(part.bends)} bends "
            f"{[b.name for b in part.bends]}, {len(ctx.grasps)} grasp candidates, stations "
            f"{[s.name for s in ctx.press.stations]}; context {time.perf_counter() - t:.2f} s"
        )
        keys = all_keys(len(part.bends))
        if not args.skip_sweep:
            sweep(ctx, keys, args.items, sizes)
        press_check(ctx, keys, args.repeat)
    print(f"\ntotal {time.perf_counter() - start:.0f} s; load average {load()}")


if __name__ == "__main__":
    main()
