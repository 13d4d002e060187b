"""Tests of workbench/assembly/robot_pairs.py: the cell's bodies, their pairs and contacts.

The arms are small stand-ins (boxes carried on a translating joint), so every pose is known in
closed form. The twin is brute force: the pair rules applied to every two bodies, and
python-fcl box primitives (solid, so a body inside another counts) at every sample and pair.
"""

from __future__ import annotations

from types import SimpleNamespace

import fcl
import numpy as np
import pytest
import trimesh

from workbench.assembly.robot_pairs import cell_bodies, cross_contacts

SIZE = {"link0": (0.3, 0.3, 0.2), "link1": (0.2, 0.2, 0.2), "tool": (0.1, 0.1, 0.3)}
PART = (0.15, 0.15, 0.15)


def _trans(x, y, z) -> np.ndarray:
    T = np.eye(4)
    T[:3, 3] = (x, y, z)
    return T


class _Arm:
    """A one-joint arm at (x0, y0): its base stays, link 1 slides along x by q [m]; the tool
    rides on the last frame (link 1) as the real arms' tool rides on the flange."""

    def __init__(self, x0: float, y0: float) -> None:
        self.x0, self.y0 = x0, y0
        moving = {b: SimpleNamespace(mesh=trimesh.creation.box(SIZE[b])) for b in SIZE}
        self.checker = SimpleNamespace(
            scene=SimpleNamespace(moving=moving), link_names=["link0", "link1"]
        )

    def link_poses(self, q: np.ndarray) -> np.ndarray:
        q = np.asarray(q)
        out = np.tile(np.eye(4), (len(q), 2, 1, 1))
        out[:, 0, :3, 3] = (self.x0, self.y0, 0.0)
        out[:, 1, 0, 3] = self.x0 + q[:, 0]
        out[:, 1, 1, 3] = self.y0
        out[:, 1, 2, 3] = 0.4
        return out


def _cell():
    arms = {"A": _Arm(0.0, 0.0), "B": _Arm(1.0, 0.1)}
    parts = {n: SimpleNamespace(name=n, mesh=trimesh.creation.box(PART)) for n in ("p1", "p2")}
    return arms, parts


def _brute_pairs(arms, parts) -> set[tuple[str, str]]:
    bodies = [(f"{a}/{b}", a, b) for a in arms for b in SIZE] + [
        (f"part {p}", "", "part") for p in parts
    ]
    out = set()
    for x, (na, oa, ba) in enumerate(bodies):
        for nb, ob, _ in bodies[x + 1 :]:
            if oa and ob and oa != ob:
                out.add((na, nb))
            elif oa and not ob and ba != "link0":
                out.add((na, nb))
    return out


def test_bodies_and_pairs_follow_the_rules() -> None:
    arms, parts = _cell()
    b = cell_bodies(arms, parts)
    assert b.names == [f"{a}/{x}" for a in arms for x in SIZE] + ["part p1", "part p2"]
    assert set(b.pairs) == _brute_pairs(arms, parts)
    assert len(b.pairs) == len(set(b.pairs)) == 9 + 2 * 2 * 2
    assert ("A/link1", "A/tool") not in b.pairs  # a robot's own bodies: its checker's job
    assert not any(p[0] == "part p1" and p[1] == "part p2" for p in b.pairs)


def _fcl_box(size, T) -> fcl.CollisionObject:
    return fcl.CollisionObject(fcl.Box(*size), fcl.Transform(T[:3, :3], T[:3, 3]))


def test_contacts_match_brute_force_fcl_and_the_carried_part_is_excused() -> None:
    arms, parts = _cell()
    bodies = cell_bodies(arms, parts)
    rng = np.random.default_rng(11)
    N = 60
    times = np.linspace(0.0, 5.9, N)
    joints = {"A": rng.uniform(0.0, 1.0, (N, 1)), "B": rng.uniform(-1.0, 0.0, (N, 1))}
    part_poses = {
        p: np.stack([_trans(*rng.uniform([0.0, -0.2, 0.2], [1.0, 0.3, 0.6])) for _ in range(N)])
        for p in parts
    }
    task = SimpleNamespace(robot="A", part="p1", t0=1.0, t1=3.0)
    got = cross_contacts(bodies, arms, parts, [task], times, joints, part_poses)

    want = set()
    for n in range(N):
        poses = {}
        for a, arm in arms.items():
            L = arm.link_poses(joints[a][n : n + 1])[0]
            poses |= {f"{a}/link0": (SIZE["link0"], L[0]), f"{a}/link1": (SIZE["link1"], L[1])}
            poses[f"{a}/tool"] = (SIZE["tool"], L[1])
        for p in parts:
            poses[f"part {p}"] = (PART, part_poses[p][n])
        for x, y in _brute_pairs(arms, parts):
            if (x, y) == ("A/tool", "part p1") and 1.0 <= times[n] <= 3.0:
                continue
            ox, oy = _fcl_box(*poses[x]), _fcl_box(*poses[y])
            if fcl.collide(ox, oy, fcl.CollisionRequest(), fcl.CollisionResult()):
                want.add((n, x, y))
    assert {(c.index, c.body_a, c.body_b) for c in got} == want
    assert len(want) > 10  # the random samples do touch
    assert any(x == "A/tool" and y == "part p1" for _, x, y in want)  # outside the task
    assert [c.index for c in got] == sorted(c.index for c in got)
    assert all(c.time == pytest.approx(times[c.index]) for c in got)


def test_part_inside_a_tool_counts_as_contact() -> None:
    """A part wholly inside a body touches no surface: the containment test finds it."""
    arms, parts = _cell()
    times = np.array([0.0])
    joints = {"A": np.array([[0.0]]), "B": np.array([[-0.5]])}
    small = {
        "p1": SimpleNamespace(name="p1", mesh=trimesh.creation.box((0.02, 0.02, 0.02))),
        "p2": parts["p2"],
    }
    bodies = cell_bodies(arms, small)
    poses = {"p1": _trans(0.0, 0.0, 0.4)[None], "p2": _trans(0.5, -2.0, 0.4)[None]}
    got = cross_contacts(bodies, arms, small, [], times, joints, poses)
    assert {(c.body_a, c.body_b) for c in got} == {("A/link1", "part p1"), ("A/tool", "part p1")}
