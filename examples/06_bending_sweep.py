"""Press-brake bending: search the bend order, the grasps and the tool stations, then plan the cycle.

Opens the example U-channel cell (a press with a straight punch), searches the bend orders with
a grasp per bend and a tool station (cheap checks first, then the full cycle of the best ones),
prints the ranked plans and the first reason of each rejected branch, puts the best plan into
the project and plans its whole cycle: pick, each bend with the robot following the flange,
regrips, unload; every frame checked.

    python examples/06_bending_sweep.py [PROJECT]
"""

from __future__ import annotations

import sys
from pathlib import Path

from workbench import Workbench

PROJECT = Path(__file__).resolve().parents[1] / "projects" / "u_channel_cell.json"


def main(project: str | Path = PROJECT) -> None:
    """Search the example's bending plans, show them, and plan the best one's cycle."""
    wb = Workbench.open(project)
    svc = wb.bending
    print(f"part {svc.part_spec().name}: bends {', '.join(svc.sequence)}")
    res = svc.find_sequences(engine="serial")
    print(res.stats.describe())
    if res.note:
        print(f"note: {res.note}")
    for rank, plan in enumerate(res.plans, 1):
        print(
            f"{rank}. {' -> '.join(plan.sequence)}: {plan.regrips} regrip(s), {plan.flips} "
            f"flip(s), cycle {plan.cycle_time:.2f} s"
        )
        for bend, grasp, station in zip(
            plan.sequence, plan.grasp_labels(), plan.stations, strict=True
        ):
            print(f"     {bend}: grasp {grasp}, station {station}")
    print("rejected (first reason of each pruned branch):")
    for branch, reason in res.rejected[:6]:
        print(f"  {' -> '.join(branch)}: {reason}")
    if not res.plans:
        return
    svc.use_plan(res.plans[0])
    cycle = svc.plan()
    print(f"planned: {cycle.summary()}")


if __name__ == "__main__":
    main(*sys.argv[1:2])
