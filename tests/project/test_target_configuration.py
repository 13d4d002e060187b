"""A pose target's `configuration` in the project file: validated naming its field, converted, saved
and loaded; files without it still load."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from workbench.errors import ProjectError
from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.kinematics.target_configuration import TargetConfiguration
from workbench.project import load_project, project_from_dict, save_project
from workbench.project.target_configuration import ConfigurationSpec

POSE = {"xyz": [430.0, 180.0, 580.0], "rpy": [180.0, 0.0, 0.0]}
CONF = {"front": True, "elbow_up": True, "wrist_flip": False, "turns": {"J6": 1}}


def _project(preset: str, *moves: dict) -> dict:
    program = {"start": [0.0, 90.0, 0.0, 0.0, -90.0, 0.0], "moves": list(moves)}
    return {"schema_version": 2, "robot": {"preset": preset}, "program": program}


def _problems(data: dict) -> dict[str, str]:
    with pytest.raises(ProjectError) as info:
        project_from_dict(data)
    return dict(info.value.problems)


def test_a_configuration_converts_both_ways_and_survives_save_and_load(tmp_path: Path) -> None:
    move = {"type": "linear", "pose": POSE, "configuration": CONF}
    project = project_from_dict(_project("irb1200_7_70", move))
    spec = project.program.moves[0].configuration
    si = spec.to_si(6)
    assert si == TargetConfiguration(ArmConfiguration(True, True, False), (0, 0, 0, 0, 0, 1))
    assert si.label() == "front/elbow up/no flip, J6 +1 turn" == spec.label()
    assert ConfigurationSpec.of(si) == spec
    assert project.program.to_si(None).moves[0].configuration.arm == si.arm
    path = tmp_path / "p.json"
    save_project(project, path)
    assert json.loads(path.read_text())["program"]["moves"][0]["configuration"] == CONF
    assert load_project(path).program.moves[0].configuration == spec


def test_a_file_without_configurations_loads_and_its_targets_have_none() -> None:
    project = project_from_dict(_project("mz07", {"type": "linear", "pose": POSE}))
    assert project.program.moves[0].configuration is None
    assert project.program.to_si(None).moves[0].configuration is None


@pytest.mark.parametrize(
    ("preset", "conf", "field", "says"),
    [
        # the IRB 1200's J6 spans +-400 deg: turns -1 to 1; its J1 (+-170 deg) only turn 0
        ("irb1200_7_70", CONF | {"turns": {"J6": 2}}, "turns.J6", "turns -1 to 1"),
        ("irb1200_7_70", CONF | {"turns": {"J1": 1}}, "turns.J1", "only turn 0"),
        ("irb1200_7_70", CONF | {"turns": {"J7": 0}}, "turns.J7", "6 joints"),
        ("mz07", CONF | {"turns": {"J6": 9}}, "turns.J6", "less than or equal to 2"),
        ("mz07", CONF | {"turns": {"six": 1}}, "turns.six.[key]", "pattern"),
        ("mz07", {"front": True, "elbow_up": True}, "wrist_flip", "required"),
        ("mz07", CONF | {"flip": True}, "flip", "unknown field"),
    ],
)
def test_bad_configurations_name_their_field(
    preset: str, conf: dict, field: str, says: str
) -> None:
    problems = _problems(_project(preset, {"type": "joint", "pose": POSE, "configuration": conf}))
    path = next(p for p in problems if p.endswith(field))
    assert path.startswith("program.moves[0]")
    assert says in problems[path]


def test_a_joint_target_refuses_a_configuration() -> None:
    move = {"type": "joint", "joints": [0.0, 90.0, 0.0, 0.0, -90.0, 0.0], "configuration": CONF}
    problems = _problems(_project("mz07", move))
    (path, msg), *_ = problems.items()
    assert "program.moves[0]" in path and "configuration" in path + msg
    assert "joint target" in msg
