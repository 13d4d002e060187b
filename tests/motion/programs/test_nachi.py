"""NACHI FD post and reader: read-back of the sample program, documented MOVEX forms parsed to
known values, NACHI's pose convention against a real MZ07F's teach pendant, bad inputs.

What a NACHI program file cannot carry: tool TCPs (H=n), accuracy distances (A=n) and user
coordinates are controller constants. write_nachi lists them in header comments
(' TOOL / ' ACCURACY / ' USERCOORD) for the operator to enter, and read_nachi reads those back,
so check_read_back runs on everything; test_without_header_* shows what a bare file gives.
"""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest
from program_round_trip import check_read_back, sample_program

from workbench.errors import InputError
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs.controller_program import MoveInstr, SyncPoint, Target
from workbench.motion.programs.nachi import accuracy_levels, nachi_pose, write_nachi
from workbench.motion.programs.nachi_read import nachi_transform, read_nachi
from workbench.motion.programs.readback import solve_moves

DEG = np.pi / 180.0


def _angle_deg(Ra: np.ndarray, Rb: np.ndarray) -> float:
    return float(np.degrees(np.arccos(np.clip((np.trace(Ra.T @ Rb) - 1) / 2, -1, 1))))


def test_sample_program_reads_back() -> None:
    prog, model = sample_program()
    out = write_nachi(prog)
    assert list(out.files) == ["r1-01-A.001"]  # the sample robot "r1": unit_name(robot)
    read = read_nachi(out.files)
    check_read_back(prog, read, model, signals_by="number")
    assert read.name == "demo"


def test_program_number_and_unit() -> None:
    prog, _ = sample_program(name="cell_12")
    # program 001 whatever the program's name (the name's digits are not a program number)
    assert list(write_nachi(prog).files) == ["r1-01-A.001"]
    assert list(write_nachi(prog, unit="MZ07L-01-A", number=5).files) == ["MZ07L-01-A.005"]
    with pytest.raises(InputError, match="unit"):
        write_nachi(prog, unit="MZ 07")


def test_written_text_reads_like_a_nachi_program() -> None:
    """Golden-free: every instruction line is a NACHI form; joints are the controller's."""
    prog, _ = sample_program()
    text = write_nachi(prog).text
    lines = [ln for ln in text.splitlines() if ln.strip()]
    assert lines[-1] == "END"
    forms = (
        r"MOVEX A=\dP?,AC=0,SM=0,M1J,(P|L|C1|C2),\((-?\d+\.\d{6},){5}-?\d+\.\d{6}\),"
        r"(R|S)=\d+\.\d{3},H=\d+,MS",
        r"(SET|RESET) O\d+",
        r"(WAITI|WAITJ) I\d+",
        r"DELAY \d+\.\d{3}",
        r"'.*",
        r"END",
    )
    for ln in lines:
        assert any(re.fullmatch(f, ln) for f in forms), ln
    # home: model (0, 0, 0, 0, -90, 0) deg is the pendant's upright (0, 90, 0, 0, 0, 0)
    assert (
        "M1J,P,(0.000000,90.000000,0.000000,0.000000,0.000000,0.000000),R=10.000,H=1" in text
    )  # the first move: at most 10 %
    # joint moves in % of the maximum, linear ones in mm/s; exact stop A=1P, blends by level
    assert "M1J,L,(-30.000000,100.000000" in text and "S=250.000,H=1" in text
    assert "' ACCURACY A=2 10.0000 mm" in text and "' ACCURACY A=3 20.0000 mm" in text
    assert "MOVEX A=3,AC=0,SM=0,M1J,P,(10.000000,70.000000" in text  # p_pick, zone 20 mm
    assert (
        "' TOOL H=1 gripper X=40.0000 Y=0.0000 Z=150.0000 RZ=10.000000 RY=0.000000 RX=30.000000"
        in text
    )
    # the notes head the file as comments too
    for note in write_nachi(prog).notes:
        assert f"' note: {note}" in text


def test_configuration_comment_follows_nachis_flip_rule() -> None:
    """NACHI (manual, quoted by gstorm-b's MZ04D page): FLIP when J5 < 0, NON-FLIP when J5 > 0.

    p_pick has controller J5 = -30 deg, p_place +30 deg (hand-checked from the sample's model
    joints: J5_ctrl = -q5 - 90).
    """
    prog, _ = sample_program()
    text = write_nachi(prog).text
    pick = next(ln for ln in text.splitlines() if ln.startswith("' TARGET p_pick"))
    place = next(ln for ln in text.splitlines() if ln.startswith("' TARGET p_place"))
    assert pick.endswith("CONFIG front,elbow_up,flip")
    assert place.endswith("CONFIG front,elbow_up,no_flip")
    assert (
        ",-30.000000,-200.000000),R=50.000" in text and ",30.000000,250.000000),S=250.000" in text
    )


# A real MZ07F's teach pendant (gstorm-b/RobotKinematics, docs/preset_references/nachi-mz07f.md):
# joints [deg] and the flange pose X, Y, Z [mm], RZ, RY, RX [deg].
PENDANT = [
    ((21.4862, 64.4801, -41.7744, -180.007, 22.7216, -158.513), (339.525, 133.617, 278.473, 0.000535733, 0.0236197, 179.986)),
    ((18.6965, 68.6763, -39.6996, -158.418, 38.2621, -180.401), (339.486, 133.658, 311.388, 1.99842, 10.7741, -169.478)),
    ((4.98917, 73.5581, -44.4732, -189.95, 35.3251, -153.57), (339.5, 21.8373, 319.019, -13.2406, 3.7502, 172.732)),
    ((-25.4971, 70.7751, -42.0408, 44.0796, -38.9396, -79.9948), (339.49, -124.109, 319.939, 14.2266, -16.2692, -159.49)),
]  # fmt: skip


def test_pose_convention_matches_the_mz07f_pendant() -> None:
    """A hand-written M1X line with the pendant's pose reads to the orientation our MZ07 model
    (through NACHI's joint convention) has at the pendant's joints, and the post's angles of
    that FK orientation are the pendant's (X, Y, Z, RZ, RY, RX) numbers: R = Rz Ry Rx."""
    model = preset_robot("mz07")
    for joints, pose in PENDANT:
        x, y, z, rz, ry, rx = pose
        text = (
            f"MOVEX A=1P,AC=0,SM=0,M1X,P,({x},{y},{z},{rz},{ry},{rx}),R=10,H=1,MS,CONF=0000\nEND\n"
        )
        read = read_nachi({"MZ07-01-A.002": text})
        T_read = read.moves[0].target.T_wobj_tcp
        T_fk = model.fk(model.convention.to_model(np.array(joints) * DEG))
        assert _angle_deg(T_read[:3, :3], T_fk[:3, :3]) < 0.02, joints
        np.testing.assert_allclose(T_read[:3, 3] * 1000, [x, y, z], atol=1e-9)
        got = nachi_pose(T_fk)[3:]
        diff = (got - np.array([rz, ry, rx]) + 180.0) % 360.0 - 180.0
        assert np.max(np.abs(diff)) < 0.03, (got, pose)
        assert any("CONF=0000" in n for n in read.notes)  # kept, not decoded


def test_nachi_pose_round_trip() -> None:
    rng = np.random.default_rng(3)
    for _ in range(50):
        v = np.concatenate([rng.uniform(-900, 900, 3), rng.uniform(-179, 179, 3)])
        v[4] = rng.uniform(-89, 89)
        np.testing.assert_allclose(nachi_pose(nachi_transform(v)), v, atol=1e-9)


def test_documented_movex_forms_parse_to_known_values() -> None:
    """Forms from Cenit's OTC-Daihen FD19 translator and RoboDK's NACHI post comments."""
    text = "\n".join(
        [
            # Cenit, OutputSourceLin: a joint target moved linearly at 500 mm/s, exact stop
            "MOVEX A=2P,AC=0,SM=0,M1J,L,(11.27, 36.04, 48.04, 21.85, 111.82, -188.45),S=500,H=0,MS",
            # Cenit, OutputSourcePtp: 50 %, with external mechanisms M2/M3 after MS
            "MOVEX A=1P,AC=0,SM=0,M1J,P,(-3.56, 41.65, 11.93, 33.56, 132.76, -157.18),R=50,H=0,"
            "MS,M2J,P,(2250.00, 0.00, 185.00),R=50,H=0,M3J,P,(90.00, 0.00),R=50,H=0",
            # RoboDK, Nachi_AX_FD.py MoveJ comment: a Cartesian target, level 1, 5 %, tool 1
            "MOVEX A=1,M1X,P,(1960,0,1725,0,0,-180),R=5.0,H=1,MS,CONF=0000",
            "END",
        ]
    )
    read = read_nachi({"MZ07-01-A.003": text})
    lin, ptp, cart = read.moves
    assert lin.kind == "linear" and lin.speed == pytest.approx(0.5) and lin.zone == 0.0
    np.testing.assert_allclose(
        lin.target.joints, np.array([11.27, 36.04, 48.04, 21.85, 111.82, -188.45]) * DEG
    )
    assert lin.tool == "H0" and lin.wobj == "base" and lin.line == 1
    assert ptp.kind == "joint" and ptp.speed == pytest.approx(0.5)
    np.testing.assert_allclose(ptp.target.joints[0], -3.56 * DEG)
    assert read.unknown == ((2, text.splitlines()[1]),)  # the external axes are not ours
    assert cart.kind == "joint" and cart.speed == pytest.approx(0.05) and cart.tool == "H1"
    T = cart.target.T_wobj_tcp
    np.testing.assert_allclose(T[:3, 3], [1.960, 0.0, 1.725], atol=1e-12)
    np.testing.assert_allclose(T[:3, :3], np.diag([1.0, -1.0, -1.0]), atol=1e-12)  # Rx(180)
    assert cart.target.configuration is None  # CONF is not decoded
    assert any("H=0" in n for n in read.notes) and any("H=1" in n for n in read.notes)


def test_hand_written_io_and_comments() -> None:
    text = "\n".join(
        [
            'REM "pick cycle"',
            "' just a comment",
            "SET O12",
            "RESET [03]",
            "WAITJ I7",
            "PAUSE 1.5",
            "END",
        ]
    )
    read = read_nachi({"MZ07-01-A.004": text})
    a = read.actions()
    assert [type(x).__name__ for x in a] == ["SetOutput", "SetOutput", "WaitInput", "WaitTime"]
    assert a[0].signal.number == 12 and a[0].value and a[1].signal.number == 3 and not a[1].value
    assert a[2].signal.number == 7 and a[2].value is False and a[2].timeout is None
    assert a[3].seconds == 1.5 and not read.unknown


def test_accuracy_levels_and_their_inverse() -> None:
    prog, _ = sample_program()
    assert accuracy_levels(prog) == {0.01: 2, 0.02: 3}
    zones = [0.0, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1]
    moves = [replace(m, zone=zones[k % len(zones)]) for k, m in enumerate(prog.moves)]
    many = replace(prog, instructions=tuple(moves))
    read = read_nachi(write_nachi(many).files)
    assert [m.zone for m in read.moves] == pytest.approx([m.zone for m in moves], abs=1e-9)
    # eight distinct blend zones need a ninth level: refused, naming the move
    first = prog.moves[0]
    assert len(moves) == 7 and len({m.zone for m in moves if m.zone > 0}) == 6
    moves8 = [*moves, replace(first, zone=0.2)]
    moves8.append(replace(first, zone=0.3, target=replace(first.target, name="p_wide")))
    write_nachi(replace(prog, instructions=tuple(moves8[:-1])))  # 7 zones: levels 2..8
    with pytest.raises(InputError, match=r"move 8 \(p_wide\).*7 distinct zones"):
        write_nachi(replace(prog, instructions=tuple(moves8)))


def test_without_header_tools_and_levels_are_noted() -> None:
    """A file without our header comments: H=n and A=n are controller constants -> noted."""
    text = "MOVEX A=4,AC=0,SM=0,M1J,P,(0,90,0,0,0,0),R=30,H=2,MS\nEND\n"
    read = read_nachi({"MZ07-01-A.006": text})
    mv = read.moves[0]
    assert mv.zone == 0.0 and mv.tool == "H2"
    assert any("A=4" in n for n in read.notes) and any("H=2" in n for n in read.notes)
    q = solve_moves(read, preset_robot("mz07"))[0]
    np.testing.assert_allclose(q / DEG, [0, 0, 0, 0, -90, 0], atol=1e-9)


def test_speed_of_1e9_mm_s_is_refused_naming_the_move() -> None:
    prog, _ = sample_program()
    moves = list(prog.instructions)
    k = next(i for i, m in enumerate(moves) if isinstance(m, MoveInstr) and m.kind == "linear")
    moves[k] = replace(moves[k], speed=1e6)  # 1e9 mm/s
    with pytest.raises(InputError, match=r"move 2 \(p_place\).*1e\+09 mm/s"):
        write_nachi(replace(prog, instructions=tuple(moves)))


def test_reserved_word_name_is_renamed_with_a_note() -> None:
    prog, model = sample_program()
    moves = list(prog.instructions)
    k = next(i for i, m in enumerate(moves) if isinstance(m, MoveInstr))
    mv = moves[k]
    moves[k] = replace(mv, target=Target("MOVEX", mv.target.q))
    out = write_nachi(replace(prog, instructions=tuple(moves)))
    assert any("'MOVEX'" in n and "reserved" in n for n in out.notes)
    assert "' TARGET MOVEX_1 WOBJ fixture" in out.text
    read = read_nachi(out.files)
    assert read.moves[0].name == "MOVEX_1"
    check_read_back(replace(prog, instructions=tuple(moves)), read, model, signals_by="number")


def test_unknown_instruction_is_listed_by_line() -> None:
    prog, _ = sample_program()
    text = write_nachi(prog).text.replace("DELAY 0.500", "DELAY 0.500\nCALLP 017\nFOO 1,2")
    read = read_nachi({"MZ07-01-A.001": text})
    lines = text.splitlines()
    want = tuple((i + 1, s) for i, s in enumerate(lines) if s in ("CALLP 017", "FOO 1,2"))
    assert read.unknown == want and len(want) == 2


def test_malformed_input_names_the_line() -> None:
    with pytest.raises(InputError, match="line 2: the MOVEX position needs 6"):
        read_nachi({"A.001": "' x\nMOVEX A=1P,M1J,P,(1,2,3,4,5),R=10,H=1,MS\nEND"})
    with pytest.raises(InputError, match="line 1: .*C1 .* not followed by its C2"):
        read_nachi({"A.001": "MOVEX A=1P,M1J,C1,(1,2,3,4,5,6),S=10,H=1,MS\nEND"})
    with pytest.raises(InputError, match="line 1: .*needs the mechanism"):
        read_nachi({"A.001": "MOVEX A=1P,(1,2,3,4,5,6),S=10,H=1,MS"})
    with pytest.raises(InputError, match="one NACHI program file"):
        read_nachi({"A.001": "END", "B.002": "END"})


def test_sync_point_needs_handshake_signals() -> None:
    prog, _ = sample_program()
    ins = tuple(
        replace(i, output=None) if isinstance(i, SyncPoint) else i for i in prog.instructions
    )
    with pytest.raises(InputError, match="sync_1.*handshake"):
        write_nachi(replace(prog, instructions=ins))
