"""Joint-space RRT-Connect for a carried part, and `Bodies` (many moving solids), against python-fcl.

The scene: an MZ07 carries a box along y under a small block that its arm, not the part,
sweeps through. The part's pose-space path is a straight line, free for the part; the
robot following it by IK hits the block; the joint-space planner goes around. Twins: the
robot's exact checker (`RobotCollisionChecker`, python-fcl), python-fcl and trimesh
containment on the raw part meshes, a crude independent motion bound (every point of the
robot and part lies within REACH of every joint axis), and brute-force pairs for `Bodies`.
"""

from __future__ import annotations

import re

import fcl
import numpy as np
import pytest
import trimesh

from workbench.assembly import InterferenceChecker, plan_part_path
from workbench.assembly.carry import carry_ik
from workbench.assembly.contacts import Bodies
from workbench.assembly.motion import path_samples
from workbench.assembly.planners.joint_rrt import (
    CarriedPath,
    CarrySpace,
    plan_carried_path,
)
from workbench.collision import RobotCollisionChecker, Solid
from workbench.errors import CollisionError, InputError, PlanningError, UnreachableError
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.kinematics import link_meshes
from workbench.kinematics.robot_library import preset_robot
from workbench.motion.joint_rrt import bisection_order, plan_joint_rrt_connect

ROBOT = preset_robot("mz07")
Q_HOME = np.array([0.0, 0.0, 0.0, 0.0, -np.pi / 2, 0.0])
TOOL = trimesh.creation.box(extents=[0.04, 0.06, 0.12])
TOOL.apply_translation([0.0, 0.0, 0.06])
T_FLANGE_TCP = xyz_rpy_to_transform([0.0, 0.0, 0.15], [0.0, 0.0, 0.0])
BLOCK = Solid("block", "box", size=(0.06, 0.06, 0.06))
T_BLOCK = xyz_rpy_to_transform([0.3, 0.0, 0.5], [0.0, 0.0, 0.0])
PART = trimesh.creation.box(extents=[0.08, 0.08, 0.04])
T_PART_TCP = xyz_rpy_to_transform([0.0, 0.0, 0.02], [np.pi, 0.0, 0.0])  # top face, z down
START = xyz_rpy_to_transform([0.45, -0.35, 0.1], [0.0, 0.0, 0.0])
GOAL = xyz_rpy_to_transform([0.45, 0.35, 0.1], [0.0, 0.0, 0.0])
#: Every point of the robot, tool and part lies within this distance [m] of every joint axis.
REACH = 1.6


@pytest.fixture(scope="module")
def scene():  # type: ignore[no-untyped-def]
    robot = RobotCollisionChecker(
        ROBOT, link_meshes(ROBOT), tool=TOOL, cell=[(BLOCK, T_BLOCK)], q_reference=Q_HOME
    )
    obstacles = [BLOCK.to_trimesh().apply_transform(T_BLOCK)]
    part = InterferenceChecker(PART, obstacles)
    space = CarrySpace(robot, part, T_FLANGE_TCP, T_PART_TCP, obstacle_names=["block"])
    return robot, obstacles, part, space


def _part_free_exact(poses: np.ndarray, obstacles: list[trimesh.Trimesh]) -> bool:
    """Twin: python-fcl mesh collision plus trimesh containment, both ways, at every pose."""
    m = fcl.BVHModel()
    m.beginModel(len(PART.vertices), len(PART.faces))
    m.addSubModel(np.asarray(PART.vertices, float), np.asarray(PART.faces, np.int32))
    m.endModel()
    moving = fcl.CollisionObject(m, fcl.Transform())
    obs = []
    for ob in obstacles:
        b = fcl.BVHModel()
        b.beginModel(len(ob.vertices), len(ob.faces))
        b.addSubModel(np.asarray(ob.vertices, float), np.asarray(ob.faces, np.int32))
        b.endModel()
        obs.append((ob, fcl.CollisionObject(b, fcl.Transform())))
    for T in poses:
        moving.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
        placed = PART.copy().apply_transform(T)
        for ob, o in obs:
            if fcl.collide(moving, o, fcl.CollisionRequest(), fcl.CollisionResult()):
                return False
            if ob.contains(placed.vertices[:1])[0] or placed.contains(ob.vertices[:1])[0]:
                return False
    return True


def _dense(q: np.ndarray, spacing: float) -> np.ndarray:
    """Twin sampling: linear joint motion, no point within REACH of the axes moves > spacing."""
    out = [q[:1]]
    for a, b in zip(q[:-1], q[1:], strict=True):
        n = max(1, int(np.ceil(np.abs(b - a).sum() * REACH / spacing)))
        out.append(a + (np.arange(1, n + 1) / n)[:, None] * (b - a))
    return np.concatenate(out)


def test_the_pose_space_path_exists_but_the_robot_cannot_follow_it(scene):
    robot, obstacles, part, _ = scene
    path = plan_part_path(START, GOAL, PART, obstacles, "rrt_connect", checker=part)
    S = path_samples(path.poses, part.radius, part.cell_size)
    assert _part_free_exact(S, obstacles)
    ik = carry_ik(ROBOT, np.eye(4), T_FLANGE_TCP, S @ T_PART_TCP, Q_HOME)
    rep = robot.check_path(ik.q)
    assert not rep.collision_free
    assert rep.first_report is not None and ("block" in rep.first_report.colliding_bodies())


@pytest.mark.slow  # over 5 s here
def test_the_joint_space_planner_solves_it_and_the_path_rechecks_free(scene):
    robot, obstacles, part, space = scene
    path = plan_carried_path(space, START, GOAL, Q_HOME, seed=0, max_time=60.0)
    assert isinstance(path, CarriedPath) and path.planner == "joint_rrt_connect"
    q = path.joints
    assert q is not None and q.shape[1] == 6 and len(q) == len(path.poses) >= 2
    # Ends: the robot's own FK holds the part at its start and goal.
    T = ROBOT.fk(q) @ T_FLANGE_TCP @ np.linalg.inv(T_PART_TCP)
    np.testing.assert_allclose(T, path.poses, atol=1e-12)
    np.testing.assert_allclose(T[0], START, atol=1e-9)
    np.testing.assert_allclose(T[-1], GOAL, atol=1e-9)
    lim = ROBOT.limits
    assert np.all(q >= lim[:, 0] - 1e-9) and np.all(q <= lim[:, 1] + 1e-9)
    # One arm configuration at both ends: the robot's own branch-wise IK agrees.
    qb, valid = ROBOT.ik_batch(T[[0, -1]] @ T_PART_TCP @ np.linalg.inv(T_FLANGE_TCP))
    assert path.branch >= 0 and valid[:, path.branch].all()
    # Re-checked densely by the exact checkers, at the twin's own (cruder) spacing.
    Q = _dense(q, part.cell_size)
    assert len(Q) > len(space.path_samples(q)) / 2
    rep = robot.check_path(Q)
    assert rep.collision_free, rep.first_report
    assert _part_free_exact(space.part_poses(Q), obstacles)


def test_edge_samples_keep_every_point_within_the_resolution(scene):
    _, _, part, space = scene
    rng = np.random.default_rng(3)
    lo, hi = ROBOT.limits[:, 0], ROBOT.limits[:, 1]
    pts_part = PART.vertices
    meshes = link_meshes(ROBOT)
    for _ in range(4):
        qa, qb = rng.uniform(lo, hi), rng.uniform(lo, hi)
        qb = qa + 0.04 * (qb - qa)
        S = np.concatenate([qa[None], space.edge_samples(qa, qb)])
        # Twin: the true point motion on a 20x finer grid between consecutive samples.
        fine = np.linspace(0, 1, 11)[:, None]
        for a, b in zip(S[:-1], S[1:], strict=True):
            qs = a + fine * (b - a)
            P = space.part_poses(qs)
            w = np.einsum("nij,vj->nvi", P[:, :3, :3], pts_part) + P[:, None, :3, 3]
            travel = np.linalg.norm(np.diff(w, axis=0), axis=2).sum(axis=0)
            assert travel.max() <= space.resolution * (1 + 1e-9)
            L = ROBOT.link_transforms(qs)
            for i, m in enumerate(meshes):
                v = np.einsum("nij,vj->nvi", L[:, i, :3, :3], m.vertices) + L[:, i, None, :3, 3]
                t = np.linalg.norm(np.diff(v, axis=0), axis=2).sum(axis=0)
                assert t.max() <= space.robot_resolution * (1 + 1e-9)


def _fcl_mesh(m: trimesh.Trimesh) -> fcl.CollisionObject:
    b = fcl.BVHModel()
    b.beginModel(len(m.vertices), len(m.faces))
    b.addSubModel(np.asarray(m.vertices, float), np.asarray(m.faces, np.int32))
    b.endModel()
    return fcl.CollisionObject(b, fcl.Transform())


def _part_hits_arm(q: np.ndarray, meshes: list[trimesh.Trimesh]) -> bool:
    """Twin: the held part against links 0..5 (those that move relative to it) by python-fcl."""
    L = ROBOT.link_transforms(q[None])[0]
    T_part = L[6] @ T_FLANGE_TCP @ np.linalg.inv(T_PART_TCP)
    part = _fcl_mesh(PART)
    part.setTransform(fcl.Transform(T_part[:3, :3], T_part[:3, 3]))
    for k in range(6):
        link = _fcl_mesh(meshes[k])
        link.setTransform(fcl.Transform(L[k][:3, :3], L[k][:3, 3]))
        if fcl.collide(part, link, fcl.CollisionRequest(), fcl.CollisionResult()):
            return True
    return False


def test_the_held_part_is_checked_against_its_own_arm(scene):
    robot, obstacles, part, space = scene
    meshes = link_meshes(ROBOT)
    # Wrist folded back: the part held at the tool swings towards the forearm and upper arm.
    rng = np.random.default_rng(5)
    lo, hi = ROBOT.limits[:, 0], ROBOT.limits[:, 1]
    qs = rng.uniform(lo, hi, size=(300, 6))
    qs[:, 4] = rng.uniform(lo[4], lo[4] + 0.6, size=300)
    only_arm = 0
    for q in qs:
        arm = _part_hits_arm(q, meshes)
        rest = (not robot.check_path(q[None]).collision_free) or not _part_free_exact(
            space.part_poses(q[None]), obstacles
        )
        assert space.any_invalid(q[None]) == (arm or rest), q
        if arm and not rest:
            only_arm += 1
            assert "carried part hits" in space.explain(q)
    assert only_arm > 0  # the case the planner used to accept


def test_bisection_order_is_a_permutation_coarse_first():
    for n in (1, 2, 3, 7, 16, 33):
        o = bisection_order(n)
        assert sorted(o.tolist()) == list(range(n)) and o[0] == n - 1
    assert bisection_order(8)[:3].tolist() == [7, 3, 1]


# -- bad input ----------------------------------------------------------------------------
def test_start_in_collision_is_named(scene):
    _, _, _, space = scene
    inside = xyz_rpy_to_transform([0.3, 0.0, 0.5], [0.0, 0.0, 0.0])  # the part in the block
    with pytest.raises(CollisionError, match=r"start: .*in contact.*part interferes with block"):
        plan_carried_path(space, inside, GOAL, Q_HOME)
    # The part is clear but the arm is not: the forearm through the block.
    under = xyz_rpy_to_transform([0.45, 0.0, 0.1], [0.0, 0.0, 0.0])
    with pytest.raises(CollisionError, match=r"goal: .*in contact.*hits block"):
        plan_carried_path(space, START, under, Q_HOME)


def test_goal_out_of_reach_is_named(scene):
    _, _, _, space = scene
    far = xyz_rpy_to_transform([1.8, 0.0, 0.3], [0.0, 0.0, 0.0])
    with pytest.raises(UnreachableError, match=r"goal: .*out of reach.*TCP at \[1800\.0, 0\.0"):
        plan_carried_path(space, START, far, Q_HOME)


def test_a_start_that_does_not_hold_the_part_is_named_in_controller_joints(scene):
    """The refusal shows the joints as the pendant does (the preset's convention), not the
    model's: twin, the convention's own `to_controller` of the same joints."""
    _, _, _, space = scene
    wrong = Q_HOME + np.array([0.3, 0.2, -0.1, 0.0, 0.4, 0.0])
    shown = np.round(np.degrees(ROBOT.convention.to_controller(wrong)), 2).tolist()
    assert shown != np.round(np.degrees(wrong), 2).tolist()  # the two conventions differ here
    with pytest.raises(InputError, match=re.escape(f"q_start (controller joints {shown} deg)")):
        plan_carried_path(space, START, GOAL, Q_HOME, q_start=wrong)


def test_a_configuration_in_collision_or_no_path_in_time_says_why(scene):
    _, _, _, space = scene
    under = xyz_rpy_to_transform([0.45, 0.0, 0.1], [0.0, 0.0, 0.0])  # the arm in the block
    bad = carry_ik(ROBOT, np.eye(4), T_FLANGE_TCP, (under @ T_PART_TCP)[None], Q_HOME).q[0]
    with pytest.raises(CollisionError, match=r"start configuration .* hits block"):
        plan_joint_rrt_connect(space, bad, Q_HOME)
    qs = carry_ik(ROBOT, np.eye(4), T_FLANGE_TCP, (START @ T_PART_TCP)[None], Q_HOME).q[0]
    qg = carry_ik(ROBOT, np.eye(4), T_FLANGE_TCP, (GOAL @ T_PART_TCP)[None], Q_HOME).q[0]
    with pytest.raises(PlanningError, match="no path within max_time"):
        plan_joint_rrt_connect(space, qs, qg, max_nodes=3)


# -- Bodies against brute force -------------------------------------------------------------
def test_bodies_contacts_match_brute_force_fcl_and_containment():
    rng = np.random.default_rng(7)
    meshes = [
        trimesh.creation.box(extents=[0.2, 0.1, 0.05]),
        trimesh.creation.icosphere(subdivisions=1, radius=0.06),
        trimesh.creation.cylinder(radius=0.03, height=0.15, sections=12),
        trimesh.creation.box(extents=[0.02, 0.02, 0.02]),  # small enough to hide inside others
    ]
    solids = [Solid(f"b{i}", "mesh", mesh=m) for i, m in enumerate(meshes)]
    pairs = [(f"b{i}", f"b{j}") for i in range(4) for j in range(i + 1, 4)]
    bodies = Bodies(solids, pairs)
    N = 300
    poses = np.empty((N, 4, 4, 4))
    for n in range(N):
        for b in range(4):
            poses[n, b] = xyz_rpy_to_transform(rng.uniform(-0.12, 0.12, 3), rng.uniform(-3, 3, 3))
    got = set(bodies.contacts(poses))
    expected = set()
    objs = []
    for m in meshes:
        bvh = fcl.BVHModel()
        bvh.beginModel(len(m.vertices), len(m.faces))
        bvh.addSubModel(np.asarray(m.vertices, float), np.asarray(m.faces, np.int32))
        bvh.endModel()
        objs.append(fcl.CollisionObject(bvh, fcl.Transform()))
    for n in range(N):
        for k, (a, b) in enumerate((i, j) for i in range(4) for j in range(i + 1, 4)):
            Ta, Tb = poses[n, a], poses[n, b]
            objs[a].setTransform(fcl.Transform(Ta[:3, :3], Ta[:3, 3]))
            objs[b].setTransform(fcl.Transform(Tb[:3, :3], Tb[:3, 3]))
            hit = fcl.collide(objs[a], objs[b], fcl.CollisionRequest(), fcl.CollisionResult()) > 0
            if not hit:
                pa = meshes[a].copy().apply_transform(Ta)
                pb = meshes[b].copy().apply_transform(Tb)
                hit = bool(pb.contains(pa.vertices[:1])[0] or pa.contains(pb.vertices[:1])[0])
            if hit:
                expected.add((n, k))
    assert got == expected
    assert len(expected) > 20 and len(expected) < N * len(pairs) / 2  # both verdicts occur
    # Containment alone (surfaces apart) is among them: the small box inside another body.
    inner = poses[:1].copy()
    inner[0, :] = np.eye(4)
    inner[0, 1, :3, 3] = [1.0, 0.0, 0.0]
    inner[0, 2, :3, 3] = [-1.0, 0.0, 0.0]
    assert bodies.contacts(inner) == [(0, pairs.index(("b0", "b3")))]
    # Only the active pairs are checked.
    assert bodies.contacts(inner, active=np.zeros((1, len(pairs)), bool)) == []
