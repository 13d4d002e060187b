from __future__ import annotations

import numpy as np
import pytest
import trimesh

from workbench.assembly import InterferenceChecker, plan_part_path
from workbench.assembly.example_scene import example_scene
from workbench.assembly.motion import path_samples
from workbench.errors import CollisionError, InputError, MeshError

SCENE = example_scene()
CHECKERS: dict[int, InterferenceChecker] = {}


def _checker(i):
    if i not in CHECKERS:
        p = SCENE.parts[i]
        CHECKERS[i] = InterferenceChecker(p.mesh, SCENE.obstacles_for(i))
    return CHECKERS[i]


def _exact_free(i, poses, step) -> bool:
    """Twin: every sample (<= step apart) checked by python-fcl + trimesh containment only."""
    import fcl

    p = SCENE.parts[i]
    ch = _checker(i)
    S = path_samples(poses, ch.radius, step)
    for T in S:
        for k in np.nonzero(ch.aabb_stage(T)[0])[0]:
            ob = ch.obstacles[k]
            ch.moving.fcl_obj.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
            if fcl.collide(
                ch.moving.fcl_obj, ob.fcl_obj, fcl.CollisionRequest(), fcl.CollisionResult()
            ):
                return False
            placed = p.mesh.vertices[:1] @ T[:3, :3].T + T[:3, 3]
            if ob.mesh.contains(placed)[0]:
                return False
    return True


@pytest.mark.parametrize("planner", ["ant", "rrt_connect"])
@pytest.mark.parametrize("i", range(len(SCENE.parts)))
def test_planners_solve_every_part_of_the_example_scene(planner, i):
    p = SCENE.parts[i]
    r = plan_part_path(
        p.start, p.goal, p.mesh, SCENE.obstacles_for(i), planner, checker=_checker(i)
    )
    assert r.poses.shape[1:] == (4, 4) and len(r.poses) >= 2
    np.testing.assert_allclose(r.poses[0], p.start, atol=1e-12)
    np.testing.assert_allclose(r.poses[-1], p.goal, atol=1e-12)
    straight = np.linalg.norm(p.goal[:3, 3] - p.start[:3, 3])
    assert straight - 1e-9 <= r.length < 2.5 * straight
    assert r.checks > 0 and r.nodes >= 1 and r.time_s > 0
    assert _exact_free(i, r.poses, r.cell_size)


def test_start_or_goal_in_collision_is_named():
    p = SCENE.parts[2]
    bad = p.goal.copy()
    bad[2, 3] -= 0.01  # head pushed into plate B
    with pytest.raises(CollisionError, match="goal pose interferes with obstacles"):
        plan_part_path(p.start, bad, p.mesh, SCENE.obstacles_for(2), checker=_checker(2))
    with pytest.raises(CollisionError, match="start pose"):
        plan_part_path(
            bad, p.goal, p.mesh, SCENE.obstacles_for(2), "rrt_connect", checker=_checker(2)
        )


def test_bad_inputs_are_refused():
    p = SCENE.parts[2]
    obs = SCENE.obstacles_for(2)
    with pytest.raises(InputError, match="planner"):
        plan_part_path(p.start, p.goal, p.mesh, obs, "astar")
    with pytest.raises(InputError, match="start"):
        plan_part_path(np.eye(3), p.goal, p.mesh, obs)
    with pytest.raises(InputError, match="cell_size"):
        plan_part_path(p.start, p.goal, p.mesh, obs, cell_size=0.0)
    with pytest.raises(InputError, match="larger than the part"):
        plan_part_path(p.start, p.goal, p.mesh, obs, cell_size=1.0)
    open_mesh = trimesh.creation.box([0.01, 0.01, 0.01])
    open_mesh.update_faces(np.arange(len(open_mesh.faces)) != 0)
    with pytest.raises(MeshError):
        plan_part_path(p.start, p.goal, open_mesh, obs)
    with pytest.raises(InputError, match="step"):
        plan_part_path(p.start, p.goal, p.mesh, obs, checker=_checker(2), step=0)


def test_ant_failure_names_the_plane():
    from workbench.errors import PlanningError

    wall = trimesh.creation.box([0.02, 2.0, 2.0])  # a wall across the whole path
    part = trimesh.creation.box([0.05, 0.05, 0.05])
    s, g = np.eye(4), np.eye(4)
    s[0, 3], g[0, 3] = -0.5, 0.5
    with pytest.raises(PlanningError, match="cutting plane"):
        plan_part_path(s, g, part, [wall], "ant", step=2, dis=0.05, half_width=0.1)


def _block_scene():
    from workbench.geometry.transforms import make_transform, rpy_to_matrix

    part = trimesh.creation.box([0.05, 0.05, 0.05])
    block = trimesh.creation.box([0.2, 0.3, 0.3])
    floor = trimesh.creation.box([1.2, 1.2, 0.02]).apply_translation([0, 0, -0.2])
    s = make_transform(np.eye(3), [-0.5, 0.0, 0.0])
    g = make_transform(rpy_to_matrix([0.0, 0.0, np.pi / 2]), [0.5, 0.02, 0.0])
    return part, [block, floor], s, g


def _twin_free(part, obstacles, poses, radius, step) -> bool:
    """Twin: every sample (<= step apart) against every obstacle by fcl + trimesh containment."""
    import fcl

    def bvh(m):
        b = fcl.BVHModel()
        b.beginModel(len(m.vertices), len(m.faces))
        b.addSubModel(np.asarray(m.vertices), np.asarray(m.faces, np.int32))
        b.endModel()
        return fcl.CollisionObject(b, fcl.Transform())

    a, obs = bvh(part), [bvh(o) for o in obstacles]
    for T in path_samples(poses, radius, step):
        a.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
        placed = part.vertices[:1] @ T[:3, :3].T + T[:3, 3]
        for o, m in zip(obs, obstacles, strict=True):
            if fcl.collide(a, o, fcl.CollisionRequest(), fcl.CollisionResult()):
                return False
            if m.contains(placed)[0]:
                return False
    return True


def test_ant_goes_around_a_block_on_the_cutting_planes():
    part, obs, s, g = _block_scene()
    r = plan_part_path(s, g, part, obs, "ant", cell_size=0.005)
    assert len(r.poses) == 21 and r.nodes > 19  # the straight line was blocked
    assert np.max(np.abs(r.poses[1:-1, 1:3, 3])) > 0.1  # went round the block
    ch = InterferenceChecker(part, obs, 0.005)
    assert _twin_free(part, obs, r.poses, ch.radius, 0.005)


def test_ant_candidate_search_matches_one_candidate_at_a_time():
    from workbench.assembly.motion import motion_samples
    from workbench.assembly.planners.ant import _first_free

    part, obs, s, g = _block_scene()
    ch = InterferenceChecker(part, obs, 0.01)
    rng = np.random.default_rng(2)
    prev = s.copy()
    prev[:3, 3] = [-0.45, 0.0, 0.0]
    R = g[:3, :3]
    wants = []
    for trial in range(8):
        goal = g if trial % 2 else None
        # Without the goal: candidates in the block's slab; with it: in front of the block.
        x, w = (-0.25, 0.7) if goal is not None else (-0.05, 0.3 if trial < 6 else 0.1)
        c = np.c_[np.full(30, x), rng.uniform(-w, w, (30, 2))]

        def free(k, goal=goal, c=c):
            T = np.eye(4)
            T[:3, :3], T[:3, 3] = R, c[k]
            moves = [motion_samples(prev, T, ch.radius, 0.01)]
            if goal is not None:
                moves.append(motion_samples(T, goal, ch.radius, 0.01))
            return not any(ch.interferes(x) for m in moves for x in m)

        want = next((k for k in range(len(c)) if free(k)), -1)
        k, tried = _first_free(ch, prev, R, c, goal, 0.01)
        assert k == want and tried == (k + 1 if k >= 0 else len(c))
        wants.append(want)
    assert -1 in wants and len(set(wants)) > 3  # varied answers: a real search
