"""The four example projects plan to the same summaries and export the same programs.

Pinned before the architecture restructuring (issue "Architecture"): a change of structure
must not change what a user gets. The files in `tests/golden_examples/` were written by
`WORKBENCH_UPDATE_GOLDEN=1 python -m pytest tests/test_golden_examples.py` on the code
before the first move; robot programs (RAPID, KRL, LS, URScript) and summaries must match
character for character, the sampled CSV/JSON exports number for number within 1e-9.
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench

ROOT = Path(__file__).resolve().parents[1]
GOLDEN = Path(__file__).parent / "golden_examples"
PROGRAM_FORMATS = ("rapid", "krl", "ls", "urscript")
SAMPLE_FORMATS = ("csv", "json")

pytestmark = pytest.mark.slow


def _mz07() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "mz07_cell.json")
    plan = wb.plan_motion()
    out = {"summary.txt": plan.summary()}
    for fmt in PROGRAM_FORMATS + SAMPLE_FORMATS:
        out[f"program.{fmt}"] = wb.export_program(fmt)
    return out


def _bending() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "bending_cell.json")
    plan = wb.bending.plan()
    placements, _ = wb.bending.placements()
    # The tree/flat timing ratio is a measurement of this machine, not a result: left out.
    summary = re.sub(r" OBB tests on free frames: tree/flat = [0-9.]+\.", "", plan.summary())
    lines = [summary, f"sequence: {wb.bending.sequence}"]
    lines += [repr(np.round(p.q, 9).tolist()) for p in placements]
    return {"summary.txt": "\n".join(lines)}


def _assembly() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "assembly_cell.json")
    plan = wb.assembly.plan_sequence()
    out = {"summary.txt": plan.summary()}
    for robot in sorted(wb.assembly.arms):
        for fmt in PROGRAM_FORMATS + SAMPLE_FORMATS:
            out[f"{robot}.{fmt}"] = wb.assembly.export_program(robot, fmt)
    return out


def _polishing() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "polishing_cell.json")
    path = wb.polishing.plan_path()
    sim = wb.polishing.simulate()
    motion = wb.polishing.plan_motion()
    out = {
        "summary.txt": "\n".join([path.summary(), sim.summary(), motion.summary()]),
    }
    for fmt in PROGRAM_FORMATS + SAMPLE_FORMATS:
        out[f"program.{fmt}"] = wb.polishing.export_program(fmt)
    return out


EXAMPLES: dict[str, Callable[[], dict[str, str]]] = {
    "mz07": _mz07,
    "bending": _bending,
    "assembly": _assembly,
    "polishing": _polishing,
}


def _numbers(text: str, name: str) -> list[float]:
    if name.endswith(".json"):
        flat: list[float] = []

        def walk(v: object) -> None:
            if isinstance(v, dict):
                for k in sorted(v):
                    walk(v[k])
            elif isinstance(v, list):
                for x in v:
                    walk(x)
            elif isinstance(v, int | float) and not isinstance(v, bool):
                flat.append(float(v))

        walk(json.loads(text))
        return flat
    rows = [line.split(",") for line in text.strip().splitlines()[1:]]
    return [float(x) for r in rows for x in r]


@pytest.mark.parametrize("example", sorted(EXAMPLES))
def test_example_plans_and_programs_unchanged(example: str) -> None:
    produced = EXAMPLES[example]()
    folder = GOLDEN / example
    if os.environ.get("WORKBENCH_UPDATE_GOLDEN") == "1":
        folder.mkdir(parents=True, exist_ok=True)
        for name, text in produced.items():
            (folder / name).write_text(text)
    expected = sorted(p.name for p in folder.iterdir())
    assert sorted(produced) == expected
    for name, text in produced.items():
        ref = (folder / name).read_text()
        if name.rsplit(".", 1)[-1] in SAMPLE_FORMATS:
            assert text.splitlines()[0] == ref.splitlines()[0], name
            got, want = _numbers(text, name), _numbers(ref, name)
            assert len(got) == len(want), name
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-9, err_msg=name)
        else:
            assert text == ref, f"{example}/{name} differs from the pinned output"
