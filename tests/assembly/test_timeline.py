"""The multi-robot timeline and what is exported from it: sampling, arm motion, held parts, programs.

Twins: each task's own trajectory evaluated at the sample times, the robot's forward
kinematics for a held part, and the exported key points read back in mm and degrees.
"""

from __future__ import annotations

import csv
import io
import json
from types import SimpleNamespace

import numpy as np
import pytest
import trimesh

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.part import AssemblyPart
from workbench.assembly.part_moves import PartPlan
from workbench.assembly.plan import PartPath
from workbench.assembly.programs import key_points_text
from workbench.assembly.tasks import TaskPlan, tcp_line, time_waypoints
from workbench.assembly.timeline import arm_motion, colliding_samples, part_poses, sample_times
from workbench.errors import InputError
from workbench.geometry.transforms import matrix_to_rpy, xyz_rpy_to_transform
from workbench.kinematics.robot_library import preset_robot

ROBOT = preset_robot("mz07")
BASE = xyz_rpy_to_transform([0.1, 0.0, 0.2], [0.0, 0.0, 0.3])
TOOL = xyz_rpy_to_transform([0.0, 0.0, 0.15], [0.0, 0.0, 0.0])
HOME = np.array([0.0, 0.3, 0.0, 0.0, -1.2, 0.0])


def _arm() -> AssemblyArm:
    setup = SimpleNamespace(
        model=ROBOT, link_meshes=[], T_world_base=BASE, T_flange_tcp=TOOL, tool_mesh=None
    )
    return AssemblyArm("A", setup, None, HOME, (0, 0, 0), main=True)  # type: ignore[arg-type]


def _task(t0: float, q_far: np.ndarray, plan: PartPlan | None = None) -> TaskPlan:
    wp = np.stack([HOME, HOME + 0.5 * (q_far - HOME), q_far, HOME])
    traj = time_waypoints(_arm(), wp, 0.5, [0, 1, 2, 3])
    wt = traj.waypoint_times
    return TaskPlan("p", "A", t0, t0 + float(wt[1]), t0 + float(wt[2]), traj, plan)  # type: ignore[arg-type]


def test_sample_times_cover_the_total_every_dt_and_end_on_it():
    t = sample_times(1.0, 0.3)
    np.testing.assert_allclose(t, [0.0, 0.3, 0.6, 0.9, 1.0])
    np.testing.assert_allclose(sample_times(1.2, 0.3), [0.0, 0.3, 0.6, 0.9, 1.2], atol=1e-12)


def test_arm_motion_is_each_task_from_its_start_and_at_rest_at_home_between():
    a = _task(0.5, HOME + np.array([0.4, -0.2, 0.1, 0.0, 0.3, 0.5]))
    b = _task(a.t1 + 0.4, HOME + np.array([-0.3, 0.1, 0.2, 0.4, 0.0, -0.5]))
    times = sample_times(b.t1 + 0.2, 0.01)
    q, v, acc = arm_motion([a, b], HOME, times)
    for task in (a, b):
        sel = (times >= task.t0) & (times <= task.t1)
        p_, v_, a_ = task.trajectory.at(times[sel] - task.t0)  # twin: the task's own trajectory
        np.testing.assert_allclose(q[sel], p_, atol=1e-12)
        np.testing.assert_allclose(v[sel], v_, atol=1e-12)
    rest = (times < a.t0) | ((times > a.t1) & (times < b.t0)) | (times > b.t1)
    np.testing.assert_allclose(q[rest], np.tile(HOME, (int(rest.sum()), 1)), atol=1e-9)
    assert np.all(v[rest] == 0.0) and np.all(acc[rest] == 0.0)


def test_a_held_part_follows_the_tcp_and_stands_at_its_goal_after():
    arm = _arm()
    task = _task(0.0, HOME + np.array([0.4, -0.2, 0.1, 0.0, 0.3, 0.5]))
    times = sample_times(task.t1, 0.02)
    q = arm_motion([task], HOME, times)[0]
    grasp = xyz_rpy_to_transform([0.0, 0.0, 0.01], [np.pi, 0.0, 0.0])
    start = arm.tcp_poses(HOME) @ np.linalg.inv(grasp)
    goal = xyz_rpy_to_transform([0.3, 0.3, 0.7], [0.0, 0.0, 0.0])
    part = AssemblyPart("p", trimesh.creation.box(), start, goal, grasp, "A", (0, 0, 0))
    P, held = part_poses(part, [task], {"A": arm}, {"A": q}, times, ["p"])
    assert held is not None and len(held) > 0
    # Twin: the robot's FK times the inverse grasp at every held sample.
    T = BASE @ ROBOT.fk(q[held]) @ TOOL @ np.linalg.inv(grasp)
    np.testing.assert_allclose(P[held], T, atol=1e-12)
    after, before = times > task.t_place, times < task.t_pick
    np.testing.assert_allclose(P[after], np.broadcast_to(goal, (int(after.sum()), 4, 4)))
    np.testing.assert_allclose(P[before], np.broadcast_to(start, (int(before.sum()), 4, 4)))


def test_colliding_samples_join_every_index_set_and_the_contacts():
    c = [SimpleNamespace(index=4)]
    out = colliding_samples(6, [(0,), ()], [(2, 3)], contacts=c)  # type: ignore[arg-type]
    assert out.tolist() == [True, False, True, True, True, False]


def test_key_points_export_in_mm_and_degrees_with_the_joints_at_each_key_point():
    keys = np.stack(
        [xyz_rpy_to_transform([0.1 * k, 0.2, 0.7], [0.1, -0.2, 0.3 * k]) for k in range(3)]
    )
    samples = np.concatenate([tcp_line(keys[0], keys[1]), tcp_line(keys[1], keys[2])[1:]])
    joints = np.arange(len(samples) * 6, dtype=float).reshape(-1, 6) * 1e-3
    path = PartPath(keys, "ant", 0.0, 0.0, 0, 0, 0, 0.2, 0.002, 0.002)
    plan = PartPlan("p", "A", path, samples, joints, 0)
    rows = list(csv.DictReader(io.StringIO(key_points_text(plan, "csv"))))
    data = json.loads(key_points_text(plan, "json"))
    assert data["units"]["position"] == "mm" and len(data["key_points"]) == len(rows) == 3
    for k, (row, T) in enumerate(zip(data["key_points"], keys, strict=True)):
        np.testing.assert_allclose([row["x"], row["y"], row["z"]], T[:3, 3] * 1000, atol=1e-9)
        rpy = np.degrees(matrix_to_rpy(T[:3, :3]))
        np.testing.assert_allclose([row["roll"], row["pitch"], row["yaw"]], rpy, atol=1e-9)
        i = int(np.argmin(np.linalg.norm(samples[:, :3, 3] - T[:3, 3], axis=1)))
        np.testing.assert_allclose(row["j1"], np.degrees(joints[i, 0]), atol=1e-9)
        assert float(rows[k]["x"]) == pytest.approx(row["x"], abs=1e-4)
    with pytest.raises(InputError, match="fmt must be one of"):
        key_points_text(plan, "xml")
