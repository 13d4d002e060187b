"""Press-brake bending (seed 000): place every bend on the die and check the transfer.

Opens the example bending cell, shows the bend sequence (and that a sequence naming a bend
twice is refused), plans the die placement of every bend by IK and the transfer of the
finished part to the pallet, and prints what hits what.

    python examples/03_bending.py [PROJECT]
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from workbench import Workbench, WorkbenchError

PROJECT = Path(__file__).resolve().parents[1] / "projects" / "bending_cell.json"


class _Progress:
    """Print a progress line each time the work advances by another 20 % (and at the end)."""

    def __init__(self) -> None:
        self.next = 0.0

    def __call__(self, fraction: float, message: str) -> None:
        if fraction >= self.next or fraction >= 1.0:
            print(f"  {fraction * 100:5.1f} %  {message}")
            self.next = fraction + 0.2


def main(project: str | Path = PROJECT) -> None:
    wb = Workbench.open(project)
    bending = wb.bending
    sequence = bending.sequence
    print(f"project: {wb.project.name}")
    print(f"bend sequence: {', '.join(sequence)}")

    # The sequence rule: every bend exactly once. A wrong sequence is refused, nothing changes.
    try:
        bending.set_sequence([sequence[0], *sequence[:-1]])
    except WorkbenchError as exc:
        print(f"refused: {exc}")
    print(f"the sequence stays {', '.join(bending.sequence)}")

    print("planning:")
    plan = bending.plan(progress=_Progress())
    print(plan.summary())
    # (a project with a press plans its whole cycle instead: see 06_bending_sweep.py)
    for p in getattr(plan, "placements", ()):
        print(
            f"  bend {p.bend} on the die: joints [deg]",  # the controller's values
            (np.round(np.degrees(wb.robot.convention.to_controller(p.q)), 1) + 0.0).tolist(),
        )
    first = getattr(plan, "first_collision", None)
    if first is not None:
        print(f"first collision: {first.describe()}")
    elif plan.ok:
        print("the transfer is collision-free")


if __name__ == "__main__":
    main(*sys.argv[1:2])
