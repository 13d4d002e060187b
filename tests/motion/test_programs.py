"""Controller angle conventions against scipy, CSV/JSON sample round trips, bad motion programs."""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.program import Move, Program
from workbench.motion.programs import (
    csv_text,
    json_text,
    load_csv,
    load_json,
    save_csv,
    save_json,
)
from workbench.motion.programs.angles import abc_deg, quaternion_wxyz, rotation_vector, wpr_deg


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


def test_orientations_are_canonical_where_the_convention_leaves_a_choice():
    """Rounding noise must not flip what a program states: a half turn about z prints C = +180
    (never -180) and a quaternion with w = 0 has its first printed component positive,
    however the noise falls; the rotation stays the same."""
    rng = np.random.default_rng(3)
    for axis in (np.array([1.0, 0, 0]), np.array([0, 0.6, -0.8]), np.array([0, 0, -1.0])):
        for _ in range(20):
            noise = Rotation.from_rotvec(rng.normal(size=3) * 1e-15)
            M = (noise * Rotation.from_rotvec(axis * np.pi)).as_matrix()
            q = quaternion_wxyz(M)
            lead = q[np.flatnonzero(np.abs(q) >= 5e-10)[0]]
            assert lead > 0, q
            np.testing.assert_allclose(
                Rotation.from_quat(np.roll(q, -1)).as_matrix(), M, atol=1e-12
            )
            for angles in (abc_deg(M), wpr_deg(M)):
                assert np.all(angles > -180.0 + 5e-7) and np.all(angles <= 180.0 + 5e-7), angles
    # C of a tool pointing down with noise on either side of the branch cut
    for eps in (1e-15, -1e-15, 0.0):
        M = Rotation.from_euler("ZYX", [30.0, 0.0, 180.0 + eps], degrees=True).as_matrix()
        assert abc_deg(M)[2] == pytest.approx(180.0, abs=1e-9)
        assert wpr_deg(M)[0] == pytest.approx(180.0, abs=1e-9)


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


def test_samples_in_the_controllers_convention_say_so(tmp_path):
    """With the robot's convention the samples are the controller's joints (the MZ07's
    upright is (0, 90, 0, 0, 0, 0) deg, the model's (0, 0, 0, 0, -90, 0)) and the headers say so."""
    conv = preset_robot("mz07").convention
    q_model = np.radians([[0, 0, 0, 0, -90, 0], [10, -20, 30, 40, -50, 60]])
    t = np.array([0.0, 1.0])
    text = csv_text(t, q_model, convention=conv)
    head = text.splitlines()[0].split(",")
    assert head[1] == "J1 controller [rad]" and head[-1] == "J6 controller [deg]"
    (tmp_path / "c.csv").write_text(text)
    _, q = load_csv(tmp_path / "c.csv")
    np.testing.assert_allclose(np.degrees(q[0]), [0, 90, 0, 0, 0, 0], atol=1e-9)
    # the twin: sign and offset per joint, as docs/programs.md tabulates them
    sign, offset = np.array([1, 1, 1, 1, -1, -1]), np.radians([0, 90, 0, 0, -90, 0])
    np.testing.assert_allclose(q, sign * q_model + offset, atol=1e-12)
    doc = json.loads(json_text(t, q_model, convention=conv))
    assert doc["joints"] == "controller"
    np.testing.assert_allclose(doc["q_rad"], q, atol=0)


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
