"""Plan and export: the MZ07 cell's program as a checked trajectory, five robot programs and its samples.

Plans the project's program (IK through its moves, a jerk-limited ruckig trajectory,
joint-limit and collision checks), prints the summary, and writes the program in every
export format into OUT_DIR (default: a new temporary folder).

    python examples/02_plan_and_export.py [OUT_DIR]
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

from workbench import Workbench, WorkbenchError

PROJECT = Path(__file__).resolve().parents[1] / "projects" / "mz07_cell.json"
# Export formats: ABB RAPID, KUKA KRL (.src + .dat), FANUC LS, URScript, NACHI FD, joint samples.
FORMATS = ("rapid", "krl", "ls", "urscript", "nachi", "csv", "json")


class _Progress:
    """Print a progress line each time the work advances by another 20 % (and at the end)."""

    def __init__(self) -> None:
        self.next = 0.0

    def __call__(self, fraction: float, message: str) -> None:
        if fraction >= self.next or fraction >= 1.0:
            print(f"  {fraction * 100:5.1f} %  {message}")
            self.next = fraction + 0.2


def main(out_dir: str | Path | None = None) -> list[Path]:
    """Plan, print the summary and return the paths of the exported files."""
    out = Path(out_dir) if out_dir is not None else Path(tempfile.mkdtemp(prefix="workbench-"))
    out.mkdir(parents=True, exist_ok=True)
    wb = Workbench.open(PROJECT)
    print(f"planning {wb.project.name!r}:")
    plan = wb.plan_motion(progress=_Progress())
    name = plan.program.name
    print(plan.summary())
    print(f"cycle time {plan.cycle_time:.3f} s; {'ready to run' if plan.ok else 'NOT ready'}")

    written: list[Path] = []
    native = wb.default_program_format()  # the robot's vendor's language (NACHI FD here)
    try:
        wb.export_program("rapid")
    except WorkbenchError as exc:  # another vendor's language is refused by default
        print(f"refused: {exc}")
    print(f"the {wb.project.robot.name}'s own language is {native}; the others for comparison")
    for fmt in FORMATS:
        # files (name -> text) and the post's notes; any_vendor: another vendor's language
        exported = wb.export_program(fmt, any_vendor=fmt != native)
        for path in exported.write_to(out):
            written.append(path)
            print(f"wrote {fmt:8s} {path} ({len(path.read_text().splitlines())} lines)")
        for note in exported.notes:
            print(f"  note: {note}")
    print(f"program {name}: {len(written)} files")
    return written


if __name__ == "__main__":
    main(*sys.argv[1:2])
