"""Transfer poses and the carried part: retract in the die frame, pallet drop, part follows the TCP."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation
from seed_part import seed_spec

from workbench.collision.shapes import Solid
from workbench.geometry.transforms import invert_transform, make_transform, rot_z
from workbench.pressbrake.die import Die, DiePlacement
from workbench.pressbrake.grasp import Grasp, T_flange_grasp, T_part_grasp
from workbench.pressbrake.obstacles import cell_obstacles
from workbench.pressbrake.transfer import (
    Transfer,
    base_flange_poses,
    carried_poses,
    check_part,
    transfer_poses,
    world_tcp,
)
from workbench.sheetmetal import SheetMetalPart


@pytest.fixture(scope="module")
def part() -> SheetMetalPart:
    return SheetMetalPart.from_spec(seed_spec())


def test_transfer_poses_retract_vias_and_pallet(part) -> None:  # type: ignore[no-untyped-def]
    die = Die(make_transform(rot_z(-np.pi / 2), [0.7, 0.0, 0.35]), 0.8)
    g = Grasp("1")
    last = DiePlacement(
        "b17", 5, np.eye(4), make_transform(np.eye(3), [0.6, 0.1, 0.4]), np.zeros(6)
    )
    vias = make_transform(np.broadcast_to(np.eye(3), (2, 3, 3)), [[0.3, -0.4, 0.6], [0, -0.6, 0.5]])
    pallet = make_transform(rot_z(0.3), [-0.2, -0.7, 0.1])
    tr = Transfer(np.array([0.0, -0.25, 0.06]), vias, pallet, "bending")
    T, names = transfer_poses(tr, die, last, part, g)
    assert names == [
        "bending.retract",
        "bending.transfer[0]",
        "bending.transfer[1]",
        "bending.pallet",
    ]
    # Retract: the last TCP moved by the offset expressed in the die frame (-y of the die = +x world).
    np.testing.assert_allclose(T[0][:3, 3], [0.6 - 0.25, 0.1, 0.46], atol=1e-12)
    np.testing.assert_allclose(T[0][:3, :3], last.T_world_tcp[:3, :3])
    np.testing.assert_allclose(T[1:3], vias)
    # Pallet: the TCP that puts the folded part's frame on the pallet pose.
    np.testing.assert_allclose(
        T[3] @ invert_transform(T_part_grasp(part, g, 6)), pallet, atol=1e-12
    )
    empty = Transfer(tr.retract, np.zeros((0, 4, 4)), pallet)
    assert transfer_poses(empty, die, last, part, g)[1] == ["transfer.retract", "transfer.pallet"]


def test_carried_poses_and_robot_frames(part) -> None:  # type: ignore[no-untyped-def]
    g = Grasp("4", np.array([0.02, 0.03]), 0.4)
    rng = np.random.default_rng(3)
    T_tcp = make_transform(
        Rotation.random(5, random_state=rng).as_matrix(), rng.uniform(-1, 1, (5, 3))
    )
    T_grasp, T_part = carried_poses(T_tcp, part, g)
    f = part.flange_index("4")
    state = part.fold(6)
    np.testing.assert_allclose(T_grasp @ T_flange_grasp(part, g), T_tcp, atol=1e-12)
    np.testing.assert_allclose(T_part @ state.T_part_flange[f], T_grasp, atol=1e-12)

    class Robot:
        def fk(self, q: np.ndarray) -> np.ndarray:
            return make_transform(
                rot_z(q[..., 0]), np.stack([q[..., 1], 0 * q[..., 1], 0 * q[..., 1]], -1)
            )

    base = make_transform(rot_z(0.2), [0.1, 0.2, 0.3])
    tool = make_transform(np.eye(3), [0, 0, 0.12])
    q = rng.uniform(-1, 1, (4, 2))
    T = world_tcp(Robot(), base, tool, q)
    np.testing.assert_allclose(base_flange_poses(base, tool, T), Robot().fk(q), atol=1e-12)


def test_check_part_confirms_cylinder_hits_exactly(part) -> None:  # type: ignore[no-untyped-def]
    tree = part.fold(6).obb_tree("1")
    # A thin cylinder whose bounding box reaches the part while the cylinder stays clear.
    cyl = Solid("post", "cylinder", radius=0.05, height=1.0)
    leaves = tree.boxes[tree.leaves]
    corner = leaves.corners()[0].max(axis=0)  # a box corner region of flange 1
    T_cyl = make_transform(np.eye(3), corner + np.array([0.05 * 0.85, 0.05 * 0.85, 0.0]))
    box = Solid("block", "box", size=(0.1, 0.1, 0.1))
    obst = cell_obstacles(
        [("post", cyl, T_cyl), ("block", box, make_transform(np.eye(3), [5.0, 0, 0]))]
    )
    assert obst.names == ("post", "block") and obst.exact[1] is None
    rough = tree.collide_frames(obst.boxes, np.eye(4)[None])
    rep = check_part(tree, obst, np.eye(4)[None])
    assert rough.collides[0] and not rep.collides[0]
    np.testing.assert_array_equal(rep.n_obb_tests, rough.n_obb_tests)
