"""The `assembly` section in SI (`AssemblySpec.to_si()`): every length in m, angle in rad, speed a fraction.

Twins: the section's own mm/deg numbers read back by hand, and the rotation built from
Rz(yaw)·Ry(pitch)·Rx(roll) with numpy.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from workbench.kinematics.presets import MZ07_CONVENTION
from workbench.project.assembly import AssemblySpec

PROJECT = Path(__file__).resolve().parents[2] / "projects" / "assembly_cell.json"


def _spec(**changes: object) -> AssemblySpec:
    data = json.loads(PROJECT.read_text())["assembly"]
    data.update(changes)
    return AssemblySpec.model_validate(data)


def _rot(roll: float, pitch: float, yaw: float) -> np.ndarray:
    r, p, w = np.radians([roll, pitch, yaw])
    Rx = np.array([[1, 0, 0], [0, np.cos(r), -np.sin(r)], [0, np.sin(r), np.cos(r)]])
    Ry = np.array([[np.cos(p), 0, np.sin(p)], [0, 1, 0], [-np.sin(p), 0, np.cos(p)]])
    Rz = np.array([[np.cos(w), -np.sin(w), 0], [np.sin(w), np.cos(w), 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


def test_the_example_section_in_si_matches_its_mm_and_degrees():
    spec = _spec()
    si = spec.to_si()
    assert [p.name for p in si.parts] == [p.name for p in spec.parts]
    for p, q in zip(spec.parts, si.parts, strict=True):
        for pose, T in ((p.start, q.start), (p.goal, q.goal), (p.grasp, q.grasp)):
            np.testing.assert_allclose(T[:3, 3], np.array(pose.xyz) / 1000.0, atol=1e-15)
            np.testing.assert_allclose(T[:3, :3], _rot(*pose.rpy), atol=1e-12)
        assert q.robot == p.robot and q.color == tuple(p.color)
    for r, q in zip(spec.robots, si.robots, strict=True):
        np.testing.assert_allclose(q.robot.T_world_base[:3, 3], np.array(r.base.xyz) / 1000.0)
        np.testing.assert_allclose(q.robot.T_world_base[:3, :3], _rot(*r.base.rpy), atol=1e-12)
        np.testing.assert_allclose(q.tool.T_flange_tcp[:3, 3], np.array(r.tcp.xyz) / 1000.0)
        np.testing.assert_allclose(q.tool.size, np.array(r.tool_size) / 1000.0)
        if r.joints is not None:
            # the file holds the controller's values (NACHI's), the SI spec the model's
            q_model = MZ07_CONVENTION.to_model(np.radians(r.joints))
            np.testing.assert_allclose(q.robot.joints, q_model, atol=1e-15)
        assert q.robot.preset == r.preset and q.name == q.robot.name == r.name
    assert si.speed == pytest.approx(spec.speed / 100.0)
    assert si.planner.cell_size == pytest.approx(spec.planner.cell_size / 1000.0)
    assert [t.part for t in si.sequence] == [t.part for t in spec.tasks()]
    for t, u in zip(spec.tasks(), si.sequence, strict=True):
        assert (u.approach, u.retreat) == pytest.approx((t.approach / 1000, t.retreat / 1000))


def test_the_default_sequence_is_every_part_in_order_and_a_subset_keeps_sequence_order():
    spec = _spec(sequence=None)
    si = spec.to_si()
    assert [t.part for t in si.sequence] == [p.name for p in spec.parts]
    assert all(t.approach == pytest.approx(0.05) for t in si.sequence)
    seq = [{"part": "screw_1", "approach": 30}, {"part": "plate_a"}]
    spec = _spec(sequence=seq)
    assert [t.part for t in spec.tasks(["plate_a", "screw_1", "plate_b"])] == [
        "screw_1",
        "plate_a",
        "plate_b",  # not in the sequence: after it, with the default distances
    ]
    assert spec.tasks(["screw_1"])[0].to_si().approach == pytest.approx(0.03)


def test_planner_options_are_si_and_per_planner():
    spec = _spec(planner={"name": "ant", "dis": 4, "robot_resolution": 5, "step": 7, "seed": 3})
    p = spec.to_si().planner
    assert p.options("ant") == {"step": 7, "dis": pytest.approx(0.004)}
    assert p.options("rrt_connect") == {"seed": 3, "max_time": 10.0}
    assert p.options("joint_rrt_connect") == {
        "seed": 3,
        "max_time": 10.0,
        "robot_resolution": pytest.approx(0.005),
    }


def test_a_pose_set_in_metres_is_stored_in_mm_and_degrees_and_reads_back():
    spec = _spec()
    T = np.eye(4)
    T[:3, :3] = _rot(10.0, -20.0, 30.0)
    T[:3, 3] = [0.1, -0.2, 0.75]
    spec.parts[2].set_pose("goal", T)
    assert spec.parts[2].goal.xyz == pytest.approx([100.0, -200.0, 750.0])
    assert spec.parts[2].goal.rpy == pytest.approx([10.0, -20.0, 30.0])
    np.testing.assert_allclose(spec.to_si().parts[2].goal, T, atol=1e-12)
