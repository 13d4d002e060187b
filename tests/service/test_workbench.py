"""The service API on the example project: joints, TCP moves by IK, collisions, saving, errors."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench, WorkbenchError
from workbench.errors import InputError, JointLimitError, MeshError, ProjectError, UnreachableError
from workbench.geometry.transforms import make_transform
from workbench.kinematics.robot_library import preset_robot

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "projects" / "mz07_cell.json"


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.open(EXAMPLE)


def test_every_example_project_opens_and_checks() -> None:
    for path in sorted((ROOT / "projects").glob("*.json")):
        w = Workbench.open(path)
        report = w.collision_status()
        assert not report.in_collision, (path.name, report.colliding)


def test_set_joints_validates(wb: Workbench) -> None:
    q0 = wb.joints
    with pytest.raises(JointLimitError, match="joint 1"):
        wb.set_joints(np.r_[np.radians(200.0), np.zeros(5)])
    # told in the controller's values: the MZ07's model J2 = -140 deg is the pendant's -50
    # (upright = 90), below its -45..170 deg
    with pytest.raises(JointLimitError, match=r"joint 2: -50\.000 deg .*\[-45\.000, 170\.000\]"):
        wb.set_joints(np.radians([0, -140, 0, 0, -90, 0]))
    with pytest.raises(InputError, match="finite"):
        wb.set_joints([np.nan] * 6)
    with pytest.raises(InputError, match="expected 6"):
        wb.set_joints([0.0] * 5)
    assert np.array_equal(wb.joints, q0), "a refused input must not move the robot"


def test_move_tcp_reaches_the_pose_by_ik(wb: Workbench) -> None:
    wb.set_joints(np.radians([10, -20, 10, 30, -40, -20]))
    target = wb.tcp_pose()
    target[:3, 3] += [0.05, -0.03, 0.02]
    q = wb.move_tcp(target)
    assert np.allclose(wb.tcp_pose(q), target, atol=1e-9)
    sols = wb.ik_solutions(target)
    assert 1 <= len(sols) <= 8
    for s in sols:  # every solution is checked by FK, not trusted
        assert np.allclose(wb.tcp_pose(s.q), target, atol=1e-9)
    # The default pick is the one nearest the joints before the move.
    assert np.allclose(sols[0].q, q)
    labels = [s.label for s in sols]
    assert len(set(labels)) == len(labels), labels
    for s in sols:
        wb.move_tcp(target, configuration=s.label)
        assert np.allclose(wb.tcp_pose(), target, atol=1e-9)
        # The same configuration, with the joint turns nearest the joints it came from.
        assert np.allclose(np.cos(wb.joints), np.cos(s.q)) and np.allclose(
            np.sin(wb.joints), np.sin(s.q)
        )
    wb.move_tcp(target, configuration=0)
    assert np.allclose(wb.tcp_pose(), target, atol=1e-9)


def test_unreachable_pose_keeps_the_robot(wb: Workbench) -> None:
    q0 = wb.joints
    far = make_transform(np.eye(3), [3.0, 0.0, 0.5])
    with pytest.raises(UnreachableError, match="unreachable"):
        wb.move_tcp(far)
    assert np.array_equal(wb.joints, q0)
    with pytest.raises(InputError, match="rotation"):
        wb.move_tcp(np.diag([1.0, 1.0, -1.0, 1.0]))


def test_collision_with_the_table_is_named() -> None:
    w = Workbench.open(EXAMPLE)
    assert not w.collision_status().in_collision
    w.set_joints(np.radians([0, -60, 0, 0, 0, 0]))
    report = w.collision_status()
    assert report.in_collision
    assert any("table" in pair for pair in report.colliding), report.colliding
    assert report.min_distance == 0.0


def test_save_writes_joints_in_degrees_atomically(tmp_path: Path) -> None:
    w = Workbench.open(EXAMPLE)
    w.set_joints(np.radians([5, -10, 15, 20, 25, 30]))  # the model's convention
    out = w.save(tmp_path / "saved.json")
    data = json.loads(out.read_text())
    # the file holds the NACHI controller's values: J2 + 90, J5 -> -J5 - 90, J6 -> -J6
    assert data["robot"]["joints"] == [5, 80, 15, 20, -115, -30]
    again = Workbench.open(out)
    assert np.allclose(again.joints, w.joints)


def test_bad_projects_raise_workbench_errors(tmp_path: Path) -> None:
    data = json.loads(EXAMPLE.read_text())
    data["cell"]["objects"].append({"name": "jig", "shape": "mesh", "path": "missing.stl"})
    with pytest.raises(MeshError, match=r"cell.objects\[5\].path: mesh file not found"):
        Workbench.from_dict(data, base_dir=tmp_path)
    data = json.loads(EXAMPLE.read_text())
    data["robot"]["joints"] = [0, 0, 0, 0, 500, 0]
    with pytest.raises(ProjectError, match=r"robot.joints\[4\]"):
        Workbench.from_dict(data)
    data["robot"]["joints"] = [0, 0, 0]
    with pytest.raises(ProjectError, match="expected 6 values"):
        Workbench.from_dict(data)
    broken = tmp_path / "broken.stl"
    broken.write_text("solid nothing\nendsolid nothing\n")
    data = json.loads(EXAMPLE.read_text())
    data["cell"]["objects"].append({"name": "jig", "shape": "mesh", "path": str(broken)})
    with pytest.raises(WorkbenchError, match="jig|broken.stl|no triangles"):
        Workbench.from_dict(data)


def test_replace_project_with_bad_one_keeps_the_old() -> None:
    w = Workbench.open(EXAMPLE)
    name = w.project.name
    data = json.loads(EXAMPLE.read_text())
    data["cell"]["objects"].append({"name": "jig", "shape": "mesh", "path": "/nope.stl"})
    from workbench.project import project_from_dict

    with pytest.raises(InputError, match="outside the project's folder"):
        w.replace_project(project_from_dict(data))
    assert w.project.name == name and len(w.cell) == 5


def test_dh_robot_from_rows_matches_preset() -> None:

    mz = preset_robot("mz07")
    rows = [
        {
            "theta_offset": float(np.degrees(r[0])),
            "d": r[1] * 1000,
            "a": r[2] * 1000,
            "alpha": float(np.degrees(r[3])),
            "min": float(np.degrees(lim[0])),
            "max": float(np.degrees(lim[1])),
        }
        for r, lim in zip(mz.dh, mz.limits, strict=True)
    ]
    w = Workbench.from_dict({"schema_version": 1, "robot": {"dh": rows}})
    q = np.radians([10, 20, -30, 40, 50, 60])
    assert np.allclose(w.robot.fk(q), mz.fk(q), atol=1e-12)
