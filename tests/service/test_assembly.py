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
from workbench.project.paths import ProjectFolders

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
    obstacles = [(m, _fcl(m)) for _, m in wb.assembly.cell.obstacles_for(name)]
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
        assert _exact_free(wb, task.part, P, a.cell.checker(task.part).cell_size)


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
    w2 = Workbench.from_dict(data, base_dir=ProjectFolders(PROJECT.parent, [tmp_path]))
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


# -- joint-space planning of carried parts ------------------------------------------------------
#: Every point of an arm, its tool and a held part lies within this distance [m] of every joint axis.
REACH = 1.6


def _ik(arm, T_world_tcp):  # type: ignore[no-untyped-def]
    s = arm.setup
    T = np.linalg.inv(s.T_world_base) @ T_world_tcp @ np.linalg.inv(s.T_flange_tcp)
    return s.model.ik(T, q_near=arm.q_home)[0]


def _dense(q: np.ndarray, spacing: float) -> np.ndarray:
    """Twin sampling: linear joint motion, no point within REACH of the axes moves > spacing."""
    out = [q[:1]]
    for a_, b_ in zip(q[:-1], q[1:], strict=True):
        n = max(1, int(np.ceil(np.abs(b_ - a_).sum() * REACH / spacing)))
        out.append(a_ + (np.arange(1, n + 1) / n)[:, None] * (b_ - a_))
    return np.concatenate(out)


def _robot_hits_parts(wb: Workbench, robot: str, q: np.ndarray, held: str) -> bool:
    """Twin: python-fcl of the robot's links and tool against every other part where it stands."""
    a = wb.assembly
    arm = a.arms[robot]
    fixed = {n for n, _ in a.cell.fixed}
    others = [_fcl(m) for n, m in a.cell.obstacles_for(held) if n not in fixed]
    meshes = [*arm.setup.link_meshes[1:], arm.setup.tool_mesh]
    links = [_fcl(m) for m in meshes]
    for qi in q:
        L = arm.setup.T_world_base @ arm.setup.model.link_transforms(qi)
        for k, obj in enumerate(links):
            T = L[min(k + 1, len(L) - 1)]
            obj.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
            for o in others:
                if fcl.collide(obj, o, fcl.CollisionRequest(), fcl.CollisionResult()):
                    return True
    return False


@pytest.mark.slow  # over 5 s here
@pytest.mark.parametrize("name", ["plate_b", "screw_2"])
def test_joint_space_plan_of_a_carried_part_rechecks_free_densely(wb, name):
    a = wb.assembly
    part = a.part(name)
    p = a.plan_part(name, "joint_rrt_connect")
    assert p.path.planner == "joint_rrt_connect" and p.robot == part.robot
    arm = a.arms[part.robot]
    K = p.path.joints
    assert K is not None and len(K) == len(p.key_points)
    # The robot's own FK holds the part at every key point, from its start to its goal.
    T = arm.setup.T_world_base @ arm.setup.model.fk(K) @ arm.setup.T_flange_tcp
    np.testing.assert_allclose(T @ np.linalg.inv(part.T_part_tcp), p.key_points, atol=1e-12)
    np.testing.assert_allclose(p.key_points[0], part.start, atol=1e-9)
    np.testing.assert_allclose(p.key_points[-1], part.goal, atol=1e-9)
    lim = arm.setup.model.limits
    assert np.all(K >= lim[:, 0] - 1e-9) and np.all(K <= lim[:, 1] + 1e-9)
    # Re-checked densely (the twin's own spacing) by the exact checkers: the robot against
    # the cell and itself, the robot against the other parts, the part against everything.
    Q = _dense(K, p.path.cell_size)
    assert arm.checker.check_path(Q).collision_free
    assert not _robot_hits_parts(wb, arm.name, Q, name)
    P = arm.setup.T_world_base @ arm.setup.model.fk(Q) @ arm.setup.T_flange_tcp
    assert _exact_free(wb, name, P @ np.linalg.inv(part.T_part_tcp), 1.0)


def test_a_sequence_planned_in_joint_space_is_continuous_and_checked(wb):
    a = wb.assembly
    p = a.plan_sequence(["screw_0"], "joint_rrt_connect")
    assert p.ok, p.summary()
    task = p.tasks[0]
    wp = task.trajectory.waypoints
    assert np.abs(np.diff(wp[1:-1], axis=0)).max() < 0.5  # approach, path, retreat: one branch
    arm = a.arms[task.robot]
    part = a.part("screw_0")
    for t, T_part in ((task.t_pick, part.start), (task.t_place, part.goal)):
        q, _, _ = task.trajectory.at([t - task.t0])
        T = arm.setup.T_world_base @ arm.setup.model.fk(q[0]) @ arm.setup.T_flange_tcp
        np.testing.assert_allclose(T, T_part @ part.T_part_tcp, atol=1e-6)
    np.testing.assert_allclose(wp[-1], arm.q_home)  # back home after the retreat


def test_robot_robot_contact_is_found_when_two_arms_reach_one_spot_and_not_when_apart(wb):
    a = wb.assembly
    spot = xyz_rpy_to_transform([0.0, 0.0, 0.80], [np.pi, 0.0, 0.0])
    times = np.array([0.0, 1.5])
    joints = {n: np.stack([arm.q_home, _ik(arm, spot)]) for n, arm in a.arms.items()}
    poses = {n: np.stack([a.part(n).start] * 2) for n in a.part_names}
    contacts = a.cross_contacts([], times, joints, poses)
    assert contacts and {c.index for c in contacts} == {1}
    assert all(c.time == 1.5 for c in contacts)
    # Twin: python-fcl on the same link and tool meshes, every pair of the two arms.
    bodies = {}
    for n, arm in a.arms.items():
        meshes = [*arm.setup.link_meshes, arm.setup.tool_mesh]
        L = arm.setup.T_world_base @ arm.setup.model.link_transforms(joints[n][1])
        names = [*arm.checker.link_names, "tool"]
        for k, (m, nm) in enumerate(zip(meshes, names, strict=True)):
            T = L[min(k, len(L) - 1)]
            o = _fcl(m)
            o.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
            bodies[f"{n}/{nm}"] = o
    expected = {
        (x, y)
        for x in bodies
        for y in bodies
        if x.startswith("MZ07/")
        and y.startswith("MZ07_B/")
        and fcl.collide(bodies[x], bodies[y], fcl.CollisionRequest(), fcl.CollisionResult())
    }
    assert {(c.body_a, c.body_b) for c in contacts} == expected
    plan = a.plan_sequence(["plate_a"])
    assert plan.contacts == ()  # the example's arms stay apart


def test_robot_part_contact_names_both_bodies_and_the_carried_tool_is_excused(wb):
    from types import SimpleNamespace

    a = wb.assembly
    plate = a.part("plate_b")
    arm = a.arms["MZ07"]  # not plate_b's robot
    # The gripper box ends 30 mm short of the TCP: 35 mm past the grasp puts it 5 mm deep.
    into = plate.goal @ plate.T_part_tcp @ xyz_rpy_to_transform([0, 0, 0.035], [0, 0, 0])
    times = np.array([0.0, 0.5, 1.0])
    joints = {n: np.stack([x.q_home] * 3) for n, x in a.arms.items()}
    joints["MZ07"][1] = _ik(arm, into)
    poses = {n: np.stack([a.part(n).goal] * 3) for n in a.part_names}
    contacts = a.cross_contacts([], times, joints, poses)
    assert ("MZ07/tool", "part plate_b") in {(c.body_a, c.body_b) for c in contacts}
    assert {c.index for c in contacts} == {1}
    c = next(c for c in contacts if c.body_a == "MZ07/tool")
    assert "MZ07/tool hits part plate_b at t = 0.500 s" in c.describe()
    # Twin: python-fcl on the tool mesh and the plate mesh.
    T = arm.setup.T_world_base @ arm.setup.model.fk(joints["MZ07"][1])
    tool, pl = _fcl(arm.setup.tool_mesh), _fcl(plate.mesh)
    tool.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
    pl.setTransform(fcl.Transform(plate.goal[:3, :3], plate.goal[:3, 3]))
    assert fcl.collide(tool, pl, fcl.CollisionRequest(), fcl.CollisionResult())
    # While MZ07 carries plate_b in a task, its tool on the plate is the grasp, not a crash.
    task = SimpleNamespace(robot="MZ07", part="plate_b", t0=0.25, t1=0.75)
    excused = a.cross_contacts([task], times, joints, poses)  # type: ignore[list-item]
    assert ("MZ07/tool", "part plate_b") not in {(c.body_a, c.body_b) for c in excused}


def test_joint_space_planning_refuses_bad_input_naming_the_field(wb):
    a = wb.assembly
    goal = a.part("plate_a").goal
    far = goal.copy()
    far[:3, 3] = [0.0, 0.0, 1.9]
    a.set_pose("plate_a", "goal", far)
    try:
        with pytest.raises(UnreachableError, match=r"assembly.parts\[0\].*goal.*out of reach"):
            a.plan_part("plate_a", "joint_rrt_connect")
    finally:
        a.set_pose("plate_a", "goal", goal)
    with pytest.raises(InputError, match="planner must be one of"):
        a.plan_part("plate_a", "prm")
    # An option of another planner is named, with the ones this planner takes.
    with pytest.raises(InputError, match=r"'joint_rrt_connect' has no option dis; .*max_time"):
        a.plan_part("plate_a", "joint_rrt_connect", dis=0.01)
    with pytest.raises(InputError, match=r"'ant' has no option max_time; .*step"):
        a.plan_part("plate_a", "ant", max_time=1.0)
    s1 = a.part("screw_1").goal.copy()
    bad = s1.copy()
    bad[2, 3] -= 0.008  # head pushed into plate B
    a.set_pose("screw_1", "goal", bad)
    try:
        with pytest.raises(CollisionError, match=r"assembly.parts\[3\].goal.*plate_b"):
            a.plan_part("screw_1", "joint_rrt_connect")
    finally:
        a.set_pose("screw_1", "goal", s1)
    data = _data()
    data["assembly"]["parts"][2]["robot"] = None
    w2 = Workbench.from_dict(data, base_dir=PROJECT.parent)
    with pytest.raises(InputError, match=r"assembly.parts\[2\].robot.*joint space"):
        w2.assembly.plan_part("screw_0", "joint_rrt_connect")
    data = _data()
    data["assembly"]["planner"]["name"] = "joint_rrt_connect"
    data["assembly"]["planner"]["robot_resolution"] = 0
    with pytest.raises(ProjectError, match=r"assembly.planner.robot_resolution"):
        Workbench.from_dict(data, base_dir=PROJECT.parent)


# -- robots through the conservative engine ---------------------------------------------------
def _active(plan, robot: str) -> np.ndarray:  # type: ignore[no-untyped-def]
    active = np.zeros(len(plan.times), dtype=bool)
    for task in plan.tasks:
        if task.robot == robot:
            active |= (plan.times >= task.t0) & (plan.times <= task.t1)
    return np.flatnonzero(active)


def _dense_hits(checker, q: np.ndarray, idx: np.ndarray) -> tuple[int, ...]:  # type: ignore[no-untyped-def]
    """Twin: python-fcl (plus containment) of every robot pair at every active sample."""
    return tuple(
        int(idx[i]) for i, qi in enumerate(q) if checker.check(qi, distance=False).in_collision
    )


def test_robots_are_checked_fast_and_equal_the_dense_exact_check(wb, plan):
    from workbench.collision.engine import EnginePathReport

    a = wb.assembly
    assert set(plan.robot_reports) == {t.robot for t in plan.tasks}
    for name, arm in a.arms.items():
        idx = _active(plan, name)
        rep = plan.robot_reports[name]
        assert isinstance(rep, EnginePathReport) and rep.mode == "spheres" and rep.fallback is None
        assert rep.samples == len(idx)
        dense = _dense_hits(arm.checker, plan.joints[name][idx], idx)
        assert plan.robot_collisions[name] == dense == rep.colliding_indices
        assert arm.checker.check_path(plan.joints[name][idx]).collision_free
        # Certified between samples too (the tasks' ends included), the clearance stated.
        assert rep.collision_free and rep.certified and plan.robot_between[name] == ()
        assert rep.evaluated > len(idx) and rep.clearance >= 0
        assert rep.message in plan.summary() and "including between samples" in rep.message
    # The bound between samples needs a C1 motion: every task starts and ends at rest.
    for task in plan.tasks:
        _, v, _ = task.trajectory.at([0.0, task.trajectory.duration])
        np.testing.assert_allclose(v, 0.0, atol=1e-9)


def _with_intruder(wb, plan, robot: str) -> Workbench:  # type: ignore[no-untyped-def]
    """The example with a 100 mm box on `robot`'s elbow at the middle of its first task."""
    arm = wb.assembly.arms[robot]
    task = next(t for t in plan.tasks if t.robot == robot)
    q = task.trajectory.at([(task.t_pick - task.t0) / 2])[0][0]
    p = (arm.setup.T_world_base @ arm.setup.model.link_transforms(q))[3, :3, 3] * 1e3
    d = _data()
    d["cell"]["objects"].append(
        {
            "name": "intruder",
            "shape": "box",
            "size": [100, 100, 100],
            "pose": {"xyz": [float(v) for v in p], "rpy": [0, 0, 0]},
            "collide": True,
        }
    )
    return Workbench.from_dict(d, base_dir=PROJECT.parent)


@pytest.mark.parametrize("robot", ["MZ07", "MZ07_B"])
def test_a_box_in_a_robot_path_is_found_at_the_same_sample_as_the_dense_check(wb, plan, robot):
    wb2 = _with_intruder(wb, plan, robot)
    arm = wb2.assembly.arms[robot]
    rep = wb2.assembly.check_robot(plan.tasks, plan.times, robot)
    assert rep is not None and rep.mode == "spheres" and not rep.collision_free
    idx = _active(plan, robot)
    q = plan.joints[robot][idx]
    dense = arm.checker.check_path(q)
    assert rep.colliding_indices == _dense_hits(arm.checker, q, idx) != ()
    assert rep.colliding_indices == tuple(int(idx[i]) for i in dense.colliding_indices)
    if rep.between:  # a collision between two earlier free samples, confirmed exactly
        assert rep.first_index < idx[dense.first_index] and rep.link is not None
        assert arm.checker.check(rep.first_q, distance=False).in_collision
    else:
        assert rep.first_index == idx[dense.first_index]
        assert rep.first_time == pytest.approx(plan.times[rep.first_index])
    assert rep.obstacle == "intruder" and rep.link in arm.checker.scene.moving
    assert "intruder" in rep.message
    # The other robot does not pass there.
    other = next(n for n in wb2.assembly.arms if n != robot)
    assert wb2.assembly.check_robot(plan.tasks, plan.times, other).colliding_indices == ()


def test_a_pose_outside_the_bounds_is_an_input_error_naming_the_part(wb):  # noqa: ANN001
    name = wb.assembly.part_names[0]
    far = np.eye(4)
    far[0, 3] = 1e6  # 1,000 km
    with pytest.raises(InputError, match=rf"'{name}': goal\.xyz\.0: .*out of range"):
        wb.assembly.set_pose(name, "goal", far)
