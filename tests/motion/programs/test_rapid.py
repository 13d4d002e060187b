"""ABB RAPID post and reader: read-back of the sample program, confdata against ABB's rules,
the RAPID manual's examples, hand-written forms (Offs, RelTool, inline targets) and bad inputs."""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest
from program_round_trip import check_read_back, sample_program
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.kinematics.arm_configuration import ArmConfiguration, arm_configuration
from workbench.motion.programs.controller_program import MoveInstr, Target, ToolData
from workbench.motion.programs.rapid import (
    RAPID_RESERVED,
    cfx_of,
    configuration_of_cfx,
    quadrant,
    write_rapid,
)
from workbench.motion.programs.rapid_read import read_rapid
from workbench.motion.programs.readback import solve_moves, to_robot_program

DEG = np.pi / 180.0


def _module(body: str, decl: str = "") -> dict[str, str]:
    return {"hand.mod": f"MODULE hand\n{decl}\n  PROC main()\n{body}\n  ENDPROC\nENDMODULE\n"}


# ------------------------------------------------------------------ read-back


def test_sample_program_reads_back():
    prog, model = sample_program()
    out = write_rapid(prog)
    assert list(out.files) == ["demo.mod"]
    read = read_rapid(out.files)
    check_read_back(prog, read, model, signals_by="name")
    assert read.name == "demo"
    # joint moves carry the planned time (\T), linear/circular moves the TCP speed
    for k, (mv, rm) in enumerate(zip(prog.moves, read.moves, strict=True)):
        if k == 0:  # the first move: reached from anywhere, no \T
            assert rm.duration is None and rm.speed is None
        elif mv.kind == "joint":
            assert rm.duration == pytest.approx(mv.duration, abs=1e-9)
            assert rm.speed is None
        else:
            assert rm.duration is None
            assert rm.speed == pytest.approx(mv.speed, rel=1e-9)


def test_read_program_plans_and_writes_the_same_moves():
    prog, model = sample_program()
    text = write_rapid(prog).text
    again = to_robot_program(read_rapid({"demo.mod": text}), model, robot="r1")
    for q_planned, mv in zip([m.target.q for m in prog.moves], again.moves, strict=True):
        assert np.max(np.abs(mv.target.q - q_planned)) < 1e-6

    def moves(t: str) -> list[str]:
        return [ln.strip() for ln in t.splitlines() if ln.strip().startswith("Move")]

    assert moves(write_rapid(again).text) == moves(text)


def test_written_module_reads_as_an_abb_programmer_expects():
    prog, _ = sample_program()
    text = write_rapid(prog).text
    lines = text.splitlines()
    assert lines[0] == "MODULE demo" and lines[-1] == "ENDMODULE"
    assert "    PROC main()" in lines and "    ENDPROC" in lines
    stmts = [ln.strip() for ln in lines[1:-1] if ln.strip() and not ln.strip().startswith("!")]
    for s in stmts:
        assert s in ("PROC main()", "ENDPROC") or s.endswith(";"), s
    # the tool is the gripper's TCP (not tool0), with its load; the work object is the fixture
    assert re.search(r"TASK PERS tooldata gripper:=\[TRUE,\[\[40,0,150\],", text)
    assert "[2.5,[10,0,80],[1,0,0,0],0,0,0]];" in text
    assert 'TASK PERS wobjdata fixture:=[FALSE,TRUE,"",[[600,-100,200],' in text
    # MultiMove sync data and the task names
    assert "VAR syncident sync_1;" in text
    assert 'PERS tasks task_list1{2}:=[["T_DEMO"],["T_OTHER"]];' in text
    assert "WaitSyncTask sync_1, task_list1;" in text
    # joint moves in the planned time, linear moves with a speeddata literal, zones
    # the first move: no \T, 250 mm/s and 45 deg/s (reached from wherever the robot stands)
    assert "MoveAbsJ home, [250,45,5000,1000], fine, gripper\\WObj:=fixture;" in text
    assert "MoveJ p_pick, v1000\\T:=0.9, z20, gripper\\WObj:=fixture;" in text
    assert "MoveL p_place, [250,500,5000,1000], fine, gripper\\WObj:=fixture;" in text
    assert "MoveC p_via, p_far, [100,500,5000,1000], fine, gripper\\WObj:=fixture;" in text
    assert "MoveL p_flip, [50,500,5000,1000], z10, flange\\WObj:=wobj0;" in text
    # I/O: gripper comment and its expansion, pulse high, wait with timeout
    i = lines.index("        ! gripper close")
    assert lines[i + 1 : i + 4] == [
        "        SetDO do_grip, 1;",
        "        WaitDI di_closed, 1\\MaxTime:=2;",
        "        WaitTime 0.2;",
    ]
    assert "        PulseDO \\High\\PLength:=0.3, do_blow;" in lines
    # every name the body uses is declared or predefined
    declared = set(re.findall(r"(?:tooldata|wobjdata|robtarget|jointtarget|syncident) (\w+)", text))
    declared |= {"task_list1", "wobj0", "tool0"}
    for m in re.finditer(r"Move\w+ (.*);", text):
        for name in re.findall(r"(?<![\\\w])([A-Za-z]\w*)", m.group(1)):
            assert name in declared | {"v1000", "fine", "z20", "z10", "WObj", "T"}, name


def test_tooldata_and_targets_are_the_poses_in_abb_units():
    """The written numbers against scipy's quaternions (scalar first) and the model's FK."""
    prog, model = sample_program()
    text = write_rapid(prog).text
    tool = prog.tool("gripper")
    q = Rotation.from_matrix(tool.T_flange_tcp[:3, :3]).as_quat(scalar_first=True)
    q = q if q[0] >= 0 else -q
    m = re.search(r"tooldata gripper:=\[TRUE,\[\[([^\]]*)\],\[([^\]]*)\]\]", text)
    assert m is not None
    assert np.allclose([float(x) for x in m.group(1).split(",")], [40.0, 0.0, 150.0])
    assert np.allclose([float(x) for x in m.group(2).split(",")], q, atol=1e-9)
    # p_pick: TCP in the fixture, in mm
    mv = prog.moves[1]
    T = (
        np.linalg.inv(prog.work_object("fixture").T_base_wobj)
        @ model.fk(mv.target.q)
        @ tool.T_flange_tcp
    )
    m = re.search(r"robtarget p_pick:=\[\[([^\]]*)\]", text)
    assert np.allclose([float(x) for x in m.group(1).split(",")], T[:3, 3] * 1000.0, atol=1e-6)


# ------------------------------------------------------------------ confdata


def test_quadrants_of_axes_1_4_6():
    """ABB: cf1/cf4/cf6 are the quadrant numbers of the axis angle (0..90 deg: 0, -90..0: -1)."""
    cases = {
        100.0: 1,
        -10.0: -1,
        0.0: 0,
        45.0: 0,
        90.0: 1,
        -90.0: -1,
        200.0: 2,
        -181.0: -3,
        359.0: 3,
    }
    for deg, cf in cases.items():
        assert quadrant(deg * DEG) == cf, deg


# The manual's table (data type confdata): cfx, wrist centre relative to axis 1, relative to
# the lower arm, axis 5 angle.
_MANUAL_CFX = """
0 in_front in_front positive
1 in_front in_front negative
2 in_front behind positive
3 in_front behind negative
4 behind in_front positive
5 behind in_front negative
6 behind behind positive
7 behind behind negative
"""


def test_cfx_against_the_manuals_rows():
    for row in _MANUAL_CFX.strip().splitlines():
        cfx, axis1, lower_arm, axis5 = row.split()
        conf = ArmConfiguration(axis1 == "in_front", lower_arm == "in_front", axis5 == "negative")
        assert cfx_of(conf) == int(cfx), row
        assert configuration_of_cfx(int(cfx)) == conf, row


def _wrist_centre_in_front(model, q_model) -> bool:  # noqa: ANN001
    """Independent of arm_configuration: the wrist centre (flange - 78 mm along its z, the
    MZ07's) against the horizontal direction of axis 1 (q1)."""
    T = model.fk(q_model)
    wc = T[:3, 3] - 0.078 * T[:3, 2]
    q1 = float(model.convention.to_controller(q_model)[0])
    return float(wc[:2] @ [np.cos(q1), np.sin(q1)]) > 0.0


@pytest.mark.parametrize(
    ("ctrl_deg", "cfx"),
    [
        ((0, 90, 0, 0, 30, 0), 0),  # upright: lower arm up, forearm forward, axis 5 positive
        ((0, 90, 0, 0, -30, 0), 1),  # the same, axis 5 negative
        ((20, 60, 150, 0, 30, 0), 2),  # forearm folded back over the lower arm
        ((20, 60, 150, 0, -30, 0), 3),
        ((0, 170, 0, 0, 30, 0), 4),  # lower arm leaning far back: wrist centre behind axis 1
        ((0, 170, 0, 0, -30, 0), 5),
        ((0, 150, 100, 0, 30, 0), 6),  # leaning back and the forearm folded back too
        ((0, 150, 100, 0, -30, 0), 7),
    ],
)
def test_cfx_of_mz07_postures(ctrl_deg, cfx):
    prog, model = sample_program()
    q = model.convention.to_model(np.array(ctrl_deg, float) * DEG)
    conf = arm_configuration(model, q)
    assert cfx_of(conf) == cfx, conf
    assert conf.front == _wrist_centre_in_front(model, q)
    assert conf.wrist_flip == (ctrl_deg[4] < 0)


# ------------------------------------------------------------------ the manual's examples


def test_manual_data_examples():
    """RAPID manual examples of tooldata, wobjdata and robtarget, parsed to their values."""
    decl = """
    PERS tooldata gripper := [ TRUE, [[97.4, 0, 223.1], [0.924, 0, 0.383 ,0]],
        [5, [23, 0, 75], [1, 0, 0, 0], 0, 0, 0]];
    PERS wobjdata wobj2 :=[ FALSE, TRUE, "", [ [300, 600, 200], [1, 0, 0 ,0] ],
        [ [0, 200, 30], [1, 0, 0 ,0] ] ];
    CONST robtarget p15 := [ [600, 500, 225.3], [1, 0, 0, 0], [1, 1, 0, 0],
        [ 11, 12.3, 9E9, 9E9, 9E9, 9E9] ];"""
    read = read_rapid(_module("    MoveL p15, v1000, z30, gripper\\WObj:=wobj2;", decl))
    assert not read.unknown
    tool = next(t for t in read.tools if t.name == "gripper")
    assert np.allclose(tool.T_flange_tcp[:3, 3], [0.0974, 0.0, 0.2231])
    angle = Rotation.from_matrix(tool.T_flange_tcp[:3, :3]).as_rotvec() / DEG
    assert np.allclose(angle, [0.0, 45.0, 0.0], atol=0.05)  # 45 deg about y
    assert tool.mass == 5.0 and np.allclose(tool.cog, [0.023, 0.0, 0.075])
    wobj = next(w for w in read.work_objects if w.name == "wobj2")
    assert np.allclose(wobj.T_base_wobj[:3, 3], [0.3, 0.8, 0.23])  # uframe then oframe
    (mv,) = read.moves
    assert (mv.kind, mv.speed, mv.zone, mv.tool, mv.wobj) == (
        "linear",
        1.0,
        0.03,
        "gripper",
        "wobj2",
    )
    assert np.allclose(mv.target.T_wobj_tcp[:3, 3], [0.6, 0.5, 0.2253])
    rng = mv.target.controller_ranges / DEG
    assert np.allclose(rng[[0, 3, 5]], [[90, 180], [90, 180], [0, 90]])
    assert np.all(np.isinf(rng[[1, 2, 4]]))
    assert mv.target.configuration == ArmConfiguration(True, True, False)


def test_manual_instruction_examples():
    body = """
    MoveJ p1, vmax, z30, tool2;
    MoveC p1, p2, v500, z30, tool2;
    MoveL p1, v1000\\V:=2200, z40 \\Z:=45, grip3;
    MoveAbsJ jpos10, v1000\\T:=5, fine, tool0;
    WaitDI di4, 1;
    WaitDI di4, high\\MaxTime:=5\\TimeFlag:=flag1;
    PulseDO \\PLength:=1.0, ignition;
    PulseDO do15;
    Set do12;
    Reset do12;
    WaitTime \\InPos, 0.5;"""
    decl = """
    CONST robtarget p1 := [[600,500,225.3],[1,0,0,0],[1,1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget p2 := [[650,450,225.3],[1,0,0,0],[0,1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget jpos10 := [[0,0,0,0,0,0],[0,9E9,9E9,9E9,9E9,9E9]];
    VAR bool flag1;"""
    read = read_rapid(_module(body, decl))
    assert not read.unknown, read.unknown
    j, c, lin, absj = read.moves
    assert (j.kind, j.speed, j.zone, j.tool) == ("joint", None, 0.03, "tool2")
    assert (c.kind, c.via.name, c.target.name, c.speed) == ("circular", "p1", "p2", 0.5)
    assert (lin.speed, lin.zone) == (2.2, 0.045)  # \V and \Z override the data
    assert (absj.duration, absj.zone) == (5.0, 0.0)
    assert np.allclose(absj.target.joints, 0.0)
    acts = read.actions()
    assert [type(a).__name__ for a in acts] == [
        "WaitInput", "WaitInput", "PulseOutput", "PulseOutput", "SetOutput", "SetOutput", "WaitTime",
    ]  # fmt: skip
    assert acts[0].timeout is None and acts[1].timeout == 5.0 and acts[1].value is True
    assert acts[2].duration == 1.0 and acts[3].duration == 0.2  # ABB's default pulse length
    assert acts[4].value is True and acts[5].value is False
    assert any("tool2" in n for n in read.notes)  # used, not declared in the file


# ------------------------------------------------------------------ hand-written forms


def test_offs_and_reltool_give_the_displaced_poses():
    decl = """
    LOCAL CONST robtarget p1:=[[500,100,400],[0.707106781,0,0.707106781,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    TASK PERS wobjdata wtable:=[FALSE,TRUE,"",[[1000,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];"""
    body = """
    MoveL Offs(p1, 5, 10, 15), v100, z10, tool0;
    MoveL RelTool(p1, 0, 0, 100 \\Rz:=25), v100, fine, tool0\\WObj:=wtable;
    MoveJ [[300,0,500],[0,0,1,0],[-1,0,1,1],[9E9,9E9,9E9,9E9,9E9,9E9]], v200, fine, tool0;
    p1 := Offs(p1, 0, 0, -50);
    MoveL p1, v100, fine, tool0;"""
    read = read_rapid(_module(body, decl))
    assert not read.unknown, read.unknown
    offs, rel, inline, moved = read.moves
    R1 = Rotation.from_quat([0.707106781, 0, 0.707106781, 0], scalar_first=True).as_matrix()
    assert np.allclose(offs.target.T_wobj_tcp[:3, 3], [0.505, 0.110, 0.415])
    assert np.allclose(offs.target.T_wobj_tcp[:3, :3], R1)
    # RelTool: 100 mm along the tool's z (R1 turns z onto x: +100 mm in x), turned 25 deg about tool z
    assert np.allclose(rel.target.T_wobj_tcp[:3, 3], np.array([0.5, 0.1, 0.4]) + R1 @ [0, 0, 0.1])
    R_rel = R1 @ Rotation.from_euler("z", 25, degrees=True).as_matrix()
    assert np.allclose(rel.target.T_wobj_tcp[:3, :3], R_rel, atol=1e-8)
    assert rel.wobj == "wtable"
    assert inline.kind == "joint" and inline.target.configuration == ArmConfiguration(
        True, True, True
    )
    assert np.allclose(np.degrees(inline.target.controller_ranges[0]), [-90, 0])
    assert np.allclose(moved.target.T_wobj_tcp[:3, 3], [0.5, 0.1, 0.35])


def test_unknown_instructions_are_listed_by_line():
    text = """MODULE hand
  CONST robtarget p1:=[[500,100,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum myint;
  PROC main()
    ConfL \\Off;
    MoveL p1, v100, fine, tool0;
    IF di1 = 1 THEN
      SetDO do1, 1;
    ENDIF
    pick;
    TPWrite "done";
  ENDPROC
  PROC pick()
    MoveL p1, v100, fine, tool0;
  ENDPROC
ENDMODULE
"""
    read = read_rapid({"hand.mod": text})
    lines = [n for n, _ in read.unknown]
    assert lines == [3, 5, 7, 8, 9, 10, 11, 13, 14, 15]
    assert dict(read.unknown)[5] == "ConfL \\Off"
    assert len(read.moves) == 1 and read.moves[0].line == 6
    assert read.actions() == ()  # the SetDO inside IF is not part of the straight-line program


def test_malformed_input_names_the_line():
    bad_shape = _module(
        "", "  CONST robtarget p1:=[[500,100],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];"
    )
    with pytest.raises(InputError, match=r"line 2: .*position \[x,y,z\] needs 3 finite numbers"):
        read_rapid(bad_shape)
    with pytest.raises(InputError, match=r"line 4: .*has no ';'"):
        read_rapid({"a.mod": "MODULE a\n  PROC main()\n    WaitTime 1;\n    WaitTime 2\n"})
    with pytest.raises(InputError, match=r"line 4: unbalanced brackets"):
        read_rapid(_module("    MoveL [[1,2,3],[1,0,0,0], v100, fine, tool0;"))
    bad_cfx = _module(
        "", "  CONST robtarget p1:=[[5,1,4],[1,0,0,0],[0,0,0,9],[9E9,9E9,9E9,9E9,9E9,9E9]];"
    )
    with pytest.raises(InputError, match=r"line 2: confdata .* cfx in 0..7"):
        read_rapid(bad_cfx)
    bad_q = _module(
        "", "  CONST robtarget p1:=[[5,1,4],[1,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];"
    )
    with pytest.raises(InputError, match=r"line 2: the quaternion .* unit"):
        read_rapid(bad_q)


# ------------------------------------------------------------------ bad programs


def test_tool_without_mass_is_refused():
    prog, _ = sample_program()
    tools = tuple(replace(t, mass=None) if t.name == "gripper" else t for t in prog.tools)
    with pytest.raises(InputError, match=r"tool 'gripper': RAPID's tooldata needs the tool's mass"):
        write_rapid(replace(prog, tools=tools))


def test_flange_without_load_is_tool0():
    prog, model = sample_program()
    tools = tuple(ToolData("flange", np.eye(4)) if t.name == "flange" else t for t in prog.tools)
    prog = replace(prog, tools=tools)
    out = write_rapid(prog)
    assert "tooldata flange" not in out.text
    assert "MoveL p_flip, [50,500,5000,1000], z10, tool0\\WObj:=wobj0;" in out.text
    read = read_rapid(out.files)
    check_read_back(prog, read, model)
    assert next(t for t in read.tools if t.name == "tool0").mass == 0.001


def test_speed_beyond_the_robot_is_refused_with_the_move():
    prog, _ = sample_program()
    ins = tuple(
        replace(i, speed=1e6) if isinstance(i, MoveInstr) and i.name == "p_place" else i
        for i in prog.instructions
    )  # 1e9 mm/s
    with pytest.raises(InputError, match=r"move 2 \(p_place\): TCP speed 1e\+09 mm/s"):
        write_rapid(replace(prog, instructions=ins))


def test_reserved_and_long_names_are_renamed_with_a_note():
    prog, model = sample_program()
    long = "a_target_name_that_is_much_longer_than_thirty_two"

    def rename(i):  # noqa: ANN001, ANN202
        if isinstance(i, MoveInstr) and i.name in ("p_place", "p_flip"):
            new = "MoveL" if i.name == "p_place" else long
            return replace(
                i, target=Target(new, i.target.q, i.target.T_wobj_tcp, i.target.configuration)
            )
        return i

    prog = replace(prog, instructions=tuple(rename(i) for i in prog.instructions))
    out = write_rapid(prog)
    assert "renamed 'MoveL' to 'MoveL_1': a reserved word in RAPID" in out.notes
    assert "    ! note: renamed 'MoveL' to 'MoveL_1': a reserved word in RAPID" in out.text
    assert "MoveL MoveL_1, [250,500,5000,1000]" in out.text
    assert f"CONST robtarget {long[:32]}:=" in out.text
    assert any("at most 32 characters" in n for n in out.notes)
    check_read_back(prog, read_rapid(out.files), model)
    assert {"MoveL", "PROC", "MODULE", "IF", "tool0", "v100", "z10"} <= set(RAPID_RESERVED)


def test_names_shared_by_a_target_and_a_tool_get_distinct_identifiers():
    prog, model = sample_program()
    ins = tuple(
        replace(
            i, target=Target("gripper", i.target.q, i.target.T_wobj_tcp, i.target.configuration)
        )
        if isinstance(i, MoveInstr) and i.name == "p_pick"
        else i
        for i in prog.instructions
    )
    prog = replace(prog, instructions=ins)
    out = write_rapid(prog)
    assert "MoveJ gripper_2, v1000\\T:=0.9, z20, gripper\\WObj:=fixture;" in out.text
    assert any("'gripper' names another datum" in n for n in out.notes)
    read = read_rapid(out.files)
    check_read_back(prog, read, model)
    assert np.allclose(solve_moves(read, model)[1], prog.moves[1].target.q, atol=1e-6)


def _pressing_program():  # noqa: ANN202
    """Return (program, model): home, a pressed run of two linear moves, a lift-off move."""
    from workbench.motion.programs.controller_program import ContactForce

    prog, model = sample_program()
    home, pick, place = prog.moves[0], prog.moves[1], prog.moves[2]
    ins = (
        home,  # an exact stop: FCCalib runs with the robot still
        replace(place, force=20.0, zone=0.01),
        MoveInstr("linear", pick.target, 0.1, 0.0, "gripper", "fixture", 1.0, force=12.5),
        MoveInstr("linear", place.target, 0.1, 0.0, "gripper", "fixture", 1.0),
    )
    return replace(prog, instructions=ins, contact=ContactForce(20.0, 5000.0)), model


def test_pressed_moves_are_force_control_and_read_back():
    prog, model = _pressing_program()
    out = write_rapid(prog)
    body = [line.strip() for line in out.text.splitlines()]
    start = body.index("FCCalib gripper_load;")
    assert body[start + 1 :][:3] == [
        "FCPress1LStart p_place, [250,500,5000,1000]\\Fz:=20, 50, z10, gripper\\WObj:=fixture;",
        "FCPressL p_pick, [100,500,5000,1000], 12.5, fine, gripper\\WObj:=fixture;",
        "FCPressEnd p_place, [100,500,5000,1000], gripper\\WObj:=fixture;",
    ]
    # the sensor is calibrated with the tool's own load (its tooldata's tload)
    assert "PERS loaddata gripper_load:=[2.5,[10,0,80],[1,0,0,0],0,0,0];" in body
    # the first move is the safe one (first_move.py): bounded speed, no \T, an exact stop
    assert body.index("MoveAbsJ home, [250,45,5000,1000], fine, gripper\\WObj:=fixture;") < start
    assert "NO FORCE CONTROL" not in out.text  # RAPID presses with F itself
    assert any("Force Control" in n for n in out.notes)
    read = read_rapid(out.files)
    assert [m.force for m in read.moves] == [0.0, 20.0, 12.5, 0.0]
    check_read_back(prog, read, model)  # targets, zones, speeds and every force
    again = to_robot_program(read, model)
    assert [m.force for m in again.moves] == [m.force for m in prog.moves]


def test_a_pressed_run_must_start_still_and_end_with_a_linear_lift_off():
    prog, _ = _pressing_program()
    home, pressed, pressed2, lift = prog.instructions
    # (the first move always ends in an exact stop, first_move.py: a blended move before the run)
    blended = replace(prog, instructions=(home, replace(lift, zone=0.02), pressed, pressed2, lift))
    with pytest.raises(InputError, match="starts after an exact stop"):
        write_rapid(blended)
    with pytest.raises(InputError, match="ends while pressing"):
        write_rapid(replace(prog, instructions=(home, pressed, pressed2)))
    with pytest.raises(InputError, match="ends with a linear move"):
        write_rapid(replace(prog, instructions=(home, pressed, home)))
    with pytest.raises(InputError, match="contact force"):
        write_rapid(replace(prog, instructions=(replace(home, force=5.0), pressed, lift)))


def test_posts_without_force_control_state_the_compliant_tool():
    from workbench.motion.programs.formats import post

    prog, _ = _pressing_program()
    d_mm = 20.0 / 5000.0 * 1000.0  # D = F/k
    for fmt in ("krl", "ls", "urscript", "nachi"):
        out = post(fmt)(prog)
        text = "\n".join(out.files.values())
        # the header says it plainly (FANUC wraps long comments: compare without line breaks)
        flat = " ".join(
            re.sub(r"^\s*(\d+:)?[\s!;#']*|\s*;?\s*$", "", ln) for ln in text.splitlines()
        )
        assert f"D = F/k = {d_mm:.3f} mm" in flat, fmt
        assert "k = 5000 N/m" in flat and "F = 20 N" in flat, fmt
        assert out.notes[0].startswith("NO FORCE CONTROL"), fmt
