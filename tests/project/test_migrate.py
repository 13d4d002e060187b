"""Schema 1 -> 2: joint values move from the kinematic model's convention to the controller's."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import ProjectError
from workbench.kinematics.presets import MZ07_CONVENTION
from workbench.kinematics.robot_library import preset_robot
from workbench.project.io import load_project, parse_project_json, project_to_json, save_project
from workbench.project.migrate import v1_to_v2
from workbench.project.models import SCHEMA_VERSION
from workbench.service import Workbench

ROOT = Path(__file__).resolve().parents[2]
Q_HOME = [10.0, -20.0, 15.0, 30.0, -100.0, 45.0]  # model degrees, as version 1 stored them
Q_START = [0.0, 0.0, 0.0, 0.0, -90.0, 0.0]  # the model's upright posture
Q_MOVE = [-30.0, 10.0, -5.0, 0.0, -60.0, 90.0]


def _v1() -> dict:
    return {
        "schema_version": 1,
        "robot": {"preset": "mz07", "joints": list(Q_HOME)},
        "program": {
            "start": list(Q_START),
            "moves": [
                {"type": "joint", "joints": list(Q_MOVE)},
                {"type": "linear", "pose": {"xyz": [400, 0, 400], "rpy": [180, 0, 0]}},
            ],
        },
        "assembly": {
            "parts": [],
            "robots": [{"name": "second", "base": {"xyz": [900, 0, 0]}, "joints": list(Q_MOVE)}],
        },
    }


def _fk(q_model_deg: list[float] | np.ndarray) -> np.ndarray:
    return preset_robot("mz07").fk(np.radians(np.asarray(q_model_deg, float)))


def test_schema_version_is_2() -> None:
    assert SCHEMA_VERSION == 2
    assert (
        json.loads(project_to_json(parse_project_json('{"schema_version": 2}')))["schema_version"]
        == 2
    )


def test_v1_joints_become_the_controllers_and_keep_the_posture() -> None:
    p = parse_project_json(json.dumps(_v1()))
    assert p.schema_version == 2
    # the file now holds the NACHI pendant's values: J2 + 90, J5 and J6 negated, J5 - 90
    np.testing.assert_allclose(p.robot.joints, [10, 70, 15, 30, 10, -45], atol=1e-9)
    assert p.program is not None
    np.testing.assert_allclose(p.program.start, [0, 90, 0, 0, 0, 0], atol=1e-9)
    np.testing.assert_allclose(p.program.moves[0].joints, [-30, 100, -5, 0, -30, -90], atol=1e-9)
    # ...and the model values in SI are the version-1 ones: the same physical posture
    si = p.robot.to_si()
    np.testing.assert_allclose(si.joints, np.radians(Q_HOME), atol=1e-12)
    np.testing.assert_allclose(_fk(np.degrees(si.joints)), _fk(Q_HOME), atol=1e-12)
    prog = p.program.to_si(MZ07_CONVENTION)
    np.testing.assert_allclose(prog.start, np.radians(Q_START), atol=1e-12)
    np.testing.assert_allclose(prog.moves[0].joints, np.radians(Q_MOVE), atol=1e-12)
    assert prog.moves[1].joints is None
    assert p.assembly is not None
    arm = p.assembly.robots[0].to_si()
    np.testing.assert_allclose(arm.robot.joints, np.radians(Q_MOVE), atol=1e-12)


def test_workbench_on_a_v1_file_has_the_same_tcp(tmp_path: Path) -> None:
    path = tmp_path / "old.json"
    path.write_text(json.dumps(_v1()))
    wb = Workbench.open(path)
    np.testing.assert_allclose(wb.joints, np.radians(Q_HOME), atol=1e-12)
    T_flange = wb.robot.fk(wb.joints)
    np.testing.assert_allclose(T_flange, _fk(Q_HOME), atol=1e-12)
    # saving writes version 2 with the controller's values, and reading it back is stable
    out = tmp_path / "new.json"
    save_project(wb.project, out)
    data = json.loads(out.read_text())
    assert data["schema_version"] == 2
    np.testing.assert_allclose(data["robot"]["joints"], [10, 70, 15, 30, 10, -45], atol=1e-9)
    again = Workbench.open(out)
    np.testing.assert_allclose(again.joints, wb.joints, atol=1e-12)
    np.testing.assert_allclose(again.project.robot.joints, data["robot"]["joints"], atol=1e-9)


def test_a_v2_file_is_not_migrated_again() -> None:
    data = _v1()
    data["schema_version"] = 2
    p = parse_project_json(json.dumps(data))
    np.testing.assert_allclose(p.robot.joints, Q_HOME)  # taken as the controller's values
    np.testing.assert_allclose(
        p.robot.to_si().joints, MZ07_CONVENTION.to_model(np.radians(Q_HOME)), atol=1e-12
    )


def test_identity_robots_keep_their_values() -> None:
    rows = [
        {"theta_offset": 0, "d": 340, "a": 50, "alpha": 90, "min": -170, "max": 170},
        {"theta_offset": 90, "d": 0, "a": 330, "alpha": 0, "min": -135, "max": 80},
        {"theta_offset": 0, "d": 0, "a": 45, "alpha": 90, "min": -120, "max": 160},
    ]
    data = {
        "schema_version": 1,
        "robot": {"dh": rows, "joints": [1.0, 2.0, 3.0]},
        "program": {"start": [4.0, 5.0, 6.0], "moves": [{"type": "joint", "joints": [7, 8, 9]}]},
    }
    migrated = v1_to_v2(data)
    assert migrated["robot"] == data["robot"] and migrated["program"] == data["program"]
    p = parse_project_json(json.dumps(data))
    np.testing.assert_allclose(p.robot.to_si().joints, np.radians([1, 2, 3]))
    assert p.robot.dh is not None and p.robot.dh[1].min == -135


def test_a_file_without_robot_section_gets_the_preset_convention() -> None:
    data = {"schema_version": 1, "program": {"start": list(Q_START), "moves": []}}
    p = parse_project_json(json.dumps(data))
    assert p.robot.preset == "mz07" and p.program is not None
    np.testing.assert_allclose(p.program.start, [0, 90, 0, 0, 0, 0], atol=1e-9)


def test_malformed_joints_are_left_for_validation_to_name() -> None:
    data = _v1()
    data["robot"]["joints"] = [1.0, 2.0]  # wrong length: not converted, reported on load
    with pytest.raises(ProjectError, match=r"robot\.joints: expected 6 values"):
        Workbench.from_dict(data)
    data["robot"]["joints"] = ["a"] * 6
    with pytest.raises(ProjectError, match=r"robot\.joints"):
        parse_project_json(json.dumps(data))


def test_limit_errors_show_the_controllers_values() -> None:
    data = {"schema_version": 2, "robot": {"preset": "mz07", "joints": [0, -50, 0, 0, 0, 0]}}
    with pytest.raises(
        ProjectError, match=r"robot\.joints\[1\]: -50\.000 deg .* \[-45\.000, 170\.000\]"
    ):
        Workbench.from_dict(data)


@pytest.mark.parametrize("name", ["mz07_cell", "bending_cell", "assembly_cell", "polishing_cell"])
def test_the_examples_are_version_2(name: str) -> None:
    path = ROOT / "projects" / f"{name}.json"
    assert json.loads(path.read_text())["schema_version"] == 2
    p = load_project(path)
    # stored back to the file's values (store_joints inverts to_si)
    q = p.robot.to_si().joints
    assert q is not None
    before = list(p.robot.joints or [])
    p.robot.store_joints(q)
    np.testing.assert_allclose(p.robot.joints, before, atol=1e-9)


def test_a_preset_with_its_own_rates_keeps_its_convention() -> None:
    data = {"schema_version": 2, "robot": {"preset": "mz07", "max_velocity": [100] * 6}}
    wb = Workbench.from_dict(data)
    assert wb.robot.convention is MZ07_CONVENTION
    np.testing.assert_allclose(wb.robot.max_velocity, np.radians([100] * 6))
