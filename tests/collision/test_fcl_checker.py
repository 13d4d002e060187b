"""The python-fcl baseline against closed forms: sphere–box distance, containment, pair names."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from workbench.collision import CollisionScene, Solid
from workbench.errors import InputError, MeshError
from workbench.geometry.transforms import make_transform, rpy_to_matrix


def sphere_box_distance(c: np.ndarray, r: float, half: np.ndarray, T_box: np.ndarray) -> float:
    """Closed form: distance from a sphere to a solid box (negative when overlapping)."""
    local = T_box[:3, :3].T @ (c - T_box[:3, 3])
    outside = np.maximum(np.abs(local) - half, 0.0)
    if np.any(outside > 0):
        return float(np.linalg.norm(outside) - r)
    return float(-np.min(half - np.abs(local)) - r)


def test_sphere_mesh_against_solid_box_matches_closed_form() -> None:
    rng = np.random.default_rng(0)
    r = 0.1
    ball = trimesh.creation.icosphere(subdivisions=4, radius=r)
    # The tessellated sphere lies between the inscribed and the true sphere.
    r_in = r * np.cos(np.max(ball.edges_unique_length) / r)
    size = np.array([0.4, 0.3, 0.2])
    # The box moves (random poses), the ball stays: one scene, many checks.
    scene = CollisionScene(
        [Solid("box", "box", size=tuple(size))], [(Solid("ball", "mesh", mesh=ball), np.eye(4))]
    )
    seen = {"free": 0, "hit": 0}
    for _ in range(400):
        T_box = make_transform(
            rpy_to_matrix(rng.uniform(-np.pi, np.pi, 3)), rng.uniform(-0.35, 0.35, 3)
        )
        rep = scene.check({"box": T_box})
        c = np.zeros(3)
        d_true = sphere_box_distance(c, r, size / 2, T_box)
        d_inner = sphere_box_distance(c, r_in, size / 2, T_box)
        if d_true > 1e-9:  # the true sphere is clear, so the polytope inside it is too
            assert not rep.in_collision
            assert d_true - 1e-6 <= rep.min_distance <= d_inner + 1e-6
            seen["free"] += 1
        elif d_inner < -1e-9:  # even the inscribed sphere overlaps
            assert rep.in_collision and rep.colliding == (("box", "ball"),)
            assert rep.min_distance == 0.0
            seen["hit"] += 1
    assert min(seen.values()) > 50, seen


def test_body_inside_closed_mesh_counts_as_collision() -> None:
    # fcl alone calls this free: meshes are surfaces. The containment test catches it.
    shell = trimesh.creation.box(extents=(1.0, 1.0, 1.0))
    small = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    scene = CollisionScene(
        [Solid("small", "mesh", mesh=small)], [(Solid("shell", "mesh", mesh=shell), np.eye(4))]
    )
    assert scene.check({"small": np.eye(4)}).colliding == (("small", "shell"),)
    far = make_transform(np.eye(3), [2.0, 0, 0])
    rep = scene.check({"small": far})
    assert not rep.in_collision
    assert rep.min_distance == pytest.approx(2.0 - 0.5 - 0.05, abs=1e-9)
    # And the other way round: the moving shell swallowing a static small box.
    scene2 = CollisionScene(
        [Solid("shell", "mesh", mesh=shell)], [(Solid("small", "mesh", mesh=small), np.eye(4))]
    )
    assert scene2.check({"shell": np.eye(4)}).in_collision


def test_self_pairs_and_errors() -> None:
    a, b = trimesh.creation.box(extents=(1, 1, 1)), trimesh.creation.box(extents=(1, 1, 1))
    scene = CollisionScene(
        [Solid("a", "mesh", mesh=a), Solid("b", "mesh", mesh=b)], [], self_pairs=[("a", "b")]
    )
    assert scene.check({"a": np.eye(4), "b": make_transform(np.eye(3), [0.9, 0, 0])}).colliding == (
        ("a", "b"),
    )
    rep = scene.check({"a": np.eye(4), "b": make_transform(np.eye(3), [1.25, 0, 0])})
    assert rep.min_distance == pytest.approx(0.25, abs=1e-9) and rep.closest_pair == ("a", "b")
    with pytest.raises(InputError, match="unknown moving body"):
        CollisionScene([Solid("a", "mesh", mesh=a)], [], self_pairs=[("a", "zz")])
    with pytest.raises(InputError, match="unique"):
        CollisionScene(
            [Solid("a", "mesh", mesh=a)], [(Solid("a", "box", size=(1, 1, 1)), np.eye(4))]
        )
    with pytest.raises(MeshError, match="no triangles"):
        Solid("empty", "mesh", mesh=trimesh.Trimesh())
    with pytest.raises(InputError, match="positive"):
        Solid("flat", "box", size=(1.0, 0.0, 1.0))
