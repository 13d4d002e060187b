"""Exact leaf confirmation of non-box obstacles: closed forms (sphere, cylinder) and brute force."""

from __future__ import annotations

import fcl
import numpy as np
import trimesh
from scipy.spatial.transform import Rotation
from seed_part import seed_spec

from workbench.geometry import OBB, obb_overlap
from workbench.geometry.transforms import make_transform
from workbench.pressbrake.obstacles import (
    ExactShape,
    Obstacles,
    box_hits_shape,
    confirm_exact,
    winding_number,
)
from workbench.sheetmetal import SheetMetalPart


def box_sphere_distance(box: OBB, center: np.ndarray) -> float:
    """Closed form: distance from a point to a solid box (0 inside)."""
    local = box.rotation.T @ (center - box.center)
    return float(np.linalg.norm(np.maximum(np.abs(local) - box.half_extents, 0.0)))


def test_winding_number_inside_outside() -> None:
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=0.1)
    w = winding_number(sphere, np.array([[0, 0, 0], [0.05, 0.02, 0], [0.2, 0, 0], [0, 0, -0.5]]))
    np.testing.assert_allclose(w, [1, 1, 0, 0], atol=1e-9)


def test_mesh_sphere_against_closed_form_including_containment() -> None:
    rng = np.random.default_rng(1)
    r = 0.1
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=r)  # faces within 0.3 % of r
    bvh = fcl.BVHModel()
    bvh.beginModel(len(sphere.vertices), len(sphere.faces))
    bvh.addSubModel(np.asarray(sphere.vertices, float), np.asarray(sphere.faces, np.int32))
    bvh.endModel()
    shape = ExactShape(bvh, np.eye(4), sphere)
    checked = inside = 0
    for i in range(700):
        # The last 100 are small boxes near the centre (wholly inside the sphere) and big
        # boxes around it (the sphere wholly inside): cases with no surface contact.
        small, big = 600 <= i < 650, i >= 650
        h = (
            rng.uniform(0.003, 0.03, 3)
            if small
            else rng.uniform(0.11, 0.2, 3)
            if big
            else rng.uniform(0.003, 0.15, 3)
        )
        c = rng.uniform(-0.02, 0.02, 3) if small or big else rng.uniform(-0.25, 0.25, 3)
        box = OBB(c, Rotation.random(random_state=rng).as_matrix(), h)
        d = box_sphere_distance(box, np.zeros(3))
        far = np.linalg.norm(box.corners(), axis=1).max()
        if abs(d - r) < 0.01 * r or abs(far - r) < 0.01 * r and d == 0:
            continue  # within the tessellation error of the icosphere
        checked += 1
        inside += far < r
        assert box_hits_shape(box, shape) == (d < r), (d, far)
    assert checked > 500 and inside > 20


def test_cylinder_against_closed_form() -> None:
    rng = np.random.default_rng(2)
    radius, height = 0.05, 0.2
    shape = ExactShape(fcl.Cylinder(radius, height), np.eye(4))
    for _ in range(300):
        # Axis-aligned boxes: distance to a z-cylinder has a closed form.
        c = rng.uniform(-0.2, 0.2, 3)
        h = rng.uniform(0.005, 0.08, 3)
        box = OBB(c, np.eye(3), h)
        near_xy = np.clip(0.0, c[:2] - h[:2], c[:2] + h[:2])  # closest box x-y point to the axis
        radial = np.linalg.norm(near_xy)
        dz = max(abs(c[2]) - h[2] - height / 2, 0.0)
        if abs(radial - radius) < 1e-4 or abs(abs(c[2]) - h[2] - height / 2) < 1e-4:
            continue
        assert box_hits_shape(box, shape) == (radial < radius and dz == 0.0), (c, h)


def test_tree_with_exact_leaves_equals_brute_force() -> None:
    rng = np.random.default_rng(3)
    state = SheetMetalPart.from_spec(seed_spec()).fold(6)
    tree = state.obb_tree("1")
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=0.04)
    sphere.apply_translation([0.05, 0.0, 0.02])
    bvh = fcl.BVHModel()
    bvh.beginModel(len(sphere.vertices), len(sphere.faces))
    bvh.addSubModel(np.asarray(sphere.vertices, float), np.asarray(sphere.faces, np.int32))
    bvh.endModel()
    cyl_T = make_transform(np.eye(3), [-0.1, 0.05, 0.0])
    s_box = OBB.from_points(sphere.vertices)
    obstacles = Obstacles(
        ("box", "sphere", "cylinder"),
        OBB(
            np.array([[0.1, -0.1, 0.05], s_box.center, cyl_T[:3, 3]]),
            np.array([np.eye(3), s_box.rotation, np.eye(3)]),
            np.array([[0.03, 0.02, 0.05], s_box.half_extents, [0.03, 0.03, 0.06]]),
        ),
        (None, ExactShape(bvh, np.eye(4), sphere), ExactShape(fcl.Cylinder(0.03, 0.12), cyl_T)),
    )
    T = make_transform(
        Rotation.random(600, random_state=rng).as_matrix(), rng.uniform(-0.3, 0.3, (600, 3))
    )
    rep = confirm_exact(tree, tree.collide_frames(obstacles.boxes, T), obstacles, T)
    leaves = tree.boxes[tree.leaves]
    brute = np.zeros(len(T), bool)
    for f in range(len(T)):
        world = leaves.transformed(T[f])
        hit = bool(obb_overlap(world, obstacles.boxes[0:1].reshape(1)).any())
        for k in range(len(tree.leaves)):
            for o in (1, 2):
                hit |= box_hits_shape(world[k], obstacles.exact[o])  # type: ignore[arg-type]
        brute[f] = hit
    assert 0.05 < brute.mean() < 0.95
    np.testing.assert_array_equal(rep.collides, brute)
