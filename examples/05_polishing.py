"""Polishing (seed 004): a tool path on a fitted surface, force control along it, the robot motion.

Opens the example polishing cell, reports the workpiece mesh, plans the project's tool
path on the fitted Bézier surface (with its coverage), simulates the force/position hybrid
control along it, plans the robot's jerk-limited motion over the path and writes it as a
KUKA KRL program into OUT_DIR (default: a new temporary folder).

    python examples/05_polishing.py [OUT_DIR]
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

from workbench import Workbench

PROJECT = Path(__file__).resolve().parents[1] / "projects" / "polishing_cell.json"


def main(out_dir: str | Path | None = None) -> Path:
    """Plan, simulate and print; return the path of the KRL program written."""
    out = Path(out_dir) if out_dir is not None else Path(tempfile.mkdtemp(prefix="workbench-"))
    out.mkdir(parents=True, exist_ok=True)
    wb = Workbench.open(PROJECT)
    polishing = wb.polishing
    print(f"project: {wb.project.name}")
    report = polishing.report
    print(
        f"workpiece {Path(report.path).name}: {report.n_faces} triangles,"
        f" {report.bbox_diagonal * 1000:.0f} mm across, read in {report.units}"
    )

    path = polishing.plan_path()
    print(f"tool path:  {path.summary()}")
    simulation = polishing.simulate()
    print(f"control:    {simulation.summary()}")
    motion = polishing.plan_motion()
    print(f"robot:      {motion.summary()}")

    # The .src and its .dat: KUKA's language for the NACHI cell's path, as a what-if (a program
    # in another vendor's language is refused unless any_vendor; the MZ07's own is "nachi").
    exported = wb.export_program("krl", "polishing", any_vendor=True)
    src, dat = exported.write_to(out)
    print(
        f"wrote the KRL program: {src} ({len(src.read_text().splitlines())} lines) and {dat.name}"
    )
    return src


if __name__ == "__main__":
    main(*sys.argv[1:2])
