"""Long programs: certification between samples has no global budget and its cost per sample
does not grow with the length; a touching interval is still reported, and one that cannot be
certified at the finest subdivision is named as such (issue 14 part 2).

Twins: the dense exact check (python-fcl meshes plus containment) at the samples, and at
samples of the real motion dense enough that no body point moves more than 5 mm between them.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from block_cell import block_cell

from workbench.collision import CollisionPolicy, check_trajectory
from workbench.collision.engine import CollisionEngine
from workbench.collision.path_check import MAX_DEPTH
from workbench.motion.trajectory import Trajectory
from workbench.service import Workbench

EXAMPLE = Path(__file__).resolve().parents[2] / "projects" / "mz07_cell.json"
# The block cell of test_path_check.py (a 300 mm block and a post).
PROJECT = block_cell(
    {"name": "post", "shape": "cylinder", "radius": 60, "height": 900,
     "pose": {"xyz": [0, -550, 450]}}
)  # fmt: skip


def _dense_times(traj: Trajectory, step: float, lever: np.ndarray) -> np.ndarray:
    """Times over the whole motion [s] spaced so no body point moves more than `step` [m].

    A point moves at most h * sup|q'| @ lever in time h; sup|q'| <= the largest |q'| sampled
    every 1 ms plus the acceleration bound times half that spacing.
    """
    from workbench.motion.validation import acceleration_bound

    _, _, qd, _ = traj.sample(1e-3)
    speed = (np.abs(qd).max(axis=0) + acceleration_bound(traj) * 0.5e-3) @ lever  # [m/s]
    return np.linspace(0.0, traj.duration, max(int(np.ceil(traj.duration * speed / step)) + 1, 2))


def there_and_back(traj: Trajectory, copies: int) -> Trajectory:
    """Return `traj` run `copies` times, every other copy backwards in time (rest to rest).

    (benchmarks/plan_checks.py has the same construction; here it is checked below.)
    """
    T = traj.duration
    st, p, v, a, j = traj.piece_start, traj.piece_p, traj.piece_v, traj.piece_a, traj.piece_j
    end = np.concatenate([st[:, 1:], np.full((st.shape[0], 1), T)], axis=1)
    L = end - st
    pe = p + L * (v + L * (a / 2 + L * j / 6))
    ve, ae = v + L * (a + L * j / 2), a + L * j
    back = ((T - end)[:, ::-1], pe[:, ::-1], -ve[:, ::-1], ae[:, ::-1], -j[:, ::-1])
    parts = [
        (st + k * T, p, v, a, j) if k % 2 == 0 else (back[0] + k * T, *back[1:])
        for k in range(copies)
    ]
    cols = [np.concatenate([c[i] for c in parts], axis=1) for i in range(5)]
    return Trajectory(
        copies * T, np.zeros(0), traj.waypoints, (), np.zeros(0), dt=traj.dt,
        piece_start=cols[0], piece_p=cols[1], piece_v=cols[2], piece_a=cols[3], piece_j=cols[4],
    )  # fmt: skip


@pytest.fixture(scope="module")
def example(engine_cache: Path) -> tuple[Workbench, Trajectory, CollisionPolicy]:
    wb = Workbench.from_dict(json.loads(EXAMPLE.read_text()))
    policy = CollisionPolicy(cache_dir=engine_cache)
    traj = wb.plan_motion().trajectory
    return wb, traj, policy


def test_there_and_back_is_the_program_forwards_and_backwards(
    example: tuple[Workbench, Trajectory, CollisionPolicy],
) -> None:
    _, traj, _ = example
    long = there_and_back(traj, 4)
    T = traj.duration
    t = np.linspace(0.0, T, 301)
    for k in range(4):
        want = traj.at(t if k % 2 == 0 else T - t)
        got = long.at(k * T + t)
        sign = 1.0 if k % 2 == 0 else -1.0
        np.testing.assert_allclose(got[0], want[0], atol=1e-9)
        np.testing.assert_allclose(got[1], sign * want[1], atol=1e-9)
        np.testing.assert_allclose(got[2], want[2], atol=1e-7)


def _certified_free(example: tuple[Workbench, Trajectory, CollisionPolicy], copies: int):  # type: ignore[no-untyped-def]
    wb, traj, policy = example
    long = there_and_back(traj, copies)
    times, q, _, _ = long.sample(0.01)
    rep = check_trajectory(long, times, q, wb.checker, policy)
    assert rep.fallback is None and rep.mode == "spheres"
    assert rep.collision_free, rep.message
    assert rep.certified and rep.colliding_indices == () and rep.between_indices == ()
    assert rep.uncertified_indices == ()
    assert "collision-free, including between samples" in rep.message
    return rep, q


def test_eight_times_the_program_is_certified_free_at_a_constant_cost_per_sample(
    example: tuple[Workbench, Trajectory, CollisionPolicy],
) -> None:
    """8x the MZ07 program (~4,100 samples at 0.01 s; the old budget of 5,000 configurations made
    it 'not certified ... treat it as touching'): certified free, nothing left uncertified,
    the configurations checked per sample and the clearance the same as for 1x (each interval
    is settled on its own). Twin: the exact check of every sample of 1x (the 8x motion
    passes through the same configurations; the slow test below checks every 16x sample)."""
    wb = example[0]
    one, q1 = _certified_free(example, 1)
    eight, _ = _certified_free(example, 8)
    assert eight.evaluated / eight.samples == pytest.approx(one.evaluated / one.samples, rel=0.02)
    assert eight.clearance == pytest.approx(one.clearance, abs=1e-4)
    assert wb.checker.check_path(q1).colliding_indices == ()


@pytest.mark.slow  # the dense exact checks (~17,000 configurations): ~25 s here
def test_sixteen_times_the_program_is_certified_free_and_the_twin_finds_no_contact(
    example: tuple[Workbench, Trajectory, CollisionPolicy],
) -> None:
    """16x (16 times the program, ~8,000 samples at 0.01 s): certified free. Twins: the exact check of every 16x sample,
    and of the program's motion dense enough that no body point moves more than 5 mm (a
    quarter of the thinnest obstacle, the 20 mm floor) between twin samples."""
    wb, traj, _ = example
    rep, q = _certified_free(example, 16)
    assert rep.samples == len(q) >= 16 * traj.duration / 0.01  # every sample of the 16 copies
    assert wb.checker.check_path(q).colliding_indices == ()
    lever = CollisionEngine(wb.checker, "exact").body_lever.max(axis=0)
    ts = _dense_times(traj, 0.005, lever)
    assert not any(wb.checker.check(x, distance=False).in_collision for x in traj.at(ts)[0])


@pytest.fixture(scope="module")
def post_cell(engine_cache: Path) -> tuple[Workbench, CollisionEngine]:
    wb = Workbench.from_dict(PROJECT)
    eng = CollisionEngine(
        wb.checker, "spheres", spheres_per_link=4, resolution=32, cache_dir=str(engine_cache)
    )
    return wb, eng


def _long_walk(copies: int) -> np.ndarray:
    """A free joint walk beside the post, run there and back `copies` times (chord motion)."""
    walk = np.linspace([-0.7, -0.68, 0.595, 0, -0.085, 0], [-1.2, -0.3, 0.3, 0.3, 0.2, 0.1], 40)
    return np.concatenate([walk if k % 2 == 0 else walk[::-1] for k in range(copies)])


def test_a_touching_interval_in_a_long_program_is_still_reported(
    post_cell: tuple[Workbench, CollisionEngine],
) -> None:
    """160 copies of a free walk (6,400 samples, beyond the old budget) with one interval that
    sweeps joint 1 through the block: that interval, and only it, is reported as a collision
    between samples, with the pair fcl confirms. Twin: the exact check of every distinct
    sample (all are free) and of the reported configuration (colliding)."""
    wb, eng = post_cell
    qs = _long_walk(160)
    sweep = np.array([[-0.7, -0.68, 0.595, 0, -0.085, 0], [0.7, -0.68, 0.595, 0, -0.085, 0]])
    k = 40 * 75 + 39  # the end of a backward copy: the walk's start, the sweep's near end
    assert np.allclose(qs[k], sweep[0])
    qs = np.concatenate([qs[: k + 1], sweep[1:], sweep[:1], qs[k + 1 :]])
    distinct = np.unique(qs, axis=0)
    assert not any(wb.checker.check(x, distance=False).in_collision for x in distinct)
    rep = eng.check_path(qs)
    assert rep.colliding_indices == ()
    assert not rep.collision_free and rep.between and rep.link is not None
    assert set(rep.between_indices) <= {k, k + 1} and rep.first_index in (k, k + 1)
    assert rep.uncertified_indices == ()
    assert wb.checker.check(rep.first_q, distance=False).in_collision
    assert f"between samples {rep.first_index} and {rep.first_index + 1}" in rep.message
    free = eng.check_path(_long_walk(160))
    assert free.collision_free and free.uncertified_indices == (), free.message


def test_an_interval_not_certified_at_the_finest_subdivision_is_named(
    post_cell: tuple[Workbench, CollisionEngine],
) -> None:
    """With the finest subdivision set to 0 halvings, intervals the chord bound cannot settle
    are reported as not certified (named, no pair), not as collisions; with MAX_DEPTH the
    same path is certified free."""
    _, eng = post_cell
    qs = _long_walk(1)[::13]  # 4 samples of the free walk, 0.17 rad apart on joint 1
    coarse = eng.check_path(qs, max_depth=0)
    assert coarse.colliding_indices == () and not coarse.collision_free
    assert coarse.link is None and not coarse.certified
    assert coarse.uncertified_indices and set(coarse.uncertified_indices) <= {0, 1, 2}
    i = coarse.uncertified_indices[0]
    assert f"not certified between samples {i} and {i + 1}" in coarse.message
    assert "finest subdivision" in coarse.message
    fine = eng.check_path(qs, max_depth=MAX_DEPTH)
    assert fine.collision_free and fine.uncertified_indices == (), fine.message
