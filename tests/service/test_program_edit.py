"""The program editor (`service.program_edit`): teach, edit, reorder, undo/redo, export.

Twins: a taught TCP target is compared with the robot's FK through the file's pose; a taught
joint target with the controller's convention; each edit with the same edit made by hand on
the project JSON; undo with the program as it was; the export with the RAPID reader.
"""

from __future__ import annotations

import copy
import json
from pathlib import Path

import numpy as np
import pytest

from workbench.errors import InputError, WorkbenchError
from workbench.motion.programs.formats import reader
from workbench.project.units import pose_to_matrix
from workbench.service import Workbench
from workbench.service.program_edit import ProgramEditor, editor

ROOT = Path(__file__).resolve().parents[2]
MZ07 = ROOT / "projects" / "mz07_cell.json"


@pytest.fixture
def wb() -> Workbench:
    return Workbench.open(MZ07)


def _moves(wb: Workbench) -> list[dict]:
    return json.loads(wb.to_json())["program"]["moves"]


def test_one_editor_per_project(wb: Workbench) -> None:
    ed = editor(wb)
    assert editor(wb) is ed and isinstance(ed, ProgramEditor)
    wb.replace_from_json(MZ07.read_text())  # another project: a new editor, empty history
    assert editor(wb) is not ed and not editor(wb).can_undo


def test_taught_tcp_targets_are_the_tcp(wb: Workbench) -> None:
    ed = editor(wb)
    wb.set_joints(wb.joints + np.radians([10, -5, 8, 12, 20, -30]))
    n = len(ed.items)
    k = ed.add_target("linear")
    j = ed.add_target("joint", at=0, name="start_here")
    assert (k, j) == (n, 0)
    for i, kind in ((k + 1, "linear"), (0, "joint")):
        move = ed.item(i)
        assert move.type == kind and move.joints is None
        # the file's pose (mm, deg) is the TCP (m) within the file's 1e-6 mm rounding
        T = pose_to_matrix(move.pose)
        assert np.allclose(T, wb.tcp_pose(), atol=1e-8)
    assert ed.item(0).name == "start_here" and ed.item(k + 1).name == "target1"


def test_taught_joints_are_the_controllers(wb: Workbench) -> None:
    ed = editor(wb)
    q = wb.joints + np.radians([15, -10, 5, 30, 10, 45])
    wb.set_joints(q)
    k = ed.add_target("joints")
    move = ed.item(k)
    assert move.type == "joint" and move.pose is None
    expected = np.degrees(wb.robot.convention.to_controller(q))
    assert np.allclose(move.joints, expected, atol=1e-8)
    ed.add_target("joints")
    assert ed.item(k + 1).name == "target2"  # the first free name


def test_each_edit_is_the_same_edit_on_the_json(wb: Workbench) -> None:
    ed = editor(wb)
    by_hand = _moves(wb)
    ed.update_item(2, name="pick_it", speed=75.0, zone=5.0)
    by_hand[2] |= {"name": "pick_it", "speed": 75.0, "zone": 5.0}
    assert _moves(wb) == by_hand
    ed.update_item(1, type="linear", speed=300.0)
    by_hand[1] |= {"type": "linear", "speed": 300.0}
    assert _moves(wb) == by_hand
    assert ed.insert_action(3, {"type": "wait", "seconds": 0.5}) == 3
    by_hand.insert(3, {"type": "wait", "seconds": 0.5})
    assert _moves(wb) == by_hand
    assert ed.move_item(3, -1) == 2
    by_hand.insert(2, by_hand.pop(3))
    assert _moves(wb) == by_hand
    assert ed.move_item(2, +2) == 4
    by_hand.insert(4, by_hand.pop(2))
    assert _moves(wb) == by_hand
    ed.delete_item(0)
    del by_hand[0]
    assert _moves(wb) == by_hand
    ed.insert_action(len(by_hand), {"type": "set_output", "signal": "grip", "value": False})
    by_hand.append({"type": "set_output", "signal": "grip", "value": False})
    assert _moves(wb) == by_hand


def test_work_objects_of_the_project(wb: Workbench) -> None:
    data = json.loads(wb.to_json())
    data["work_objects"] = [{"name": "table", "pose": {"xyz": [550, 0, 400]}}]
    wb.replace_from_json(json.dumps(data))
    ed = editor(wb)
    assert ed.work_objects() == ["base", "table"]
    ed.update_item(1, wobj="table")
    assert ed.item(1).wobj == "table"
    ed.update_item(1, wobj="base")  # the default: left out of the file
    assert ed.item(1).wobj is None and "wobj" not in _moves(wb)[1]


@pytest.mark.parametrize(
    ("edit", "field"),
    [
        (lambda ed: ed.update_item(2, speed=-1.0), "program.moves[2].speed"),
        (lambda ed: ed.update_item(2, speed=1e9), "program.moves[2]"),
        (lambda ed: ed.update_item(2, zone=-5.0), "program.moves[2].zone"),
        (lambda ed: ed.update_item(2, wobj="nowhere"), "program.moves[2].wobj"),
        (lambda ed: ed.update_item(9, type="linear"), "program.moves[9]"),  # joints target
        (lambda ed: ed.update_item(2, colour="red"), "program.moves[2].colour"),
        (lambda ed: ed.update_item(3, action="squeeze"), "program.moves[3].action"),
        (lambda ed: ed.update_item(99, speed=10.0), "program.moves[99]"),
        (
            lambda ed: ed.insert_action(0, {"type": "set_output", "signal": "nope"}),
            "program.moves[0].signal",
        ),
        (lambda ed: ed.insert_action(0, {"type": "teleport"}), "action type"),
        (lambda ed: ed.insert_action(0, {"type": "wait", "seconds": -1}), "program.moves[0]"),
        (lambda ed: ed.insert_action(42, {"type": "wait", "seconds": 1}), "insert at 42"),
        (lambda ed: ed.move_item(0, -1), "program.moves[0]: cannot move it up"),
        (lambda ed: ed.move_item(9, +1), "program.moves[9]: cannot move it down"),
        (lambda ed: ed.delete_item(-1), "program.moves[-1]"),
        (lambda ed: ed.add_target("circle"), "target kind"),
        (lambda ed: ed.undo(), "undo"),
        (lambda ed: ed.redo(), "redo"),
    ],
)
def test_refused_edits_name_the_field_and_keep_the_program(wb: Workbench, edit, field) -> None:  # type: ignore[no-untyped-def]
    ed = editor(wb)
    before = _moves(wb)
    with pytest.raises(WorkbenchError) as info:
        edit(ed)
    assert str(info.value).startswith(field), str(info.value)
    assert _moves(wb) == before
    assert not ed.can_undo  # nothing was recorded


def test_undo_and_redo_every_edit(wb: Workbench) -> None:
    ed = editor(wb)
    states = [_moves(wb)]
    edits = [
        lambda: ed.add_target("linear", at=1),
        lambda: ed.update_item(1, speed=42.0, name="taught"),
        lambda: ed.insert_action(2, {"type": "gripper", "action": "close"}),
        lambda: ed.move_item(2, -1),
        lambda: ed.delete_item(0),
        lambda: ed.insert_action(0, {"type": "comment", "text": "taught in the GUI"}),
    ]
    for e in edits:
        e()
        states.append(copy.deepcopy(_moves(wb)))
    for k in range(len(edits), 0, -1):  # undo all the way back
        ed.undo()
        assert _moves(wb) == states[k - 1]
    assert not ed.can_undo and ed.can_redo
    for k in range(1, len(edits) + 1):  # and redo all the way forward
        ed.redo()
        assert _moves(wb) == states[k]
    ed.undo()
    ed.insert_action(
        0, {"type": "wait", "seconds": 1.0}
    )  # an edit after an undo drops the redo history
    assert not ed.can_redo


def test_teaching_starts_a_program_when_there_is_none(wb: Workbench) -> None:
    data = json.loads(wb.to_json())
    del data["program"]
    wb.replace_from_json(json.dumps(data))
    ed = editor(wb)
    assert ed.items == []
    ed.add_target("joints")
    assert wb.project.program is not None and wb.project.program.name == "main"
    ed.undo()
    assert wb.project.program is None


def test_planned_times_and_stale_plans(wb: Workbench) -> None:
    ed = editor(wb)
    assert ed.planned_times() is None
    plan = wb.plan_motion()
    times = ed.planned_times()
    assert times is not None and not times.stale
    assert times.cycle_time == plan.cycle_time
    moves = wb.robot_programs("motion")[0].moves
    got = [
        d for d, it in zip(times.durations, ed.items, strict=True) if it.type in ("joint", "linear")
    ]
    assert got == [m.duration for m in moves]
    assert all(
        d is None
        for d, it in zip(times.durations, ed.items, strict=True)
        if it.type not in ("joint", "linear")
    )
    # the moves' durations and the program's waits (gripper settle times) add up to the motion
    assert sum(got) + 0.4 == pytest.approx(plan.cycle_time, abs=0.05)
    ed.update_item(2, speed=50.0)
    assert ed.plan_is_stale() and ed.planned_times().stale  # type: ignore[union-attr]
    wb.plan_motion()
    assert not ed.plan_is_stale()


def test_exports_follow_the_edited_program(wb: Workbench) -> None:
    ed = editor(wb)
    wb.plan_motion()
    wb.set_joints(wb.joints + np.radians([20, 0, 0, 0, 0, 0]))
    k = ed.add_target("linear", at=len(ed.items) - 1, name="taught")
    ed.update_item(k, speed=120.0, zone=10.0)
    ed.insert_action(k + 1, {"type": "wait", "seconds": 0.25})
    ed.move_item(k + 1, -1)  # the wait before the taught move (a move before a wait stops)
    # the export of a stale plan plans again: the program written is the edited one
    text = wb.export_program("rapid", any_vendor=True).text
    assert not ed.plan_is_stale()
    read = reader("rapid")({"pick_place.mod": text})
    assert not read.unknown
    names = [m.name for m in read.moves]
    spec = [it for it in ed.items if it.type in ("joint", "linear")]
    assert len(names) == len(spec) and "taught" in names
    i = names.index("taught")
    taught = read.moves[i]
    assert taught.kind == "linear"
    assert taught.speed == pytest.approx(0.120, abs=1e-6)
    assert taught.zone == pytest.approx(0.010, abs=1e-6)
    # the read target (base frame = world here) is the taught TCP pose
    assert np.allclose(
        taught.target.T_wobj_tcp[:3, 3], pose_to_matrix(spec[i].pose)[:3, 3], atol=1e-5
    )
    waits = [a for a in read.actions() if type(a).__name__ == "WaitTime"]
    assert [w.seconds for w in waits] == [0.2, 0.2, 0.25]  # the gripper's settle times, ours


def test_bad_index_types_are_refused(wb: Workbench) -> None:
    ed = editor(wb)
    with pytest.raises(InputError, match=r"program.moves\[True\]"):
        ed.delete_item(True)  # type: ignore[arg-type]
    with pytest.raises(InputError, match="insert at"):
        ed.add_target("joints", at=-1)


def test_a_taught_pose_target_stores_the_configuration_of_the_current_joints(
    wb: Workbench,
) -> None:
    ed = editor(wb)
    # the jog panel's "no flip" solution with J6 a turn down: not the nearest one
    sols = wb.ik_solutions(wb.tcp_pose())
    chosen = next(s for s in sols if s.label == "front/elbow up/no flip, J6 -1 turn")
    wb.move_tcp(wb.tcp_pose(), configuration=chosen.label)
    k = ed.add_target("joint")
    conf = ed.item(k).configuration
    assert conf.label() == chosen.label  # the Robot tab's label of the joints taught
    assert _moves(wb)[k]["configuration"] == {
        "front": True,
        "elbow_up": True,
        "wrist_flip": False,
        "turns": {"J6": -1},
    }
    assert ed.item(ed.add_target("joints")).configuration is None  # joints need none
