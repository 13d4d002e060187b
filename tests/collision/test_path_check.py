"""Fast path check (spheres first, flagged pairs to fcl) against the dense exact check of every sample."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from block_cell import block_cell

from workbench.collision.engine import CollisionEngine
from workbench.collision.path_check import PathCertifier
from workbench.service import Workbench

PROJECT = block_cell(
    {
        "name": "post",
        "shape": "cylinder",
        "radius": 60,
        "height": 900,
        "pose": {"xyz": [0, -550, 450]},
    }
)


# The thinnest obstacle of PROJECT [m]: the post's diameter (the block is 300 mm).
THIN = 0.12


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.from_dict(PROJECT)


@pytest.fixture(scope="module")
def engine(wb: Workbench, engine_cache: Path) -> CollisionEngine:
    cache = str(engine_cache)
    return CollisionEngine(
        wb.checker, "spheres", spheres_per_link=4, resolution=32, cache_dir=cache
    )


def _paths(wb: Workbench, count: int, samples: int, seed: int) -> list[np.ndarray]:
    """Random joint walks through the reachable space in front of the robot (near the cell)."""
    rng = np.random.default_rng(seed)
    lim = wb.robot.limits
    out = []
    for _ in range(count):
        q0 = rng.uniform(lim[:, 0], lim[:, 1])
        q0[1:3] = rng.uniform(-1.2, 1.2, 2)
        step = rng.normal(0.0, 0.05, 6)
        qs = q0 + np.arange(samples)[:, None] * step
        out.append(np.clip(qs, lim[:, 0], lim[:, 1]))
    return out


def _fine(engine: CollisionEngine, qs: np.ndarray, step: float) -> np.ndarray:
    """Return the straight joint segments through qs resampled so that no point of any body
    moves more than `step` [m] between samples (at least 8 per segment).

    A body point moves at most |dq| @ lever along a joint step dq (`JointLevers`, independent
    of the configuration), so a contact reaching deeper than step / 2 into an obstacle holds
    at the resample nearest to it.
    """
    lever = engine.body_lever.max(axis=0)  # (dof,) [m/rad], every body
    parts = []
    for a, b in zip(qs[:-1], qs[1:], strict=True):
        m = max(8, int(np.ceil(np.abs(b - a) @ lever / step)))
        parts.append(np.linspace(a, b, m + 1)[:-1])
    return np.concatenate([*parts, qs[-1:]])


def _sweeps(count: int, seed: int) -> list[np.ndarray]:
    """Sweeps of joint 1 whose two samples are beside the block and whose motion goes through it."""
    rng = np.random.default_rng(seed)
    return [
        np.array([[-0.7, -0.68, 0.595, 0, -0.085, 0], [0.7, -0.68, 0.595, 0, -0.085, 0]])
        + rng.normal(0, 0.04, 6)
        for _ in range(count)
    ]


def _dense(wb: Workbench, qs: np.ndarray) -> list[tuple[tuple[str, str], ...]]:
    return [wb.checker.check(q, distance=False).colliding for q in qs]


def test_sample_verdicts_equal_the_dense_exact_check(
    wb: Workbench, engine: CollisionEngine
) -> None:
    """Twin: python-fcl (+ containment) on every pair at every sample; cell and self pairs."""
    moving = set(engine.body_names)
    hits = self_hits = 0
    for qs in _paths(wb, 40, 12, seed=0):
        dense = _dense(wb, qs)
        rep = engine.check_path(qs)
        want = tuple(i for i, c in enumerate(dense) if c)
        assert rep.colliding_indices == want
        hits += len(want)
        self_hits += sum(any(b in moving for _, b in c) for c in dense)
        if want and not rep.between:  # a sample first: the same pairs as the dense check
            assert rep.first_report is not None and rep.first_index == want[0]
            assert set(rep.first_report.colliding) == set(dense[want[0]])
    assert hits > 40 and self_hits > 0  # the paths do go through contacts, self ones included


def test_no_misses_between_samples_and_no_false_hits(
    wb: Workbench, engine: CollisionEngine
) -> None:
    """Twin: the dense exact check on the straight joint segments resampled to `_fine`'s step.

    No body point moves more than THIN / 4 between twin samples, so the twin sees every contact
    that reaches deeper than THIN / 8 into an obstacle, e.g. any crossing of the post's middle.
    """
    free = between = 0
    for qs in _paths(wb, 24, 6, seed=1) + _sweeps(6, seed=1):
        rep = engine.check_path(qs)
        fine = _fine(engine, qs, THIN / 4)
        dense_fine = [bool(c) for c in _dense(wb, fine)]
        if any(dense_fine):
            assert not rep.collision_free, "a contact between samples was missed"
        if rep.collision_free:
            free += 1
            assert rep.clearance >= 0.0
            assert "collision-free, including between samples" in rep.message
        elif rep.between and rep.first_q is not None and rep.link is not None:
            between += 1
            assert wb.checker.check(rep.first_q, distance=False).in_collision  # confirmed exactly
            assert f"{rep.link} hits {rep.obstacle}" in rep.message
    assert free > 3 and between > 0


def test_free_path_clearance_is_a_lower_bound_of_fcl(
    wb: Workbench, engine: CollisionEngine
) -> None:
    qs = np.linspace(np.zeros(6), [1.0, 0.3, 0.0, 0.5, 0.0, 0.0], 12)
    rep = engine.check_path(qs)
    assert rep.collision_free, rep.message
    fine = np.linspace(qs[0], qs[-1], 90)
    d = min(wb.checker.check(q).min_distance for q in fine)
    assert 0.0 < rep.clearance <= d + 1e-9


def test_exact_mode_gives_the_same_sample_verdicts(wb: Workbench, engine: CollisionEngine) -> None:
    """Same sample verdicts; an interval where exact mode finds a contact (a bisection midpoint
    fcl confirms) is one the spheres mode reports too: colliding or not certified."""
    exact = CollisionEngine(wb.checker, "exact")
    certifier = PathCertifier(exact)
    exact_hits = 0
    for qs in _paths(wb, 6, 8, seed=2) + _sweeps(3, seed=2):
        a, b = engine.check_path(qs), exact.check_path(qs)
        assert a.colliding_indices == b.colliding_indices
        out = certifier.run(
            qs,
            np.arange(len(qs), dtype=float),
            sampler=None,
            acceleration=None,
            deviation=np.zeros(exact.dof),
            max_depth=12,
        )
        hit_intervals = {e[1] for e in out.events if e[3]}  # midpoints fcl found colliding
        assert hit_intervals <= set(b.between_indices)
        assert hit_intervals <= set(a.between_indices), "spheres mode certified a contact"
        if hit_intervals:
            assert not a.collision_free
        exact_hits += len(hit_intervals)
    assert exact_hits > 0  # the sweeps do cross the block between samples


def test_obstacle_wholly_inside_a_link_is_found(tmp_path_factory: pytest.TempPathFactory) -> None:
    """A peg inside link 3 touches none of its surface (fcl collide: free); containment finds it."""
    q = np.array([0.3, -0.2, 0.4, 0.0, 0.5, 0.0])
    probe = Workbench.from_dict(PROJECT)
    T = probe.checker.world_poses(q)["link3"]
    centre = T[:3, :3] @ probe.checker.scene.moving["link3"].mesh.centroid + T[:3, 3]
    data = {
        **PROJECT,
        "cell": {
            "objects": [
                {
                    "name": "peg",
                    "shape": "box",
                    "size": [30, 30, 30],
                    "pose": {"xyz": list(centre * 1000)},
                }
            ]
        },
    }
    wb = Workbench.from_dict(data)
    eng = CollisionEngine(
        wb.checker,
        "spheres",
        spheres_per_link=4,
        resolution=32,
        cache_dir=str(tmp_path_factory.mktemp("peg")),
    )
    assert ("link3", "peg") in eng.always_pairs
    scene = wb.checker.scene
    wb.checker.check(q, distance=False)
    import fcl

    a, b = scene.moving["link3"], scene.static["peg"]
    assert not fcl.collide(a.obj, b.obj, fcl.CollisionRequest(), fcl.CollisionResult())
    assert ("link3", "peg") in wb.checker.check(q, distance=False).colliding  # by containment
    qs = np.linspace(q - 0.02, q + 0.02, 5)
    dense = [i for i, x in enumerate(qs) if wb.checker.check(x, distance=False).in_collision]
    held = eng.contained(qs)[:, eng.always_pairs.index(("link3", "peg"))]
    assert held[2]  # the batched containment test sees it
    rep = eng.check_path(qs)
    assert list(rep.colliding_indices) == dense and 2 in dense


def test_a_new_node_is_always_placed_even_where_a_dropped_one_was():
    """The certifier must re-place poses for every new node: a dropped node's id() is reused."""
    from types import SimpleNamespace

    from workbench.collision.path_check import PathCertifier
    from workbench.collision.path_oracle import PathNode

    placed: list[np.ndarray] = []
    oracle = SimpleNamespace(
        place=lambda poses: placed.append(poses),
        pair_lever={("a", "b"): np.ones(1)},
        group_pairs=[[("a", "b")]],
    )
    cert = PathCertifier(oracle)  # type: ignore[arg-type]

    def node(value: float) -> PathNode:
        z = np.zeros(1)
        return PathNode(0.0, z, z, z, np.full((1, 4, 4), value), z, z)

    # With an id() check the dropped node's address comes back for the next node (CPython) and
    # that node's poses are never placed; holding the node itself keeps it alive instead.
    for k in range(200):
        a = node(float(k))
        cert._place(a)
        del a  # as the certifier drops a settled node; CPython reuses its address at once
        b = node(float(k) + 0.5)
        cert._place(b)
        assert placed[-1] is b.poses, f"round {k}: the new node's poses were never placed"
        cert._place(b)  # the same node again: no second placement
        assert len(placed) == 2 * (k + 1)
        del b


def _contacts(wb: Workbench, q: np.ndarray) -> np.ndarray:
    return np.array([wb.checker.check(x, distance=False).in_collision for x in q])


def _dense_times(traj, t0: float, t1: float, step: float, lever: np.ndarray) -> np.ndarray:
    """Times in [t0, t1] [s] spaced so no body point moves more than `step` [m] between them.

    A point moves at most h * sup|q'| @ lever in time h; sup|q'| <= the largest |q'| sampled
    every 0.1 ms plus the acceleration bound times half that spacing.
    """
    from workbench.motion.validation import acceleration_bound

    _, _, qd, _ = traj.sample(1e-4)
    speed = (np.abs(qd).max(axis=0) + acceleration_bound(traj) * 0.5e-4) @ lever  # [m/s]
    count = int(np.ceil((t1 - t0) * speed / step)) + 1
    return np.linspace(t0, t1, max(count, 2))


@pytest.mark.slow  # over 5 s here
def test_a_planned_trajectory_is_checked_on_its_real_motion(
    monkeypatch: pytest.MonkeyPatch, tmp_path_factory: pytest.TempPathFactory
) -> None:
    """Twin: the exact check of `trajectory.at()` dense enough that no body point moves more
    than a quarter of the thinnest obstacle between twin samples; a free report never hides
    a contact. A 10 mm plate across the tool's path between two (0.2 s apart) samples that
    clear it must be found between them on the real motion (sampler + acceleration bound),
    not the chord."""
    import json
    from pathlib import Path

    from workbench.collision import CollisionPolicy, check_trajectory

    monkeypatch.setenv("WORKBENCH_CACHE", str(tmp_path_factory.mktemp("plan")))
    example = Path(__file__).resolve().parents[2] / "projects" / "mz07_cell.json"
    data = json.loads(example.read_text())
    wb = Workbench.from_dict(data)
    plan = wb.plan_motion()
    traj, rep = plan.trajectory, plan.collision_report
    lever = CollisionEngine(wb.checker, "exact").body_lever.max(axis=0)
    # The free plan: every body point within 5 mm (a quarter of the 20 mm floor, the thinnest
    # obstacle) of a twin sample over the whole motion.
    assert rep.collision_free and rep.fallback is None, rep.message
    ts = _dense_times(traj, 0.0, traj.duration, 0.005, lever)
    assert not np.any(_contacts(wb, traj.at(ts)[0])), "a free report missed a contact"

    # Coarse samples (every 20th: 0.2 s) and a thin plate across the tool's path halfway
    # between two of them, where the plate touches neither of the two.
    k_step = 20
    t_c = plan.times[::k_step]
    tcp = (wb.checker.T_world_base @ wb.robot.fk(traj.at(t_c)[0]))[:, :3, 3]
    order = np.argsort(-np.linalg.norm(np.diff(tcp, axis=0), axis=1))  # fastest first
    found = None
    trials = [(k, side) for side in (60.0, 30.0) for k in order[:20]]
    for k, side in trials:
        # halfway along the flange's path between the two samples (not in time: an interval
        # that starts or ends at rest covers little of its way in its first or last half)
        t_try = np.linspace(t_c[k], t_c[k + 1], 41)
        p_try = (wb.checker.T_world_base @ wb.robot.fk(traj.at(t_try)[0]))[:, :3, 3]
        d0 = np.linalg.norm(p_try - tcp[k], axis=1)
        d1 = np.linalg.norm(p_try - tcp[k + 1], axis=1)
        tm = float(t_try[np.argmin(np.abs(d0 - d1))])
        qm, qdm, _ = traj.at([tm])
        T = wb.checker.T_world_base @ wb.robot.fk(qm)[0]
        tip = T[:3, :3] @ np.array([0.0, 0.0, 0.1]) + T[:3, 3]  # inside the 120 mm tool box
        axis = int(np.argmax(np.abs(np.diff(tcp[k : k + 2], axis=0)[0])))
        size = [side, side, side]
        size[axis] = 10.0  # thicker than the twin's 5 mm step
        plate = {"name": "plate", "shape": "box", "size": size, "pose": {"xyz": list(tip * 1e3)}}
        trial = Workbench.from_dict(
            {**data, "cell": {"objects": [*data["cell"]["objects"], plate]}}
        )
        if np.any(_contacts(trial, traj.at(t_c[k : k + 2])[0])):
            continue  # a sample of the interval touches it
        t_in = _dense_times(traj, t_c[k], t_c[k + 1], 0.005, lever)
        if _contacts(trial, traj.at(t_in)[0]).any():  # the motion crosses it between them
            found = (int(k), trial)
            break
    assert found is not None, "no plate the motion crosses between two samples that clear it"
    k, trial = found
    # (the straight chord between the samples need not; the check must follow the real motion)
    # the check on the interval's two samples alone (the program passes the plate's place
    # again elsewhere, so other coarse samples may touch it)
    t2 = t_c[k : k + 2]
    got = check_trajectory(traj, t2, traj.at(t2)[0], trial.checker, CollisionPolicy())
    assert got.fallback is None and got.mode == "spheres"
    assert got.colliding_indices == ()
    assert not got.collision_free, "a free report missed the plate between samples"
    assert 0 in got.between_indices
    assert got.first_time is not None and t_c[k] <= got.first_time <= t_c[k + 1]
    assert got.obstacle in ("plate", None)  # the plate, or an interval left uncertified
    print(f"\ntwin: {len(ts)} + {len(t_in)} configurations; interval {k}: {got.message}")
