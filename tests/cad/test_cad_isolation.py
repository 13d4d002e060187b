"""CAD files read where they cannot hurt (issue 29 part 3): the bounds before the readers, the
worker process with its time and memory limit, and the refusal of broken files on every route.

The fast tests check the bounds in this process against brute-force twins, and the hostile
files through the worker (started once per test process and reused: about 1 s, 4-6 s once
it loads Open CASCADE). The slow ones need a crash, a time limit or a memory limit to run
out: each costs that limit's seconds and a fresh worker.
"""

from __future__ import annotations

import pickle
import random
import re
from pathlib import Path

import numpy as np
import pytest
from hostile_cad import (
    HOSTILE,
    STEP_EXAMPLES,
    block_bomb_dxf,
    broken_step,
    circle_dxf,
    deep_step,
    sphere_step,
)

from workbench.cad import dxf_checks, isolation, step_checks
from workbench.cad.dxf import read_flat_pattern
from workbench.cad.flat_pattern import FlatPatternError
from workbench.cad.step import StepTolerance, read_step_mesh, read_step_sheet
from workbench.errors import InputError, MeshError, WorkbenchError
from workbench.project import bounds

ROOT = Path(__file__).resolve().parents[2]

# What each hostile case is refused for (the list; docs/security.md).
REFUSED = {
    "step_deep_nesting": r"nests lists 100,001 deep, more than 64 .*MAX_STEP_NESTING",
    "step_broken_references": r"does not load whole: 10 entities fail \(#21 EDGE_CURVE: .*unresolved",
    "step_sphere_100m": r"would mesh into some [\d,]+ triangles at 0.05 mm.*MAX_TRIANGLES",
    "step_sphere_1e300": r"reaches 1e\+300 mm from its origin.*MAX_COORDINATE_MM",
    "step_many_entities": r"holds 2,000,001 entities, more than 2,000,000",
    "dxf_spline_degree_30": r"SPLINE on layer '0' has degree 30, more than 11",
    "dxf_circle_1e9": r"CIRCLE on layer '0' reaches 1e\+09 mm from the origin",
    "dxf_block_bomb": r"expands to more than 200,000 entities through its block references",
    "dxf_million_lines": r"holds 1,000,005 objects, more than 200,000",
    "dxf_3000_bends": r"has 3,000 bend lines, more than 100",
}


def _read(name: str, data: bytes, field: str = "cell.objects[0].path") -> object:
    if name.endswith(".dxf"):
        return read_flat_pattern(data, name, field)
    return read_step_mesh(data, name, field, StepTolerance())


# -- the bounds, against brute-force twins -----------------------------------------------------------
def _depth_twin(text: bytes) -> int:
    """Walk the text character by character: strings ('..', '' inside) and comments skipped."""
    depth = best = 0
    i, inside = 0, False
    while i < len(text):
        c = text[i : i + 1]
        if not inside and text[i : i + 2] == b"/*":
            i = text.index(b"*/", i) + 2 if b"*/" in text[i:] else len(text)
            continue
        if c == b"'":
            inside = not inside
        elif not inside and c == b"(":
            depth += 1
            best = max(best, depth)
        elif not inside and c == b")":
            depth -= 1
        i += 1
    return best


def test_nesting_depth_counts_parentheses_outside_strings_and_comments() -> None:
    rng = random.Random(29)
    alphabet = [b"(", b")", b"'", b"''", b"x", b",", b"/* ( */"]
    for _ in range(300):
        text = b"".join(rng.choice(alphabet) for _ in range(rng.randrange(60)))
        if text.count(b"'") % 2:
            text += b"'"
        assert step_checks.nesting_depth(text) == _depth_twin(text), text
    example = STEP_EXAMPLES[0].read_bytes()
    assert step_checks.nesting_depth(example) == _depth_twin(example) <= 4


def test_the_text_bounds_refuse_before_any_reader(monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(MeshError, match=r"^tool\.mesh: .*nests lists 1,001 deep"):
        step_checks.check_text(deep_step(1000), "d.step", "tool.mesh")
    monkeypatch.setattr(step_checks, "MAX_STEP_ENTITIES", 900)
    example = STEP_EXAMPLES[0].read_bytes()
    assert len(re.findall(rb"(?m)^#\d+ =", example)) > 900
    with pytest.raises(MeshError, match=r"holds 998 entities, more than 900"):
        step_checks.check_text(example, "u.step", "x")
    monkeypatch.setattr(dxf_checks, "MAX_DXF_ENTITIES", 10)
    with pytest.raises(FlatPatternError, match=r"'b\.dxf' holds \d+ objects, more than 10"):
        dxf_checks.check_text(block_bomb_dxf(2, 20), "b.dxf", "x")


def test_the_block_expansion_count_is_the_expansion_itself() -> None:
    import io

    from ezdxf import recover

    from workbench.cad.dxf import _entities

    for levels, fan in ((1, 3), (2, 4), (3, 5), (4, 3)):
        doc, _ = recover.read(io.BytesIO(block_bomb_dxf(levels, fan)))
        counted = dxf_checks._count(doc.modelspace(), doc, 0, {}, (), 10**9)
        expanded = _entities(doc.modelspace())  # what the reader then walks: one per leaf
        inserts = sum(fan**k for k in range(levels))  # every INSERT counted besides its content
        assert counted == len(expanded) + inserts, (levels, fan)


def test_the_coordinate_bound_is_the_cells() -> None:
    assert step_checks.MAX_COORDINATE_MM == bounds.CELL_HALF_EXTENT_MM
    for path in isolation.SETTINGS:
        assert f"`{path.removeprefix('workbench.')}`" in (ROOT / "docs/security.md").read_text()


def test_the_limits_are_read_from_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    assert isolation.cad_seconds() == isolation.DEFAULT_SECONDS
    monkeypatch.setenv("WORKBENCH_CAD_SECONDS", "0")
    with pytest.raises(InputError, match=r"WORKBENCH_CAD_SECONDS: 0 must lie in"):
        isolation.cad_seconds()
    monkeypatch.setenv("WORKBENCH_CAD_MEMORY_BYTES", "1000")
    with pytest.raises(InputError, match=r"WORKBENCH_CAD_MEMORY_BYTES: 1000 is below"):
        isolation.cad_memory_bytes()


def test_a_reply_may_hold_arrays_and_the_readers_classes_only() -> None:
    import io

    ok = pickle.dumps(("ok", np.arange(3.0), True))
    assert isolation._Unpickler(io.BytesIO(ok)).load()[1].tolist() == [0.0, 1.0, 2.0]

    class Evil:
        def __reduce__(self) -> tuple:
            return (print, ("owned",))

    with pytest.raises(pickle.UnpicklingError, match=r"builtins\.print"):
        isolation._Unpickler(io.BytesIO(pickle.dumps(Evil()))).load()

    class Sneaky:  # a function of the allowed package: refused too
        def __reduce__(self) -> tuple:
            return (isolation.stop_workers, ())

    with pytest.raises(pickle.UnpicklingError, match=r"isolation\.stop_workers"):
        isolation._Unpickler(io.BytesIO(pickle.dumps(Sneaky()))).load()


def test_every_cad_read_goes_through_the_isolated_entry_points() -> None:
    """Only the worker's modules call the readers (OCP's STEPControl_Reader, ezdxf's readers)."""
    allowed = {"workbench/cad/step.py", "workbench/cad/dxf.py"}
    readers = re.compile(
        r"STEPControl_Reader\(|read_step_shape\(|recover\.read\(|ezdxf\.readfile\("
    )
    found = {
        str(p.relative_to(ROOT))
        for p in (ROOT / "workbench").rglob("*.py")
        if readers.search(p.read_text())
    }
    assert found == allowed


# -- the hostile files through the worker --------------------------------------------------------------
BIG = ("step_many_entities", "dxf_million_lines", "dxf_3000_bends")  # 4-8 s each: made, sent, read


@pytest.mark.parametrize(
    "case",
    [pytest.param(c, marks=pytest.mark.slow) if c in BIG else c for c in sorted(REFUSED)],
)
def test_a_hostile_file_is_refused_naming_the_file_and_the_setting(case: str) -> None:
    name, make = HOSTILE[case]
    with pytest.raises(WorkbenchError) as info:
        _read(name, make())
    assert info.value.field == "cell.objects[0].path"
    assert repr(name) in str(info.value) and re.search(REFUSED[case], str(info.value))


def test_the_worker_applies_the_bounds_set_here(monkeypatch: pytest.MonkeyPatch) -> None:
    data = (ROOT / "projects/parts/pan_flat.dxf").read_bytes()
    assert len(read_flat_pattern(data, "pan_flat.dxf", "x").bend_lines) == 4
    monkeypatch.setattr(dxf_checks, "MAX_BEND_LINES", 3)
    with pytest.raises(FlatPatternError, match=r"'pan_flat\.dxf' has 4 bend lines, more than 3"):
        read_flat_pattern(data, "pan_flat.dxf", "x")


def test_a_library_exception_becomes_a_workbench_error(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(dxf_checks, "MAX_SPLINE_DEGREE", 99)  # let ezdxf meet the spline
    name, make = HOSTILE["dxf_spline_degree_30"]
    with pytest.raises(
        MeshError, match=r"^bending\.part_file: cannot read 'spline\.dxf': ValueError"
    ):
        _read(name, make(), "bending.part_file")


def test_a_sphere_at_a_sane_size_still_reads() -> None:
    coarse = StepTolerance(linear=0.5e-3, angular=np.radians(20.0))  # fast to mesh
    mesh = read_step_mesh(sphere_step(50.0), "s.step", "x", coarse)
    assert mesh.is_watertight and mesh.volume == pytest.approx(4 / 3 * np.pi * 50.0**3, rel=5e-2)


def test_a_step_with_broken_references_is_refused_on_the_part_route_too() -> None:
    with pytest.raises(MeshError, match=r"does not load whole: 10 entities fail"):
        read_step_sheet(broken_step(), "broken.step", "bending.part_file")


def test_a_solid_that_meshes_open_is_refused() -> None:
    """The fixture block's closed shell without its first face: no load failure (the face is
    only left unnamed), but what should be a solid is an open shell."""
    text = STEP_EXAMPLES[2].read_bytes()
    holed = re.sub(rb"CLOSED_SHELL\('',\(#\d+,", b"CLOSED_SHELL('',(", text, count=1)
    assert holed != text
    with pytest.raises(
        MeshError, match=r"^x: STEP file 'block\.step': its solid meshes open \(\d+"
    ):
        read_step_mesh(holed, "block.step", "x", StepTolerance())


def test_closed_meshes_pass_and_open_or_inside_out_ones_are_refused() -> None:
    import trimesh

    box = trimesh.creation.box((10.0, 20.0, 30.0))
    step_checks.check_closed([box], "b.step", "x")
    with pytest.raises(MeshError, match=r"solid 2 of 2 is inside out .*volume -6000 mm³"):
        step_checks.check_closed([box, trimesh.Trimesh(box.vertices, box.faces[:, ::-1])], "b", "x")
    with pytest.raises(MeshError, match=r"its solid meshes open \(3 triangle edges"):
        step_checks.check_closed([trimesh.Trimesh(box.vertices, box.faces[1:])], "b", "x")


# -- crashes, hangs and swelling: the limits' seconds ---------------------------------------------------
@pytest.mark.slow  # a crash of Open CASCADE's parser (2-4 s) and a fresh worker that loads OCP again
def test_a_reader_that_crashes_is_a_refusal_and_the_next_read_works(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(step_checks, "MAX_STEP_NESTING", 10**9)  # let the parser meet the list
    with pytest.raises(
        MeshError, match=r"^tool\.mesh: the reader crashed on 'deep\.step' \(with SIGSEGV\)"
    ):
        read_step_mesh(deep_step(), "deep.step", "tool.mesh", StepTolerance())
    coarse = StepTolerance(linear=0.5e-3, angular=np.radians(20.0))
    assert read_step_mesh(sphere_step(50.0), "s.step", "x", coarse).is_watertight


@pytest.mark.slow  # runs into the 3 s time limit, then a fresh worker
def test_a_reader_that_hangs_is_stopped_at_the_time_limit(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("WORKBENCH_CAD_SECONDS", "3")
    fine = StepTolerance(linear=1e-6, angular=np.radians(0.5))  # 0.001 mm: the mesher takes minutes
    with pytest.raises(
        MeshError,
        match=r"reading 's\.step' took longer than 3 s \(WORKBENCH_CAD_SECONDS\) and was stopped;"
        r" simplify the file, raise the tolerances \(0\.001 mm, the project's 'cad' section\)",
    ):
        read_step_mesh(sphere_step(50.0), "s.step", "workpiece", fine)


@pytest.mark.slow  # ezdxf flattens a circle of 1e12 mm until the 1 GiB limit (some 5-10 s)
def test_a_reader_that_swells_is_stopped_at_the_memory_limit(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setenv("WORKBENCH_CAD_MEMORY_BYTES", str(1024**3))
    monkeypatch.setattr(step_checks, "MAX_COORDINATE_MM", 1e300)  # let ezdxf meet the circle
    with pytest.raises(
        MeshError,
        match=r"^bending\.part_file: reading 'c\.dxf' took more than the 1 GiB its reader may use"
        r" \(WORKBENCH_CAD_MEMORY_BYTES\)",
    ):
        read_flat_pattern(circle_dxf(1e12), "c.dxf", "bending.part_file")


def test_a_workpiece_is_read_as_a_mesh_or_a_step_only(tmp_path: Path) -> None:
    """trimesh reads a DXF as a 2D path, in this process and unbounded: refused by its ending."""
    from workbench.polishing.workpiece import load_workpiece

    path = tmp_path / "lines.dxf"
    path.write_bytes(block_bomb_dxf(2, 3))
    with pytest.raises(MeshError, match=r"workpiece file 'lines\.dxf' is not a mesh file"):
        load_workpiece(path, name="lines.dxf")


def test_import_part_refuses_a_step_with_broken_references(tmp_path: Path) -> None:
    from cli_run import run_cli

    path = tmp_path / "broken.step"
    path.write_bytes(broken_step())
    done = run_cli("import-part", str(path), "--out", str(tmp_path / "part.json"))
    assert done.returncode == 2 and not (tmp_path / "part.json").exists()
    assert (
        "broken.step (broken.step): STEP file 'broken.step' does not load whole: 10 entities"
        in (done.stderr)
    )


def test_a_worker_that_ended_while_idle_is_replaced() -> None:
    import os
    import signal

    data = (ROOT / "projects/parts/pan_flat.dxf").read_bytes()
    read_flat_pattern(data, "pan_flat.dxf", "x")
    assert isolation._idle, "the worker waits for the next read"
    for worker in isolation._idle:
        os.kill(worker.proc.pid, signal.SIGKILL)  # no wait: the read may reach it still dying
    assert len(read_flat_pattern(data, "pan_flat.dxf", "x").bend_lines) == 4
    # the race that check leaves: a worker that ends after it, before the request is sent
    gone = isolation._Worker(isolation.cad_memory_bytes())
    os.kill(gone.proc.pid, signal.SIGKILL)
    gone.proc.wait()
    assert gone.call("workbench.cad.dxf:flat_pattern_here", (data, "p.dxf", "x", "BEND"), 5.0) == (
        "gone",
        None,
    )


@pytest.mark.slow  # starts two more workers (some 3 s each on two cores)
def test_reads_from_several_threads_each_get_a_worker() -> None:
    """A server reads for several clients at once: each read takes an idle worker or starts one,
    and no more than MAX_IDLE_WORKERS stay afterwards."""
    from concurrent.futures import ThreadPoolExecutor

    data = (ROOT / "projects/parts/pan_flat.dxf").read_bytes()
    with ThreadPoolExecutor(4) as pool:
        done = list(pool.map(lambda i: read_flat_pattern(data, f"p{i}.dxf", "x"), range(4)))
    assert [len(p.bend_lines) for p in done] == [4] * 4
    assert 1 <= len(isolation._idle) <= isolation.MAX_IDLE_WORKERS
