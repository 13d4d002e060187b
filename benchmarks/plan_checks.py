"""Bending transfer and assembly sequence: plan time, and the robot check dense-exact vs fast.

Usage: PYTHONPATH=. python benchmarks/plan_checks.py [--repeat 3]

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

ROOT = Path(__file__).resolve().parents[1]


def best(fn, repeat: int) -> float:  # type: ignore[no-untyped-def]
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t)
    return min(out)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    print(f"load average: {Path('/proc/loadavg').read_text().split()[:3]}")

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
