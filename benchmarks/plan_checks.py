"""Bending transfer and assembly sequence: plan time, and the robot check dense-exact vs fast.

Usage: PYTHONPATH=. python benchmarks/plan_checks.py [--repeat 3] [--only plans|long]

`--only long`: the fast check's cost per sample on the MZ07 cell's program run there and back
1x, 2x, 4x, 8x, 16x (`there_and_back`, the same jerk-limited motion reversed in time every
other copy): wall and CPU time per sample, configurations checked, the verdict, and the
dense exact check (python-fcl at every sample) of the longest one.

Prints, per example, the best-of-`repeat` wall time of the whole plan (`wb.bending.plan()`,
`wb.assembly.plan_sequence()`), and of the robot-versus-cell/self check alone over the same
samples in the same process: the dense exact check (`RobotCollisionChecker.check_path`, python-fcl
at every sample, nothing between samples) against the fast conservative check (spheres + SDF,
flagged pairs confirmed with fcl, certified between samples). The engine is built (or loaded
from the disk cache) before timing.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from workbench import Workbench
from workbench.collision import check_trajectory, shared_engine
from workbench.motion.trajectory import Trajectory

ROOT = Path(__file__).resolve().parents[1]


def best(fn, repeat: int) -> float:  # type: ignore[no-untyped-def]
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t)
    return min(out)


def there_and_back(traj: Trajectory, copies: int) -> Trajectory:
    """Return `traj` run `copies` times, every other copy backwards (rest to rest, so C1).

    The reversed copy of a constant-jerk piece p(h) on [s, e] starts at T - e with the
    piece's end state: position p(e), velocity -v(e), acceleration a(e), jerk -j.
    """
    T = traj.duration
    st, p, v, a, j = traj.piece_start, traj.piece_p, traj.piece_v, traj.piece_a, traj.piece_j
    end = np.concatenate([st[:, 1:], np.full((st.shape[0], 1), T)], axis=1)
    L = end - st
    pe = p + L * (v + L * (a / 2 + L * j / 6))
    ve, ae = v + L * (a + L * j / 2), a + L * j
    back = ((T - end)[:, ::-1], pe[:, ::-1], -ve[:, ::-1], ae[:, ::-1], -j[:, ::-1])
    parts = [
        (st + k * T, p, v, a, j) if k % 2 == 0 else (back[0] + k * T, *back[1:])
        for k in range(copies)
    ]
    s_, p_, v_, a_, j_ = (np.concatenate([c[i] for c in parts], axis=1) for i in range(5))
    return Trajectory(
        copies * T,
        np.zeros(0),
        traj.waypoints,
        (),
        np.zeros(0),
        dt=traj.dt,
        piece_start=s_,
        piece_p=p_,
        piece_v=v_,
        piece_a=a_,
        piece_j=j_,
    )


def long_programs(repeat: int) -> None:
    """Print the fast check's cost per sample on the MZ07 program run 1x..16x."""
    wb = Workbench.open(ROOT / "projects" / "mz07_cell.json")
    policy = wb.collision_policy
    shared_engine(wb.checker, policy)
    traj = wb.plan_motion().trajectory
    print(f"MZ07 program {traj.duration:.2f} s, samples every 10 ms, run there and back:")
    for copies in (1, 2, 4, 8, 16):
        long = there_and_back(traj, copies)
        times, q, _, _ = long.sample(0.01)
        check_trajectory(long, times, q, wb.checker, policy)  # pair tables filled once
        walls, cpus = [], []
        for _ in range(repeat):
            t0, c0 = time.perf_counter(), time.process_time()
            rep = check_trajectory(long, times, q, wb.checker, policy)
            walls.append(time.perf_counter() - t0)
            cpus.append(time.process_time() - c0)
        w, c, n = min(walls), min(cpus), len(times)
        print(
            f"  {copies:2d}x {long.duration:6.1f} s {n:5d} samples: {w * 1e6 / n:5.0f} us/sample"
            f" wall, {c * 1e6 / n:5.0f} us/sample CPU, {rep.evaluated} configurations"
            f" ({rep.evaluated / n:.2f}/sample); {rep.message}"
        )
    t0 = time.perf_counter()
    dense = wb.checker.check_path(q)
    print(
        f"  dense exact check of the 16x samples: {len(dense.colliding_indices)} colliding"
        f" ({time.perf_counter() - t0:.1f} s)"
    )


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", choices=("plans", "long"), default=None)
    args = ap.parse_args()
    print(f"load average: {Path('/proc/loadavg').read_text().split()[:3]}")
    if args.only != "plans":
        long_programs(args.repeat)
    if args.only == "long":
        print(f"load average: {Path('/proc/loadavg').read_text().split()[:3]}")
        return

    wb = Workbench.open(ROOT / "projects" / "bending_cell.json")
    shared_engine(wb.checker, wb.collision_policy)
    plan = wb.bending.plan()
    t_plan = best(wb.bending.plan, args.repeat)
    q, times = plan.joints, plan.times
    t_dense = best(lambda: wb.checker.check_path(q), args.repeat)
    policy = wb.collision_policy
    t_fast = best(
        lambda: check_trajectory(plan.trajectory, times, q, wb.checker, policy), args.repeat
    )
    rep = check_trajectory(plan.trajectory, times, q, wb.checker, policy)
    print(
        f"bending plan ({len(times)} frames): {t_plan * 1e3:.0f} ms; robot check dense exact"
        f" {t_dense * 1e3:.1f} ms, fast {t_fast * 1e3:.1f} ms (ratio dense/fast"
        f" {t_dense / t_fast:.2f}); {rep.message}"
    )

    wb = Workbench.open(ROOT / "projects" / "assembly_cell.json")
    for arm in wb.assembly.arms.values():
        shared_engine(arm.checker, wb.collision_policy)
    plan_a = wb.assembly.plan_sequence()
    t_plan = best(wb.assembly.plan_sequence, args.repeat)
    print(f"assembly sequence ({len(plan_a.times)} samples): {t_plan * 1e3:.0f} ms")
    fast = getattr(wb.assembly, "check_robot", None)  # absent before the fast route
    for name, arm in wb.assembly.arms.items():
        active = np.zeros(len(plan_a.times), bool)
        for task in plan_a.tasks:
            if task.robot == name:
                active |= (plan_a.times >= task.t0) & (plan_a.times <= task.t1)
        qa = plan_a.joints[name][active]
        t_dense = best(lambda qa=qa, arm=arm: arm.checker.check_path(qa), args.repeat)
        if fast is None:
            print(f"  {name}: dense exact {t_dense * 1e3:.1f} ms over {len(qa)} samples")
            continue
        t_fast = best(
            lambda name=name, fast=fast: fast(plan_a.tasks, plan_a.times, name), args.repeat
        )
        r = fast(plan_a.tasks, plan_a.times, name)
        print(
            f"  {name}: dense exact {t_dense * 1e3:.1f} ms, fast {t_fast * 1e3:.1f} ms over"
            f" {len(qa)} samples (ratio {t_dense / t_fast:.2f}); {r.message}"
        )
    print(f"load average: {Path('/proc/loadavg').read_text().split()[:3]}")


if __name__ == "__main__":
    main()
