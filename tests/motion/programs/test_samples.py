"""Tests of workbench/motion/programs/samples.py: CSV/JSON joint samples that load back."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs import csv_text, json_text, load_csv, load_json, save_csv, save_json


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


def test_bad_sample_files(tmp_path):
    with pytest.raises(InputError, match="positions"):
        save_csv(tmp_path / "x.csv", [0.0, 1.0], np.zeros((3, 6)))
    (tmp_path / "bad.json").write_text("{}")
    with pytest.raises(InputError, match="format"):
        load_json(tmp_path / "bad.json")


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
