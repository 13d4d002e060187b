"""Spheres mode, links against the cell: zero false negatives against python-fcl + containment.

(These are the twin tests of the former `ConservativeChecker`, which folded into `SpheresMode`:
`cell_clearance` is its check, `early_exit` included.)"""

from __future__ import annotations

from pathlib import Path

import fcl
import numpy as np
import pytest
import trimesh

from workbench.collision import RobotCollisionChecker, Solid
from workbench.collision.engine import CollisionEngine
from workbench.collision.spheres_mode import SpheresMode
from workbench.errors import InputError
from workbench.geometry.transforms import matrix_to_wxyz
from workbench.kinematics import DHRobot
from workbench.kinematics.link_shapes import link_meshes
from workbench.kinematics.robot_library import preset_robot

BOXES = [
    ((0.45, 0.0, 0.25), (0.25, 0.5, 0.3)),
    ((0.0, -0.55, 0.6), (0.6, 0.1, 0.5)),
]  # centre, size
SPHERE = ((0.15, 0.45, 0.55), 0.12)


def _cell() -> trimesh.Trimesh:
    parts = []
    for centre, size in BOXES:
        b = trimesh.creation.box(size)
        b.apply_translation(centre)
        parts.append(b)
    s = trimesh.creation.icosphere(subdivisions=3, radius=SPHERE[1])
    s.apply_translation(SPHERE[0])
    parts.append(s)
    return trimesh.util.concatenate(parts)


def _exact(robot: DHRobot, meshes: list[trimesh.Trimesh], q: np.ndarray) -> np.ndarray:
    """python-fcl mesh-vs-primitive collide, plus a link vertex inside an obstacle."""
    obstacles = [
        fcl.CollisionObject(fcl.Box(*size), fcl.Transform(np.asarray(c, float)))
        for c, size in BOXES
    ]
    obstacles.append(
        fcl.CollisionObject(fcl.Sphere(SPHERE[1]), fcl.Transform(np.asarray(SPHERE[0], float)))
    )
    links = []
    for m in meshes[1:]:
        bvh = fcl.BVHModel()
        bvh.beginModel(len(m.vertices), len(m.faces))
        bvh.addSubModel(np.asarray(m.vertices), np.asarray(m.faces))
        bvh.endModel()
        links.append(fcl.CollisionObject(bvh, fcl.Transform()))
    T = robot.link_transforms(q)
    # Exact prefilter: a link whose bounding ball misses every obstacle cannot touch one.
    ball_c = np.stack([m.bounding_sphere.primitive.center for m in meshes[1:]])
    ball_r = np.array([m.bounding_sphere.primitive.radius for m in meshes[1:]])
    bc = np.einsum("nlij,lj->nli", T[:, 1:, :3, :3], ball_c) + T[:, 1:, :3, 3]
    gap = np.linalg.norm(bc - SPHERE[0], axis=2) - SPHERE[1]
    for c, size in BOXES:
        out = np.maximum(np.abs(bc - c) - np.asarray(size) / 2, 0.0)
        gap = np.minimum(gap, np.linalg.norm(out, axis=2))
    near = gap <= ball_r * (1 + 1e-9)
    hit = np.zeros(len(q), dtype=bool)
    req = fcl.CollisionRequest()
    for n, li in zip(*np.nonzero(near), strict=True):
        if hit[n]:
            continue
        obj, i = links[li], li + 1
        obj.setTransform(fcl.Transform(matrix_to_wxyz(T[n, i, :3, :3]), T[n, i, :3, 3]))
        hit[n] = any(fcl.collide(obj, o, req, fcl.CollisionResult()) for o in obstacles)
    # Containment (fcl meshes are surfaces): one vertex of each link inside an obstacle.
    v0 = np.stack([m.vertices[0] for m in meshes[1:]])
    p = np.einsum("nlij,lj->nli", T[:, 1:, :3, :3], v0) + T[:, 1:, :3, 3]
    inside = np.linalg.norm(p - SPHERE[0], axis=2) <= SPHERE[1]
    for c, size in BOXES:
        inside |= np.all(np.abs(p - c) <= np.asarray(size) / 2, axis=2)
    return hit | inside.any(axis=1)


def _exact_distance(robot: DHRobot, meshes: list[trimesh.Trimesh], q: np.ndarray) -> np.ndarray:
    """python-fcl distance [m] of the links (1..n) to the nearest obstacle, per configuration."""
    obstacles = [
        fcl.CollisionObject(fcl.Box(*size), fcl.Transform(np.asarray(c, float)))
        for c, size in BOXES
    ]
    obstacles.append(
        fcl.CollisionObject(fcl.Sphere(SPHERE[1]), fcl.Transform(np.asarray(SPHERE[0], float)))
    )
    links = []
    for m in meshes[1:]:
        bvh = fcl.BVHModel()
        bvh.beginModel(len(m.vertices), len(m.faces))
        bvh.addSubModel(np.asarray(m.vertices), np.asarray(m.faces))
        bvh.endModel()
        links.append(fcl.CollisionObject(bvh, fcl.Transform()))
    T = robot.link_transforms(q)
    out = np.full(len(q), np.inf)
    req = fcl.DistanceRequest(enable_nearest_points=False)
    for n in range(len(q)):
        for i, obj in enumerate(links, start=1):
            obj.setTransform(fcl.Transform(matrix_to_wxyz(T[n, i, :3, :3]), T[n, i, :3, 3]))
            for o in obstacles:
                out[n] = min(out[n], fcl.distance(obj, o, req, fcl.DistanceResult()))
    return out


def _checker(robot: DHRobot, meshes: list[trimesh.Trimesh]) -> RobotCollisionChecker:
    cell = [
        (Solid(f"box{k}", "box", size=size), _translation(c)) for k, (c, size) in enumerate(BOXES)
    ]
    ball = trimesh.creation.icosphere(subdivisions=3, radius=SPHERE[1])
    cell.append((Solid("ball", "mesh", mesh=ball), _translation(SPHERE[0])))
    return RobotCollisionChecker(robot, meshes, cell=cell)


def _translation(c: tuple[float, float, float]) -> np.ndarray:
    T = np.eye(4)
    T[:3, 3] = c
    return T


@pytest.fixture(scope="module")
def setup(engine_cache: Path) -> tuple[DHRobot, list[trimesh.Trimesh], SpheresMode]:
    robot = preset_robot("mz07")
    meshes = link_meshes(robot)
    eng = CollisionEngine(
        _checker(robot, meshes),
        "spheres",
        spheres_per_link=6,
        resolution=24,
        cache_dir=str(engine_cache),
    )
    assert isinstance(eng.checker, SpheresMode)
    return robot, meshes, eng.checker


def test_zero_false_negatives_on_10000_configurations(setup) -> None:
    robot, meshes, spheres = setup
    rng = np.random.default_rng(0)
    lim = np.asarray(robot.limits)
    q = rng.uniform(lim[:, 0], lim[:, 1], (10_000, 6))
    q[:, 1:3] = rng.uniform(-0.9, 0.9, (10_000, 2))  # keep the arm over the obstacles
    clearance, _ = spheres.cell_clearance(q)
    flagged = clearance <= 0.0
    exact = _exact(robot, meshes, q)
    assert exact.sum() > 1000  # many configurations do touch the cell
    assert not np.any(exact & ~flagged), f"missed {np.sum(exact & ~flagged)}"
    fp = np.sum(flagged & ~exact) / max(np.sum(~exact), 1)
    assert fp < 0.5  # conservative, not useless (figure printed with -s)
    print(f"\n10000 configurations: {exact.sum()} collide, false-positive rate {fp:.1%}")
    # Early exit (one bounding sphere per link first): never misses either. Its clearance is
    # not a bound of the full check's (the field is not 1-Lipschitz), but both are lower
    # bounds of python-fcl's distance: checked on the free configurations nearest to the
    # cell by either report (where a wrong bound would show first).
    fast, _ = spheres.cell_clearance(q, early_exit=True)
    assert not np.any(exact & ~(fast <= 0.0))
    free = np.flatnonzero(~exact)
    near = np.unique(
        np.r_[
            free[np.argsort(clearance[free])[:150]],
            free[np.argsort(fast[free])[:150]],
        ]
    )
    dist = _exact_distance(robot, meshes, q[near])
    assert np.all(clearance[near] <= dist + 1e-6)
    assert np.all(fast[near] <= dist + 1e-6)
    print(f"near: {len(near)}, distance max {dist.max():.4f}, median {np.median(dist):.4f} m")
    assert np.median(dist) < 0.02  # near the cell: the bounds are tested where they matter


def test_spheres_contain_every_link_vertex(setup) -> None:
    robot, meshes, spheres = setup
    q = np.random.default_rng(1).uniform(-1, 1, (20, 6))
    c = spheres.sphere_centres(q)
    T = robot.link_transforms(q)
    for i in spheres.bodies.checked:
        v = np.einsum("nij,vj->nvi", T[:, i, :3, :3], meshes[i].vertices) + T[:, i, None, :3, 3]
        own = spheres.sphere_body == i
        d = np.linalg.norm(v[:, :, None] - c[:, None, own], axis=3)
        assert np.all(np.any(d <= spheres.radii[own] + 1e-12, axis=2))


def test_bad_input(setup) -> None:
    robot, meshes, spheres = setup
    with pytest.raises(InputError, match="q: expected finite joints of shape"):
        spheres.cell_clearance(np.zeros((3, 5)))
    checker = _checker(robot, meshes)
    with pytest.raises(InputError, match="margin"):
        CollisionEngine(checker, "spheres", margin=-1.0)
    with pytest.raises(InputError, match="spheres_per_link"):
        CollisionEngine(checker, "spheres", spheres_per_link=0)


def test_an_empty_cell_clears_every_configuration(setup, engine_cache) -> None:
    """No obstacles: clearance inf and a body index per configuration, one q or a batch."""
    robot, meshes, _ = setup
    eng = CollisionEngine(
        RobotCollisionChecker(robot, meshes),
        "spheres",
        spheres_per_link=6,
        resolution=24,
        cache_dir=str(engine_cache),
    )
    assert isinstance(eng.checker, SpheresMode) and eng.sdf is None
    for q, n in ((np.zeros(6), 1), (np.zeros((3, 6)), 3)):
        clearance, body = eng.checker.cell_clearance(q)
        assert clearance.shape == body.shape == (n,) and np.all(np.isinf(clearance))
