"""Narrow passages (issue 14 part 6): a box through a window in a wall.

Twin: python-fcl's own BVH meshes of the box and the wall pieces (built here, not through
the InterferenceChecker), collided every RES / 4 along the planned path's straight motions.
The planners check every RES = 1 mm, which bounds a graze between their samples to RES
(the orientation is fixed here), so the twin's box is RES smaller on every side.
The box (5 cm) cannot hide inside a 2 cm wall piece, so surface contact is the whole test.
"""

from __future__ import annotations

import fcl
import numpy as np
import pytest
import trimesh

from workbench.assembly import InterferenceChecker, plan_part_path
from workbench.assembly.motion import path_samples
from workbench.errors import PlanningError
from workbench.geometry.transforms import make_transform

EDGE = 0.05
RES = 0.001
BOUNDS = np.array([[-0.4, -0.3, -0.3], [0.4, 0.3, 0.3]])  # the wall spans them: no way round


def _slab(lo, hi) -> trimesh.Trimesh:
    size = [0.02, hi[0] - lo[0], hi[1] - lo[1]]
    return trimesh.creation.box(size).apply_translation(
        [0.0, (hi[0] + lo[0]) / 2, (hi[1] + lo[1]) / 2]
    )


def window_scene(side: float, yc: float = 0.03, zc: float = -0.02):
    """Return (box, wall pieces, start, goal): a square window of `side` [m] in a wall at x = 0
    that fills BOUNDS; start and goal 0.3 m either side, off the window (the line is blocked)."""
    w, L = side / 2, 0.3
    wall = [
        _slab((-L, -L), (yc - w, L)),
        _slab((yc + w, -L), (L, L)),
        _slab((yc - w, -L), (yc + w, zc - w)),
        _slab((yc - w, zc + w), (yc + w, L)),
    ]
    start = make_transform(np.eye(3), [-0.3, yc + 0.15, zc + 0.1])
    goal = make_transform(np.eye(3), [0.3, yc + 0.2, zc + 0.12])
    return trimesh.creation.box([EDGE] * 3), wall, start, goal


def _fcl_free(part, wall, poses, radius) -> bool:
    def bvh(m):
        b = fcl.BVHModel()
        b.beginModel(len(m.vertices), len(m.faces))
        b.addSubModel(np.asarray(m.vertices, float), np.asarray(m.faces, np.int32))
        b.endModel()
        return b

    box = fcl.CollisionObject(bvh(trimesh.creation.box([EDGE - 2 * RES] * 3)), fcl.Transform())
    walls = [fcl.CollisionObject(bvh(m), fcl.Transform()) for m in wall]
    for T in path_samples(poses, radius, RES / 4):
        box.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
        for ob in walls:
            if fcl.collide(box, ob, fcl.CollisionRequest(), fcl.CollisionResult()):
                return False
    return True


def _check(r, part, wall, s, g, ch):
    np.testing.assert_allclose(r.poses[0], s, atol=1e-12)
    np.testing.assert_allclose(r.poses[-1], g, atol=1e-12)
    x = r.poses[:, 0, 3]
    assert x.min() < -0.01 and x.max() > 0.01  # it did cross the wall
    assert _fcl_free(part, wall, r.poses, ch.radius)


def test_ant_takes_a_box_through_a_window_one_and_a_half_times_its_size():
    part, wall, s, g = window_scene(1.5 * EDGE)
    ch = InterferenceChecker(part, wall, 0.005)
    r = plan_part_path(s, g, part, wall, "ant", checker=ch, bounds=BOUNDS, resolution=RES)
    _check(r, part, wall, s, g, ch)


def test_ant_refines_a_plane_whose_grid_misses_a_tight_window():
    # 1.08 x the box: 4 mm of play against a 6.9 mm grid: a plane in the wall needs a finer one
    part, wall, s, g = window_scene(1.08 * EDGE)
    ch = InterferenceChecker(part, wall, 0.005)
    r = plan_part_path(s, g, part, wall, "ant", checker=ch, bounds=BOUNDS, resolution=RES)
    assert r.stats["refined_planes"] >= 1 and r.stats["refine_levels"] >= 1
    _check(r, part, wall, s, g, ch)


def test_rrt_connect_takes_a_box_through_a_window():
    # RRT-Connect samples orientations at random: at 1.5 x the edge it finds no path in 20 s
    # (benchmarks/README.md); 1.5 x the box's diagonal leaves room to turn.
    part, wall, s, g = window_scene(1.5 * np.sqrt(3) * EDGE)
    ch = InterferenceChecker(part, wall, 0.005)
    r = plan_part_path(
        s,
        g,
        part,
        wall,
        "rrt_connect",
        checker=ch,
        bounds=BOUNDS,
        resolution=RES,
        seed=0,
        max_time=30.0,
    )
    _check(r, part, wall, s, g, ch)


def test_a_window_smaller_than_the_box_is_refused_naming_plane_and_finest_step():
    part, wall, s, g = window_scene(0.9 * EDGE)
    ch = InterferenceChecker(part, wall, 0.005)
    with pytest.raises(PlanningError) as err:
        plan_part_path(
            s, g, part, wall, "ant", checker=ch, bounds=BOUNDS, resolution=RES, min_dis=0.0035
        )
    msg = str(err.value)
    assert "cutting plane 9 of 19" in msg and "x = -0.0300 m" in msg
    assert "refined down to dis = 0.00344507 m (min_dis = 0.0035 m)" not in msg
    assert "min_dis = 0.0035 m" in msg
