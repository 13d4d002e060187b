"""Fuzzed CAD files (issue 29): the examples' STEP and DXF files, mutated, and the issue's
hostile files, through every route a CAD file takes.

The routes: a mesh named by a project (`load_mesh_file`: cell objects, the tool, links and
assembly parts), the polishing workpiece (the Polishing tab's upload and the project's
`polishing.workpiece`), the part file (`import_part`: `bending.part_file` and `workbench
import-part`), and the Project tab's part and obstacle uploads (`import_bending_part`,
`add_cell_file`) on an open workbench. Every case must end in a result or a `WorkbenchError`
within the CAD time limit (set to `CAD_SECONDS` here) plus `MARGIN_SECONDS`, the parent's peak
memory may grow by at most `CASE_MEMORY`, and after a case whose reader crashed or was stopped
the next read must work (the process that holds the workbench lives on).

Slow (every case reads through the CAD worker, 0.1-2 s each; the hostile ones 4-8 s): `CASES`
seeded mutations, and each hostile file through each route. A failure prints the seed and the
mutations: `case(seed)` reproduces it.
"""

from __future__ import annotations

import random
import resource
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hostile_cad import DXF_EXAMPLES, HOSTILE, STEP_EXAMPLES, mutate

from workbench.errors import WorkbenchError

ROOT = Path(__file__).resolve().parent.parent
CASES = 120
CAD_SECONDS = 20.0
MARGIN_SECONDS = 10.0  # worker start-up (Open CASCADE loads in 4-6 s) and the transfer
CASE_MEMORY = 512 * 1024**2  # bytes of peak RSS growth of this process in one case
STOPPED = ("the reader crashed", "took longer than", "took more than")

pytestmark = pytest.mark.slow


def case(seed: int) -> tuple[str, bytes, list[str]]:
    """Return the file name, bytes and mutations of fuzz case `seed`."""
    rng = random.Random(seed)
    source = rng.choice(STEP_EXAMPLES + DXF_EXAMPLES + STEP_EXAMPLES)
    data, done = source.read_bytes(), []
    for _ in range(rng.randint(1, 3)):
        data, what = mutate(data, rng, step=source.suffix == ".step")
        done.append(what)
    return source.name, data, done


@pytest.fixture(scope="module")
def routes(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Callable[[str, bytes], Any]]:
    """Return each route as a function of (file name, bytes)."""
    from workbench import Workbench
    from workbench.project.part_import import PartImportSpec, import_part
    from workbench.service.mesh_files import load_mesh_file
    from workbench.service.project_imports import add_cell_file, import_bending_part

    folder = tmp_path_factory.mktemp("cad-fuzz")
    bending = Workbench.open(ROOT / "projects" / "u_channel_cell.json")
    polishing = Workbench.open(ROOT / "projects" / "polishing_cell.json")
    for wb in (bending, polishing):
        wb.folders = wb.folders.with_session(folder)

    def saved(name: str, data: bytes) -> Path:
        path = folder / name
        path.write_bytes(data)
        return path

    def settings(name: str) -> dict[str, Any]:
        return {"thickness": 1.5} if name.endswith(".dxf") else {}

    return {
        "cell object": lambda n, d: load_mesh_file(
            saved(n, d).name, folder, 0.001, "cell.objects[0].path"
        ),
        "workpiece upload": lambda n, d: polishing.polishing.load_workpiece(saved(n, d)),
        "part file": lambda n, d: import_part(d, n, PartImportSpec(**settings(n))),
        "part upload": lambda n, d: import_bending_part(bending, n, d, settings(n)),
        "obstacle upload": lambda n, d: add_cell_file(bending, saved(n, d), xyz_mm=[0, 0, 0]),
    }


def _run(route: Callable[[str, bytes], Any], name: str, data: bytes, what: str) -> str:
    """Run one case; return "ok" or the error's text; fail on anything else."""
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    start = time.monotonic()
    try:
        route(name, data)
        outcome = "ok"
    except WorkbenchError as exc:
        outcome = str(exc)
    except Exception as exc:  # the failure this test exists to catch
        pytest.fail(f"{what}: {type(exc).__name__}: {exc}")
    took = time.monotonic() - start
    grew = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024 - peak
    assert took < CAD_SECONDS + MARGIN_SECONDS, f"{what}: {took:.1f} s"
    assert grew < CASE_MEMORY, f"{what}: peak memory grew {grew / 1024**2:.0f} MB"
    return outcome


def _alive_after(outcome: str) -> None:
    """After a crash or a stop, the next read works (a fresh worker, the same parent)."""
    if any(s in outcome for s in STOPPED):
        from workbench.cad.dxf import read_flat_pattern

        assert read_flat_pattern(DXF_EXAMPLES[0].read_bytes(), "pan_flat.dxf", "x").bend_lines


@pytest.fixture(autouse=True)
def _cad_limit(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("WORKBENCH_CAD_SECONDS", str(CAD_SECONDS))


def test_mutated_examples_through_every_route(routes: dict[str, Callable]) -> None:
    names = sorted(routes)
    outcomes: dict[str, int] = {}
    for seed in range(CASES):
        name, data, done = case(seed)
        route = names[seed % len(names)]
        what = f"seed {seed} ({name}: {', '.join(done)}) via {route}"
        outcome = _run(routes[route], name, data, what)
        _alive_after(outcome)
        key = "ok" if outcome == "ok" else "refused"
        outcomes[key] = outcomes.get(key, 0) + 1
    assert outcomes.get("refused"), "no mutation was refused: the fuzz does not bite"


@pytest.mark.parametrize("hostile", sorted(HOSTILE))
def test_every_hostile_file_is_refused_on_every_route(
    hostile: str, routes: dict[str, Callable]
) -> None:
    name, make = HOSTILE[hostile]
    data = make()
    for route in sorted(routes):
        outcome = _run(routes[route], name, data, f"{hostile} via {route}")
        assert outcome != "ok", f"{hostile} via {route} was accepted"
        _alive_after(outcome)


def test_a_crashing_step_file_leaves_the_workbench_working(
    routes: dict[str, Callable], monkeypatch: pytest.MonkeyPatch
) -> None:
    """The GUI's part upload with a file that crashes Open CASCADE's parser (its nesting bound
    lifted): a refusal naming the crash, and the same workbench imports the next part."""
    from workbench.cad import step_checks

    monkeypatch.setattr(step_checks, "MAX_STEP_NESTING", 10**9)
    name, make = HOSTILE["step_deep_nesting"]
    outcome = _run(routes["part upload"], name, make(), "deep nesting via part upload")
    assert "the reader crashed on 'deep.step' (with SIGSEGV)" in outcome, outcome
    part = STEP_EXAMPLES[0]
    assert "3 flanges, 2 bends" in routes["part upload"](part.name, part.read_bytes())
