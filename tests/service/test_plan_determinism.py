"""One project, one program: exported programs do not depend on where the robot was jogged, and a
pose target's stored configuration survives save and load and is the branch the plan takes
(checked against pinocchio's FK and every IK solution of the pose)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin
import pytest
from twins import load_module

from workbench import Workbench
from workbench.errors import PlanningError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.arm_configuration import every_solution
from workbench.kinematics.pinocchio_dh import build_dh_model
from workbench.motion.programs import EXPORT_FORMATS
from workbench.project import project_from_dict
from workbench.service.programs import plan_workflow

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "projects" / "mz07_cell.json"
pytestmark = pytest.mark.slow  # every test plans the example, some of them 20 times


TWIN = load_module("tests/kinematics/test_target_configuration.py", "target_configuration_twin")


def _without_start_and_configurations() -> Workbench:
    """The example as an older file has it: no program.start, no configurations."""
    wb = Workbench.open(EXAMPLE)
    program = wb.project.program
    moves = [
        m.model_copy(update={"configuration": None}) if hasattr(m, "configuration") else m
        for m in program.moves
    ]
    bare = program.model_copy(update={"start": None, "moves": moves})
    wb.replace_project(wb.project.model_copy(update={"program": bare}))
    return wb


def _configurations(wb: Workbench) -> list[Any]:
    """The stored configuration of each pose target."""
    return [m.configuration for m in wb.project.program.moves if getattr(m, "pose", None)]


def _exports(wb: Workbench) -> dict[str, str]:
    wb.plan_motion()
    out = {}
    for fmt in EXPORT_FORMATS:
        for name, text in wb.export_program(fmt, force=True, any_vendor=True).files.items():
            out[f"{fmt}/{name}"] = text
    return out


def test_programs_are_byte_identical_from_20_random_jog_states() -> None:
    shipped, bare = Workbench.open(EXAMPLE), _without_start_and_configurations()
    assert not any(c is not None for c in _configurations(bare))
    rng = np.random.default_rng(27)
    lim = shipped.robot.limits
    reference: dict[int, dict[str, str]] = {}
    for k in range(20):
        q = rng.uniform(lim[:, 0], lim[:, 1])  # the Robot tab's sliders, anywhere in limits
        for i, wb in enumerate((shipped, bare)):
            wb.set_joints(q)
            got = _exports(wb)
            assert np.array_equal(wb.joints, q)  # planning does not move the jogged robot
            if k == 0:
                reference[i] = got
                continue
            assert got.keys() == reference[i].keys()
            for name, text in got.items():
                assert text == reference[i][name], (k, i, name)
    # the first plan stored each pose target's configuration: the ones the shipped file states
    assert _configurations(bare) == _configurations(shipped)
    assert all(c is not None for c in _configurations(shipped))
    assert len(reference[0]) == len(reference[1]) == 7 + 1  # KRL writes .src and .dat


def _planned_target(wb: Workbench, index: int) -> np.ndarray:
    return wb.robot_programs()[0].moves[index].target.q


def test_a_stored_branch_survives_save_and_load_and_is_the_branch_planned(tmp_path: Path) -> None:
    wb = Workbench.open(EXAMPLE)
    program = wb.project.program
    target = program.moves[1]  # above_left: a joint move to a pose, front/elbow up/flip
    assert target.type == "joint" and target.pose is not None
    other = target.configuration.model_copy(update={"wrist_flip": False, "turns": {"J6": 1}})
    data = wb.project.model_dump(mode="json", exclude_none=True)
    moves = data["program"]["moves"]
    moves[1]["configuration"] = other.model_dump(mode="json")
    home = {"type": "joint", "joints": list(program.start)}
    data["program"]["moves"] = [moves[1], home]
    wb.replace_project(project_from_dict(data))
    path = tmp_path / "cell.json"
    wb.save(path)
    again = Workbench.open(path)
    assert again.project.program.moves[0].configuration == other
    again.set_joints(np.zeros(6).clip(again.robot.limits[:, 0], again.robot.limits[:, 1]))
    again.plan_motion()
    q = _planned_target(again, 0)
    # the twin: pinocchio's FK reaches the pose, and its labels pick this solution alone
    robot, setup = again.robot, again.setup
    twin = build_dh_model(robot.dh, robot.limits, robot.max_velocity)
    data = twin.createData()
    pin.framesForwardKinematics(twin, data, q)
    flange = data.oMf[twin.getFrameId("flange")].homogeneous
    T_world_tcp = np.eye(4)
    T_world_tcp[:3, :3] = _rpy(target.pose.rpy)
    T_world_tcp[:3, 3] = np.asarray(target.pose.xyz) * 1e-3
    want = invert_transform(setup.T_world_base) @ T_world_tcp @ invert_transform(setup.T_flange_tcp)
    assert np.allclose(flange, want, atol=1e-9)
    label = (True, True, False, (0, 0, 0, 0, 0, 1))
    assert TWIN.twin_configuration(robot, twin, q) == label
    matching = [
        s for s in every_solution(robot, want) if TWIN.twin_configuration(robot, twin, s) == label
    ]
    assert len(matching) == 1 and np.allclose(matching[0], q, atol=1e-9)
    # the robot jogged elsewhere (where the nearest solution is the stored default): the same
    default = program.moves[1].configuration
    assert default.wrist_flip and not default.turns
    again.set_joints(np.radians([0.0, 0.0, 0.0, 0.0, -90.0, 0.0]).clip(*robot.limits.T))
    again.plan_motion()
    assert np.array_equal(_planned_target(again, 0), q)


def _rpy(rpy_deg: list[float]) -> np.ndarray:
    r, p, y = np.radians(rpy_deg)
    Rx = np.array([[1, 0, 0], [0, np.cos(r), -np.sin(r)], [0, np.sin(r), np.cos(r)]])
    Ry = np.array([[np.cos(p), 0, np.sin(p)], [0, 1, 0], [-np.sin(p), 0, np.cos(p)]])
    Rz = np.array([[np.cos(y), -np.sin(y), 0], [np.sin(y), np.cos(y), 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


def test_a_linear_target_reached_in_another_configuration_is_refused_naming_it() -> None:
    wb = Workbench.open(EXAMPLE)
    program = wb.project.program
    moves = list(program.moves)
    pick = moves[2]
    assert pick.type == "linear"
    moves[2] = pick.model_copy(
        update={"configuration": pick.configuration.model_copy(update={"elbow_up": False})}
    )
    wb.replace_project(
        wb.project.model_copy(update={"program": program.model_copy(update={"moves": moves})})
    )
    with pytest.raises(PlanningError, match="elbow down") as exc:
        wb.plan_motion()
    assert exc.value.field == "program.moves[2].configuration"


@pytest.mark.parametrize(
    ("project", "workflow"),
    [
        ("assembly_cell.json", "assembly"),
        ("polishing_cell.json", "polishing"),
        ("bending_cell.json", "bending"),
    ],
)
def test_every_workflow_exports_the_same_programs_whatever_the_jog(
    project: str, workflow: str
) -> None:
    """Assembly, polishing and bending plan from the robot's joints as the project stores them
    (`RobotSetup.q0`), not from the jogged ones."""
    wb = Workbench.open(ROOT / "projects" / project)
    rng = np.random.default_rng(5)
    lim = wb.robot.limits
    seen = []
    for _ in range(2):
        wb.set_joints(rng.uniform(lim[:, 0], lim[:, 1]))
        plan_workflow(wb, workflow)
        files = {}
        for fmt in EXPORT_FORMATS:
            out = wb.export_program(fmt, workflow, force=True, any_vendor=True)
            files |= {f"{fmt}/{name}": text for name, text in out.files.items()}
        seen.append(files)
    assert seen[0] == seen[1]
