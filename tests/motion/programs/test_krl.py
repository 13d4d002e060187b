"""KUKA KRL post (write_krl) and reader (read_krl): read-back of the sample program, Status and
Turn against KUKA's definitions, hand-written modules and the bad inputs of issue 12."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from program_round_trip import check_read_back, sample_program

from workbench.errors import InputError
from workbench.kinematics import DHRobot
from workbench.kinematics.arm_configuration import ArmConfiguration, arm_configuration
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs.controller_program import SetOutput, SyncPoint, WaitInput
from workbench.motion.programs.krl import status_turn, write_krl
from workbench.motion.programs.krl_read import read_krl
from workbench.motion.programs.readback import solve_moves

DEG = np.pi / 180.0


@pytest.fixture(scope="module")
def sample():  # noqa: ANN201
    return sample_program()


@pytest.fixture(scope="module")
def written(sample):  # noqa: ANN001, ANN201
    return write_krl(sample[0])


def test_sample_program_reads_back(sample, written) -> None:  # noqa: ANN001
    prog, model = sample
    assert list(written.files) == ["demo.src", "demo.dat"]
    read = read_krl(written.files)
    assert read.name == "demo"
    check_read_back(prog, read, model, signals_by="number")
    assert [t.name for t in read.tools] == ["gripper", "flange"]
    assert [w.name for w in read.work_objects] == ["fixture", "base"]
    gripper = read.tools[0]
    assert gripper.mass == pytest.approx(2.5) and np.allclose(gripper.cog, [0.01, 0.0, 0.08])
    sync = [a for a in read.actions() if isinstance(a, SyncPoint)]
    assert [(s.name, s.robots, s.output.number, s.input.number) for s in sync] == [
        ("sync_1", ("demo", "other"), 7, 8)
    ]
    waits = [a for a in read.actions() if isinstance(a, WaitInput)]
    assert [(w.signal.number, w.timeout) for w in waits] == [(4, 2.0), (6, 5.0)]


def test_written_lines_a_kuka_programmer_reads(written) -> None:  # noqa: ANN001
    src, dat = written.files["demo.src"], written.files["demo.dat"]
    lines = [ln.strip() for ln in src.splitlines()]
    assert lines[0] == "DEF demo()" and lines[-1] == "END"
    assert (
        "TOOL_DATA[1] = {X 40.000000, Y 0.000000, Z 150.000000, A 10.000000, B 0.000000, C 30.000000} ; tool gripper"
        in lines
    )
    assert (
        "BASE_DATA[1] = {X 600.000000, Y -100.000000, Z 200.000000, A 25.000000, B 0.000000, C 0.000000} ; base fixture"
        in lines
    )
    assert (
        "LOAD_DATA[1] = {M 2.5, CM {X 10.0000, Y 0.0000, Z 80.0000, A 0.0, B 0.0, C 0.0}, J {X 0.0, Y 0.0, Z 0.0}} ; tool gripper"
        in lines
    )
    # tool, load and base selected before the first move; the first move (the BCO run) at
    # 10 % on every axis (its plan said 60 %); PTP to E6AXIS
    i = lines.index("PTP Xhome_1")
    assert lines[i - 9 : i] == [
        "$TOOL = TOOL_DATA[1]",
        "$LOAD = LOAD_DATA[1]",
        "$BASE = BASE_DATA[1]",
        *[f"$VEL_AXIS[{k}] = 10" for k in range(1, 7)],
    ]
    # the zone is a distance: $APO.CDIS [mm] with C_DIS on PTP too; $APO.CPTP (a % of the
    # machine datum $APO_DIS_PTP) is never written
    assert "$APO.CDIS = 20.0" in lines and "PTP Xp_pick C_DIS" in lines
    assert not any("CPTP" in ln or "C_PTP" in ln for ln in lines)
    assert "$VEL.CP = 0.25" in lines and "LIN Xp_place" in lines
    assert "CIRC Xp_via, Xp_far" in lines and "LIN Xp_flip C_DIS" in lines
    g = lines.index("; gripper close")
    assert lines[g + 1 : g + 11] == [
        "$OUT[3] = TRUE ; do_grip",
        "$TIMER[1] = -2000 ; timeout 2.0 s",
        "$TIMER_STOP[1] = FALSE",
        "WAIT FOR $IN[4] OR $TIMER_FLAG[1] ; di_closed",
        "$TIMER_STOP[1] = TRUE",
        "IF $TIMER_FLAG[1] THEN",
        "HALT ; $IN[4] (di_closed) not TRUE within 2.0 s",
        "WAIT FOR $IN[4] ; di_closed: Start waits for it again",
        "ENDIF",
        "WAIT SEC 0.2",
    ]
    assert "PULSE($OUT[5], TRUE, 0.3) ; do_blow" in lines
    s = lines.index("; sync point sync_1: robots demo, other")
    assert lines[s + 1 : s + 5] == [  # the four-phase handshake, led by demo
        "WAIT FOR NOT $IN[8] ; di_sync",
        "$OUT[7] = TRUE ; do_sync",
        "WAIT FOR $IN[8] ; di_sync",
        "$OUT[7] = FALSE ; do_sync",
    ]
    assert (
        "; note: renamed 'home' to 'home_1': a reserved word in KRL" in lines
    )  # XHOME is $config.dat's
    d = [ln.strip() for ln in dat.splitlines()]
    assert d[0] == "DEFDAT demo" and d[-1] == "ENDDAT"
    # the upright posture in NACHI's convention: controller A2 = 90 deg
    assert (
        "DECL E6AXIS Xhome_1={A1 0.000000, A2 90.000000, A3 0.000000, A4 0.000000,"
        " A5 0.000000, A6 0.000000, E1 0.0, E2 0.0, E3 0.0, E4 0.0, E5 0.0, E6 0.0}"
    ) in d
    pick = next(x for x in d if x.startswith("DECL E6POS Xp_pick="))
    assert ", S 6, T 48, E1 0.0," in pick  # front, elbow up, A5 < 0; A5 and A6 negative
    assert all(len(x.split()[2].split("=")[0]) <= 24 for x in d if x.startswith("DECL"))


def _kuka_case(model: DHRobot, q_ctrl_deg: list[float]) -> tuple[int, int]:
    q_ctrl = np.array(q_ctrl_deg) * DEG
    q = model.convention.to_model(q_ctrl)
    return status_turn(arm_configuration(model, q), q_ctrl)


def test_status_turn_hand_checked_against_kukas_definition() -> None:
    """The MZ07 in NACHI's convention (upright = (0, 90, 0, 0, 0, 0) deg, J3 grows as the forearm
    rises, so the stretched arm is J3 ~ +82.5 deg), each case worked out from KUKA's text:
    S bit 0 overhead, bit 1 elbow up (A3 on the upright posture's side of the stretched arm),
    bit 2 A5 < 0; T bit i axis i+1 < 0."""
    m = preset_robot("mz07")
    # upright: wrist root in front of A1, elbow up, A5 = 0 -> S 'B010' = 2, all axes >= 0
    assert _kuka_case(m, [0, 90, 0, 0, 0, 0]) == (2, 0)
    # wrist bent to A5 = -30: bit 2 and T bit 4 -> S 6, T 16
    assert _kuka_case(m, [0, 90, 0, 0, -30, 0]) == (6, 16)
    # A1 = -90 turns the A1 frame with the arm: still the basic area; T bit 0
    assert _kuka_case(m, [-90, 90, 0, 0, 0, 0]) == (2, 1)
    # upper arm leant 80 deg back (J2 = 170): the wrist root lies behind A1 -> overhead, S 3
    assert _kuka_case(m, [0, 170, 60, 0, 0, 0]) == (3, 0)
    # forearm raised past the stretched arm (J3 = 120): elbow down -> S 0; A4, A6 < 0 -> T 8 + 32
    assert _kuka_case(m, [0, 60, 120, -10, 20, -5]) == (0, 40)
    # the Turn example {91, -45, 37, 1, -1, 0}: A2 and A5 negative -> 2 + 16 = 18
    cfg = ArmConfiguration(True, True, True)
    assert status_turn(cfg, np.array([91, -45, 37, 1, -1, 0]) * DEG) == (6, 18)


def test_status_bits_against_an_independent_geometric_twin() -> None:
    """Bit 0 from the wrist root's x in the A1 coordinate system (the base turned by A1), bit 1
    from A3 against the stretched arm found as the A3 that puts the wrist root farthest from
    axis 2, bit 2 from A5: KUKA's definitions computed without ArmConfiguration."""
    m = preset_robot("mz07")
    rng = np.random.default_rng(12)
    lo, hi = m.limits[:, 0], m.limits[:, 1]

    def wrist(q: np.ndarray) -> np.ndarray:
        return np.asarray(m.link_transforms(q), float)[..., 4, :3, 3]

    # the wrist root is the point the wrist joints do not move
    q0 = rng.uniform(lo, hi)
    q1 = q0.copy()
    q1[3:] = rng.uniform(lo[3:], hi[3:])
    assert np.allclose(wrist(q0), wrist(q1), atol=1e-12)
    # stretched arm: A3 (controller) maximising the distance axis 2 -> wrist root
    j3 = np.linspace(-120, 160, 28001) * DEG
    qc = np.zeros((len(j3), 6))
    qc[:, 1], qc[:, 2] = 90 * DEG, j3
    qm = m.convention.to_model(qc)
    shoulder = np.asarray(m.link_transforms(qm), float)[:, 1, :3, 3]
    phi = j3[np.argmax(np.linalg.norm(wrist(qm) - shoulder, axis=1))]
    assert 80 * DEG < phi < 85 * DEG
    checked = 0
    for _ in range(300):
        q = rng.uniform(lo, hi)
        qc = m.convention.to_controller(q)
        if qc[2] < -96 * DEG or abs(qc[2] - phi) < 0.05 * DEG:
            continue  # the folded arm (see the KRL docs) and the boundary itself
        p = wrist(q)
        x_a1 = np.cos(q[0]) * p[0] + np.sin(q[0]) * p[1]  # model J1 turns about base z
        s, t = status_turn(arm_configuration(m, q), qc)
        assert bool(s & 1) == (x_a1 < 0.0)
        assert bool(s & 2) == (qc[2] < phi)  # NACHI's J3 grows as the forearm rises
        assert bool(s & 4) == (qc[4] < 0.0)
        assert t == sum(1 << i for i in range(6) if qc[i] < 0.0)
        checked += 1
    assert checked > 200


def test_hand_written_module_with_inline_targets_and_folds() -> None:
    src = """&ACCESS RVP
&REL 1
DEF pick_place( )
;FOLD INI;%{PE}
  BAS (#INITMOV,0 )
;ENDFOLD (INI)
  $TOOL = tool_tip
  $BASE = $NULLFRAME
  $LOAD = {M 3.2, CM {X 0, Y 0, Z 90, A 0, B 0, C 0}, J {X 0, Y 0, Z 0}}
  $VEL_AXIS[1] = 30
  $VEL_AXIS[2] = 30
  $VEL_AXIS[3] = 30
  $VEL_AXIS[4] = 30
  $VEL_AXIS[5] = 30
  $VEL_AXIS[6] = 30
  PTP {A1 0, A2 90, A3 0, A4 0, A5 -30, A6 0}
  PTP {A5 -45}
  $VEL.CP = 0.2
  $APO.CDIS = 5
  LIN {E6POS: X 400, Y 0, Z 600, A 0, B 90, C 0, S 'B110', T 'B010000'} C_DIS
  LIN XP1
  WAIT FOR $IN[3]==TRUE
  $OUT[2]=FALSE
  SPTP XP1
END
"""
    dat = """DEFDAT pick_place PUBLIC
;FOLD EXTERNAL DECLARATIONS
DECL FRAME tool_tip={X 0.0,Y 0.0,Z 120.0,A 0.0,B 0.0,C 0.0}
DECL E6POS XP1={X 450.0,Y 10.0,Z 600.0,A 0.0,B 90.0,C 0.0,S 6,T 16,E1 0.0,E2 0.0,E3 0.0,E4 0.0,E5 0.0,E6 0.0}
DECL FDAT FP1={TOOL_NO 1,BASE_NO 0,IPO_FRAME #BASE,POINT2[] " "}
;ENDFOLD
ENDDAT
"""
    read = read_krl({"PICK_PLACE.SRC": src, "pick_place.dat": dat})
    assert read.name == "pick_place"
    assert read.unknown == (
        (5, "BAS (#INITMOV,0 )"),
        (5, 'pick_place.dat: DECL FDAT FP1={TOOL_NO 1,BASE_NO 0,IPO_FRAME #BASE,POINT2[] " "}'),
        (24, "SPTP XP1"),
    )
    tool = next(t for t in read.tools if t.name == "tool_tip")
    assert np.allclose(tool.T_flange_tcp[:3, 3], [0, 0, 0.12]) and tool.mass == pytest.approx(3.2)
    mv = read.moves
    assert [m.kind for m in mv] == ["joint", "joint", "linear", "linear"]
    assert mv[0].speed == pytest.approx(0.3) and mv[0].wobj == "$NULLFRAME"
    # a partial E6AXIS keeps the previous target's other axes
    assert np.allclose(np.degrees(mv[1].target.joints), [0, 90, 0, 0, -45, 0])
    lin = mv[2]
    assert lin.zone == pytest.approx(0.005) and lin.speed == pytest.approx(0.2)
    assert lin.target.configuration == ArmConfiguration(front=True, elbow_up=True, wrist_flip=True)
    assert np.allclose(
        lin.target.T_wobj_tcp[:3, :3], [[0, 0, 1], [0, 1, 0], [-1, 0, 0]], atol=1e-12
    )  # Ry(90)
    assert lin.target.controller_ranges[4, 0] == pytest.approx(
        -2 * np.pi
    ) and lin.target.controller_ranges[0, 0] == pytest.approx(-np.radians(1e-6), abs=1e-15)
    assert mv[3].target.name == "P1" and np.allclose(
        mv[3].target.T_wobj_tcp[:3, 3], [0.45, 0.01, 0.6]
    )
    assert [type(a).__name__ for a in read.actions()] == ["WaitInput", "SetOutput"]
    assert read.actions()[0].value is True and read.actions()[1].value is False


def test_abc_is_z_y_x_euler() -> None:
    """A, B, C rotate about z, then the new y, then the new x (KUKA's convention)."""
    src = "DEF t()\n  $TOOL = {X 0, Y 0, Z 0, A 0, B 0, C 0}\n  $BASE = {X 0, Y 0, Z 0, A 90, B 0, C 0}\n"
    src += "  $VEL.CP = 0.1\n  LIN {X 100, Y 0, Z 0, A 90, B 0, C 90, S 2, T 0}\nEND\n"
    read = read_krl({"t.src": src})
    R = read.moves[0].target.T_wobj_tcp[:3, :3]
    # Rz(90) @ Rx(90): x -> y, y -> z, z -> x
    assert np.allclose(R, [[0, 0, 1], [1, 0, 0], [0, 1, 0]], atol=1e-12)
    assert np.allclose(
        read.work_objects[0].T_base_wobj[:3, :3], [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-12
    )


def _with(prog, k: int, **changes):  # noqa: ANN001, ANN202
    ins = list(prog.instructions)
    ins[k] = dataclasses.replace(ins[k], **changes)
    return dataclasses.replace(prog, instructions=tuple(ins))


def test_a_speed_of_1e9_mm_per_s_is_refused_naming_the_move(sample) -> None:  # noqa: ANN001
    prog, _ = sample
    bad = _with(prog, 3, speed=1e6)  # 1e9 mm/s on the LIN to p_place
    with pytest.raises(InputError, match=r"move 2 \(p_place\): TCP speed 1e\+09 mm/s"):
        write_krl(bad)


def test_a_target_named_lin_is_renamed_with_a_note(sample) -> None:  # noqa: ANN001
    prog, model = sample
    mv = prog.instructions[3]
    bad = _with(prog, 3, target=dataclasses.replace(mv.target, name="LIN"))
    out = write_krl(bad)
    assert "renamed 'LIN' to 'LIN_1': a reserved word in KRL" in out.notes
    assert "  ; note: renamed 'LIN' to 'LIN_1': a reserved word in KRL" in out.files["demo.src"]
    assert "  LIN XLIN_1" in out.files["demo.src"] and "DECL E6POS XLIN_1=" in out.files["demo.dat"]
    check_read_back(bad, read_krl(out.files), model, signals_by="number")


def test_long_names_keep_to_krls_24_characters(sample) -> None:  # noqa: ANN001
    prog, _ = sample
    mv = prog.instructions[3]
    long = "place_on_the_second_fixture_left"
    out = write_krl(_with(prog, 3, target=dataclasses.replace(mv.target, name=long)))
    decl = next(x for x in out.files["demo.dat"].splitlines() if "E6POS Xplace" in x)
    name = decl.split()[2].split("=")[0]
    assert len(name) == 24 and name == "X" + long[:23]
    assert any("at most 23 characters" in n for n in out.notes)


def test_a_src_without_its_dat_names_the_dat_and_the_first_target(written) -> None:  # noqa: ANN001
    src = written.files["demo.src"]
    line = next(i for i, t in enumerate(src.splitlines(), 1) if t.strip() == "PTP Xhome_1")
    with pytest.raises(
        InputError, match=rf"demo.src line {line}: the target 'Xhome_1' .* demo.dat is missing"
    ):
        read_krl({"demo.src": src})


def test_an_unknown_instruction_is_listed_by_line(written) -> None:  # noqa: ANN001
    lines = written.files["demo.src"].splitlines()
    k = next(i for i, t in enumerate(lines) if t.strip() == "LIN Xp_place")
    lines.insert(k + 1, "  SPLINE")
    lines.insert(k + 2, "  ENDSPLINE")
    files = dict(written.files, **{"demo.src": "\n".join(lines)})
    read = read_krl(files)
    assert read.unknown == ((k + 2, "SPLINE"), (k + 3, "ENDSPLINE"))
    assert len(read.moves) == 7


def test_whole_percents_and_a_note_when_rounding_changes_the_speed(sample) -> None:  # noqa: ANN001
    prog, _ = sample
    out = write_krl(_with(prog, 2, speed=0.123))  # p_pick (the first move is made 10 %)
    assert "  $VEL_AXIS[1] = 12" in out.files["demo.src"]
    assert any("joint speed 12.3 % written as $VEL_AXIS 12 %" in n for n in out.notes)


def test_sync_point_without_signals_is_refused(sample) -> None:  # noqa: ANN001
    prog, _ = sample
    k = next(i for i, x in enumerate(prog.instructions) if isinstance(x, SyncPoint))
    with pytest.raises(InputError, match="sync point 'sync_1'.*output and an input"):
        write_krl(_with(prog, k, output=None))


def test_read_program_replans_from_the_read_joints(sample, written) -> None:  # noqa: ANN001
    """A Cartesian target re-solved through Status/Turn gives the planned joints although the
    same pose has other solutions (the sample's J6 = 200 deg also reaches it at -160 deg)."""
    prog, model = sample
    read = read_krl(written.files)
    joints = solve_moves(read, model)
    pick = next(k for k, m in enumerate(prog.moves) if m.name == "p_pick")
    assert np.degrees(joints[pick])[5] == pytest.approx(200.0, abs=1e-6)
    assert not any(isinstance(a, SetOutput) and a.signal.number == 7 for a in read.actions())


def test_two_targets_of_one_name_get_distinct_declarations(sample) -> None:  # noqa: ANN001
    prog, model = sample
    mv = prog.instructions[2]  # the PTP to p_pick, renamed like the LIN's p_place
    bad = _with(prog, 2, target=dataclasses.replace(mv.target, name="p_place"))
    out = write_krl(bad)
    decls = [x.split("=")[0].strip() for x in out.files["demo.dat"].splitlines() if "DECL" in x]
    assert "DECL E6POS Xp_place" in decls and "DECL E6POS Xp_place_2" in decls
    assert any("two targets are named 'p_place'" in n for n in out.notes)
    check_read_back(bad, read_krl(out.files), model, signals_by="number")


def _turn_twin(q_ctrl_deg: np.ndarray) -> int:
    """Brute force: T bit i set when axis i+1, as the pendant shows it (rounded to the file's
    6 decimals of a degree), is below 0."""
    return sum(1 << i for i, x in enumerate(q_ctrl_deg) if float(f"{x:.6f}") < 0.0)


def test_status_turn_counts_an_axis_within_1e_6_deg_of_zero_as_zero() -> None:
    cfg = ArmConfiguration(True, True, False)
    eps = np.radians(1e-9)
    for q5 in (0.0, eps, -eps, np.radians(-1e-7)):
        # exactly 0 and +-1e-9 deg (and -1e-7 deg) count as 0: no "< 0" bit anywhere
        assert status_turn(cfg, np.full(6, q5)) == (2, 0), q5
    # -1e-5 deg is below 0: A5 sets S bit 2, every axis its T bit
    assert status_turn(cfg, np.full(6, np.radians(-1e-5))) == (6, 63)
    rng = np.random.default_rng(5)
    for _ in range(2000):
        deg = rng.choice([0.0, 1e-9, -1e-9, 1e-7, -1e-7, -2e-6, 3e-6], 6) * rng.choice([1, 100], 6)
        deg += rng.choice([0.0, 1.0], 6) * rng.uniform(-200, 200, 6)
        s, t = status_turn(cfg, np.radians(deg))
        assert t == _turn_twin(deg), deg
        assert bool(s & 4) == (float(f"{deg[4]:.6f}") < 0.0), deg


def test_a_timed_out_wait_waits_again_and_never_runs_on() -> None:
    """After the timeout's HALT, Start resumes at the next statement: the post's next
    statement waits for the same input again (no timer), so the program cannot go on with
    the signal unconfirmed; the reader takes the block as the one timed wait."""
    src = write_krl(sample_program()[0]).files["demo.src"]
    lines = [ln.strip() for ln in src.splitlines()]
    for i, ln in enumerate(lines):
        if ln.startswith("IF $TIMER_FLAG"):
            block = lines[i + 1 : lines.index("ENDIF", i)]
            assert block[0].startswith("HALT") and block[1].startswith("WAIT FOR $IN[")
            assert "TIMER" not in block[1]
            # the re-wait is the same condition as the timed wait above it
            cond = lines[i - 2].split(" OR ")[0]
            assert block[1].split(" ;")[0] == cond
    read = read_krl(write_krl(sample_program()[0]).files)
    waits = [a for a in read.actions() if isinstance(a, WaitInput)]
    timed = [a for a in sample_program()[0].actions() if isinstance(a, WaitInput)]
    assert [w.timeout for w in waits] == [w.timeout for w in timed] and len(waits) == 2
    assert not read.unknown
