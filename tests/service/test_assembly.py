"""`Workbench.assembly` on the Fig. 11 example project: part plans, carrying robots, the sequence, export.

Twins: python-fcl on the raw meshes plus trimesh containment (interference), the robot's
own forward kinematics (IK along the path), finite differences of the sampled joints
(velocity limits), and the project's mm/deg poses re-read from the exports.
"""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import fcl
import numpy as np
import pytest
import trimesh

from workbench import Workbench
from workbench.assembly import plan_part_path
from workbench.assembly.motion import path_samples
from workbench.errors import (
    CollisionError,
    InputError,
    MeshError,
    ProjectError,
    UnreachableError,
)
from workbench.geometry.transforms import xyz_rpy_to_transform

ROOT = Path(__file__).resolve().parents[2]
PROJECT = ROOT / "projects" / "assembly_cell.json"


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.open(PROJECT)


@pytest.fixture(scope="module")
def plan(wb: Workbench):  # type: ignore[no-untyped-def]
    return wb.assembly.plan_sequence()


def _data() -> dict:
    return json.loads(PROJECT.read_text())


def _fcl(mesh: trimesh.Trimesh) -> fcl.CollisionObject:
    m = fcl.BVHModel()
    m.beginModel(len(mesh.vertices), len(mesh.faces))
    m.addSubModel(np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int32))
    m.endModel()
    return fcl.CollisionObject(m, fcl.Transform())


def _exact_free(wb: Workbench, name: str, poses: np.ndarray, step: float) -> bool:
    """Twin: python-fcl mesh collision and trimesh containment at every sample <= step apart."""
    part = wb.assembly.part(name)
    radius = float(np.max(np.linalg.norm(part.mesh.vertices, axis=1)))
    moving = _fcl(part.mesh)
    obstacles = [(m, _fcl(m)) for _, m in wb.assembly.obstacles_for(name)]
    for T in path_samples(poses, radius, step):
        moving.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
        placed = part.mesh.copy().apply_transform(T)
        for mesh, obj in obstacles:
            if fcl.collide(moving, obj, fcl.CollisionRequest(), fcl.CollisionResult()):
                return False
            if mesh.is_watertight and mesh.contains(placed.vertices[:1])[0]:
                return False
    return True


def test_the_example_project_holds_two_robots_a_table_two_plates_and_five_screws(wb):
    a = wb.assembly
    assert list(a.arms) == ["MZ07", "MZ07_B"]
    assert a.part_names == ["plate_a", "plate_b"] + [f"screw_{k}" for k in range(5)]
    assert [t.part for t in a.sequence()][:2] == ["plate_a", "plate_b"]
    for name, arm in a.arms.items():
        assert not arm.checker.check(arm.q_home).in_collision, name
    for name in a.part_names:
        part = a.part(name)
        assert part.mesh.is_watertight
        assert a.interference(name) == [] and a.interference(name, part.goal) == []


@pytest.mark.parametrize(("name", "planner"), [("plate_b", "ant"), ("screw_3", "rrt_connect")])
def test_part_plan_is_free_and_the_robot_follows_it_in_one_configuration(wb, name, planner):
    a = wb.assembly
    part = a.part(name)
    p = a.plan_part(name, planner)
    assert p.path.planner == planner and p.robot == part.robot
    np.testing.assert_allclose(p.key_points[0], part.start, atol=1e-12)
    np.testing.assert_allclose(p.key_points[-1], part.goal, atol=1e-12)
    assert _exact_free(wb, name, p.key_points, p.path.cell_size)
    # The robot's own FK puts the TCP on the grasp at every sample.
    arm = a.arms[part.robot]
    T_tcp = arm.setup.T_world_base @ arm.setup.model.fk(p.joints) @ arm.setup.T_flange_tcp
    np.testing.assert_allclose(T_tcp, p.samples @ part.T_part_tcp, atol=1e-7)
    lim = arm.setup.model.limits
    assert np.all(p.joints >= lim[:, 0] - 1e-9) and np.all(p.joints <= lim[:, 1] + 1e-9)
    assert np.abs(np.diff(p.joints, axis=0)).max() < 0.5  # no configuration flip


def test_sequence_places_plates_then_screws_and_the_timed_motion_is_checked(wb, plan):
    a = wb.assembly
    assert [t.part for t in plan.tasks] == a.part_names
    assert plan.ok, plan.summary()
    for k in range(1, len(plan.tasks)):
        assert plan.tasks[k].t0 == pytest.approx(plan.tasks[k - 1].t1)
    for task in plan.tasks:
        part = a.part(task.part)
        arm = a.arms[task.robot]
        # Held from pick to place: the part pose is the robot's FK times the inverse grasp.
        for t in np.linspace(task.t_pick, task.t_place, 5):
            q, _, _ = task.trajectory.at([t - task.t0])
            T = arm.setup.T_world_base @ arm.setup.model.fk(q[0]) @ arm.setup.T_flange_tcp
            expected = T @ np.linalg.inv(part.T_part_tcp)
            i = int(np.argmin(np.abs(plan.times - t)))
            if abs(plan.times[i] - t) < 1e-9:
                np.testing.assert_allclose(plan.part_poses[task.part][i], expected, atol=1e-7)
        q_pick, _, _ = task.trajectory.at([task.t_pick - task.t0])
        T = arm.setup.T_world_base @ arm.setup.model.fk(q_pick[0]) @ arm.setup.T_flange_tcp
        np.testing.assert_allclose(T, part.start @ part.T_part_tcp, atol=1e-6)
        np.testing.assert_allclose(plan.part_poses[task.part][-1], part.goal, atol=1e-12)
        np.testing.assert_allclose(plan.part_poses[task.part][0], part.start, atol=1e-12)
    # Velocity limits: finite differences of the sampled joints (the twin of ruckig's profile).
    for name, arm in a.arms.items():
        q = plan.joints[name]
        v = np.abs(np.diff(q, axis=0)) / np.diff(plan.times)[:, None]
        assert np.all(v <= arm.setup.model.max_velocity * 1.001)
    # Carried parts stay clear of everything along the executed (timed) motion (a plate and
    # two screws, to keep the test fast; the service checks every part).
    for task in plan.tasks[::3]:
        held = (plan.times >= task.t_pick) & (plan.times <= task.t_place)
        P = plan.part_poses[task.part][held]
        assert _exact_free(wb, task.part, P, a.checker(task.part).cell_size)


def test_a_one_part_plan_shows_earlier_parts_assembled_and_later_ones_waiting(wb):
    a = wb.assembly
    p = a.plan_sequence(["screw_0"])
    assert [t.part for t in p.tasks] == ["screw_0"] and p.ok
    for n in ("plate_a", "plate_b"):
        np.testing.assert_allclose(
            p.part_poses[n], np.broadcast_to(a.part(n).goal, (len(p.times), 4, 4))
        )
    np.testing.assert_allclose(p.part_poses["screw_1"][-1], a.part("screw_1").start)
    np.testing.assert_allclose(p.part_poses["screw_0"][-1], a.part("screw_0").goal)


def test_key_points_export_to_csv_and_json_in_mm_and_degrees(wb):
    a = wb.assembly
    p = a.plan_part("plate_a", "rrt_connect")
    rows = list(csv.DictReader(io.StringIO(a.export_key_points("csv"))))
    data = json.loads(a.export_key_points("json"))
    assert data["part"] == "plate_a" and len(data["key_points"]) == len(rows) == len(p.key_points)
    for row, kp, T in zip(rows, data["key_points"], p.key_points, strict=True):
        xyz = [float(row[k]) for k in "xyz"]
        rpy = [float(row[k]) for k in ("roll", "pitch", "yaw")]
        np.testing.assert_allclose(
            xyz_rpy_to_transform(np.array(xyz) / 1000, np.radians(rpy)), T, atol=1e-6
        )
        assert kp["x"] == pytest.approx(T[0, 3] * 1000)
        assert {"j1", "j6"} <= set(row)
    with pytest.raises(InputError, match="fmt"):
        a.export_key_points("xml")


def test_each_robot_exports_its_part_of_the_sequence_as_a_program(wb, plan):
    a = wb.assembly
    for robot in a.arms:
        tasks = [t for t in plan.tasks if t.robot == robot]
        text = a.export_program(robot, "rapid", plan)
        assert text.count("MoveAbsJ") == sum(len(t.trajectory.waypoints) - 1 for t in tasks)
        first = np.degrees(tasks[0].trajectory.waypoints[1])
        decl = text.split("CONST jointtarget ")[1].split(":=[[")[1].split("]")[0]
        np.testing.assert_allclose([float(v) for v in decl.split(",")], first, atol=1e-3)
        rows = a.export_program(robot, "csv", plan).strip().splitlines()
        assert len(rows) == len(plan.times) + 1
    with pytest.raises(InputError, match="format"):
        a.export_program("MZ07", "gcode", plan)


# -- bad input, through the service API and through the project file --------------------------
def test_goal_in_collision_is_named(wb):
    a = wb.assembly
    goal = a.part("screw_1").goal.copy()
    bad = goal.copy()
    bad[2, 3] -= 0.008  # head pushed into plate B
    a.set_pose("screw_1", "goal", bad)
    try:
        with pytest.raises(CollisionError, match=r"assembly.parts\[3\].goal.*plate_b"):
            a.plan_part("screw_1")
    finally:
        a.set_pose("screw_1", "goal", goal)
    data = _data()
    data["assembly"]["parts"][3]["start"]["xyz"] = [100.0, -200.0, 705.0]  # into the table top
    w2 = Workbench.from_dict(data, base_dir=PROJECT.parent)
    with pytest.raises(CollisionError, match=r"assembly.parts\[3\].start.*table"):
        w2.assembly.plan_part("screw_1")


def test_goal_out_of_reach_of_the_robot_is_named(wb):
    a = wb.assembly
    goal = a.part("plate_a").goal
    far = goal.copy()
    far[:3, 3] = [0.0, 0.0, 1.9]
    a.set_pose("plate_a", "goal", far)
    try:
        with pytest.raises(UnreachableError, match=r"assembly.parts\[0\].*out of reach"):
            a.plan_part("plate_a", "rrt_connect")
    finally:
        a.set_pose("plate_a", "goal", goal)
    data = _data()
    data["assembly"]["parts"][0]["goal"]["xyz"] = [0, 0, 1900]
    w2 = Workbench.from_dict(data, base_dir=PROJECT.parent)
    with pytest.raises(UnreachableError, match=r"assembly.parts\[0\]"):
        w2.assembly.plan_part("plate_a", "rrt_connect")


def test_cell_size_zero_or_larger_than_the_part_is_refused(wb):
    a = wb.assembly
    with pytest.raises(InputError, match="cell_size"):
        a.plan_part("screw_0", cell_size=0.0)
    with pytest.raises(InputError, match="larger than the part"):
        a.plan_part("screw_0", cell_size=0.05)
    data = _data()
    data["assembly"]["planner"]["cell_size"] = 0
    with pytest.raises(ProjectError, match=r"assembly.planner.cell_size"):
        Workbench.from_dict(data, base_dir=PROJECT.parent)
    data["assembly"]["planner"]["cell_size"] = 30  # screws are 23 mm long
    w2 = Workbench.from_dict(data, base_dir=PROJECT.parent)
    with pytest.raises(InputError, match=r"assembly.planner.cell_size.*larger than the part"):
        w2.assembly.plan_part("screw_0")


def test_a_part_mesh_that_is_not_closed_is_refused(tmp_path):
    box = trimesh.creation.box(extents=[50.0, 40.0, 10.0])
    open_box = trimesh.Trimesh(box.vertices, box.faces[:-2], process=False)
    open_box.export(tmp_path / "open.stl")
    data = _data()
    data["assembly"]["parts"][0]["path"] = str(tmp_path / "open.stl")
    w2 = Workbench.from_dict(data, base_dir=PROJECT.parent)
    with pytest.raises(MeshError, match=r"assembly.parts\[0\].path.*not closed"):
        _ = w2.assembly.parts
    obstacle = trimesh.creation.box(extents=[0.1, 0.1, 0.1])
    with pytest.raises(MeshError, match="not closed"):
        plan_part_path(np.eye(4), np.eye(4), open_box, [obstacle])


def test_unknown_part_robot_or_sequence_entry_names_the_field():
    data = _data()
    data["assembly"]["parts"][2]["robot"] = "KR6"
    w2 = Workbench.from_dict(data, base_dir=PROJECT.parent)
    with pytest.raises(ProjectError, match=r"assembly.parts\[2\].robot.*KR6"):
        _ = w2.assembly.parts
    data = _data()
    data["assembly"]["sequence"][0]["part"] = "plate_x"
    with pytest.raises(ProjectError, match="plate_x"):
        Workbench.from_dict(data, base_dir=PROJECT.parent)
