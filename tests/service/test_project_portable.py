"""Portable projects (issue 29 part 7): every example saved to another folder (files rebased or
copied) and downloaded as a .zip and unpacked again is the same project, its files the same
files (rebase) or the same bytes (copy, zip); hostile zips are refused naming the member.

The twin is the loader: the saved file is opened again from its new place and compared with the
original with every path resolved to the real file it names.
"""

from __future__ import annotations

import io
import os
import shutil
import stat
import zipfile
from pathlib import Path
from typing import Any

import pytest

from workbench import Workbench
from workbench.errors import InputError, WorkbenchError
from workbench.project import Project, load_project
from workbench.project.archive import read_zip, write_zip
from workbench.service.project_files import named_fields, named_files
from workbench.service.project_save import save_project_file

ROOT = Path(__file__).resolve().parents[2]
PROJECTS = ROOT / "projects"
EXAMPLES = sorted(PROJECTS.glob("*.json"))
IDS = [p.stem for p in EXAMPLES]

# Every text field of the project file, by JSON path: those that name a file, and the others.
# A new text field must be added to one of the two (the test below reads the schema), so a new
# file field cannot be missed by the save, the copy and the zip.
FILE_FIELDS = {
    ".assembly.parts[].path",
    ".bending.part_file",
    ".cell.objects[].path",
    ".polishing.workpiece",
    ".robot.link_meshes[]",
    ".robot.urdf",
    ".tool.mesh",
}
NOT_FILES = {
    ".assembly.parts[].name", ".assembly.parts[].robot", ".assembly.parts[].shape",
    ".assembly.planner.name", ".assembly.robots[].name", ".assembly.robots[].preset",
    ".assembly.sequence[].part", ".bending.grasp.face", ".bending.grasp.flange",
    ".bending.grasp_grid.faces[]", ".bending.part.bends[].child",
    ".bending.part.bends[].direction", ".bending.part.bends[].name",
    ".bending.part.bends[].parent", ".bending.part.flanges[].name", ".bending.part.name",
    ".bending.part.note", ".bending.part.sequence[]", ".bending.part.units",
    ".bending.part_import.base", ".bending.part_import.bend_layer",
    ".bending.press.stations[].name", ".bending.sequence[]", ".bending.steps[].bend",
    ".bending.steps[].grasp.face", ".bending.steps[].grasp.flange", ".bending.steps[].station",
    ".cell.objects[].name", ".cell.objects[].shape", ".collision.exempt[][]", ".collision.mode",
    ".description", ".io.gripper.closed_input", ".io.gripper.opened_input", ".io.gripper.output",
    ".io.inputs[].name", ".io.outputs[].name", ".io.press.clamped", ".io.press.start",
    ".io.press.top", ".name", ".polishing.pattern", ".polishing.units", ".program.moves[].action",
    ".program.moves[].name", ".program.moves[].signal", ".program.moves[].text",
    ".program.moves[].type", ".program.moves[].wobj", ".program.name", ".robot.name",
    ".robot.preset", ".tool.name", ".work_objects[].name",
}  # fmt: skip


def _text_fields() -> set[str]:
    """Return the JSON path of every text field of the project schema."""
    schema = Project.model_json_schema()
    defs = schema.get("$defs", {})
    out: set[str] = set()

    def walk(node: dict[str, Any], path: str, seen: frozenset[str]) -> None:
        if "$ref" in node:
            name = node["$ref"].split("/")[-1]
            if name not in seen:
                walk(defs[name], path, seen | {name})
            return
        for key in ("anyOf", "oneOf", "allOf"):
            for sub in node.get(key, []):
                walk(sub, path, seen)
        if node.get("type") == "string":
            out.add(path)
        for key, sub in node.get("properties", {}).items():
            walk(sub, f"{path}.{key}", seen)
        if isinstance(node.get("items"), dict):
            walk(node["items"], path + "[]", seen)
        if isinstance(node.get("additionalProperties"), dict):
            walk(node["additionalProperties"], path + "{}", seen)

    walk(schema, "", frozenset())
    return out


def test_every_text_field_of_the_schema_is_known_as_a_file_or_not() -> None:
    fields = _text_fields()
    unknown = fields - FILE_FIELDS - NOT_FILES
    assert not unknown, f"new text fields: add each to FILE_FIELDS or NOT_FILES: {unknown}"
    assert FILE_FIELDS <= fields  # none renamed away


def test_named_fields_lists_every_file_field_of_the_schema() -> None:
    """A project with every file field set: `named_fields` (what save, copy and zip walk)
    names each, as the schema's paths."""
    p = load_project(PROJECTS / "step_cell.json")
    object.__setattr__(p.robot, "urdf", "robot.urdf")  # past the one-robot-source check
    object.__setattr__(p.robot, "link_meshes", ["l0.stl"])
    object.__setattr__(p.tool, "mesh", "tool.stl")
    object.__setattr__(p, "bending", load_project(PROJECTS / "bending_cell.json").bending)
    object.__setattr__(p, "assembly", load_project(PROJECTS / "assembly_cell.json").assembly)
    listed = {_schema_path(where) for where, _, _, _ in named_fields(p)}
    assert listed == FILE_FIELDS


def _schema_path(where: str) -> str:
    import re

    return "." + re.sub(r"\[\d+\]", "[]", where)


def _without_paths(project: Project) -> dict[str, Any]:
    project = project.model_copy(deep=True)
    for _, path, model, attr in named_fields(project):
        blank = "file" + Path(path).suffix
        if isinstance(model, list):
            model[int(attr)] = blank
        else:
            setattr(model, attr, blank)
    return project.model_dump(mode="json")


def _real_files(wb: Workbench) -> list[Path]:
    """Return the real file each path of the project names, in order (the path rule's)."""
    return [wb.folders.resolve(p, w) for w, p in named_files(wb.project)]


@pytest.mark.slow  # about 15 s: every example opened three times
@pytest.mark.parametrize("mode", ["rebase", "copy"])
@pytest.mark.parametrize("example", EXAMPLES, ids=IDS)
def test_an_example_saved_to_another_folder_reopens_as_the_same_project(
    example: Path, mode: str, tmp_path: Path
) -> None:
    wb = Workbench.open(example)
    before, files = _without_paths(wb.project), _real_files(wb)
    target = tmp_path / "elsewhere" / "mine.json"
    target.parent.mkdir()
    saved = save_project_file(wb, target, files=mode)
    again = Workbench.open(target)  # every file it names checked, the lazy ones too
    assert _without_paths(again.project) == before
    now = _real_files(again)
    assert len(now) == len(files)
    for (field, path), old, new in zip(named_files(again.project), files, now, strict=True):
        assert new.read_bytes() == old.read_bytes(), field
        if mode == "copy":  # the folder is whole: everything inside it, by relative paths
            assert not os.path.isabs(path) and new.is_relative_to(target.parent.resolve())
        elif new != old:  # rebase copies only what the new place may not read
            assert new in saved.copied, field
            assert not old.is_relative_to((ROOT / "web_assets").resolve()), field
        else:
            assert not os.path.isabs(path), field  # rebased, still relative


def test_rebase_names_the_bundled_meshes_from_the_new_folder(tmp_path: Path) -> None:
    wb = Workbench.open(PROJECTS / "step_cell.json")
    wb.save(tmp_path / "x.json")
    paths = dict(named_files(wb.project))
    expected = os.path.relpath(ROOT / "web_assets/parts/fixture_block.step", tmp_path.resolve())
    assert paths["cell.objects[2].path"] == Path(expected).as_posix()
    assert not (tmp_path / "files").exists()  # nothing copied
    wb.save(tmp_path / "y.json", files="copy")
    assert dict(named_files(wb.project))["cell.objects[2].path"] == "files/fixture_block.step"


def test_copy_never_replaces_another_file_and_a_refused_copy_leaves_nothing(
    tmp_path: Path,
) -> None:
    (tmp_path / "files").mkdir()
    (tmp_path / "files" / "panel.stl").write_text("the user's own file")
    wb = Workbench.open(PROJECTS / "polishing_cell.json")
    saved = save_project_file(wb, tmp_path / "p.json", files="copy")
    assert dict(named_files(wb.project))["polishing.workpiece"] == "files/panel_2.stl"
    assert (tmp_path / "files" / "panel.stl").read_text() == "the user's own file"
    assert saved.copied == (tmp_path.resolve() / "files" / "panel_2.stl",)
    src = tmp_path / "src"
    (src / "parts").mkdir(parents=True)
    shutil.copy(PROJECTS / "pan_cell.json", src)
    shutil.copy(PROJECTS / "parts" / "pan.json", src / "parts")
    wb = Workbench.open(src / "pan_cell.json")
    (src / "parts" / "pan.json").write_text("{ broken")  # gone bad since open
    out = tmp_path / "out"
    out.mkdir()
    with pytest.raises(WorkbenchError, match="nothing written.*bending.part_file"):
        wb.save(out / "p.json", files="copy")
    assert list(out.iterdir()) == []  # the copies made are gone too


def test_an_unknown_mode_is_refused_naming_the_choices(tmp_path: Path) -> None:
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    with pytest.raises(InputError, match="'rebase'.*'copy'"):
        wb.save(tmp_path / "x.json", files="move")
    assert not (tmp_path / "x.json").exists()


@pytest.mark.slow  # about 8 s: every example opened twice
@pytest.mark.parametrize("example", EXAMPLES, ids=IDS)
def test_an_example_zipped_and_unzipped_is_the_same_project(example: Path, tmp_path: Path) -> None:
    wb = Workbench.open(example)
    before_json = wb.to_json()
    data = wb.to_zip()
    assert wb.to_json() == before_json and wb.path == example  # the project is unchanged
    names = zipfile.ZipFile(io.BytesIO(data)).namelist()
    assert names[0] == example.name
    assert all(not n.startswith("/") and ".." not in n.split("/") for n in names)
    again = Workbench.from_zip(data, tmp_path / "unzipped")
    assert again.path == tmp_path / "unzipped" / example.name
    assert _without_paths(again.project) == _without_paths(wb.project)
    old, new = _real_files(wb), _real_files(again)
    assert [p.read_bytes() for p in new] == [p.read_bytes() for p in old]
    assert all(p.is_relative_to((tmp_path / "unzipped").resolve()) for p in new)
    assert len(names) == 1 + len({p for p in old})  # the JSON and each file once
    assert again.to_zip() == data  # the same project gives the same bytes


def _zip(members: list[tuple[zipfile.ZipInfo | str, bytes]]) -> bytes:
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        for info, body in members:
            z.writestr(info, body)
    return out.getvalue()


MZ07 = (PROJECTS / "mz07_cell.json").read_bytes()


def _link(name: str) -> zipfile.ZipInfo:
    info = zipfile.ZipInfo(name)
    info.external_attr = (stat.S_IFLNK | 0o777) << 16
    return info


@pytest.mark.parametrize(
    ("members", "words"),
    [
        ([("/etc/cell.json", MZ07)], "'/etc/cell.json' has an absolute name"),
        ([("C:/cell.json", MZ07)], "absolute name"),
        ([("cell.json", MZ07), ("../x.stl", b"x")], r"'\.\./x\.stl' leaves the zip's folder"),
        ([("a/../../cell.json", MZ07)], "leaves the zip's folder"),
        ([("cell.json", MZ07), (_link("files/x.stl"), b"/etc/passwd")], "symbolic link"),
        ([("cell.json", MZ07), ("x\x01.stl", b"x")], "unusable name"),
        ([("cell.json", MZ07), ("bomb.stl", b"\0" * (8 << 20))], "zip bomb"),
        ([("cell.json", MZ07), ("cell.json", MZ07)], "appears twice"),
    ],
    ids=["absolute", "drive", "dotdot", "dotdot-inside", "symlink", "control", "bomb", "twice"],
)
def test_a_hostile_zip_is_refused_naming_the_member_and_nothing_written(
    members: list[tuple[zipfile.ZipInfo | str, bytes]], words: str, tmp_path: Path
) -> None:
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # zipfile warns of the duplicate name
        data = _zip(members)
    with pytest.raises(InputError, match=f"hostile.zip: .*{words}"):
        Workbench.from_zip(data, tmp_path / "out", source="hostile.zip")
    assert not (tmp_path / "out").exists()


def test_the_zip_limits_are_settings(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    data = _zip([("cell.json", MZ07), ("a.stl", os.urandom(len(MZ07) + 3000)), ("b.stl", b"b")])
    monkeypatch.setenv("WORKBENCH_MAX_ZIP_MEMBERS", "2")
    with pytest.raises(InputError, match="holds 3 files, at most 2.*WORKBENCH_MAX_ZIP_MEMBERS"):
        read_zip(data, "z.zip")
    monkeypatch.setenv("WORKBENCH_MAX_ZIP_MEMBERS", "3")
    monkeypatch.setenv("WORKBENCH_MAX_ZIP_BYTES", str(len(MZ07) + 2000))
    with pytest.raises(InputError, match="'a.stl'.*WORKBENCH_MAX_ZIP_BYTES"):
        read_zip(data, "z.zip")
    monkeypatch.delenv("WORKBENCH_MAX_ZIP_BYTES")
    monkeypatch.setenv("WORKBENCH_MAX_MESH_BYTES", str(len(MZ07) + 1000))
    with pytest.raises(InputError, match="'a.stl' is .* over the file limit"):
        read_zip(data, "z.zip")
    monkeypatch.delenv("WORKBENCH_MAX_MESH_BYTES")
    assert [n for n, _ in read_zip(data, "z.zip")] == ["cell.json", "a.stl", "b.stl"]


def test_a_member_that_unpacks_to_more_than_it_declares_is_refused() -> None:
    body = b"\0" * 100_000
    data = bytearray(_zip([("cell.json", MZ07), ("x.stl", body)]))
    # lower x.stl's declared size in its central directory entry (offset 24 of the entry)
    at = data.rfind(b"PK\x01\x02")
    data[at + 24 : at + 28] = (1000).to_bytes(4, "little")
    with pytest.raises(InputError, match="'x.stl'"):
        read_zip(bytes(data), "z.zip")


def test_a_zip_lacking_a_file_or_without_a_project_is_refused(tmp_path: Path) -> None:
    bending = (PROJECTS / "bending_cell.json").read_bytes()
    with pytest.raises(InputError, match=r"lacks files its project names \(parts/seed_part"):
        Workbench.from_zip(_zip([("cell/b.json", bending)]), tmp_path / "a")
    with pytest.raises(InputError, match="holds no project .json"):
        Workbench.from_zip(_zip([("x.stl", b"x")]), tmp_path / "b")
    with pytest.raises(InputError, match="not a readable zip"):
        Workbench.from_zip(b"PK not really", tmp_path / "c")
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "mine.txt").write_text("kept")
    with pytest.raises(InputError, match="new or empty folder"):
        Workbench.from_zip(_zip([("m.json", MZ07)]), tmp_path / "d")
    assert [p.name for p in (tmp_path / "d").iterdir()] == ["mine.txt"]
    assert not any((tmp_path / n).exists() for n in "abc")


def test_write_zip_round_trips_through_read_zip() -> None:
    files = [("p.json", b"{}"), ("files/a.stl", os.urandom(5000)), ("parts/b.dxf", b"0\nEOF")]
    assert read_zip(write_zip(files), "z.zip") == files


@pytest.mark.slow  # about 5 s: a program of 374 items read and re-solved twice
def test_the_cli_saves_with_files_rebase_or_copy(tmp_path: Path) -> None:
    from workbench.cli import main

    program = str(ROOT / "tests/golden_examples/polishing/urscript/polish.script")
    project = str(PROJECTS / "step_cell.json")
    for mode in ("rebase", "copy"):
        out = tmp_path / mode / "cell.json"
        out.parent.mkdir()
        assert main(["import", project, program, "--out", str(out), "--files", mode]) == 0
        paths = dict(named_files(Workbench.open(out).project))
        where = (out.parent / paths["polishing.workpiece"]).resolve()
        expected = (
            ROOT / "web_assets/workpieces/panel.step"
            if mode == "rebase"
            else out.parent.resolve() / "files/panel.step"
        )
        assert where == expected.resolve()
