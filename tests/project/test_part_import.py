"""Parts from CAD in a project: `bending.part_file` naming a STEP or DXF, `bending.part_import`.

- projects/step_channel_cell.json (the U-channel cell with parts/u_channel.step) loads, its
  part equals projects/parts/u_channel.json's (names mapped: F2 = base, F3 = A, F1 = B) in SI,
  and it plans the same cycle as projects/u_channel_cell.json;
- the settings: unknown fields and out-of-range values refused; a thickness or radius that
  contradicts the STEP refused naming the field; k_factor applied; base chosen by name;
- refusals name `bending.part_file` (truncated file, a block) or the setting;
- `workbench import-part` writes a part JSON that loads back to the same part;
- DXF: the thickness is required (before the reader is called); the reader and the flat-pattern
  conversion are called with the contract's arguments (stubbed: they land separately).
"""

from __future__ import annotations

import copy
import json
import shutil
import sys
import types
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from example_plans import bending_plan

from workbench import Workbench, WorkbenchError
from workbench.cli import main
from workbench.errors import MeshError, ProjectError

ROOT = Path(__file__).resolve().parents[2]
CELL = ROOT / "projects" / "step_channel_cell.json"
JSON_CELL = ROOT / "projects" / "u_channel_cell.json"
STEP = ROOT / "projects" / "parts" / "u_channel.step"
FLANGES = {"F2": "base", "F3": "A", "F1": "B"}
BENDS = {"B1": "bB", "B2": "bA"}


def _project(tmp_path: Path, **bending: Any) -> dict[str, Any]:
    """Return the STEP cell's dict with `bending` fields replaced (None: removed); its part
    file copied into `tmp_path`/parts."""
    (tmp_path / "parts").mkdir(exist_ok=True)
    shutil.copy(STEP, tmp_path / "parts" / STEP.name)
    data = json.loads(CELL.read_text())
    for k, v in bending.items():
        if v is None:
            data["bending"].pop(k, None)
        else:
            data["bending"][k] = v
    return data


def _part(tmp_path: Path, **bending: Any) -> Any:
    wb = Workbench.from_dict(_project(tmp_path, **bending), base_dir=tmp_path)
    return wb.bending.part


def test_the_step_cell_part_is_the_json_part() -> None:
    step = Workbench.open(CELL).bending.si().part
    ref = Workbench.open(JSON_CELL).bending.si().part
    assert step.thickness == pytest.approx(ref.thickness, abs=1e-12)
    by_name = {f.name: f for f in ref.flanges}
    assert [FLANGES[f.name] for f in step.flanges] == ["base", "B", "A"]
    for f in step.flanges:
        assert np.allclose(f.polygon, by_name[FLANGES[f.name]].polygon, atol=1e-12)
    ref_bends = {b.name: b for b in ref.bends}
    for b in step.bends:
        r = ref_bends[BENDS[b.name]]
        assert (FLANGES[b.parent], b.parent_edge, FLANGES[b.child], b.child_edge) == (
            r.parent,
            r.parent_edge,
            r.child,
            r.child_edge,
        )
        assert b.included_angle == pytest.approx(r.included_angle, abs=1e-12)
        assert b.inner_radius == pytest.approx(r.inner_radius, abs=1e-12)
        assert b.direction == r.direction


def test_the_step_cell_plans_the_json_cells_cycle() -> None:
    plan = Workbench.open(CELL).bending.plan()
    ref = bending_plan(JSON_CELL.name)[1]  # the JSON cell's plan, shared
    assert plan.ok, plan.summary()
    assert plan.cycle_time == pytest.approx(ref.cycle_time, rel=1e-9)
    assert plan.summary() == ref.summary().replace("bB bA", "B1 B2")


def test_k_factor_and_base_settings_apply(tmp_path: Path) -> None:
    part = _part(tmp_path, part_import={"k_factor": 0.4, "base": "F3"})
    assert part.flanges[0].name == "F3"
    assert all(b.k == 0.4 for b in part.bends)
    assert _part(tmp_path, part_import=None).flanges[0].name == "F3"  # the largest


@pytest.mark.parametrize(
    ("settings", "message"),
    [
        ({"colour": 1}, r"bending.part_import.colour: unknown field"),
        ({"thickness": -1}, r"bending.part_import.thickness"),
        ({"thickness": 1.5}, r"part_import.thickness: 1.5 mm, but the sheet .* is 2 mm thick"),
        ({"inner_radius": 2}, r"part_import.inner_radius: 2 mm, but bend B1 .* has 1.92 mm"),
        ({"bend_layer": "BENDS"}, r"part_import.bend_layer: only for a DXF part file"),
        ({"base": "F9"}, r"part_import.base: no flange 'F9'; the part's flanges are F1, F2, F3"),
    ],
)
def test_bad_settings_are_refused_naming_the_field(
    tmp_path: Path, settings: dict[str, Any], message: str
) -> None:
    with pytest.raises(WorkbenchError, match=message):
        _part(tmp_path, part_import=settings)


def test_part_import_needs_a_cad_part_file(tmp_path: Path) -> None:
    shutil.copy(ROOT / "projects" / "parts" / "u_channel.json", tmp_path / "u.json")
    with pytest.raises(ProjectError, match=r"part_import: only for a CAD part_file"):
        _part(tmp_path, part_file="u.json", part_import={"thickness": 2})


def test_a_truncated_step_is_refused_naming_the_part_file(tmp_path: Path) -> None:
    data = _project(tmp_path)
    path = tmp_path / "parts" / "cut.step"
    path.write_bytes(STEP.read_bytes()[:20_000])
    data["bending"]["part_file"] = "parts/cut.step"
    with pytest.raises(MeshError, match=r"bending.part_file \(parts/cut.step\): cannot read STEP"):
        _ = Workbench.from_dict(data, base_dir=tmp_path).bending.part


def test_a_block_is_refused_naming_the_part_file(tmp_path: Path) -> None:
    from bent_parts import block, step_of

    data = _project(tmp_path)
    (tmp_path / "parts" / "block.step").write_bytes(step_of(block()))
    data["bending"]["part_file"] = "parts/block.step"
    with pytest.raises(MeshError, match=r"bending.part_file \(parts/block.step\): no bends found"):
        _ = Workbench.from_dict(data, base_dir=tmp_path).bending.part


def test_import_part_command_writes_a_part_json_that_loads_back(tmp_path: Path) -> None:
    out = tmp_path / "u.json"
    assert main(["import-part", str(STEP), "--base", "F2", "--out", str(out)]) == 0
    written = json.loads(out.read_text())
    assert [f["name"] for f in written["flanges"]] == ["F2", "F1", "F3"]
    ref = Workbench.open(CELL).bending.si().part
    got = _part(tmp_path, part_file=str(out), part_import=None)
    assert [f.name for f in got.flanges] == [f.name for f in ref.flanges]
    for f, g in zip(got.flanges, ref.flanges, strict=True):
        assert np.allclose(f.polygon, g.polygon, atol=1e-12)
    assert main(["import-part", str(STEP), "--thickness", "3", "--out", str(tmp_path / "x")]) == 2
    assert not (tmp_path / "x").exists()


def test_a_dxf_needs_a_thickness(tmp_path: Path) -> None:
    (tmp_path / "flat.dxf").write_bytes(b"0\nEOF\n")
    with pytest.raises(ProjectError, match=r"bending.part_import.thickness: missing: a DXF"):
        _part(tmp_path, part_file="flat.dxf", part_import=None)


def test_a_dxf_goes_through_the_flat_pattern_contract(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import workbench.sheetmetal.flat_split as fp

    calls: dict[str, Any] = {}
    spec = {
        "thickness": 0.002,
        "flanges": [
            {"name": "F1", "polygon": [[0, 0], [0.2, 0], [0.2, 0.1], [0, 0.1]]},
            {"name": "F2", "polygon": [[0, 0], [0.2, 0], [0.2, 0.11], [0, 0.11]]},
            {"name": "F3", "polygon": [[0, 0], [0.2, 0], [0.2, 0.025], [0, 0.025]]},
        ],
        "bends": [
            {"name": "B1", "parent": "F1", "parent_edge": 0, "child": "F3", "child_edge": 0,
             "included_angle": np.pi / 2, "inner_radius": 0.00192, "direction": "up"},
            {"name": "B2", "parent": "F1", "parent_edge": 2, "child": "F2", "child_edge": 0,
             "included_angle": np.pi / 2, "inner_radius": None, "direction": "up"},
        ],
    }  # fmt: skip

    def read_flat_pattern(data: bytes, name: str, field: str, *, bend_layer: str) -> str:
        calls["read"] = (data, name, field, bend_layer)
        return "pattern"

    def part_spec(pattern: Any, **kw: Any) -> dict[str, Any]:
        calls["spec"] = (pattern, kw)
        return copy.deepcopy(spec)

    monkeypatch.setitem(
        sys.modules, "workbench.cad.dxf", types.SimpleNamespace(read_flat_pattern=read_flat_pattern)
    )
    monkeypatch.setattr(fp, "part_spec_from_flat_pattern", part_spec)
    (tmp_path / "flat.dxf").write_bytes(b"0\nEOF\n")
    settings = {"thickness": 2, "bend_layer": "FOLD", "k_factor": 0.4, "inner_radius": 3}
    data = _project(tmp_path, part_file="flat.dxf", part_import=settings)
    data["bending"]["grasp"]["flange"] = "F1"
    wb = Workbench.from_dict(data, base_dir=tmp_path)
    part = wb.bending.part_spec()
    where = "bending.part_file (flat.dxf)"
    assert calls["read"] == (b"0\nEOF\n", "flat.dxf", where, "FOLD")
    assert calls["spec"] == (
        "pattern",
        {"thickness": 0.002, "inner_radius": 0.003, "k_factor": 0.4, "field": where},
    )
    assert part.thickness == 2.0 and [b.inner_radius for b in part.bends] == [1.92, None]
    assert part.bends[0].included_angle == 90.0 and part.flanges[2].polygon[2] == [200.0, 25.0]
