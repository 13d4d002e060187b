"""The robot-program sections of a project: tool load, work objects, I/O, program actions, limits."""

from __future__ import annotations

import copy
import json
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import ProjectError
from workbench.geometry.transforms import rpy_to_matrix
from workbench.motion.programs import Comment, Gripper, MotionLimits, SetOutput, WaitInput, WaitTime
from workbench.project import load_project, project_from_dict
from workbench.project.program_io import (
    motion_limits,
    program_items,
    program_settings,
    tool_data,
    work_objects,
)

ROOT = Path(__file__).resolve().parents[2]
GRIPPER_IO = {
    "outputs": [{"name": "grip", "number": 1}, {"name": "blow", "number": 2}],
    "inputs": [{"name": "closed", "number": 1}, {"name": "opened", "number": 2}],
    "gripper": {
        "output": "grip",
        "close_value": False,
        "closed_input": "closed",
        "opened_input": "opened",
        "timeout": 2.0,
        "settle": 0.1,
    },
    "sync": {"MZ07": {"output": "blow", "input": "opened"}},
}
J0 = [0.0, 90.0, 0.0, 0.0, -90.0, 0.0]


def _project(**extra: object) -> dict:
    return {"schema_version": 2, "robot": {"preset": "mz07", "name": "MZ07"}, **extra}


def _error(data: dict) -> ProjectError:
    with pytest.raises(ProjectError) as info:
        project_from_dict(data)
    return info.value


@pytest.mark.parametrize("path", sorted((ROOT / "projects").glob("*.json")), ids=lambda p: p.stem)
def test_files_without_the_new_sections_load_as_before(path: Path) -> None:
    data = json.loads(path.read_text())
    for key in ("io", "work_objects"):
        data.pop(key, None)
    data["tool"].pop("mass", None)
    data["tool"].pop("cog", None)
    if "program" in data:
        data["program"]["moves"] = [
            m for m in data["program"]["moves"] if m["type"] in ("joint", "linear")
        ]
    p = project_from_dict(data)
    assert p.io is None and p.work_objects is None and p.tool.mass is None
    assert tool_data(p.tool).mass is None and tool_data(p.tool).cog is None
    assert motion_limits(p.robot) == MotionLimits()  # 2000 mm/s, 500 mm
    assert [w.name for w in work_objects(p)] == ["base"]


def test_actions_become_the_program_models_actions_in_order() -> None:
    moves = [
        {"type": "comment", "text": "start"},
        {"type": "joint", "joints": J0},
        {"type": "gripper", "action": "close"},
        {"type": "set_output", "signal": "blow", "value": True},
        {"type": "pulse_output", "signal": "blow", "duration": 0.3},
        {"type": "wait_input", "signal": "closed", "value": False, "timeout": 4},
        {"type": "wait", "seconds": 1.5},
        {"type": "gripper", "action": "open"},
    ]
    p = project_from_dict(_project(io=GRIPPER_IO, program={"moves": moves}))
    items = program_items(p, p.robot.convention())
    assert isinstance(items[0], Comment) and items[0].text == "start"
    assert np.allclose(items[1].joints, 0.0)  # controller (0, 90, 0, 0, -90, 0) = model zero
    close, open_ = items[2], items[7]
    assert isinstance(close, Gripper) and isinstance(open_, Gripper)
    # close_value False: closing sets the output low and waits for "closed" (number 1)
    assert (close.close, close.value, close.output.number, close.confirm.name) == (
        True,
        False,
        1,
        "closed",
    )
    assert (open_.close, open_.value, open_.confirm.number) == (False, True, 2)
    assert [type(a) for a in close.expand()] == [SetOutput, WaitInput, WaitTime]
    a3, a4, a5, a6 = items[3:7]
    assert isinstance(a3, SetOutput) and (a3.signal.number, a3.value) == (2, True)
    assert a4.duration == 0.3 and a4.signal.name == "blow"
    assert isinstance(a5, WaitInput) and (a5.value, a5.timeout, a5.signal.number) == (False, 4.0, 1)
    assert isinstance(a6, WaitTime) and a6.seconds == 1.5
    assert p.program is not None and len(p.program.to_si().moves) == 1  # only the move
    assert p.io is not None and p.io.sync_signals("MZ07") is not None


@pytest.mark.parametrize(
    ("patch", "words"),
    [
        (
            {"program": {"moves": [{"type": "set_output", "signal": "nope"}]}},
            "program.moves[0].signal: 'nope' is not one of io.outputs",
        ),
        (
            {"program": {"moves": [{"type": "wait_input", "signal": "grip"}]}},
            "program.moves[0].signal: 'grip' is not one of io.inputs",
        ),
        (
            {"program": {"moves": [{"type": "joint", "joints": J0, "wobj": "table"}]}},
            "program.moves[0].wobj: 'table' is not a work object",
        ),
        (
            {"program": {"moves": [{"type": "shake"}]}},
            "'type' must be one of joint, linear, gripper",
        ),
        ({"program": {"moves": [{"type": "wait", "seconds": -1}]}}, "program.moves[0].seconds"),
        ({"work_objects": [{"name": "base"}]}, "work_objects[0].name: 'base' is the robot base"),
        (
            {"work_objects": [{"name": "t"}, {"name": "t"}]},
            "work_objects[1].name: 't' is used twice",
        ),
        ({"tool": {"mass": 0}}, "tool.mass"),
        ({"tool": {"cog": [1, 2]}}, "tool.cog"),
        ({"robot": {"preset": "mz07", "max_tcp_speed": 1e9}}, "robot.max_tcp_speed"),
    ],
)
def test_bad_names_and_values_name_their_field(patch: dict, words: str) -> None:
    data = _project(io=copy.deepcopy(GRIPPER_IO))
    data.update(patch)
    err = _error(data)
    assert words in str(err), str(err)


@pytest.mark.parametrize(
    ("io_patch", "words"),
    [
        ({"gripper": {"output": "grap"}}, "gripper.output: 'grap' is not one of io.outputs"),
        (
            {"gripper": {"output": "grip", "closed_input": "grip"}},
            "gripper.closed_input: 'grip' is not one of io.inputs",
        ),
        ({"sync": {"R2": {"output": "blow", "input": "x"}}}, "sync.R2.input: 'x'"),
        (
            {"outputs": [{"name": "a", "number": 1}, {"name": "a", "number": 2}]},
            "outputs[1].name: 'a' is used twice",
        ),
        ({"inputs": [{"name": "grip", "number": 9}]}, "name both an output and an input"),
        # the press's signals: the defaults name press_start / press_clamped / press_done
        ({"press": {}}, "press.start: 'press_start' is not one of io.outputs"),
        ({"press": {"start": "blow"}}, "press.clamped: 'press_clamped' is not one of io.inputs"),
        (
            {"press": {"start": "blow", "clamped": "closed", "top": "grip"}},
            "press.top: 'grip' is not one of io.inputs",
        ),
        ({"press": {"start": "blow", "timeout": 0}}, "timeout"),
    ],
)
def test_io_references_are_checked(io_patch: dict, words: str) -> None:
    io = copy.deepcopy(GRIPPER_IO)
    io.update(io_patch)
    err = _error(_project(io=io))
    assert words in str(err), str(err)


def test_the_press_signals_in_si_with_their_defaults() -> None:
    io = copy.deepcopy(GRIPPER_IO)
    io["outputs"].append({"name": "press_start", "number": 7})
    io["inputs"] += [{"name": "press_clamped", "number": 8}, {"name": "press_done", "number": 9}]
    assert program_settings(project_from_dict(_project(io=io))).press is None
    io["press"] = {}
    press = program_settings(project_from_dict(_project(io=io))).press
    assert press is not None
    assert (press.start.number, press.clamped.number, press.top.number) == (7, 8, 9)
    assert press.timeout == 30.0
    io["press"] = {"clamped": "opened", "timeout": 12.5}
    press = program_settings(project_from_dict(_project(io=io))).press
    assert press is not None and press.clamped.name == "opened" and press.timeout == 12.5


def test_a_gripper_action_needs_the_gripper() -> None:
    io = {k: v for k, v in GRIPPER_IO.items() if k != "gripper"}
    err = _error(_project(io=io, program={"moves": [{"type": "gripper", "action": "open"}]}))
    assert "program.moves[0]: the project has no io.gripper" in str(err)


def test_work_objects_tool_and_limits_in_si() -> None:
    base = {"xyz": [100, -200, 300], "rpy": [0, 0, 90]}
    data = _project(
        work_objects=[{"name": "table", "pose": {"xyz": [600, 0, 400], "rpy": [0, 0, 30]}}],
        tool={"tcp": {"xyz": [0, 0, 150]}, "mass": 2.5, "cog": [10, 0, 60]},
    )
    data["robot"].update(base=base, max_tcp_speed=800, max_zone=25)
    p = project_from_dict(data)
    base_w, table = work_objects(p)
    assert base_w.name == "base" and np.allclose(base_w.T_base_wobj, np.eye(4))
    # twin: the table's world point (600, 0, 400) mm seen from a base at (100, -200, 300) mm
    # turned 90 deg: x_base = y_world offset, y_base = -x_world offset
    assert np.allclose(table.T_base_wobj[:3, 3], [0.2, -0.5, 0.1], atol=1e-12)
    assert np.allclose(
        table.T_base_wobj[:3, :3], rpy_to_matrix(np.radians([0, 0, -60])), atol=1e-12
    )
    tool = tool_data(p.tool)
    assert tool.mass == 2.5 and np.allclose(tool.cog, [0.01, 0, 0.06])
    assert np.allclose(tool.T_flange_tcp[:3, 3], [0, 0, 0.15])
    assert motion_limits(p.robot) == MotionLimits(max_tcp_speed=0.8, max_zone=0.025)


def test_the_mz07_example_has_its_gripper() -> None:
    p = load_project(ROOT / "projects" / "mz07_cell.json")
    items = program_items(p, p.robot.convention())
    grippers = [i for i in items if isinstance(i, Gripper)]
    assert [g.close for g in grippers] == [True, False]
    assert p.tool.mass is not None and p.tool.cog is not None
