"""FANUC LS post and reader: read-back of the sample program, FANUC's configuration and turn
rules against hand-checked cases, the CNT mapping, a manual example, bad inputs."""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest
from program_round_trip import check_read_back, sample_program

from workbench.errors import InputError
from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs.controller_program import MoveInstr, RobotProgram, WaitInput
from workbench.motion.programs.fanuc import (
    config_text,
    termination,
    turn_number,
    turn_range_deg,
    write_ls,
    zone_of_termination,
)
from workbench.motion.programs.fanuc_read import controller_ranges, parse_config, read_ls


def _with(prog: RobotProgram, k: int, **changes: object) -> RobotProgram:
    """Return prog with instruction k replaced by a copy with `changes`."""
    ins = list(prog.instructions)
    ins[k] = dataclasses.replace(ins[k], **changes)  # type: ignore[type-var]
    return dataclasses.replace(prog, instructions=tuple(ins))


def test_sample_program_reads_back() -> None:
    prog, model = sample_program()
    out = write_ls(prog)
    assert list(out.files) == ["DEMO.ls"]
    read = read_ls(out.files)
    assert read.name == "DEMO"
    check_read_back(prog, read, model, signals_by="number", joint_zones=False)
    # the signal names travel in the I/O comments too
    assert [a.signal.name for a in read.actions() if hasattr(a, "signal")][:2] == [
        "do_grip",
        "di_closed",
    ]
    assert read.tools[1].mass == pytest.approx(2.5) and read.tools[1].cog[2] == pytest.approx(0.08)


def test_written_program_reads_as_a_fanuc_programmer_expects() -> None:
    prog, _ = sample_program()
    text = write_ls(prog).text
    mn = text.split("/MN\n")[1].split("/POS\n")[0].splitlines()
    body = [re.sub(r"^\s*\d+:", "", ln) for ln in mn]
    # frames are set from the spare PR before the first move, then selected by number
    assert body[10:18] == [
        "  PR[90]=LPOS-LPOS ;", "  PR[90,1]=40.000000 ;", "  PR[90,2]=0.000000 ;",
        "  PR[90,3]=150.000000 ;", "  PR[90,4]=30.000000 ;", "  PR[90,5]=0.000000 ;",
        "  PR[90,6]=10.000000 ;", "  UTOOL[1]=PR[90] ;",
    ]  # fmt: skip
    first_move = next(i for i, ln in enumerate(body) if ln.startswith("J "))
    assert body[first_move - 2 : first_move + 1] == [
        "  UTOOL_NUM=1 ;",
        "  UFRAME_NUM=1 ;",
        "J P[1] 10% FINE ;",  # the first move: at most 10 %, untimed
    ]
    assert "J P[2] 50% CNT100 ;" in body and "L P[3] 250mm/sec FINE ;" in body
    # circular: via on the numbered line, end on FANUC's continuation line
    k = body.index("C P[4]")
    assert body[k + 1] == "    :  P[5] 100mm/sec FINE ;"
    # the timed wait: $WAITTMOUT in 1/100 s, then WAIT .. TIMEOUT,LBL; handler after END
    k = body.index("  $WAITTMOUT=200 ;")
    assert body[k + 1] == "  WAIT DI[4:di_closed]=ON TIMEOUT,LBL[1] ;"
    end = body.index("  END ;")
    assert body[end + 1 : end + 5] == [
        "  LBL[1] ;",
        "  !timeout DI[4] 2 s ;",
        "  MESSAGE[TIMEOUT DI 4] ;",
        "  ABORT ;",
    ]
    assert "  DO[5:do_blow]=PULSE,0.3sec ;" in body and "  WAIT 0.50(sec) ;" in body
    k = body.index("  !SYNC sync_1: demo,other ;")
    # the four-phase handshake, led by demo (the first robot named)
    assert body[k + 1 : k + 5] == [
        "  WAIT DI[8:di_sync]=OFF ;",
        "  DO[7:do_sync]=ON ;",
        "  WAIT DI[8:di_sync]=ON ;",
        "  DO[7:do_sync]=OFF ;",
    ]
    assert all(len(ln.strip()[1:-2]) <= 32 for ln in body if ln.strip().startswith("!"))
    numbered = [ln for ln in mn if re.match(r"^\s*\d+:", ln)]
    assert f"LINE_COUNT\t= {len(numbered)};" in text
    # the positions: UF/UT of the move, CONFIG from the joints, 6 decimals
    assert "P[2:\"p_pick\"]{\n   GP1:\n\tUF : 1, UT : 1,\t\tCONFIG : 'F U T, 0, 0, -1'," in text
    assert "J2=     90.000000 deg" in text


@pytest.mark.parametrize(
    ("deg", "turn"),
    [(0.0, 0), (179.9, 0), (-179.9, 0), (180.0, 1), (200.0, 1), (539.9, 1), (540.0, 2),
     (-180.0, -1), (-200.0, -1), (-539.9, -1), (-540.0, -2)],
)  # fmt: skip
def test_turn_number_hand_checked(deg: float, turn: int) -> None:
    assert turn_number(deg) == turn
    lo, hi = turn_range_deg(turn)
    assert lo <= deg <= hi


def test_turn_number_against_brute_force() -> None:
    """The turn is the k with deg - 360 k in (-180, 180), ties at +-180 away from zero."""
    for deg in np.random.default_rng(3).uniform(-900, 900, 2000):
        ks = [k for k in range(-3, 4) if -180.0 < deg - 360.0 * k < 180.0]
        assert [turn_number(deg)] == ks


def test_configuration_letters_hand_checked() -> None:
    # the sample's p_pick: controller J = (10, 70, 30, 40, -30, -200) deg, planned front,
    # elbow up; J5 < 0 is FANUC's flip, J6 = -200 is turn -1
    q = np.radians([10, 70, 30, 40, -30, -200])
    assert config_text(ArmConfiguration(True, True, True), q) == "F U T, 0, 0, -1"
    q = np.radians([-30, 100, 60, -100, 30, 250])
    assert config_text(ArmConfiguration(True, True, False), q) == "N U T, 0, 0, 1"
    q = np.radians([29, 136, 83, 185, 12, 95])
    assert config_text(ArmConfiguration(False, False, False), q) == "N D B, 0, 1, 0"
    cfg, turns = parse_config("N D B, 0, 1, 0", "test")
    assert cfg == ArmConfiguration(front=False, elbow_up=False, wrist_flip=False) and turns == (
        0,
        1,
        0,
    )
    rng = np.degrees(controller_ranges(turns))
    assert rng[3] == pytest.approx([180, 540], abs=1e-3) and np.isinf(rng[1]).all()
    with pytest.raises(InputError, match="CONFIG"):
        parse_config("X U T, 0, 0, 0", "line 9")


def test_blends_are_cr_in_mm_on_cartesian_moves_and_cnt100_on_joint_moves() -> None:
    """FANUC operator's manual, "Motion options": CRy is the corner region in mm (0..1000),
    LINEAR and CIRCULAR only; CNTn is the percentage of speed kept, not a distance."""
    assert termination("linear", 0.0, "m") == ("FINE", 0.0)
    assert termination("joint", 0.0, "m") == ("FINE", 0.0)
    assert termination("linear", 0.02, "m") == ("CR20", 0.02)
    assert termination("circular", 0.0004, "m") == ("CR1", 0.001)  # a blend stays a blend
    # a joint move keeps its speed through a blended point: CNT100, whatever the zone
    assert termination("joint", 0.002, "m") == ("CNT100", 0.002)
    assert termination("joint", 0.2, "m") == ("CNT100", 0.2)
    for n in range(0, 1001, 7):
        assert zone_of_termination(f"CR{n}") == pytest.approx(n / 1000)
        if n:
            assert termination("linear", n / 1000, "m")[0] == f"CR{n}"
    assert zone_of_termination("CNT0") == 0.0 and zone_of_termination("FINE") == 0.0
    assert all(zone_of_termination(f"CNT{n}") is None for n in range(1, 101))
    with pytest.raises(InputError, match="1000"):
        termination("linear", 1.5, "move 3")
    with pytest.raises(InputError, match="CR0..CR1000"):
        zone_of_termination("CR1001")


def test_polishing_like_blends_never_write_a_small_cnt() -> None:
    """The old post wrote CNTn with n = the blend in mm (CNT2: the robot nearly stops at every
    point); every blended point is now CR (mm) or CNT100."""
    prog, _ = sample_program()
    text = write_ls(prog).files
    body = "\n".join(text.values())

    for m in re.finditer(r"\bCNT(\d+)", body):
        assert m.group(1) == "100", m.group(0)
    assert re.search(r"\bCR\d+", body) or "CNT100" in body


def test_rounded_zone_and_speed_are_noted() -> None:
    prog, _ = sample_program()
    k = next(
        i
        for i, x in enumerate(prog.instructions)
        if isinstance(x, MoveInstr) and x.kind == "linear"
    )
    out = write_ls(_with(prog, k, zone=0.0125, speed=0.2504))
    assert any("zone 12.5 mm written as 13 mm" in n for n in out.notes)
    assert any("TCP speed 250.4 mm/s written as 250 mm/s" in n for n in out.notes)
    assert "!note:" in out.text


def test_slow_speeds_use_cm_per_min_where_mm_per_sec_is_too_coarse() -> None:
    prog, model = sample_program()
    k = next(
        i
        for i, x in enumerate(prog.instructions)
        if isinstance(x, MoveInstr) and x.kind == "linear"
    )
    prog = _with(prog, k, speed=0.03762)  # 37.62 mm/s: 38 mm/sec is 1 % off, 226 cm/min 0.12 %
    out = write_ls(prog)
    assert "L P[3] 226cm/min FINE ;" in out.text
    read = read_ls(out.files)
    assert read.moves[2].speed == pytest.approx(2.26 / 60)
    check_read_back(prog, read, model, signals_by="number", joint_zones=False)


def test_manual_wait_example_and_hand_written_lines() -> None:
    """The operator's manual: $WAITTMOUT in 1/100 s (150 = 1.5 s); WAIT .. TIMEOUT,LBL[i]."""
    text = """/PROG  HAND
/MN
   1:  UFRAME_NUM=0 ;
   2:  UTOOL_NUM=0 ;
   3:J P[1:HOME] 100% CNT50 ;
   4:  $WAITTMOUT=(150) ;
   5:  WAIT DI[12]=OFF TIMEOUT,LBL[7] ;
   6:  WAIT DI[13]=ON TIMEOUT,LBL[7] ;
   7:  CALL GRIP_OPEN ;
   8:  LBL[7] ;
/POS
P[1:"HOME"]{
   GP1:
	UF : 0, UT : 0,
	J1= 0.000 deg,	J2= -30.000 deg,	J3= 0.000 deg,
	J4= 0.000 deg,	J5= -60.000 deg,	J6= 0.000 deg
};
/END
"""
    read = read_ls({"hand.ls": text})
    (mv,) = read.moves
    # CNT50 is a speed percentage, not a radius: no zone stated (0), noted
    assert mv.name == "HOME" and mv.speed == 1.0 and mv.zone == 0.0
    assert any("CNT50" in n and "not a radius" in n for n in read.notes)
    assert np.degrees(mv.target.joints) == pytest.approx([0, -30, 0, 0, -60, 0])
    assert (mv.tool, mv.wobj) == ("UTOOL0", "UFRAME0")
    waits = [a for a in read.actions() if isinstance(a, WaitInput)]
    assert [(w.signal.number, w.value, w.timeout) for w in waits] == [
        (12, False, 1.5),
        (13, True, 1.5),
    ]
    # an unknown instruction, and a label outside a handler, are listed by file line
    assert read.unknown == ((9, "CALL GRIP_OPEN"), (10, "LBL[7]"))


def test_speed_of_1e9_mm_per_s_is_refused_naming_the_move() -> None:
    prog, _ = sample_program()
    k = next(
        i
        for i, x in enumerate(prog.instructions)
        if isinstance(x, MoveInstr) and x.kind == "linear"
    )
    with pytest.raises(InputError, match=r"move 2 \(p_place\).*1e\+12 mm/s"):
        write_ls(_with(prog, k, speed=1e9))


def test_reserved_names_are_renamed_with_a_note() -> None:
    prog, _ = sample_program()
    k = next(
        i
        for i, x in enumerate(prog.instructions)
        if isinstance(x, MoveInstr) and x.kind == "linear"
    )
    mv = prog.instructions[k]
    prog = _with(prog, k, target=dataclasses.replace(mv.target, name="WAIT"))  # type: ignore[union-attr]
    out = write_ls(dataclasses.replace(prog, name="end"))
    assert "renamed 'WAIT' to 'WAIT_1': a reserved word in FANUC LS" in out.notes
    assert "renamed 'END' to 'END_1': a reserved word in FANUC LS" in out.notes
    assert list(out.files) == ["END_1.ls"]
    assert 'P[3:"WAIT_1"]' in out.text and "!note: renamed 'WAIT' to" in out.text
    assert read_ls(out.files).moves[2].name == "WAIT_1"


def test_unknown_instruction_is_listed_by_line() -> None:
    prog, _ = sample_program()
    text = write_ls(prog).text.replace("  !gripper close ;", "  CALL GRIPPER_CLOSE ;")
    lines = text.splitlines()
    no = next(i for i, ln in enumerate(lines, start=1) if "CALL GRIPPER_CLOSE" in ln)
    assert read_ls({"DEMO.ls": text}).unknown == ((no, "CALL GRIPPER_CLOSE"),)


def test_malformed_files_name_the_line() -> None:
    prog, _ = sample_program()
    text = write_ls(prog).text
    with pytest.raises(InputError, match=r"line \d+: P\[3\] is not in /POS"):
        read_ls({"DEMO.ls": text.replace('P[3:"p_place"]', 'P[33:"p_place"]')})
    with pytest.raises(InputError, match=r"line \d+ \(P\[2\]\): CONFIG"):
        read_ls({"DEMO.ls": text.replace("'F U T, 0, 0, -1'", "'F U, 0'")})
    with pytest.raises(InputError, match="exactly one .ls"):
        read_ls({"a.txt": text})
    with pytest.raises(InputError, match="/PROG"):
        read_ls({"x.ls": "/MN\n/END\n"})


def test_frames_the_program_does_not_set_read_as_identity_with_a_note() -> None:
    prog, _ = sample_program()
    text = write_ls(prog).text
    cut = re.sub(
        r"\n\s*\d+:  (PR\[90[^\n]*|UTOOL\[\d\]=PR\[90\]|UFRAME\[\d\]=PR\[90\]) ;", "", text
    )
    read = read_ls({"DEMO.ls": cut})
    assert any("UFRAME[1] is used but not set" in n for n in read.notes)
    assert np.allclose(
        next(w for w in read.work_objects if w.name == "fixture").T_base_wobj, np.eye(4)
    )


def test_a_joint_on_a_turn_boundary_is_found_in_one_turn_only() -> None:
    """J6 at exactly 180 deg (turn 1) and -180 deg (turn -1): the other turn is not taken too."""
    from workbench.kinematics.arm_configuration import arm_configuration, select_solution
    from workbench.motion.programs.fanuc import turn_number
    from workbench.motion.programs.fanuc_read import controller_ranges

    robot = preset_robot("mz07")
    for j6 in (180.0, -180.0, 0.0):
        q_ctrl = np.radians([10.0, 80.0, 20.0, 30.0, -40.0, j6])
        q = robot.convention.to_model(q_ctrl)
        turns = tuple(turn_number(np.degrees(q_ctrl[j])) for j in (0, 3, 5))
        got = select_solution(
            robot, robot.fk(q), arm_configuration(robot, q), controller_ranges(turns)
        )
        assert np.max(np.abs(got - q)) < 1e-9, j6
