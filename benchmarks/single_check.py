"""One configuration per call (jogging, the gizmo): the fast check's latency, FK included.

Usage: PYTHONPATH=. python benchmarks/single_check.py [--repeat 5]

On the MZ07 cell (projects/mz07_cell.json, the spheres engine of its policy, built or loaded
from the disk cache before timing) at every 4th sample of its program: per call, the best of
`repeat` passes, CPU time (process_time; the wall time on this shared machine is printed too):
`CollisionEngine.check(q)` and the service's `wb.collision.check(q)`, and their parts
(FK of all bodies, the spheres' items, the containment tests).
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from workbench import Workbench
from workbench.collision.plan_check import engine

ROOT = Path(__file__).resolve().parents[1]


def per_call(
    fn: Callable[[np.ndarray], object], qs: list[np.ndarray], repeat: int
) -> tuple[float, float]:
    """Return (CPU, wall) seconds per call, best of `repeat` passes over qs."""
    cpu, wall = [], []
    for _ in range(repeat):
        c0, w0 = time.process_time(), time.perf_counter()
        for q in qs:
            fn(q)
        cpu.append((time.process_time() - c0) / len(qs))
        wall.append((time.perf_counter() - w0) / len(qs))
    return min(cpu), min(wall)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    print(f"load average: {Path('/proc/loadavg').read_text().split()[:3]}")
    wb = Workbench.open(ROOT / "projects" / "mz07_cell.json")
    eng = engine(wb.checker, wb.collision_policy)
    qs = list(wb.plan_motion().positions[::4])
    flagged = sum(eng.check(q).flagged for q in qs)
    print(f"MZ07 cell, {len(qs)} configurations of its program ({flagged} flagged by the items):")
    rows = [
        ("CollisionEngine.check(q)", eng.check),
        ("wb.collision.check(q)", wb.collision.check),
        ("  FK: poses (batched code)", lambda q: eng.bodies.poses(q[None] + 0.0)),
        ("  items (batched, FK included)", lambda q: eng.items(q[None] + 0.0)),
        ("  FK: bodies.poses_one(q)", eng.bodies.poses_one),
        ("  items_one (FK included)", lambda q: eng.checker.items_one(eng.bodies.poses_one(q))),
        (
            "  containment (poses given)",
            lambda q: eng.containment.contained_one(eng.poses(q[None])[0]),
        ),
        ("  robot.link_transforms(q)", wb.robot.link_transforms),
    ]
    for name, fn in rows:
        cpu, wall = per_call(fn, qs, args.repeat)
        print(f"  {name:32s} {cpu * 1e6:7.1f} us CPU  {wall * 1e6:7.1f} us wall")
    print(f"load average: {Path('/proc/loadavg').read_text().split()[:3]}")


if __name__ == "__main__":
    main()
