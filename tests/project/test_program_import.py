"""Tests of workbench/project/program_import.py: a read program becomes the project's program.

The project and the read program are built by hand; each linear target's world pose is checked
against the matrix product written out here (robot base @ work object @ target), each joint
target against the joint convention applied by hand (sign * q + offset, in degrees), and the
notes against what was given.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.kinematics.joint_convention import JointConvention
from workbench.motion.programs.controller_program import (
    Comment,
    PulseOutput,
    ReadMove,
    ReadProgram,
    ReadTarget,
    SetOutput,
    Signal,
    SyncPoint,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
)
from workbench.project.io import project_from_dict
from workbench.project.program_import import imported_project
from workbench.project.units import pose_to_matrix

ROOT = Path(__file__).resolve().parents[2]


def _rot_z(deg: float, xyz=(0.0, 0.0, 0.0)) -> np.ndarray:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    T = np.eye(4)
    T[:2, :2] = [[c, -s], [s, c]]
    T[:3, 3] = xyz
    return T


@pytest.fixture(scope="module")
def project():
    data = json.loads((ROOT / "projects" / "mz07_cell.json").read_text())
    data["robot"]["base"] = {"xyz": [100, -50, 200], "rpy": [0, 0, 90]}
    data["work_objects"] = [{"name": "table", "pose": {"xyz": [0, 0, 0], "rpy": [0, 0, 0]}}]
    return project_from_dict(data)


TOOL = ToolData("gripper", np.array(_rot_z(0, (0, 0, 0.15))), 2.0, np.array([0, 0, 0.06]))
WOBJ = WorkObject("table", _rot_z(30, (0.5, 0.1, 0.0)))
CONV = JointConvention(np.array([0.0, 0.0, -math.pi / 2, 0, 0, 0]), np.array([1, 1, -1, 1, 1, 1.0]))


def _lin(name, T, line, **kw):
    return ReadMove(
        "linear", ReadTarget(name, T_wobj_tcp=T), 0.25, 0.01, "gripper", "table", line=line, **kw
    )


WOBJ0 = WorkObject("wobj0", np.eye(4))


def _program(instructions, tools=(TOOL,), wobjs=(WOBJ, WOBJ0), **kw) -> ReadProgram:
    return ReadProgram("3rd cell", tuple(tools), tuple(wobjs), tuple(instructions), **kw)


def test_moves_and_actions_in_order(project) -> None:
    q0 = np.array([0.1, 0.2, 0.3, 0.4, 0.5, 0.6])
    T1 = _rot_z(45, (0.05, 0.02, 0.3))
    instr = [
        ReadMove("joint", ReadTarget("home", joints=q0), 0.5, 0.02, "gripper", "wobj0", line=3),
        _lin("above", T1, 4),
        SetOutput(Signal("grip", 1), True),
        PulseOutput(Signal("", 7), 0.3),
        WaitInput(Signal("gripper_closed", 1), True, timeout=2.0),
        WaitTime(0.5),
        Comment("x" * 300),
        SyncPoint("handover", ("r2",)),
    ]
    out = imported_project(project, _program(instr), [q0, q0], CONV, source="cell.mod")
    items = out.data["program"]["moves"]
    assert out.data["program"]["name"] == "p_3rd_cell"
    j = items[0]
    assert j["type"] == "joint" and j["speed"] == 50.0 and j["zone"] == pytest.approx(20.0)
    assert "wobj" not in j  # wobj0 is the base frame
    assert np.allclose(j["joints"], np.degrees(CONV.sign * q0 + CONV.offset))
    lin = items[1]
    assert lin["type"] == "linear" and lin["wobj"] == "table" and lin["speed"] == 250.0
    T_world = pose_to_matrix(project.robot.base) @ WOBJ.T_base_wobj @ T1
    got = pose_to_matrix(type(project.robot.base).model_validate(lin["pose"]))
    assert np.allclose(got, T_world, atol=1e-9)
    assert items[2] == {"type": "set_output", "signal": "grip", "value": True}
    assert items[3] == {"type": "pulse_output", "signal": "do_7", "duration": 0.3}
    assert items[4] == {
        "type": "wait_input",
        "signal": "gripper_closed",
        "value": True,
        "timeout": 2.0,
    }
    assert items[5] == {"type": "wait", "seconds": 0.5}
    assert items[6] == {"type": "comment", "text": "x" * 200}
    assert items[7] == {"type": "comment", "text": "sync handover"}
    assert {"name": "do_7", "number": 7} in out.data["io"]["outputs"]
    assert any("sync point 'handover' (with r2)" in n for n in out.notes)
    # the work object is the program's frame, in world
    (table,) = [w for w in out.data["work_objects"] if w["name"] == "table"]
    T_tab = pose_to_matrix(type(project.robot.base).model_validate(table["pose"]))
    assert np.allclose(T_tab, pose_to_matrix(project.robot.base) @ WOBJ.T_base_wobj, atol=1e-9)
    assert any("'table' takes the program's frame" in n for n in out.notes)
    # same tool as the project's: no tool note; mass and cog copied (mm)
    assert not any(n.startswith("tool:") for n in out.notes)
    assert out.data["tool"]["cog"] == pytest.approx([0, 0, 60])
    # the input project is left as it was
    assert project.program is not None and project.program.name == "pick_place"


def test_notes_for_what_the_project_cannot_take(project) -> None:
    other = ToolData("probe", _rot_z(0, (0, 0, 0.2)))
    via = ReadTarget("via", T_wobj_tcp=_rot_z(0, (0.1, 0, 0.3)))
    instr = [
        ReadMove(
            "joint",
            ReadTarget("a", joints=np.zeros(6)),
            None,
            0.0,
            "probe",
            "base",
            duration=1.5,
            line=2,
        ),
        ReadMove(
            "circular",
            ReadTarget("b", T_wobj_tcp=_rot_z(0, (0.2, 0, 0.3))),
            0.1,
            0.0,
            "probe",
            "base",
            via=via,
            line=3,
        ),
        _lin("c", _rot_z(0, (0.3, 0, 0.3)), 4),
        SetOutput(Signal("nameless", 0), False),
        SetOutput(Signal("grip", 1), False),
        WaitInput(Signal("grip", 1), True),
    ]
    read = _program(
        instr,
        tools=(TOOL, other),
        wobjs=(WOBJ, WorkObject("base", np.eye(4))),
        unknown=((9, "ConfL \\Off;"),),
        notes=("speed clipped",),
    )
    out = imported_project(project, read, [np.zeros(6)] * 3, CONV, source="p.mod")
    notes = out.notes
    assert notes[0] == "p.mod: line 9: 'ConfL \\\\Off;' is not understood; it was left out"
    assert notes[1] == "p.mod: speed clipped"
    assert any("line 2 (a): a joint move given by its time only (1.5 s)" in n for n in notes)
    assert any("line 3 (b): a circular move is imported as two linear moves" in n for n in notes)
    assert any("the program's tool 'probe' replaces the project's TCP" in n for n in notes)
    assert any("moves with ['gripper'] are planned with 'probe'" in n for n in notes)
    assert out.data["tool"]["tcp"]["xyz"] == pytest.approx([0, 0, 200])
    names = [m.get("name") for m in out.data["program"]["moves"]]
    assert names[:4] == ["a", "via", "b", "c"]
    assert out.data["program"]["moves"][0]["speed"] == 100.0
    # an output without a number gets the next free one, with a note; an input named like an
    # output gets its own name
    assert {"name": "nameless", "number": 2} in out.data["io"]["outputs"]
    assert any("'nameless' has no number in the program; numbered 2" in n for n in notes)
    assert {"name": "grip_input", "number": 3} in out.data["io"]["inputs"]


def test_no_moves_is_refused_with_what_was_not_understood(project) -> None:
    read = _program([WaitTime(1.0)], unknown=((1, "FOO"), (2, "BAR")))
    with pytest.raises(
        InputError,
        match=r"x.mod: the program has no moves the reader understood \(not understood: line 1: 'FOO'; line 2: 'BAR'\)",
    ):
        imported_project(project, read, [], CONV, source="x.mod")


def test_linear_move_without_pose_names_its_line(project) -> None:
    bad = ReadMove(
        "linear", ReadTarget("t", joints=np.zeros(6)), 0.1, 0.0, "gripper", "table", line=12
    )
    with pytest.raises(InputError) as exc:
        imported_project(project, _program([bad]), [np.zeros(6)], CONV, source="x")
    assert exc.value.field == "line 12 (t)"
