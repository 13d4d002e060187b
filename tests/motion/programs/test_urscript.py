"""URScript post and reader: read-back of the sample program, the rotation-vector pose against
scipy, the URScript manual's move examples, I/O numbering, timeouts, bad inputs."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from program_round_trip import check_read_back, sample_program
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.kinematics.arm_configuration import arm_configuration
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs.controller_program import (
    MoveInstr,
    RobotProgram,
    SetOutput,
    Signal,
    Target,
    ToolData,
    WaitInput,
    WorkObject,
)
from workbench.motion.programs.urscript import blend_radii, pose_text, write_urscript
from workbench.motion.programs.urscript_read import read_urscript, rotvec_matrix


def _with(prog: RobotProgram, k: int, **changes: object) -> RobotProgram:
    ins = list(prog.instructions)
    ins[k] = dataclasses.replace(ins[k], **changes)  # type: ignore[type-var]
    return dataclasses.replace(prog, instructions=tuple(ins))


def _first(prog: RobotProgram, kind: str) -> int:
    return next(
        i for i, x in enumerate(prog.instructions) if isinstance(x, MoveInstr) and x.kind == kind
    )


def test_sample_program_reads_back() -> None:
    prog, model = sample_program()
    out = write_urscript(prog)
    assert list(out.files) == ["demo.script"]
    read = read_urscript(out.files)
    assert read.name == "demo" and not read.notes
    check_read_back(prog, read, model, signals_by="number")
    gripper = next(t for t in read.tools if t.name == "gripper")
    assert gripper.mass == pytest.approx(2.5) and gripper.cog == pytest.approx([0.01, 0.0, 0.08])


def test_written_program_reads_as_a_ur_programmer_expects() -> None:
    prog, _ = sample_program()
    lines = [ln.strip() for ln in write_urscript(prog).text.splitlines()]
    assert lines[1] == "def demo():" and lines[-2:] == ["end", "demo()"]
    assert "fixture = p[0.6, -0.1, 0.2, 0.0, 0.0, 0.436332313]" in lines
    k = lines.index("set_tcp(gripper)")
    assert lines[k + 1] == "set_payload(2.5, [0.01, 0.0, 0.08])"
    assert lines[k + 2 : k + 4] == [
        "# home, work object fixture",
        # the first move: no t= (reached from anywhere), 10 % of 180 deg/s
        "movej([0.0, 1.570796327, 0.0, 0.0, 0.0, 0.0], a=1.4, v=0.314159265, r=0.0)",
    ]
    # a Cartesian joint move: the controller's IK nearest the planned (controller) joints
    pick = next(ln for ln in lines if ln.startswith("movej(get_inverse_kin("))
    q = np.radians([10, 70, 30, 40, -30, -200])
    assert f"qnear=[{', '.join(f'{x:.9f}'.rstrip('0') for x in q)}]), t=0.9, r=0.02)" in pick
    assert pick.startswith("movej(get_inverse_kin(pose_trans(fixture, p[")
    movel = next(ln for ln in lines if ln.startswith("movel("))
    assert movel.endswith("a=1.2, v=0.25, r=0.0)")
    assert next(ln for ln in lines if ln.startswith("movec(")).endswith(
        "a=1.2, v=0.1, r=0.0, mode=0)"
    )
    # the timed wait, the plain wait of the sync handshake, the pulse
    k = lines.index("while not get_standard_digital_in(4):")
    assert lines[k - 1] == "wait_t = 0" and lines[k + 1] == "if wait_t >= 2.0:"
    assert lines[k + 3 : k + 8] == [
        "halt",
        "end",
        "sync()",
        "wait_t = wait_t + get_steptime()",
        "end",
    ]
    k = lines.index("# sync sync_1: demo, other")
    assert lines[k + 1 : k + 9] == [  # the four-phase handshake, led by demo
        "while get_configurable_digital_in(0):",
        "sync()",
        "end",
        "set_standard_digital_out(7, True)",
        "while not get_configurable_digital_in(0):",
        "sync()",
        "end",
        "set_standard_digital_out(7, False)",
    ]
    k = lines.index("# pulse DO 5 for 0.3 s")
    assert lines[k + 1 : k + 4] == [
        "set_standard_digital_out(5, True)",
        "sleep(0.3)",
        "set_standard_digital_out(5, False)",
    ]


def test_pose_rotation_vector_against_scipy() -> None:
    rng = np.random.default_rng(7)
    for rv in rng.normal(size=(200, 3)) * 1.5:
        R = Rotation.from_rotvec(rv).as_matrix()
        assert rotvec_matrix(rv) == pytest.approx(R, abs=1e-12)
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = R, rng.normal(size=3)
        v = np.array([float(x) for x in pose_text(T)[2:-1].split(",")])
        assert Rotation.from_rotvec(v[3:]).as_matrix() == pytest.approx(R, abs=1e-8)
        assert v[:3] == pytest.approx(T[:3, 3], abs=1e-9)


def test_manual_examples_and_hand_written_forms() -> None:
    """URScript manual examples: movej([..], a=1.4, v=1.05, t=0, r=0) -> speed 1.05 rad/s
    (1/3 of UR's 180 deg/s); movel(pose, a=1.2, v=0.25, t=0, r=0) in the base frame."""
    text = """def hand():
  set_tcp(p[0, 0, 0.1, 0, 0, 0])
  movej([0, 1.57, -1.57, 3.14, -1.57, 1.57], a=1.4, v=1.05, t=0, r=0)
  movel(p[0.2, 0.3, 0.5, 0, 0, 3.14], a=1.2, v=0.25, t=0, r=0.01)
  set_configurable_digital_out(2, True)
  textmsg("done")
end
hand()
"""
    read = read_urscript({"hand.script": text})
    j, lin = read.moves
    assert j.kind == "joint" and j.speed == pytest.approx(1.05 / np.pi) and j.duration is None
    assert j.target.joints == pytest.approx([0, 1.57, -1.57, 3.14, -1.57, 1.57])
    assert lin.speed == 0.25 and lin.zone == 0.01 and lin.wobj == "base" and lin.tool == "tcp_1"
    assert lin.target.T_wobj_tcp[:3, 3] == pytest.approx([0.2, 0.3, 0.5])
    assert read.tools[0].T_flange_tcp[2, 3] == pytest.approx(0.1)
    (out,) = [a for a in read.actions() if isinstance(a, SetOutput)]
    assert out.signal.number == 10 and out.value  # configurable 2 = signal 10
    assert read.unknown == ((6, 'textmsg("done")'),)
    assert any("states no joints" in n for n in read.notes)


def test_joint_move_without_a_planned_time_writes_its_speed() -> None:
    prog, model = sample_program()
    last = max(
        i for i, x in enumerate(prog.instructions) if isinstance(x, MoveInstr) and x.kind == "joint"
    )
    prog = _with(prog, last, duration=0.0)
    out = write_urscript(prog)
    assert "movej([0.0, 1.570796327, 0.0, 0.0, 0.0, 0.0], a=1.4, v=3.141592654, r=0.0)" in out.text
    read = read_urscript(out.files)
    assert read.moves[-1].speed == pytest.approx(1.0) and read.moves[-1].duration is None
    check_read_back(prog, read, model, signals_by="number")


def test_io_numbers_ur_does_not_have_are_refused() -> None:
    prog, _ = sample_program()
    k = next(i for i, x in enumerate(prog.instructions) if isinstance(x, WaitInput))
    with pytest.raises(InputError, match="signal 'di_part': input 16 is not a UR digital input"):
        write_urscript(_with(prog, k, signal=Signal("di_part", 16)))


def test_speed_of_1e9_mm_per_s_is_refused_naming_the_move() -> None:
    prog, _ = sample_program()
    with pytest.raises(InputError, match=r"move 2 \(p_place\).*1e\+12 mm/s"):
        write_urscript(_with(prog, _first(prog, "linear"), speed=1e9))


def test_reserved_names_are_renamed_with_a_note() -> None:
    prog, _ = sample_program()
    k = _first(prog, "linear")
    mv = prog.instructions[k]
    prog = _with(prog, k, target=dataclasses.replace(mv.target, name="movej"))  # type: ignore[union-attr]
    tools = (dataclasses.replace(prog.tools[0], name="end"), prog.tools[1])
    ins = tuple(
        dataclasses.replace(i, tool="end")
        if isinstance(i, MoveInstr) and i.tool == "gripper"
        else i
        for i in prog.instructions
    )
    out = write_urscript(dataclasses.replace(prog, name="def", tools=tools, instructions=ins))
    assert "renamed 'def' to 'def_1': a reserved word in URScript" in out.notes
    assert "renamed 'end' to 'end_1': a reserved word in URScript" in out.notes
    assert "renamed 'movej' to 'movej_1': a reserved word in URScript" in out.notes
    assert list(out.files) == ["def_1.script"] and "set_tcp(end_1)" in out.text
    assert "# note: renamed 'movej' to 'movej_1'" in out.text
    read = read_urscript(out.files)
    assert read.moves[2].name == "movej_1" and read.moves[0].tool == "end_1"


def test_unknown_instruction_is_listed_by_line() -> None:
    prog, _ = sample_program()
    text = write_urscript(prog).text.replace("  # gripper close\n", '  textmsg("closing")\n')
    no = next(i for i, ln in enumerate(text.splitlines(), start=1) if "textmsg" in ln)
    assert read_urscript({"demo.script": text}).unknown == ((no, 'textmsg("closing")'),)
    # a wait loop of another shape is listed whole, not read as a wait
    odd = text.replace("wait_t = wait_t + get_steptime()", "wait_t = wait_t + 0.008", 1)
    unknown = read_urscript({"demo.script": odd}).unknown
    assert any(t.startswith("while not get_standard_digital_in(4)") for _, t in unknown)


def test_malformed_files_name_the_line() -> None:
    prog, _ = sample_program()
    text = write_urscript(prog).text
    with pytest.raises(InputError, match=r"line \d+: expected 6 numbers"):
        read_urscript(
            {"demo.script": text.replace("fixture = p[0.6, -0.1, 0.2,", "fixture = p[0.6, -0.1,")}
        )
    with pytest.raises(InputError, match=r"line \d+: pose_trans of 'table'"):
        bad = text.replace("pose_trans(fixture, p[", "pose_trans(table, p[", 1)
        assert bad != text
        read_urscript({"demo.script": bad})
    with pytest.raises(InputError, match="no 'def"):
        read_urscript({"x.script": "movej([0,0,0,0,0,0])\n"})
    with pytest.raises(InputError, match="exactly one .script"):
        read_urscript({"x.ls": text})


def _line_program(steps_mm: list[float], zones_mm: list[float]) -> RobotProgram:
    """Linear moves along x through points `steps_mm` apart (Cartesian targets, base frame)."""
    model = preset_robot("mz07")
    q = np.radians([0, 90, 0, 0, -90, 0])
    tool = ToolData("t", np.eye(4))
    x = np.cumsum([0.0, *steps_mm]) / 1000.0
    moves = []
    for k, (xi, z) in enumerate(zip(x, [0.0, *zones_mm], strict=True)):
        T = np.eye(4)
        T[:3, 3] = [0.4 + xi, 0.0, 0.3]
        moves.append(
            MoveInstr(
                "linear",
                Target(f"p{k}", q, T, arm_configuration(model, q)),
                0.1,
                z / 1000.0,
                "t",
                "base",
            )
        )
    return RobotProgram(
        "line", (tool,), (WorkObject("base", np.eye(4)),), tuple(moves), model.convention
    )


def _radii_twin(steps_mm: list[float], zones_mm: list[float]) -> list[float]:
    """Brute force: for each waypoint, the largest r (0.001 mm grid) up to its zone that is at
    most half of each segment it touches; the last waypoint and exact stops 0."""
    zones = [0.0, *zones_mm]
    out = []
    for k, z in enumerate(zones):
        if z <= 0 or k == len(zones) - 1:
            out.append(0.0)
            continue
        segs = [steps_mm[k - 1]] if k > 0 else []
        segs.append(steps_mm[k])
        grid = np.arange(0.0, z + 1e-9, 0.001)
        out.append(
            float(
                grid[np.all(grid[:, None] <= 0.5 * np.array(segs)[None, :] + 1e-12, axis=1)].max()
            )
        )
    return out


def test_blend_radii_never_overlap_against_a_brute_force_twin() -> None:
    """UR: a blend may not overlap the next one (r_i + r_(i+1) <= the segment) nor reach past
    half of a segment. 5 mm blends on 9.4 mm segments (the bending programs) become 4.7 mm."""
    steps = [9.4] * 6
    r = blend_radii(_line_program(steps, [5.0] * 6))
    assert np.allclose(np.array(r) * 1000, [0, 4.7, 4.7, 4.7, 4.7, 4.7, 0])
    rng = np.random.default_rng(3)
    for _ in range(40):
        n = int(rng.integers(2, 8))
        steps = list(np.round(rng.uniform(0.5, 30.0, n), 3))
        zones = list(np.round(rng.choice([0.0, 1.0, 5.0, 20.0], n) * rng.uniform(0.5, 1.5, n), 3))
        got = np.array(blend_radii(_line_program(steps, zones))) * 1000
        assert np.allclose(got, _radii_twin(steps, zones), atol=2e-3), (steps, zones)
        for i in range(n):
            assert got[i] + got[i + 1] <= steps[i] + 1e-6
    # the script writes the cut radii and says so
    out = write_urscript(_line_program([9.4] * 3, [5.0] * 3))
    text = out.files["line.script"]
    assert text.count("r=0.0047)") == 2 and "r=0.005)" not in text
    assert any("no two blends overlap" in n for n in out.notes)
