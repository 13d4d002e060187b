"""Sections convert themselves to SI: robot, tool, cell and program `to_si()` against hand math."""

from __future__ import annotations

import math

import numpy as np

from workbench.geometry.transforms import rpy_to_matrix
from workbench.project import CellObject, Pose, Robot, Tool
from workbench.project.models import ProgramSpec
from workbench.project.units import DEG, MM, matrix_to_pose, pose_to_matrix, to_deg, to_mm


def test_pose_round_trip_and_convention() -> None:
    pose = Pose(xyz=[100.0, -20.0, 300.0], rpy=[10.0, -30.0, 45.0])
    T = pose.to_si()
    # Twin: R = Rz(yaw) Ry(pitch) Rx(roll), built from elementary rotations by hand.
    r, p, y = (math.radians(v) for v in pose.rpy)
    Rx = np.array([[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]])
    Ry = np.array([[math.cos(p), 0, math.sin(p)], [0, 1, 0], [-math.sin(p), 0, math.cos(p)]])
    Rz = np.array([[math.cos(y), -math.sin(y), 0], [math.sin(y), math.cos(y), 0], [0, 0, 1]])
    np.testing.assert_allclose(T[:3, :3], Rz @ Ry @ Rx, atol=1e-15)
    np.testing.assert_allclose(T[:3, 3], [0.1, -0.02, 0.3])
    np.testing.assert_array_equal(pose_to_matrix(pose), T)
    back = matrix_to_pose(T)
    np.testing.assert_allclose(back.xyz, pose.xyz, atol=1e-9)
    np.testing.assert_allclose(back.rpy, pose.rpy, atol=1e-9)
    assert float(to_deg(math.pi)) == 180.0 and float(to_mm(0.25)) == 250.0


def test_robot_and_tool_sections_in_si() -> None:
    rows = [
        {"d": 400.0, "a": 25.0, "alpha": -90.0, "min": -170.0, "max": 170.0},
        {"theta_offset": -90.0, "d": 0.0, "a": 315.0, "alpha": 0.0, "min": -90, "max": 135},
    ]
    robot = Robot(dh=rows, joints=[10.0, 20.0], max_velocity=[180.0, 90.0])
    si = robot.to_si()
    assert si.dh is not None and si.limits is not None
    np.testing.assert_allclose(si.dh, [[0, 0.4, 0.025, -np.pi / 2], [-np.pi / 2, 0, 0.315, 0]])
    np.testing.assert_allclose(si.limits[1], np.radians([-90, 135]))
    assert si.joints is not None and si.max_velocity is not None
    np.testing.assert_allclose(si.joints, np.radians([10, 20]))
    np.testing.assert_allclose(si.max_velocity, [np.pi, np.pi / 2])
    assert si.max_jerk is None and si.link_mesh_scale == MM
    robot.store_joints(np.radians([1.0, 2.0]))
    assert robot.joints is not None
    np.testing.assert_allclose(robot.joints, [1.0, 2.0])
    tool = Tool(tcp=Pose(xyz=[0, 0, 150.0]), size=[40.0, 40.0, 150.0]).to_si()
    np.testing.assert_allclose(tool.T_flange_tcp[:3, 3], [0, 0, 0.15])
    assert tool.size is not None
    np.testing.assert_allclose(tool.size, [0.04, 0.04, 0.15])


def test_cell_objects_and_program_in_si() -> None:
    box = CellObject(name="b", shape="box", size=[100.0, 200.0, 50.0], pose=Pose(rpy=[0, 0, 90]))
    si = box.to_si()
    assert si.size == (0.1, 0.2, 0.05) and si.radius is None
    np.testing.assert_allclose(si.T_world_body[:3, :3], rpy_to_matrix([0, 0, np.pi / 2]))
    cyl = CellObject(name="c", shape="cylinder", radius=30.0, height=120.0).to_si()
    assert cyl.radius == 30.0 * MM and cyl.height == 120.0 * MM
    prog = ProgramSpec(
        start=[0, 10, 20, 0, -60, 0],
        moves=[
            {"type": "joint", "joints": [0, 0, 0, 0, -90, 0], "speed": 50, "zone": 5},
            {"type": "linear", "pose": {"xyz": [400, 0, 300], "rpy": [180, 0, 0]}, "speed": 250},
        ],
    ).to_si()
    assert prog.start is not None
    np.testing.assert_allclose(prog.start, np.array([0, 10, 20, 0, -60, 0]) * DEG)
    j, lin = prog.moves
    assert j.speed == 0.5 and j.zone == 0.005 and j.T_world_tcp is None
    assert lin.speed == 0.25 and lin.joints is None and lin.T_world_tcp is not None
    np.testing.assert_allclose(lin.T_world_tcp[:3, 3], [0.4, 0.0, 0.3])
