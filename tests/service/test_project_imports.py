"""Bringing your own cell (service.project_imports): a library robot, an obstacle file, a CAD part.

Each import is checked from outside: the robot in use is the library's model (its FK), an
imported obstacle is what the collision check sees (python-fcl on the same mesh), an imported
part is what the project file's own `part_file` route recognises, and Save as keeps an
imported file that lived in an upload folder. A refused import leaves the project as it was.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import fcl
import numpy as np
import pytest
import trimesh

from workbench import Workbench, WorkbenchError
from workbench.errors import InputError, MeshError, ProjectError
from workbench.kinematics.robot_library import LIBRARY, library_robot
from workbench.project.part_import import PartImportSpec, import_part
from workbench.service.project_imports import (
    add_cell_file,
    import_bending_part,
    import_settings,
    robot_choices,
    use_robot,
)

ROOT = Path(__file__).resolve().parents[2]
PROJECTS = ROOT / "projects"


def _robot_only(tmp_path: Path) -> Workbench:
    """A project with a robot and a tool, no cell and no program: every robot may take it."""
    data = {
        "schema_version": 2,
        "name": "empty cell",
        "robot": {"preset": "mz07", "base": {"xyz": [0, 0, 0]}},
        "tool": {"name": "gripper", "tcp": {"xyz": [0, 0, 150]}},
    }
    return Workbench.from_dict(data, base_dir=tmp_path)


def test_the_choices_are_the_library() -> None:
    choices = robot_choices()
    assert [c.name for c in choices] == list(LIBRARY)
    assert {c.vendor for c in choices} == {"abb", "kuka", "fanuc", "ur", "nachi"}
    for c in choices:
        assert c.program_format == library_robot(c.name).program_format
        assert c.title in c.label and c.program_format in c.label


@pytest.mark.parametrize("name", list(LIBRARY))
def test_use_robot_puts_the_library_model_at_the_same_base(name: str, tmp_path: Path) -> None:
    wb = _robot_only(tmp_path)
    wb.project.robot.base.xyz = [100.0, -50.0, 20.0]
    wb.replace_project(wb.project)
    use_robot(wb, name)
    robot = library_robot(name)
    assert wb.project.robot.preset == name
    assert wb.project.robot.base.xyz == [100.0, -50.0, 20.0]
    np.testing.assert_allclose(wb.project.robot.joints, robot.home_deg, atol=1e-9)
    # The model in use is the library's: its FK at random joints inside the limits.
    q = np.random.default_rng(0).uniform(*robot.dh_robot().limits.T, size=(20, 6))
    np.testing.assert_allclose(wb.robot.fk(q), robot.dh_robot().fk(q), atol=1e-12)
    assert wb.default_program_format() == robot.program_format


def test_an_unknown_robot_names_the_library_and_changes_nothing(tmp_path: Path) -> None:
    wb = _robot_only(tmp_path)
    before = wb.to_json()
    with pytest.raises(WorkbenchError, match="mz07"):
        use_robot(wb, "irb9999")
    assert wb.to_json() == before


def test_a_joint_move_outside_the_new_robots_limits_is_refused_by_the_plan_naming_it(
    tmp_path: Path,
) -> None:
    wb = _robot_only(tmp_path)
    data = json.loads(wb.to_json())
    # J2 = 160 deg: inside the MZ07's -45..170, outside the ABB IRB 1200's -100..135
    data["program"] = {
        "name": "p",
        "start": [0, 90, 0, 0, -90, 0],  # a one-move program moves from its start
        "moves": [{"name": "j", "type": "joint", "joints": [0, 160, 0, 0, -90, 0]}],
    }
    wb.replace_from_json(json.dumps(data))
    wb.plan_motion()  # the MZ07 takes it
    use_robot(wb, "irb1200_7_70")
    with pytest.raises(
        WorkbenchError,
        match=r"program.moves\[0\] \(j\).joints\[1\]: 160 deg is outside the joint limits"
        r" \[-100.0, 135.0\] deg",
    ):
        wb.plan_motion()
    # Said in the controller's values where they differ from the model's: the MZ07's J5 is
    # the model's turned round (sign -1, offset -90 deg); 130 deg on the pendant is past 120.
    use_robot(wb, "mz07")
    wb.project.program.moves[0].joints = [0, 90, 0, 0, 130, 0]  # type: ignore[union-attr]
    with pytest.raises(
        WorkbenchError,
        match=r"joints\[4\]: 130 deg is outside the joint limits"
        r" \[-120.0, 120.0\] deg",
    ):
        wb.plan_motion()


def _box_file(folder: Path, kind: str) -> Path:
    box = trimesh.creation.box(extents=(200.0, 300.0, 400.0))  # mm, centred on its origin
    if kind == "stl":
        path = folder / "block.stl"
        box.export(path)
        return path
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox
    from OCP.gp import gp_Pnt
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer

    shape = BRepPrimAPI_MakeBox(gp_Pnt(-100, -150, -200), 200.0, 300.0, 400.0).Shape()
    writer = STEPControl_Writer()
    writer.Transfer(shape, STEPControl_AsIs)
    path = folder / "block.step"
    writer.Write(str(path))
    return path


@pytest.mark.parametrize("kind", ["stl", "step"])
def test_an_imported_obstacle_is_what_the_collision_check_sees(kind: str, tmp_path: Path) -> None:
    wb = _robot_only(tmp_path)
    path = _box_file(tmp_path, kind)
    tcp = wb.tcp_pose()[:3, 3] * 1000.0
    name = add_cell_file(wb, path, xyz_mm=list(tcp))  # the box around the TCP
    assert name == "block"
    assert add_cell_file(wb, path, xyz_mm=[2000.0, 0.0, 0.0]) == "block_2"
    status = wb.collision_status()
    hits = {p for pair in status.colliding for p in pair}
    assert "block" in hits and "block_2" not in hits
    # python-fcl on the same box (m) at the same place: the tool's rod from flange to TCP
    # crosses it.
    box = fcl.CollisionObject(fcl.Box(0.2, 0.3, 0.4), fcl.Transform(np.eye(3), tcp / 1000.0))
    flange = wb.tcp_pose()[:3, 3] - wb.tcp_pose()[:3, 2] * 0.15
    rod = fcl.CollisionObject(
        fcl.Capsule(0.001, 0.15),
        fcl.Transform(wb.tcp_pose()[:3, :3], (flange + wb.tcp_pose()[:3, 3]) / 2),
    )
    assert fcl.collide(box, rod, fcl.CollisionRequest(), fcl.CollisionResult()) > 0


def test_a_broken_obstacle_file_is_refused_and_nothing_changes(tmp_path: Path) -> None:
    wb = _robot_only(tmp_path)
    bad = tmp_path / "broken.step"
    bad.write_bytes(b"ISO-10303-21;\nHEADER;\n")
    before = wb.to_json()
    with pytest.raises(MeshError, match="cell.objects"):
        add_cell_file(wb, bad)
    assert wb.to_json() == before


def test_save_as_copies_an_obstacle_from_its_upload_folder(tmp_path: Path) -> None:
    upload = tmp_path / "upload"
    upload.mkdir()
    path = _box_file(upload, "step")
    wb = _robot_only(tmp_path / "nowhere")
    wb.folders = wb.folders.with_session(upload)
    add_cell_file(wb, path, xyz_mm=[900.0, 0.0, 200.0])
    saved = tmp_path / "saved" / "cell.json"
    saved.parent.mkdir()
    wb.save(saved, overwrite=False)
    shutil.rmtree(upload)  # the upload folder goes at exit
    again = Workbench.open(saved)
    obj = again.project.cell.objects[0]
    assert obj.path == "files/block.step" and (saved.parent / "files/block.step").is_file()
    assert len(again.cell) == 1


def test_an_imported_step_part_is_the_part_files_part_stored_inline() -> None:
    wb = Workbench.open(PROJECTS / "u_channel_cell.json")
    data = (PROJECTS / "parts" / "u_channel.step").read_bytes()
    summary = import_bending_part(wb, "u_channel.step", data, {})
    assert "3 flanges, 2 bends" in summary
    bending = wb.project.bending
    assert bending is not None and bending.part_file is None and bending.steps is None
    twin = import_part(data, "u_channel.step", PartImportSpec())
    assert bending.part == twin
    assert bending.grasp.flange == twin.flanges[0].name
    # The project saves and opens with the part and without the file.
    again = Workbench.from_dict(json.loads(wb.to_json()))
    assert again.project.bending is not None and again.project.bending.part == twin


def test_an_imported_dxf_part_needs_its_thickness_named() -> None:
    wb = Workbench.open(PROJECTS / "u_channel_cell.json")
    data = (PROJECTS / "parts" / "pan_flat.dxf").read_bytes()
    before = wb.to_json()
    with pytest.raises(WorkbenchError, match="thickness"):
        import_bending_part(wb, "pan_flat.dxf", data, {})
    assert wb.to_json() == before
    import_bending_part(wb, "pan_flat.dxf", data, {"thickness": 1.5, "inner_radius": 1.5})
    part = wb.project.bending.part  # type: ignore[union-attr]
    assert part is not None and len(part.flanges) == 5 and part.thickness == 1.5
    assert {b.inner_radius for b in part.bends} == {1.5}


def test_bad_settings_are_refused_naming_the_field() -> None:
    with pytest.raises(ProjectError, match=r"part_import.thickness"):
        import_settings({"thickness": -1.0}, "pan.dxf")
    with pytest.raises(ProjectError, match=r"part_import.inner_radius"):
        import_settings({"inner_radius": float("nan")}, "pan.dxf")
    # A DXF's bend layer is not a STEP setting: the GUI's layer box does not refuse a STEP.
    assert import_settings({"bend_layer": "BEND"}, "u.step") == PartImportSpec()
    assert import_settings({"bend_layer": "BENDS"}, "u.dxf").bend_layer == "BENDS"


def test_a_part_needs_a_bending_section() -> None:
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    data = (PROJECTS / "parts" / "u_channel.step").read_bytes()
    with pytest.raises(InputError, match="no 'bending' section"):
        import_bending_part(wb, "u_channel.step", data, {})


def test_a_file_that_is_not_a_part_is_refused() -> None:
    wb = Workbench.open(PROJECTS / "u_channel_cell.json")
    with pytest.raises((ProjectError, MeshError, InputError), match="x.txt|not a"):
        import_bending_part(wb, "x.txt", b"hello", {})
