"""Issue 16 part 2: every path a project names stays in the project's folder or an allowed one.

The twin of each refusal is the same file reached from inside (or through an allowed folder),
which loads: the rule refuses the place, not the file.
"""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import pytest
import trimesh

from workbench import Workbench
from workbench.errors import InputError, MeshError, ProjectError, WorkbenchError
from workbench.project import load_project
from workbench.project.paths import ProjectFolders, read_regular_file, size_limit

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "projects" / "mz07_cell.json"
BENDING = ROOT / "projects" / "bending_cell.json"


def _project(folder: Path, mesh_path: str) -> Path:
    """Write the example cell with one mesh object at `mesh_path` into `folder`."""
    data = json.loads(EXAMPLE.read_text())
    data["cell"]["objects"].append({"name": "jig", "shape": "mesh", "path": mesh_path})
    p = folder / "cell.json"
    p.write_text(json.dumps(data))
    return p


@pytest.fixture
def tree(tmp_path: Path) -> dict[str, Path]:
    """A project folder beside an outside folder, each with a small closed mesh."""
    proj, outside = tmp_path / "proj", tmp_path / "outside"
    proj.mkdir()
    outside.mkdir()
    box = trimesh.creation.box(extents=[10.0, 10.0, 10.0])
    box.export(proj / "inside.stl")
    box.export(outside / "secret.stl")
    return {"proj": proj, "outside": outside}


def test_a_relative_path_inside_loads_and_an_escape_is_refused(tree: dict[str, Path]) -> None:
    proj, outside = tree["proj"], tree["outside"]
    wb = Workbench.open(_project(proj, "inside.stl"))
    assert len(wb.cell) == 6
    for given in ("../outside/secret.stl", str(outside / "secret.stl")):
        with pytest.raises(InputError, match=r"cell\.objects\[5\]\.path: .*outside the project"):
            Workbench.open(_project(proj, given))


def test_the_refusal_does_not_tell_whether_the_outside_file_exists(tree: dict[str, Path]) -> None:
    proj, outside = tree["proj"], tree["outside"]
    assert (outside / "secret.stl").is_file() and not (outside / "no_such_file.stl").exists()
    messages = []
    for name in ("secret.stl", "no_such_file.stl"):
        with pytest.raises(InputError) as err:
            Workbench.open(_project(proj, f"../outside/{name}"))
        messages.append(str(err.value).replace(name, "X"))
    assert messages[0] == messages[1]


def test_a_symlink_leaving_the_folder_is_refused(tree: dict[str, Path]) -> None:
    proj, outside = tree["proj"], tree["outside"]
    (proj / "link.stl").symlink_to(outside / "secret.stl")
    (proj / "sub").symlink_to(outside, target_is_directory=True)
    for given in ("link.stl", "sub/secret.stl"):
        with pytest.raises(InputError, match="outside the project"):
            Workbench.open(_project(proj, given))
    # A symlink that stays inside is fine.
    (proj / "alias.stl").symlink_to(proj / "inside.stl")
    assert len(Workbench.open(_project(proj, "alias.stl")).cell) == 6


def test_allowed_dirs_let_a_folder_in(tree: dict[str, Path]) -> None:
    proj, outside = tree["proj"], tree["outside"]
    wb = Workbench.open(_project(proj, str(outside / "secret.stl")), allowed_dirs=[outside])
    assert wb.cell[-1].name == "jig"
    wb = Workbench.open(_project(proj, "../outside/secret.stl"), allowed_dirs=[str(outside)])
    assert wb.cell[-1].name == "jig"


def test_only_regular_files_are_read(tree: dict[str, Path]) -> None:
    proj = tree["proj"]
    os.mkfifo(proj / "pipe.stl")  # would block a plain open() forever
    (proj / "folder.stl").mkdir()
    for given in ("pipe.stl", "folder.stl"):
        with pytest.raises(InputError, match="not a regular file"):
            Workbench.open(_project(proj, given))
    # /dev/zero stays refused even when its folder is allowed.
    folders = ProjectFolders(proj, ["/dev"])
    with pytest.raises(InputError, match="not a regular file"):
        folders.read("/dev/zero", "bending.part_file", kind="part")
    with pytest.raises(ProjectError, match="not a regular file"):
        load_project("/dev/zero")
    with pytest.raises(InputError, match="not a regular file"):
        read_regular_file(proj / "pipe.stl", kind="project", field="project")


def test_size_limits_are_settings(tree: dict[str, Path], monkeypatch: pytest.MonkeyPatch) -> None:
    proj = tree["proj"]
    size = (proj / "inside.stl").stat().st_size
    monkeypatch.setenv("WORKBENCH_MAX_MESH_BYTES", str(size - 1))
    assert size_limit("mesh") == size - 1
    with pytest.raises(InputError, match="WORKBENCH_MAX_MESH_BYTES"):
        Workbench.open(_project(proj, "inside.stl"))
    monkeypatch.setenv("WORKBENCH_MAX_MESH_BYTES", str(size))
    assert len(Workbench.open(_project(proj, "inside.stl")).cell) == 6
    monkeypatch.setenv("WORKBENCH_MAX_PROJECT_BYTES", "100")
    with pytest.raises(ProjectError, match="WORKBENCH_MAX_PROJECT_BYTES"):
        load_project(EXAMPLE)
    monkeypatch.setenv("WORKBENCH_MAX_PROJECT_BYTES", "lots")
    with pytest.raises(InputError, match="WORKBENCH_MAX_PROJECT_BYTES"):
        size_limit("project")


def test_a_missing_mesh_inside_says_so(tree: dict[str, Path]) -> None:
    with pytest.raises(MeshError, match=r"cell\.objects\[5\]\.path: mesh file not found"):
        Workbench.open(_project(tree["proj"], "missing.stl"))


def test_the_bending_part_file_stays_inside(tree: dict[str, Path]) -> None:
    proj, outside = tree["proj"], tree["outside"]
    data = json.loads(BENDING.read_text())
    part = (BENDING.parent / data["bending"]["part_file"]).read_text()
    (outside / "part.json").write_text(part)
    (proj / "part.json").write_text(part)
    for given, ok in (("part.json", True), ("../outside/part.json", False), ("/dev/zero", False)):
        data["bending"]["part_file"] = given
        if ok:
            wb = Workbench.from_dict(data, base_dir=proj)
            assert wb.bending.part_spec().thickness > 0
        else:  # refused at open: the part file is checked with the project
            with pytest.raises(InputError, match=r"bending\.part_file: .*outside the project"):
                Workbench.from_dict(data, base_dir=proj)
    (proj / "part.json").write_text('{"thickness": ')  # broken JSON names the field only
    data["bending"]["part_file"] = "part.json"
    with pytest.raises(ProjectError, match=r"bending\.part_file"):
        Workbench.from_dict(data, base_dir=proj)


def test_the_polishing_workpiece_stays_inside(tree: dict[str, Path]) -> None:
    data = json.loads((ROOT / "projects" / "polishing_cell.json").read_text())
    shutil.copyfile(ROOT / "web_assets" / "workpieces" / "panel.stl", tree["proj"] / "panel.stl")
    data["polishing"]["workpiece"] = "panel.stl"
    wb = Workbench.from_dict(data, base_dir=tree["proj"])
    with pytest.raises(InputError, match=r"polishing\.workpiece: .*outside the project"):
        wb.polishing.load_workpiece(tree["outside"] / "secret.stl")


URDF = """<robot name="r">
  <link name="base"><visual><geometry><mesh filename="{mesh}"/></geometry></visual></link>
  <link name="l1"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_the_urdf_and_its_meshes_stay_inside(tree: dict[str, Path]) -> None:
    proj, outside = tree["proj"], tree["outside"]
    folders = ProjectFolders(proj)
    (proj / "ok.urdf").write_text(URDF.format(mesh="inside.stl"))
    assert folders.check_urdf("ok.urdf", "robot.urdf") == (proj / "ok.urdf").resolve()
    for i, mesh in enumerate(
        ("../outside/secret.stl", str(outside / "secret.stl"), f"file://{outside}/secret.stl")
    ):
        (proj / f"bad{i}.urdf").write_text(URDF.format(mesh=mesh))
        with pytest.raises(InputError, match=r"robot\.urdf \(mesh 1.*outside the project"):
            folders.check_urdf(f"bad{i}.urdf", "robot.urdf")
    (proj / "dev.urdf").write_text(URDF.format(mesh="/dev/zero"))
    with pytest.raises(WorkbenchError):
        ProjectFolders(proj, ["/dev"]).check_urdf("dev.urdf", "robot.urdf")
    with pytest.raises(InputError, match=r"robot\.urdf: .*outside the project"):
        folders.check_urdf("../outside/ok.urdf", "robot.urdf")


def test_hostile_path_values_are_input_errors(tree: dict[str, Path]) -> None:
    folders = ProjectFolders(tree["proj"])
    for bad in ("", "a\x00b.stl", 3, None):
        with pytest.raises(InputError):
            folders.resolve(bad, "tool.mesh")
