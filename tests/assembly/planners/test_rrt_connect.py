"""RRT-Connect's path shortening (issue 14 part 4): far-to-near vertex joins with batched
motion checks, random point-to-point joins, joins again; on window scenes (a 5 cm cube
through a window 3x its edge in a wall), twins: python-fcl on a dense resampling of the
path, brute-force `motion_free` for the greedy joins, the old shortcut (50 random vertex
pairs) on the same raw path."""

from __future__ import annotations

import fcl
import numpy as np
import pytest
import trimesh

from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import path_samples, pose_distance
from workbench.assembly.planners import rrt_connect as rc
from workbench.assembly.planners.common import motion_free
from workbench.geometry.transforms import make_transform, rpy_to_matrix

EDGE = 0.05


def _slab(lo: tuple[float, float], hi: tuple[float, float]) -> trimesh.Trimesh:
    size = [0.02, hi[0] - lo[0], hi[1] - lo[1]]
    return trimesh.creation.box(size).apply_translation(
        [0.0, (hi[0] + lo[0]) / 2, (hi[1] + lo[1]) / 2]
    )


def window_scene(factor: float, seed: int):  # type: ignore[no-untyped-def]
    """A 5 cm cube, a 1 m wall at x = 0 with a square window factor x the edge, ends 0.3 m
    either side off the window (the straight move hits the wall), random orientations."""
    rng = np.random.default_rng(seed)
    w = factor * EDGE
    yc, zc = rng.uniform(-0.25, 0.25, 2)
    wall = [
        _slab((-0.5, -0.5), (yc - w / 2, 0.5)),
        _slab((yc + w / 2, -0.5), (0.5, 0.5)),
        _slab((yc - w / 2, -0.5), (yc + w / 2, zc - w / 2)),
        _slab((yc - w / 2, zc + w / 2), (yc + w / 2, 0.5)),
    ]
    off = rng.uniform(0.15, 0.3, 2) * rng.choice([-1, 1], 2)
    rpy = rng.uniform(-np.pi, np.pi, (2, 3))
    start = make_transform(rpy_to_matrix(rpy[0]), [-0.3, yc + off[0], zc + off[1]])
    off2 = np.abs(rng.uniform(0.15, 0.3, 2)) * np.sign(off)
    goal = make_transform(rpy_to_matrix(rpy[1]), [0.3, yc + off2[0], zc + off2[1]])
    return trimesh.creation.box([EDGE] * 3), wall, start, goal


def _length(P: np.ndarray) -> float:
    return float(np.sum(pose_distance(P[:-1], P[1:], 0.0)))


def _fcl_free(part: trimesh.Trimesh, wall: list[trimesh.Trimesh], poses, step: float) -> bool:
    """Twin: python-fcl collide of the part's mesh with every wall slab at every sample."""

    def bvh(m: trimesh.Trimesh) -> fcl.BVHModel:
        b = fcl.BVHModel()
        b.beginModel(len(m.vertices), len(m.faces))
        b.addSubModel(m.vertices, m.faces)
        b.endModel()
        return b

    moving = fcl.CollisionObject(bvh(part))
    slabs = [fcl.CollisionObject(bvh(m)) for m in wall]
    for T in path_samples(poses, float(np.linalg.norm(part.extents) / 2), step):
        moving.setTransform(fcl.Transform(T[:3, :3], T[:3, 3]))
        for s in slabs:
            if fcl.collide(moving, s, fcl.CollisionRequest(), fcl.CollisionResult()):
                return False
    return True


def _old_shortcut(path, ch, res, rng, iterations=50):  # type: ignore[no-untyped-def]
    """The shortcut before issue 14 part 4: random vertex pairs joined where free."""
    path = list(path)
    for _ in range(iterations):
        if len(path) < 3:
            break
        i, j = sorted(rng.choice(len(path), 2, replace=False))
        if j - i >= 2 and motion_free(ch, path[i], path[j], res):
            path = path[: i + 1] + path[j:]
    return path


@pytest.mark.parametrize("seed", [0, 2])
def test_window_paths_are_free_by_fcl_and_shorter_than_the_old_shortcut(
    seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    part, wall, start, goal = window_scene(3.0, seed)
    ch = InterferenceChecker(part, wall, 0.01)
    raw: list[list[np.ndarray]] = []
    new_shortcut = rc.shortcut

    def spy(path, *a, **k):  # type: ignore[no-untyped-def]
        raw.append(list(path))
        return new_shortcut(path, *a, **k)

    monkeypatch.setattr(rc, "shortcut", spy)
    P, _ = rc.plan_rrt_connect(ch, start, goal, seed=seed, max_time=20.0)
    assert len(raw) == 1 and len(raw[0]) >= 3  # a tree was needed
    np.testing.assert_allclose(P[0], start, atol=1e-12)
    np.testing.assert_allclose(P[-1], goal, atol=1e-12)
    assert rc.check_path(ch, P, ch.cell_size) < 0
    assert _fcl_free(part, wall, P, ch.cell_size / 4)  # 4x denser than the planner checks
    old = np.asarray(_old_shortcut(raw[0], ch, ch.cell_size, np.random.default_rng(seed)))
    assert _length(P) < _length(old)
    assert _length(P) < 1.2 * _length(np.asarray([start, goal])) + 0.2  # no detour round the wall


def test_vertex_joins_are_the_farthest_free_ones_by_brute_force() -> None:
    part, wall, start, goal = window_scene(3.0, 0)
    ch = InterferenceChecker(part, wall, 0.01)
    rng = np.random.default_rng(1)
    # A free zig-zag on the start side of the wall, then one through the window.
    pts = [start[:3, 3]] + [
        np.array([-0.3 + 0.02 * k, start[1, 3] + 0.05 * (-1) ** k, start[2, 3]])
        for k in range(1, 9)
    ]
    path = [
        make_transform(rpy_to_matrix(rng.uniform(-0.2, 0.2, 3)) @ start[:3, :3], p) for p in pts
    ]
    path = [path[0]] + [T for T in path[1:] if not ch.interferes(T)]
    path = [
        p for k, p in enumerate(path) if k == 0 or motion_free(ch, path[k - 1], p, ch.cell_size)
    ]
    res = ch.cell_size
    out = rc.reduce_vertices(path, ch, res)
    idx = [next(k for k, T in enumerate(path) if T is o) for o in out]
    assert len(path) >= 6 and len(out) < len(path)
    assert idx[0] == 0 and idx[-1] == len(path) - 1
    for a, b in zip(idx, idx[1:], strict=False):
        assert b == a + 1 or motion_free(ch, path[a], path[b], res)
        assert not any(motion_free(ch, path[a], path[c], res) for c in range(b + 1, len(path)))
