"""Post-processors: golden files, angle conventions against scipy, CSV/JSON round trips."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.geometry.transforms import make_transform, rpy_to_matrix
from workbench.motion.program import Move, Program
from workbench.motion.programs import (
    load_csv,
    load_json,
    save_csv,
    save_json,
    to_krl,
    to_ls,
    to_rapid,
    to_urscript,
)
from workbench.motion.programs.angles import abc_deg, quaternion_wxyz, rotation_vector, wpr_deg

GOLDEN = Path(__file__).parent / "golden"


def _program() -> Program:
    T1 = make_transform(rpy_to_matrix(np.radians([180.0, 0.0, 90.0])), [0.5, 0.1, 0.4])
    T2 = make_transform(rpy_to_matrix(np.radians([170.0, 10.0, 45.0])), [0.5, -0.2, 0.3])
    return Program(
        "demo",
        (
            Move.joint(np.radians([0, -30, 60, 0, 45, 0]), speed=0.5, name="home"),
            Move.linear(T1, speed=0.25, zone=0.01, name="approach"),
            Move.linear(T2, speed=0.1, zone=0.0, name="pick"),
            Move.joint(np.radians([10, -20, 50, 5, 40, -5]), speed=1.0, zone=0.025, name="leave"),
        ),
    )


@pytest.mark.parametrize(
    ("fmt", "fn", "ext"),
    [
        ("rapid", to_rapid, "mod"),
        ("krl", to_krl, "src"),
        ("ls", to_ls, "ls"),
        ("urscript", to_urscript, "script"),
    ],
)
def test_golden(fmt, fn, ext):
    text = fn(_program())
    ref = GOLDEN / f"demo.{ext}"
    if not ref.exists():  # first run writes the file; review it, then it pins the output
        ref.write_text(text)
    assert text == ref.read_text()


def test_golden_content_is_in_controller_units():
    rapid, krl, ls, urs = (f(_program()) for f in (to_rapid, to_krl, to_ls, to_urscript))
    assert "CONST jointtarget home:=[[0.0000, -30.0000, 60.0000, 0.0000, 45.0000, 0.0000]" in rapid
    assert "MoveL approach, [250.0,500,5000,1000], z10, tool0;" in rapid
    assert "MoveL pick, [100.0,500,5000,1000], fine, tool0;" in rapid
    # 25 mm is not predefined: zonedata literal
    assert (
        "MoveAbsJ leave, [7000.0,500,5000,1000], [FALSE,25.0,37.5,37.5,3.75,37.5,3.75], tool0;"
        in rapid
    )
    assert "[[500.000,100.000,400.000]," in rapid
    assert "PTP {E6AXIS: A1 0.000, A2 -30.000, A3 60.000, A4 0.000, A5 45.000, A6 0.000}" in krl
    assert "LIN {E6POS: X 500.000, Y 100.000, Z 400.000, A 90.000, B 0.000, C 180.000} C_DIS" in krl
    assert "$APO.CDIS = 10.0" in krl and "$VEL.CP = 0.2500" in krl
    assert "   2:L P[2] 250mm/sec CNT10 ;" in ls and "   1:J P[1] 50% FINE ;" in ls
    assert ls.startswith("/PROG  DEMO\n/ATTR") and "/MN\n" in ls and "/POS\n" in ls
    assert ls.rstrip().endswith("/END")
    assert (
        "movej([0.000000, -0.523599, 1.047198, 0.000000, 0.785398, 0.000000], a=1.4000, v=1.5700, r=0.0000)"
        in urs
    )
    assert "r=0.0100)" in urs and "r=0.0250)" in urs


def test_angle_conventions_against_scipy():
    rng = np.random.default_rng(0)
    for R in Rotation.random(200, random_state=1):
        M = R.as_matrix()
        xyzw = R.as_quat()
        wxyz = np.roll(xyzw, 1) * np.sign(xyzw[3] if xyzw[3] != 0 else 1.0)
        np.testing.assert_allclose(quaternion_wxyz(M), wxyz, atol=1e-12)
        # KUKA A, B, C = intrinsic Z, Y', X'' = scipy "ZYX"
        np.testing.assert_allclose(abc_deg(M), R.as_euler("ZYX", degrees=True), atol=1e-9)
        # FANUC W, P, R = fixed x, y, z = scipy extrinsic "xyz"
        np.testing.assert_allclose(wpr_deg(M), R.as_euler("xyz", degrees=True), atol=1e-9)
        rv = R.as_rotvec()
        np.testing.assert_allclose(rotation_vector(M), rv, atol=1e-9)
    # Near 0 and near pi, where axis-angle formulas lose precision: the angle is kept and the
    # vector rebuilds the matrix.
    axes = rng.normal(size=(50, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = np.concatenate([rng.uniform(0, 1e-6, 25), np.pi - rng.uniform(0, 1e-6, 25)])
    for axis, angle in zip(axes, angles, strict=True):
        M = Rotation.from_rotvec(axis * angle).as_matrix()
        rv = rotation_vector(M)
        assert np.linalg.norm(rv) == pytest.approx(angle, abs=1e-9)
        np.testing.assert_allclose(Rotation.from_rotvec(rv).as_matrix(), M, atol=1e-12)
    np.testing.assert_allclose(rotation_vector(np.eye(3)), 0.0)


def test_csv_and_json_round_trip(tmp_path):
    rng = np.random.default_rng(0)
    t = np.sort(rng.uniform(0, 5, 57))
    q = rng.uniform(-3, 3, (57, 6))
    save_csv(tmp_path / "s.csv", t, q)
    save_json(tmp_path / "s.json", t, q)
    for loader, name in ((load_csv, "s.csv"), (load_json, "s.json")):
        t2, q2 = loader(tmp_path / name)
        np.testing.assert_array_equal(t2, t)
        np.testing.assert_array_equal(q2, q)
    head = (tmp_path / "s.csv").read_text().splitlines()[0]
    assert head.startswith("t [s],q1 [rad]") and head.endswith("q6 [deg]")
    # the degree columns are the radians converted
    row = (tmp_path / "s.csv").read_text().splitlines()[1].split(",")
    assert float(row[7]) == pytest.approx(np.degrees(q[0, 0]), abs=1e-6)


def test_bad_program_inputs(tmp_path):
    with pytest.raises(InputError, match="speed"):
        Move.joint(np.zeros(6), speed=1.5)
    with pytest.raises(InputError, match="zone"):
        Move.joint(np.zeros(6), zone=-0.01)
    with pytest.raises(InputError, match="target"):
        Move.joint(np.zeros(5))
    with pytest.raises(InputError, match="rotation"):
        Move.linear(np.diag([1.0, 1.0, -1.0, 1.0]))
    with pytest.raises(InputError, match="name"):
        Program("2bad name", (Move.joint(np.zeros(6)),))
    with pytest.raises(InputError, match="positions"):
        save_csv(tmp_path / "x.csv", [0.0, 1.0], np.zeros((3, 6)))
    (tmp_path / "bad.json").write_text("{}")
    with pytest.raises(InputError, match="format"):
        load_json(tmp_path / "bad.json")


def test_export_dispatches_every_format_and_names_a_bad_one(tmp_path):
    from workbench.motion.programs import EXPORT_FORMATS, export

    program = _program()
    times = np.array([0.0, 0.5])
    joints = np.radians([[0, -30, 60, 0, 45, 0], [10, -20, 50, 5, 40, -5]])
    assert export("rapid", program, times, joints) == to_rapid(program)
    assert export("krl", program, times, joints) == str(to_krl(program))
    assert export("ls", program, times, joints) == to_ls(program)
    assert export("urscript", program, times, joints) == to_urscript(program)
    (tmp_path / "s.csv").write_text(export("csv", program, times, joints))
    (tmp_path / "s.json").write_text(export("json", program, times, joints))
    t, q = load_csv(tmp_path / "s.csv")
    tj, qj = load_json(tmp_path / "s.json")
    np.testing.assert_array_equal(tj, t)
    np.testing.assert_array_equal(qj, q)
    np.testing.assert_allclose(t, times, atol=1e-9)
    np.testing.assert_allclose(q, joints, atol=1e-6)
    assert set(EXPORT_FORMATS) == {"rapid", "krl", "ls", "urscript", "nachi", "csv", "json"}
    with pytest.raises(InputError, match=r"format: 'gcode' is not one of rapid, krl"):
        export("gcode", program, times, joints)
