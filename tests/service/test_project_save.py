"""Nothing saved is lost: every save reopens (and plans) wherever it was written.

The twin of `service.project_save` is the loader itself: a saved file is opened again from its
new place (here, and from a fresh process in the slow test) and compared field by field with
the project that was saved, its named files byte for byte with the originals.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from workbench import Workbench
from workbench.errors import InputError, ProjectError, WorkbenchError
from workbench.project import project_from_dict
from workbench.project.paths import ProjectFolders
from workbench.service.project_files import named_fields, named_files
from workbench.service.project_imports import add_cell_file
from workbench.service.project_save import save_project_file

ROOT = Path(__file__).resolve().parents[2]
PROJECTS = ROOT / "projects"
EXAMPLES = sorted(PROJECTS.glob("*.json"))
IDS = [p.stem for p in EXAMPLES]


def _dump_without_paths(wb: Workbench) -> dict[str, Any]:
    """Return the project's JSON with every file path blanked (they are rebased on a save)."""
    project = wb.project.model_copy(deep=True)
    for _, path, model, attr in named_fields(project):
        blank = "file" + Path(path).suffix  # the kind stays: validators read the suffix
        if isinstance(model, list):
            model[int(attr)] = blank
        else:
            setattr(model, attr, blank)
    return project.model_dump(mode="json")


def _files(wb: Workbench) -> list[bytes]:
    """Return the bytes of every file the project names, in order."""
    return [wb.folders.resolve(p, w).read_bytes() for w, p in named_files(wb.project)]


def _tree(tmp_path: Path) -> Path:
    """Return a copy of the examples with the meshes beside them, as in the repository."""
    tree = tmp_path / "tree"
    shutil.copytree(PROJECTS, tree / "projects")
    shutil.copytree(ROOT / "web_assets", tree / "web_assets")
    return tree


@pytest.mark.parametrize("example", EXAMPLES, ids=IDS)
def test_an_example_saved_elsewhere_reopens_the_same_project_with_the_same_files(
    example: Path, tmp_path: Path
) -> None:
    wb = Workbench.open(example)
    before, files = _dump_without_paths(wb), _files(wb)
    target = tmp_path / "elsewhere" / "mine.json"
    target.parent.mkdir()
    saved = save_project_file(wb, target, files="copy")  # rebase: test_project_portable
    again = Workbench.open(target)  # checks every file it names, the lazy ones too
    assert _dump_without_paths(again) == before
    assert _files(again) == files
    for field, path in named_files(again.project):
        assert not Path(path).is_absolute(), field
        assert (target.parent / path).resolve().is_relative_to(target.parent), field
    assert set(saved.copied) <= {p for p in target.parent.rglob("*") if p.is_file()}
    assert wb.path == target and wb.folders.base == target.parent
    assert Workbench.open(target).project.model_dump() == again.project.model_dump()


@pytest.mark.parametrize("example", EXAMPLES, ids=IDS)
def test_an_example_saved_in_place_changes_no_path_and_round_trips(
    example: Path, tmp_path: Path
) -> None:
    tree = _tree(tmp_path)
    path = tree / "projects" / example.name
    meshes = [tree / "web_assets"]
    wb = Workbench.open(path, allowed_dirs=meshes)
    before = wb.project.model_dump(mode="json")
    wb.save()
    assert json.loads(path.read_text()) == wb.project.model_dump(mode="json", exclude_none=True)
    again = Workbench.open(path, allowed_dirs=meshes)
    assert again.project.model_dump(mode="json") == before  # every section, paths included
    assert sorted(p.name for p in (tree / "projects").iterdir()) == sorted(
        p.name for p in PROJECTS.iterdir()
    )  # nothing copied


def test_a_step_part_project_saved_in_place_opens_again(tmp_path: Path) -> None:
    """The reported case: the save wrote bending.part_import.bend_layer, which the loader
    refuses for a STEP part; older files holding the default "BEND" open too."""
    tree = _tree(tmp_path)
    path = tree / "projects" / "step_channel_cell.json"
    wb = Workbench.open(path)
    wb.save(path)
    assert "bend_layer" not in path.read_text()
    Workbench.open(path)
    data = json.loads(path.read_text())
    data["bending"].setdefault("part_import", {})["bend_layer"] = "BEND"  # as older saves wrote
    path.write_text(json.dumps(data))
    Workbench.open(path)
    data["bending"]["part_import"]["bend_layer"] = "FOLDS"
    path.write_text(json.dumps(data))
    with pytest.raises(ProjectError, match="bend_layer: only for a DXF part file"):
        Workbench.open(path)


def test_an_obstacle_from_a_temporary_folder_is_copied_beside_the_project(
    tmp_path: Path,
) -> None:
    upload = tmp_path / "upload"  # under the system's temporary folder, as an upload is
    upload.mkdir()
    box = upload / "block.stl"
    _box(box)
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    wb.folders = wb.folders.with_allowed(upload)
    add_cell_file(wb, box, xyz_mm=[900.0, 0.0, 200.0])
    target = tmp_path / "saved" / "cell.json"
    target.parent.mkdir()
    wb.save(target)
    shutil.rmtree(upload)  # the upload folder goes when the server stops
    again = Workbench.open(target)
    obj = again.project.cell.objects[-1]
    assert obj.path == "files/block.stl"
    assert (target.parent / "files" / "block.stl").read_bytes() == _box_bytes()


def test_a_session_folder_is_copied_and_a_copy_never_replaces_another_file(
    tmp_path: Path,
) -> None:
    session = Path(tmp_path / "session")
    session.mkdir()
    _box(session / "block.stl")
    target = tmp_path / "saved" / "cell.json"
    (target.parent / "files").mkdir(parents=True)
    (target.parent / "files" / "block.stl").write_text("the user's own file")
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    wb.folders = wb.folders.with_session(session)
    add_cell_file(wb, session / "block.stl")
    saved = save_project_file(wb, target)
    assert wb.project.cell.objects[-1].path == "files/block_2.stl"
    assert (target.parent / "files" / "block.stl").read_text() == "the user's own file"
    assert saved.copied == (target.parent / "files" / "block_2.stl",)
    assert "copied block.stl to files/block_2.stl" in saved.notes
    assert not any(str(session) in n for n in saved.notes)  # no server folder in a note


def test_a_file_in_a_folder_allowed_at_start_is_named_absolutely(tmp_path: Path) -> None:
    shared = Path(ROOT / "web_assets").resolve()  # allowed, but bundled: rebased instead
    wb = Workbench.open(PROJECTS / "polishing_cell.json", allowed_dirs=[shared])
    target = tmp_path / "p" / "polish.json"
    target.parent.mkdir()
    wb.save(target)
    assert wb.project.polishing is not None
    rebased = os.path.relpath(shared / "workpieces" / "panel.stl", target.parent.resolve())
    assert wb.project.polishing.workpiece == rebased
    mine = Path.home() / ".cache" / "workbench-test-allowed"  # outside the temporary folder
    mine.mkdir(parents=True, exist_ok=True)
    try:
        _box(mine / "block.stl")
        wb = Workbench.open(PROJECTS / "mz07_cell.json", allowed_dirs=[mine])
        add_cell_file(wb, mine / "block.stl")
        saved = save_project_file(wb, tmp_path / "p" / "cell.json")
        assert wb.project.cell.objects[-1].path == str((mine / "block.stl").resolve())
        assert any("--allow-dir" in n for n in saved.notes)
        Workbench.open(tmp_path / "p" / "cell.json", allowed_dirs=[mine])
        with pytest.raises(InputError, match="outside the project's folder"):
            Workbench.open(tmp_path / "p" / "cell.json")
    finally:
        shutil.rmtree(mine)


def test_a_save_that_would_not_open_writes_nothing(tmp_path: Path) -> None:
    tree = _tree(tmp_path)
    path = tree / "projects" / "pan_cell.json"
    wb = Workbench.open(path)
    original = path.read_bytes()
    (tree / "projects" / "parts" / "pan.json").write_text("{ broken")  # gone bad since open
    target = tmp_path / "out" / "pan.json"
    target.parent.mkdir()
    target.write_bytes(b"the previous file")
    with pytest.raises(WorkbenchError, match="bending.part_file") as caught:
        wb.save(target)
    assert "nothing written" in str(caught.value)
    assert target.read_bytes() == b"the previous file"
    assert sorted(p.name for p in target.parent.iterdir()) == ["pan.json"]  # no parts/ left
    with pytest.raises(WorkbenchError, match="bending.part_file"):
        wb.save()
    assert path.read_bytes() == original
    assert wb.path == path  # a refused save keeps the project's file
    (tree / "projects" / "parts" / "pan.json").unlink()  # gone since open
    with pytest.raises(WorkbenchError, match=r"bending\.part_file.*no such file"):
        wb.save(target)
    assert target.read_bytes() == b"the previous file"


def test_a_missing_folder_or_an_existing_file_without_overwrite_is_refused(
    tmp_path: Path,
) -> None:
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    with pytest.raises(InputError, match="does not exist; create it first"):
        wb.save(tmp_path / "missing" / "x.json")
    assert not (tmp_path / "missing").exists()
    (tmp_path / "x.json").write_text("mine")
    with pytest.raises(InputError, match="tick 'Overwrite'"):
        wb.save(tmp_path / "x.json", overwrite=False)
    assert (tmp_path / "x.json").read_text() == "mine"


def test_open_checks_the_files_read_later(tmp_path: Path) -> None:
    """A project that would fail at plan (a part file, a workpiece, an assembly mesh gone)
    fails at open, naming the field."""
    cases = {
        "pan_cell.json": ("parts/pan.json", "bending.part_file"),
        "polishing_cell.json": ("../web_assets/workpieces/panel.stl", "polishing.workpiece"),
        "assembly_cell.json": ("../web_assets/parts/plate.stl", "assembly.parts[0].path"),
    }
    for name, (rel, field) in cases.items():
        tree = _tree(tmp_path / name)
        (tree / "projects" / rel).unlink()
        with pytest.raises(WorkbenchError, match=field.replace("[", r"\[")):
            Workbench.open(tree / "projects" / name, allowed_dirs=[tree / "web_assets"])


def test_the_writer_refuses_what_the_loader_would_refuse() -> None:
    wb = Workbench.open(PROJECTS / "step_channel_cell.json")
    assert wb.project.bending is not None
    # a state the models' own checks did not see (as the dumped default bend_layer was):
    # part_import is for CAD part files only
    object.__setattr__(wb.project.bending, "part_file", "parts/u_channel.json")
    with pytest.raises(ProjectError, match="(?s)would not load.*part_import"):
        wb.to_json()


def test_use_robot_on_a_step_part_project_and_the_cli_out(tmp_path: Path) -> None:
    from workbench.cli import main

    wb = Workbench.open(PROJECTS / "step_channel_cell.json")
    wb.use_robot("irb1200_7_70")  # rebuilt from the saved JSON: refused before the fix
    target = tmp_path / "robot.json"
    wb.save(target)
    Workbench.open(target)
    assert (
        main(["import-part", str(PROJECTS / "parts/u_channel.step"), "--out", "/nowhere/x.json"])
        == 2
    )


def _box_bytes() -> bytes:
    import trimesh

    return bytes(trimesh.creation.box((0.2, 0.3, 0.4)).export(file_type="stl"))


def _box(path: Path) -> None:
    path.write_bytes(_box_bytes())


@pytest.mark.slow
def test_every_example_saved_in_place_and_elsewhere_plans_from_a_fresh_process(
    tmp_path: Path,
) -> None:
    """The copies saved elsewhere are planned from a fresh process (no file cached); the ones
    saved in place reopen as the same project with the same files, which plans the same (the
    planners are deterministic: test_plan_determinism), so they are not planned twice."""
    tree = _tree(tmp_path)
    meshes = tree / "web_assets"
    saved: list[Path] = []
    for example in EXAMPLES:
        in_place = tree / "projects" / example.name
        opened = Workbench.open(in_place, allowed_dirs=[meshes])
        before, files = _dump_without_paths(opened), _files(opened)
        opened.save()
        again = Workbench.open(in_place, allowed_dirs=[meshes])
        assert _dump_without_paths(again) == before and _files(again) == files, example.name
        elsewhere = tmp_path / "elsewhere" / example.stem / example.name
        elsewhere.parent.mkdir(parents=True)
        Workbench.open(example).save(elsewhere)
        saved.append(elsewhere)
    script = (
        "import sys\n"
        "from workbench import Workbench\n"
        "from workbench.service.programs import plan_workflow\n"
        "for path in sys.argv[2:]:\n"
        "    wb = Workbench.open(path, allowed_dirs=[sys.argv[1]])\n"
        "    for wf in wb.project.workflows():\n"
        "        plan = plan_workflow(wb, wf)\n"
        "        print('planned', path, wf, plan.summary(), flush=True)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script, str(meshes), *map(str, saved)],
        capture_output=True,
        text=True,
        timeout=1500,
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-4000:]
    for path in saved:
        workflows = project_from_dict(json.loads(path.read_text())).workflows()
        for wf in workflows:
            assert f"planned {path} {wf}" in done.stdout


def test_folders_moved_keep_the_allowed_and_the_session_ones(tmp_path: Path) -> None:
    folders = ProjectFolders(tmp_path, [tmp_path / "a"], [tmp_path / "s"])
    moved = folders.moved_to(tmp_path / "new")
    assert moved.base == tmp_path / "new"
    assert moved.allowed == folders.allowed and moved.session == folders.session
    assert folders.without(tmp_path / "s").session == ()
