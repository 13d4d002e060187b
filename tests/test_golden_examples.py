"""The four example projects plan to the same summaries and export the same programs.

First pinned before the architecture restructuring (issue "Architecture"): a change of
structure must not change what a user gets. Issue 12 changed the programs on purpose (tools,
work objects, configuration data, I/O, controller joints, every workflow); the files were
regenerated then, each read as a controller programmer would before it was committed.

`WORKBENCH_UPDATE_GOLDEN=1 python -m pytest tests/test_golden_examples.py` rewrites them
(only on purpose). Each example keeps `summary.txt` and, per export format, the files
`Workbench.export_program(fmt, workflow)` writes, in `<format>/<file name>`; robot programs
must match character for character, the sampled CSV/JSON exports number for number within 1e-9.
"""

from __future__ import annotations

import json
import os
import re
import shutil
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.motion.programs import EXPORT_FORMATS, SAMPLE_FORMATS

ROOT = Path(__file__).resolve().parents[1]
GOLDEN = Path(__file__).parent / "golden_examples"

pytestmark = pytest.mark.slow


def _exports(wb: Workbench, workflow: str) -> dict[str, str]:
    """Return every format's exported files as {"<format>/<file>": text}."""
    out = {}
    for fmt in EXPORT_FORMATS:
        for name, text in wb.export_program(fmt, workflow, force=True).files.items():
            out[f"{fmt}/{name}"] = text
    return out


def _mz07() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "mz07_cell.json")
    plan = wb.plan_motion()
    return {"summary.txt": plan.summary(), **_exports(wb, "motion")}


def _bending() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "bending_cell.json")
    plan = wb.bending.plan()
    placements, _ = wb.bending.placements()
    # The tree/flat timing ratio is a measurement of this machine, not a result: left out.
    summary = re.sub(r" OBB tests on free frames: tree/flat = [0-9.]+\.", "", plan.summary())
    lines = [summary, f"sequence: {wb.bending.sequence}"]
    lines += [repr(np.round(p.q, 9).tolist()) for p in placements]
    out = {"summary.txt": "\n".join(lines)}
    return {**out, **_exports(wb, "bending")}


def _assembly() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "assembly_cell.json")
    plan = wb.assembly.plan_sequence()
    return {"summary.txt": plan.summary(), **_exports(wb, "assembly")}


def _polishing() -> dict[str, str]:
    wb = Workbench.open(ROOT / "projects" / "polishing_cell.json")
    path = wb.polishing.plan_path()
    sim = wb.polishing.simulate()
    motion = wb.polishing.plan_motion()
    out = {"summary.txt": "\n".join([path.summary(), sim.summary(), motion.summary()])}
    return {**out, **_exports(wb, "polishing")}


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
        shutil.rmtree(folder, ignore_errors=True)
        for name, text in produced.items():
            (folder / name).parent.mkdir(parents=True, exist_ok=True)
            (folder / name).write_text(text)
    expected = sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file())
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
