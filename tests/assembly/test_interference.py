from __future__ import annotations

import fcl
import numpy as np
import pytest

from workbench.assembly.example_scene import example_scene, plate_mesh, screw_mesh
from workbench.assembly.interference import InterferenceChecker
from workbench.geometry.transforms import rpy_to_matrix


def _twin(moving, T, obstacle) -> bool:
    """python-fcl surfaces + trimesh's ray containment: an independent exact verdict."""

    def bvh(m):
        b = fcl.BVHModel()
        b.beginModel(len(m.vertices), len(m.faces))
        b.addSubModel(np.asarray(m.vertices), np.asarray(m.faces, np.int32))
        b.endModel()
        return b

    a = fcl.CollisionObject(bvh(moving), fcl.Transform(T[:3, :3], T[:3, 3]))
    o = fcl.CollisionObject(bvh(obstacle), fcl.Transform())
    if fcl.collide(a, o, fcl.CollisionRequest(), fcl.CollisionResult()):
        return True
    placed = moving.copy().apply_transform(T)
    return bool(
        obstacle.contains(placed.vertices[:1])[0] or placed.contains(obstacle.vertices[:1])[0]
    )


def _screw_near_hole(rng, n):
    sc = example_scene()
    G = sc.parts[2].goal
    T = np.repeat(G[None], n, axis=0)
    T[:, :3, 3] += rng.normal(0, [0.0015, 0.0015, 0.004], (n, 3))
    T[:, :3, :3] = rpy_to_matrix(rng.normal(0, 0.04, (n, 3)))
    return T


def test_verdicts_match_fcl_twin_and_cells_are_conservative():
    rng = np.random.default_rng(0)
    screw, plate = screw_mesh(), plate_mesh()
    sc = example_scene()
    plate_world = plate.copy().apply_transform(sc.parts[1].goal)
    ch = InterferenceChecker(screw, [plate_world], cell_size=0.002)
    T = _screw_near_hole(rng, 150)
    # Include enclosure: a small screw wholly inside a big box.
    ref = np.array([_twin(screw, t, plate_world) for t in T])
    ours = np.array([ch.interferes(t) for t in T])
    cells = ch.cell_stage_pair(T, 0)
    assert 0.2 < ref.mean() < 0.95
    assert np.array_equal(ours, ref)
    assert np.all(cells[ref])  # the cell stage never misses a real interference


def test_enclosed_part_counts_as_interference():
    import trimesh

    big = trimesh.creation.box([0.2, 0.2, 0.2])
    ch = InterferenceChecker(screw_mesh(), [big])
    assert ch.interferes(np.eye(4))
    assert ch.cell_stage_pair(np.eye(4), 0)[0]
    ch2 = InterferenceChecker(big, [screw_mesh()])  # obstacle inside the moving part
    assert ch2.interferes(np.eye(4))


def test_false_positives_of_the_cell_stage_fall_with_cell_size():
    rng = np.random.default_rng(1)
    sc = example_scene()
    plate_world = plate_mesh().apply_transform(sc.parts[1].goal)
    # Screws standing over solid plate (between holes): only the height gap decides.
    top = sc.parts[1].goal[2, 3] + 0.005
    T = np.repeat(np.eye(4)[None], 60, axis=0)
    T[:, :3, 3] = np.c_[
        rng.uniform(-0.02, 0.02, (60, 2)), top + 0.018 + rng.uniform(-0.002, 0.006, 60)
    ]
    T[:, :3, :3] = rpy_to_matrix(rng.normal(0, 0.02, (60, 3)))
    ref = np.array([_twin(screw_mesh(), t, plate_world) for t in T])
    fps = []
    for c in (0.004, 0.002, 0.001):
        ch = InterferenceChecker(screw_mesh(), [plate_world], cell_size=c, obstacle_cell_size=c)
        cells = ch.cell_stage_pair(T, 0)
        assert np.all(cells[ref])  # conservative at every cell size
        fps.append(float(np.mean(cells[~ref])))
        assert fps[0] > 0.2
    assert all(a >= b for a, b in zip(fps, fps[1:], strict=False))


def test_cells_on_or_off_give_the_twins_verdict_in_order():
    rng = np.random.default_rng(5)
    sc = example_scene()
    plate_world = plate_mesh().apply_transform(sc.parts[1].goal)
    table = sc.fixed[0]
    ch = InterferenceChecker(screw_mesh(), [table, plate_world], cell_size=0.002)
    T = _screw_near_hole(rng, 120)
    T[rng.random(120) < 0.5, 2, 3] += 0.02  # half of them lifted out of the hole
    T[:8, 2, 3] += 0.05  # the first ones clear
    ref = np.array(
        [_twin(screw_mesh(), t, plate_world) or _twin(screw_mesh(), t, table) for t in T]
    )
    assert 0.2 < ref.mean() < 0.8
    first = int(np.argmax(ref))
    assert first >= 8
    assert ch.first_interference(T, cells=True) == first
    assert ch.first_interference(T, cells=False) == first
    assert ch.first_interference(T[~ref], cells=False) == -1
    # Groups of consecutive poses: the first group without a twin hit.
    sizes = rng.integers(0, 6, 40)
    sizes[-1] += len(T) - sizes.sum() if sizes.sum() < len(T) else 0
    sizes = sizes[np.cumsum(sizes) <= len(T)]
    S = T[: sizes.sum()]
    bounds = np.concatenate([[0], np.cumsum(sizes)])
    free = [not ref[a:b].any() for a, b in zip(bounds[:-1], bounds[1:], strict=True)]
    for g0 in range(0, len(sizes), 2):  # every other suffix of groups: varied answers
        want = free.index(True, g0) - g0 if True in free[g0:] else -1
        for cells in (True, False):
            assert ch.first_free_group(S[bounds[g0] :], sizes[g0:], cells=cells) == want
    only_hits = [g for g in range(len(sizes)) if not free[g]]
    keep = np.concatenate([np.arange(bounds[g], bounds[g + 1]) for g in only_hits])
    assert ch.first_free_group(S[keep], sizes[only_hits]) == -1


def test_enclosure_is_found_at_any_rotation():
    import trimesh

    # A ball fits in the box at any rotation, but its rotated local AABB does not:
    # the enclosure pre-test must not use that box.
    ball = trimesh.creation.icosphere(subdivisions=2, radius=0.09)
    box = trimesh.creation.box([0.2, 0.2, 0.2])
    T = np.eye(4)
    T[:3, :3] = rpy_to_matrix([np.pi / 4, 0.0, np.pi / 4])
    for moving, obstacle in ((ball, box), (box, ball)):
        ch = InterferenceChecker(moving, [obstacle])
        assert _twin(moving, T, obstacle)
        assert ch.interferes(T)
        assert ch.first_interference(T[None], cells=False) == 0
        assert ch.exact_pair(T, 0)
        far = T.copy()
        far[0, 3] = 0.5
        assert not ch.interferes(far) and ch.first_interference(far[None], cells=False) == -1


def test_bad_group_sizes_are_refused():
    from workbench.errors import InputError

    ch = InterferenceChecker(screw_mesh(), [plate_mesh()])
    with pytest.raises(InputError, match="sizes"):
        ch.first_free_group(np.repeat(np.eye(4)[None], 3, axis=0), [1, 1])


def test_random_poses_in_and_around_a_box_match_the_twin():
    import trimesh

    rng = np.random.default_rng(8)
    small = trimesh.creation.box([0.03, 0.02, 0.05])
    big = trimesh.creation.icosphere(subdivisions=1, radius=0.08)
    T = np.repeat(np.eye(4)[None], 80, axis=0)
    T[:, :3, :3] = rpy_to_matrix(rng.uniform(-np.pi, np.pi, (80, 3)))
    T[:, :3, 3] = rng.uniform(-0.12, 0.12, (80, 3))
    for moving, obstacle in ((small, big), (big, small)):
        ch = InterferenceChecker(moving, [obstacle])
        ref = np.array([_twin(moving, t, obstacle) for t in T])
        assert 0.2 < ref.mean() < 0.9
        for cells in (True, False):
            got = np.array([ch.first_interference(t[None], cells=cells) == 0 for t in T])
            assert np.array_equal(got, ref)
        assert ch.first_interference(T, cells=False) == int(np.argmax(ref))
