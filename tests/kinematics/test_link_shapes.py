"""Generated link shapes: watertight, cover the arm's segments, adjacent links touch, i/i+2 apart."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from mesh_overlap import fcl_overlap

from workbench.kinematics import DHRobot
from workbench.kinematics.link_shapes import flange_mesh, link_meshes
from workbench.kinematics.robot_library import preset_robot


@pytest.fixture(scope="module")
def robot() -> DHRobot:
    return preset_robot("mz07")


@pytest.fixture(scope="module")
def meshes(robot: DHRobot) -> list[trimesh.Trimesh]:
    return link_meshes(robot)


def placed(meshes: list[trimesh.Trimesh], frames: np.ndarray) -> list[trimesh.Trimesh]:
    return [m.copy().apply_transform(F) for m, F in zip(meshes, frames, strict=False)]


def test_meshes_are_watertight_and_non_empty(robot: DHRobot, meshes: list[trimesh.Trimesh]) -> None:
    assert len(meshes) == robot.dof + 1
    for m in meshes:
        assert m.is_watertight and m.is_volume
        assert len(m.faces) > 0 and m.volume > 1e-6
    f = flange_mesh(robot)
    assert f.is_watertight and f.volume > 0
    np.testing.assert_allclose(f.bounds[:, 2], [-0.01 * 1.149, 0.0], atol=2e-3)


def test_union_covers_the_segments_between_joint_origins(
    robot: DHRobot, meshes: list[trimesh.Trimesh]
) -> None:
    rng = np.random.default_rng(0)
    qs = np.vstack([np.zeros(6), rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (4, 6))])
    # The base origin and the flange centre lie on the surface; stay just inside them.
    s = np.linspace(0.005, 0.995, 21)[:, None]
    for q in qs:
        frames = robot.link_transforms(q)
        world = placed(meshes, frames)
        o = frames[:, :3, 3]
        pts = np.vstack([o[i] + s * (o[i + 1] - o[i]) for i in range(robot.dof)])
        inside = np.zeros(len(pts), dtype=bool)
        for m in world:
            inside |= m.contains(pts)
        assert inside.all(), pts[~inside]


def test_adjacent_links_touch_and_links_two_apart_do_not_at_home(
    robot: DHRobot, meshes: list[trimesh.Trimesh]
) -> None:
    world = placed(meshes, robot.link_transforms(np.zeros(6)))
    for i in range(robot.dof):
        assert fcl_overlap(world[i], world[i + 1]), (i, i + 1)
    for i in range(robot.dof - 1):
        assert not fcl_overlap(world[i], world[i + 2]), (i, i + 2)


def test_adjacent_links_touch_at_random_poses(
    robot: DHRobot, meshes: list[trimesh.Trimesh]
) -> None:
    rng = np.random.default_rng(1)
    for q in rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (3, 6)):
        world = placed(meshes, robot.link_transforms(q))
        for i in range(robot.dof):
            assert fcl_overlap(world[i], world[i + 1])
