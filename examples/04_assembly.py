"""Virtual assembly (seed 003): plan the part moves, time both robots, export their programs.

Opens the example assembly cell (two MZ07 arms, two plates and five screws), plans the
whole sequence (part paths, the carrying robots' joints, ruckig timing, robot-robot and
robot-part checks), prints each task on the shared time axis, and writes each robot's
share as an ABB RAPID module into OUT_DIR (default: a new temporary folder).

    python examples/04_assembly.py [OUT_DIR]
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

from workbench import Workbench

PROJECT = Path(__file__).resolve().parents[1] / "projects" / "assembly_cell.json"


class _Progress:
    """Print a progress line each time the work advances by another 20 % (and at the end)."""

    def __init__(self) -> None:
        self.next = 0.0

    def __call__(self, fraction: float, message: str) -> None:
        if fraction >= self.next or fraction >= 1.0:
            print(f"  {fraction * 100:5.1f} %  {message}")
            self.next = fraction + 0.2


def main(out_dir: str | Path | None = None) -> list[Path]:
    """Plan the sequence, print it and return the paths of the robot programs written."""
    out = Path(out_dir) if out_dir is not None else Path(tempfile.mkdtemp(prefix="workbench-"))
    out.mkdir(parents=True, exist_ok=True)
    wb = Workbench.open(PROJECT)
    assembly = wb.assembly
    print(f"project: {wb.project.name}")
    print(f"parts: {', '.join(assembly.part_names)}; robots: {', '.join(assembly.arms)}")

    print("planning the sequence:")
    plan = assembly.plan_sequence(progress=_Progress())
    print(plan.summary())
    for task in plan.tasks:
        route = task.part_plan.path
        print(
            f"  {task.part:8s} by {task.robot:8s} picked at {task.t_pick:6.2f} s,"
            f" placed at {task.t_place:6.2f} s ({route.planner}, {len(route.poses)} key points)"
        )

    # One RAPID task per robot, synced (ABB MultiMove's WaitSyncTask): the MZ07s' cell written
    # as an ABB cell would run it; the MZ07's own language is "nachi", so any_vendor says so.
    exported = wb.export_program("rapid", "assembly", any_vendor=True)
    written = exported.write_to(out)
    for path in written:
        print(f"wrote a robot's program: {path}")
    return written


if __name__ == "__main__":
    main(*sys.argv[1:2])
