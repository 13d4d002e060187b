"""OBB tree (§2.1 split rules) and its DFS check against brute force and python-fcl."""

from __future__ import annotations

import itertools

import fcl
import numpy as np
import pytest
from numpy.typing import ArrayLike
from scipy.spatial.transform import Rotation
from twins import load_module

from workbench.errors import InputError
from workbench.geometry import OBB, obb_overlap
from workbench.geometry.transforms import make_transform, rot_z
from workbench.sheetmetal import SheetMetalPart
from workbench.sheetmetal.obbtree import OBBTree

_tp = load_module("tests/sheetmetal/test_part.py", "part_twin")


@pytest.fixture(scope="module")
def seed_state():
    return SheetMetalPart.from_spec(_tp.seed_spec()).fold(6)


def random_obstacles(rng: np.random.Generator, n: int, spread: float) -> OBB:
    return OBB(
        rng.uniform(-spread, spread, (n, 3)),
        Rotation.random(n, random_state=rng).as_matrix(),
        rng.uniform(0.005, 0.08, (n, 3)),
    )


def random_poses(rng: np.random.Generator, n: int, spread: float) -> np.ndarray:
    return make_transform(
        Rotation.random(n, random_state=rng).as_matrix(), rng.uniform(-spread, spread, (n, 3))
    )


def test_tree_follows_fig8_split(seed_state) -> None:
    tree = seed_state.obb_tree("1")
    names = [tuple(seed_state.part.flanges[f].name for f in s) for s in tree.flanges]
    root_children = [
        names[c]
        for c in tree.child_index[tree.child_start[0] : tree.child_start[0] + tree.child_count[0]]
    ]
    assert sorted(root_children) == sorted([("1",), ("2", "3"), ("4", "5"), ("6",), ("7",)])
    assert names.count(("2",)) == names.count(("3",)) == 1 and max(tree.level) == 2
    # Every node's box contains the boxes of the flanges below it.
    corners = tree.boxes.corners()
    for node, flanges in enumerate(tree.flanges):
        leaf_nodes = [int(np.nonzero(tree.leaf_flange == f)[0][0]) for f in flanges]
        assert tree.boxes[node].contains(corners[leaf_nodes].reshape(-1, 3), tol=1e-9).all()
    # Grasping another flange: its frame is the tree's frame, the root's first child is its leaf.
    t3 = seed_state.obb_tree("3")
    assert t3.flanges[t3.child_index[t3.child_start[0]]] == (2,)
    assert seed_state.obb_tree("3") is t3  # cached: rebuilt only with the bend state


def test_tree_verdict_equals_brute_force_on_random_placements(seed_state) -> None:
    rng = np.random.default_rng(0)
    tree = seed_state.obb_tree("1")
    obstacles = random_obstacles(rng, 4, 0.05)
    T = random_poses(rng, 10_000, 0.3)
    rep = tree.collide_frames(obstacles, T)
    flat = tree.flat_collide_frames(obstacles, T)
    # Brute force: every flange box in the world against every obstacle, all at once.
    leaves = tree.boxes[tree.leaves].reshape(1, -1, 1).transformed(T[:, None, None])
    brute = obb_overlap(leaves, obstacles.reshape(1, 1, -1))  # (F, flanges, obstacles)
    assert 0.1 < brute.any(axis=(1, 2)).mean() < 0.9
    np.testing.assert_array_equal(rep.collides, brute.any(axis=(1, 2)))
    np.testing.assert_array_equal(flat.collides, rep.collides)
    got = np.zeros_like(brute)
    got[rep.hits[:, 0], rep.hits[:, 1], rep.hits[:, 2]] = True
    np.testing.assert_array_equal(got, brute)
    assert np.all(flat.n_obb_tests == 7 * 4)
    # Single-frame DFS equals the batched run; python-fcl boxes agree on the first 300 frames.
    for i in range(300):
        one = tree.collide(obstacles, T[i])
        assert one.collides == rep.collides[i] and one.n_obb_tests == rep.n_obb_tests[i]
        assert set(one.hit_pairs) == set(map(tuple, np.argwhere(brute[i])))
        fcl_hit = False
        for f in range(7):
            box = leaves[i, f, 0]
            a = fcl.CollisionObject(
                fcl.Box(*(2 * box.half_extents)), fcl.Transform(box.rotation, box.center)
            )
            for o in range(4):
                b = fcl.CollisionObject(
                    fcl.Box(*(2 * obstacles.half_extents[o])),
                    fcl.Transform(obstacles.rotation[o], obstacles.center[o]),
                )
                fcl_hit |= fcl.collide(a, b, fcl.CollisionRequest()) > 0
        assert fcl_hit == rep.collides[i]


def test_tree_needs_a_third_of_flat_tests_on_free_transfer(seed_state) -> None:
    tree = seed_state.obb_tree("1")
    # A cell of boxes around a straight carry at 1 m height: fixtures off to the side.
    rng = np.random.default_rng(1)
    cell = OBB(
        np.c_[
            rng.uniform(-1, 1, 12),
            rng.choice([-1, 1], 12) * rng.uniform(0.6, 1.0, 12),
            rng.uniform(0, 2, 12),
        ],
        np.eye(3),
        rng.uniform(0.05, 0.3, (12, 3)),
    )
    s = np.linspace(0, 1, 22)
    T = make_transform(rot_z(s * np.pi), np.c_[np.cos(s * np.pi) - 0.5, 0 * s, 1 + 0 * s])
    rep, flat = tree.collide_frames(cell, T), tree.flat_collide_frames(cell, T)
    free = ~flat.collides
    assert free.sum() >= 15
    assert rep.n_obb_tests[free].sum() * 3 <= flat.n_obb_tests[free].sum()
    one = tree.collide(cell, T[0])
    assert one.nodes_tested == (0,) and one.nodes_hit == () and one.n_obb_tests == 12


def test_hit_reports_flange_obstacle_and_nodes(seed_state) -> None:
    tree = seed_state.obb_tree("1")
    # A small block touching the outside of wall 6 (flange index 5) only.
    box6 = tree.boxes[tree.leaves[5]]
    probe = OBB(
        box6.center + box6.rotation[:, 2] * (box6.half_extents[2] + 0.004),
        box6.rotation,
        [0.01, 0.01, 0.005],
    )
    far = OBB([5.0, 5, 5], np.eye(3), [0.1, 0.1, 0.1])
    obstacles = OBB(
        np.stack([far.center, probe.center]),
        np.stack([far.rotation, probe.rotation]),
        np.stack([far.half_extents, probe.half_extents]),
    )
    rep = tree.collide(obstacles, np.eye(4))
    assert rep.collides and rep.hit_flanges == (5,) and rep.hit_obstacles == (1,)
    assert 0 in rep.nodes_hit and tree.leaves[5] in rep.nodes_hit
    assert rep.n_obb_tests < tree.flat_collide(obstacles, np.eye(4)).n_obb_tests


def test_bad_input(seed_state) -> None:
    tree = seed_state.obb_tree(0)
    with pytest.raises(InputError, match="T_world_grasp"):
        tree.collide(OBB(np.zeros(3), np.eye(3), np.ones(3)), np.eye(3))
    with pytest.raises(InputError, match="obstacles"):
        tree.collide([1, 2, 3], np.eye(4))  # type: ignore[arg-type]


def slow_dfs(tree, obstacles: OBB, T: np.ndarray):
    """Fig. 9 one pair at a time: test the root against each obstacle, recurse into hits."""
    world = tree.boxes.transformed(T)
    tested, hit_nodes, hits = [], [], set()

    def visit(node: int, o: int) -> None:
        tested.append(node)
        if not bool(obb_overlap(world[node], obstacles[o])):
            return
        hit_nodes.append(node)
        if tree.leaf_flange[node] >= 0:
            hits.add((int(tree.leaf_flange[node]), o))
        lo = tree.child_start[node]
        for child in tree.child_index[lo : lo + tree.child_count[node]]:
            visit(int(child), o)

    for o in range(len(obstacles)):
        visit(0, o)
    return sorted(tested), sorted(hit_nodes), sorted(hits)


def test_batched_report_equals_a_pair_by_pair_dfs(seed_state) -> None:
    # The batched traversal (AABB pre-filter, level-wide exact tests, lazily derived rows)
    # against the recursive DFS above, test for test: counts, tested and hit nodes, hits.
    rng = np.random.default_rng(5)
    tree = seed_state.obb_tree("1")
    obstacles = random_obstacles(rng, 5, 0.12)
    T = random_poses(rng, 400, 0.2)
    rep = tree.collide_frames(obstacles, T)
    descended = 0
    for i in range(len(T)):
        tested, hit_nodes, hits = slow_dfs(tree, obstacles, T[i])
        assert rep.n_obb_tests[i] == len(tested)
        assert sorted(rep.tested[rep.tested[:, 0] == i, 1].tolist()) == tested
        assert sorted(rep.hit_nodes[rep.hit_nodes[:, 0] == i, 1].tolist()) == hit_nodes
        assert sorted(map(tuple, rep.hits[rep.hits[:, 0] == i, 1:].tolist())) == hits
        one = rep.frame(i)
        assert one.collides == bool(hits) == rep.collides[i]
        assert one.hit_pairs == tuple(hits) and one.n_obb_tests == len(tested)
        assert one.nodes_tested == tuple(sorted(set(tested)))
        assert one.nodes_hit == tuple(sorted(set(hit_nodes)))
        descended += len(tested) > len(obstacles)
    assert 50 < descended < 390 and 0.1 < rep.collides.mean() < 0.9


def test_touching_placements_are_hits_at_every_level(seed_state) -> None:
    # Poses that put a flange box exactly against an obstacle face (gap 0), just inside and
    # just outside: the AABB pre-filter and the internal boxes must not lose a touching pair.
    rng = np.random.default_rng(6)
    tree = seed_state.obb_tree("1")
    leaves = tree.boxes[tree.leaves]
    # Axis-aligned, the obstacle's and the flange's world AABBs are the boxes themselves, so
    # the pre-filter is as tight as it gets; rotated, the exact test decides.
    rotations = (np.eye(3), Rotation.random(random_state=rng).as_matrix())
    n = 300
    flange = rng.integers(0, 7, n)
    axis = rng.integers(0, 3, n)
    side = rng.choice([-1.0, 1.0], n)
    for rotation, (gap, expect) in itertools.product(
        rotations, ((0.0, True), (-1e-7, True), (1e-7, False))
    ):
        obstacle = OBB([0.4, -0.2, 0.9], rotation, [0.05, 0.2, 0.1])
        T = np.empty((n, 4, 4))
        for k in range(n):
            leaf = leaves[int(flange[k])]
            # World pose of the flange box: the obstacle's axes, slid along one of them until
            # the faces meet (plus gap), and shifted sideways within the face.
            ax = int(axis[k])
            offset = (
                rng.uniform(-1, 1, 3) * 0.3 * np.minimum(leaf.half_extents, obstacle.half_extents)
            )
            offset[ax] = side[k] * (leaf.half_extents[ax] + obstacle.half_extents[ax] + gap)
            T_world_leaf = make_transform(
                obstacle.rotation, obstacle.center + obstacle.rotation @ offset
            )
            T_leaf_grasp = np.linalg.inv(make_transform(leaf.rotation, leaf.center))
            T[k] = T_world_leaf @ T_leaf_grasp
        rep = tree.collide_frames(obstacle.reshape(1), T)
        world = leaves.reshape(1, -1).transformed(T[:, None])
        brute = obb_overlap(world, obstacle.reshape(1, 1))  # (n, 7)
        np.testing.assert_array_equal(rep.collides, brute.any(axis=1))
        touched = brute[np.arange(n), flange]
        assert touched.all() if expect else not touched.any()
        if expect:
            assert rep.collides.all()


def test_no_obstacles_and_no_frames(seed_state) -> None:
    tree = seed_state.obb_tree("1")
    none = OBB(np.zeros((0, 3)), np.zeros((0, 3, 3)), np.zeros((0, 3)))
    rep = tree.collide(none, np.eye(4))
    assert not rep.collides and rep.n_obb_tests == 0 and rep.nodes_tested == ()
    cup = OBB([0.0, 0, 0], np.eye(3), [0.01, 0.01, 0.01]).reshape(1)
    empty = tree.collide_frames(cup, np.zeros((0, 4, 4)))
    assert empty.collides.shape == empty.n_obb_tests.shape == (0,)
    assert empty.hits.shape == (0, 3) and empty.tested.shape == (0, 2)


def one_box_tree(half: ArrayLike) -> OBBTree:
    """A tree of one leaf: a box on the grasp frame's axes with half extents `half` [m]."""
    return OBBTree(
        0,
        OBB(np.zeros((1, 3)), np.eye(3)[None], np.asarray(half, float)[None]),
        ((0,),),
        np.array([0]),
        np.array([0]),
        np.array([0]),
        np.array([0]),
        np.zeros(0, dtype=np.int64),
    )


def thin_plate_tree(depth: int) -> OBBTree:
    """Coplanar plates (half thickness 1e-5 m) on the world axes: `depth` 0 is one leaf, 1 a
    root over three leaves, 2 a root over a leaf and a node over two leaves."""
    half = np.array([0.5, 0.5, 1e-5])
    leaf_x = [0.0] if depth == 0 else [-1.0, 0.0, 1.0]
    boxes = [(x, half) for x in leaf_x]
    if depth == 0:
        return one_box_tree(half)
    wide = np.array([1.5, 0.5, 1e-5])
    if depth == 1:  # root; leaves 1, 2, 3
        boxes = [(0.0, wide)] + boxes
        flanges = ((0, 1, 2), (0,), (1,), (2,))
        leaf, level = [-1, 0, 1, 2], [0, 1, 1, 1]
        start, count, index = [0, 4, 4, 4], [3, 0, 0, 0], [1, 2, 3]
    else:  # root; leaf 1 (flange 0), node 2 over leaves 3, 4 (flanges 1, 2)
        boxes = [(0.0, wide), boxes[0], (0.5, np.array([1.0, 0.5, 1e-5]))] + boxes[1:]
        flanges = ((0, 1, 2), (0,), (1, 2), (1,), (2,))
        leaf, level = [-1, 0, -1, 1, 2], [0, 1, 1, 2, 2]
        start, count, index = [0, 2, 2, 4, 4], [2, 0, 2, 0, 0], [1, 2, 3, 4]
    return OBBTree(
        0,
        OBB(np.array([[x, 0, 0] for x, _ in boxes]), np.eye(3), np.array([h for _, h in boxes])),
        flanges,
        np.array(leaf),
        np.array(level),
        np.array(start),
        np.array(count),
        np.array(index),
    )


@pytest.mark.parametrize("depth", [0, 1, 2])
def test_touching_thin_plates_are_hits_at_every_level(depth: int) -> None:
    # Thin plates on the world axes against a thin plate obstacle, faces a gap apart along z:
    # the exact test keeps gaps up to its absolute SAT_EPS term (~1e-12 m here), far more
    # than a relative slack of the 1e-5 m half thickness; the AABB pre-filter (at the start
    # nodes and, with >= AABB_FILTER_MIN pairs, at every level below) must keep them too.
    from workbench.sheetmetal.obbcheck import AABB_FILTER_MIN

    rng = np.random.default_rng(9)
    tree = thin_plate_tree(depth)
    leaves = tree.boxes[tree.leaves]
    obstacle = OBB([0.0, 0, 0], np.eye(3), [0.5, 0.5, 1e-5])
    n = 8 * AABB_FILTER_MIN
    flange = rng.integers(0, len(leaves), n)
    side = rng.choice([-1.0, 1.0], n)
    for gap, expect in ((0.0, True), (1e-13, True), (5e-13, True), (1e-11, False)):
        # Frame k puts leaf flange[k] right above or below the obstacle, shifted sideways.
        shift = np.c_[rng.uniform(-0.3, 0.3, (n, 2)), side * (2e-5 + gap)]
        T = make_transform(np.eye(3), shift - leaves.center[flange])
        for one_frame in (False, True):
            rep = (
                [tree.collide(obstacle.reshape(1), T[k]) for k in range(n)]
                if one_frame
                else tree.collide_frames(obstacle.reshape(1), T)
            )
            collides = np.array([r.collides for r in rep]) if one_frame else rep.collides
            world = leaves.reshape(1, -1).transformed(T[:, None])
            brute = obb_overlap(world, obstacle.reshape(1, 1))  # (n, leaves)
            np.testing.assert_array_equal(collides, brute.any(axis=1))
            touched = brute[np.arange(n), flange]
            assert touched.all() if expect else not touched.any()


@pytest.mark.parametrize(
    "half_box, half_obstacle",
    [([0.5, 0.5, 1e-5], [0.5, 0.5, 1e-5]), ([0.3, 1e-6, 0.2], [0.05, 0.05, 0.05])],
)
def test_pre_filter_keeps_pairs_at_the_exact_tests_boundary(half_box, half_obstacle) -> None:
    # Bisect, per frame, the largest offset along a random direction at which the exact test
    # still says "overlap" (its eps slack fully used), for world-aligned, slightly turned
    # (near-parallel edges) and random orientations: the batched tree must agree with it.
    rng = np.random.default_rng(10)
    tree = one_box_tree(half_box)
    obstacle = OBB([0.1, -0.2, 0.3], np.eye(3), half_obstacle)
    n = 1500
    R = Rotation.random(n, random_state=rng).as_matrix()
    R[: n // 3] = np.eye(3)
    tiny = rng.normal(size=(n // 3, 3)) * 10 ** rng.uniform(-12, -4, (n // 3, 1))
    R[n // 3 : 2 * n // 3] = Rotation.from_rotvec(tiny).as_matrix()
    u = rng.normal(size=(n, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    box = tree.boxes[0]

    def overlap(s: np.ndarray) -> np.ndarray:
        T = make_transform(R, obstacle.center + s[:, None] * u)
        return obb_overlap(box.transformed(T), obstacle), T

    lo, hi = np.zeros(n), np.full(n, 4.0)
    for _ in range(70):
        mid = (lo + hi) / 2
        ok, _ = overlap(mid)
        lo, hi = np.where(ok, mid, lo), np.where(ok, hi, mid)
    for s, expect in ((lo, True), (hi, False)):
        brute, T = overlap(s)
        assert brute.all() if expect else not brute.any()
        np.testing.assert_array_equal(tree.collide_frames(obstacle.reshape(1), T).collides, brute)
