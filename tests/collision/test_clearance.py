"""The plan's clearance against the margin: exact on the samples, its pair named, exemptions."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from block_cell import block_cell

from workbench.collision import CollisionPolicy, check_motion
from workbench.collision.clearance import Clearance, margin_kept, plan_clearance
from workbench.collision.engine import CollisionEngine
from workbench.errors import InputError
from workbench.service import Workbench

# Towards the block: the tool's face ends a few centimetres short of it (Q_HIT in
# test_engine.py puts it 50 mm deep).
Q0 = np.zeros(6)
Q1 = np.array([0.3, -0.55, 0.55, 0.2, 0.1, 0.0])


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.from_dict(block_cell())


@pytest.fixture(scope="module")
def spheres(wb: Workbench, engine_cache: Path) -> CollisionEngine:
    """A fast engine on the checker (capsules: built in milliseconds, items like the spheres')."""
    return CollisionEngine(wb.checker, "capsules", cache_dir=str(engine_cache))


def _brute_force(wb: Workbench, qs: np.ndarray, skip: set[frozenset[str]]) -> tuple[float, tuple]:
    """Twin: python-fcl's distance of every pair at every sample (0 where a pair collides)."""
    scene = wb.checker.scene
    best, pair = np.inf, None
    for q in qs:
        scene.place(wb.checker.world_poses(q))
        for a, b in scene.pairs:
            if frozenset((a, b)) in skip:
                continue
            d = 0.0 if scene.collides(a, b) else scene.distance(a, b)
            if d < best:
                best, pair = d, (a, b)
    return best, pair


@pytest.mark.parametrize("with_engine", [False, True])
def test_least_distance_equals_fcl_over_every_pair_and_sample(
    wb: Workbench, spheres: CollisionEngine, with_engine: bool
) -> None:
    """Twin: the brute force over every (sample, pair) gives the same distance and pair."""
    qs = np.linspace(Q0, Q1, 9)
    t = np.linspace(0.0, 0.8, 9)
    got = plan_clearance(wb.checker, t, qs, engine=spheres if with_engine else None)
    want, pair = _brute_force(wb, qs, set())
    assert got.distance == pytest.approx(want, abs=1e-9)
    assert got.pair == pair
    assert got.time == pytest.approx(t[got.index])
    assert 0.0 < got.distance < 0.3  # the tool approaches the block: a real figure


@pytest.mark.parametrize("with_engine", [False, True])
def test_margin_verdict_equals_the_least_distance_verdict(
    wb: Workbench, spheres: CollisionEngine, with_engine: bool
) -> None:
    """Twin: `margin_kept` (fcl only under the margin, first violation ends it) gives the
    verdict of `plan_clearance` (the exact least distance) for margins on either side of the
    real clearance of each motion, with and without an exempt pair."""
    eng = spheres if with_engine else None
    rng = np.random.default_rng(3)
    verdicts = set()
    for trial in range(4):
        qs = np.linspace(Q0, Q1 * rng.uniform(0.6, 1.2), 5)
        exempt = [] if trial % 2 else [list(wb.checker.scene.pairs[0])]
        least = plan_clearance(wb.checker, np.arange(5.0), qs, exempt=exempt, engine=eng)
        for margin in (
            0.0,
            least.distance * 0.5,
            least.distance * 0.999,
            least.distance * 1.001,
            0.45,
        ):
            margin = min(margin, 0.5)
            want = plan_clearance(
                wb.checker, np.arange(5.0), qs, margin=margin, exempt=exempt, engine=eng
            ).keeps_margin
            got = margin_kept(wb.checker, qs, margin=margin, exempt=exempt, engine=eng)
            assert got == want, (trial, margin, least.distance)
            verdicts.add(got)
    assert verdicts == {True, False}  # both verdicts were met


@pytest.mark.parametrize("with_engine", [False, True])
def test_a_tie_is_named_by_its_first_sample(
    wb: Workbench, spheres: CollisionEngine, with_engine: bool
) -> None:
    """The robot holds its nearest posture, to within nanometres, over three samples (a rigid
    pair at one distance over a stretch of a plan): the clearance names the first of them, not
    whichever rounding made least (a golden summary's time flipped between installs); the
    distance is still the least.
    Twin: the brute force's per-sample least distances, the first within the tie."""
    mid = (Q0 + Q1) / 2
    nearer = Q1 + 1e-7 * (Q1 - Q0)  # a hair further towards the block: nanometres nearer
    qs = np.array([Q0, mid, Q1, nearer, nearer, mid, Q0])
    t = np.arange(len(qs)) * 0.5
    got = plan_clearance(wb.checker, t, qs, engine=spheres if with_engine else None)
    per_sample = [_brute_force(wb, q[None], set())[0] for q in qs]
    assert 0.0 < per_sample[2] - per_sample[3] < 1e-7  # sample 3 is least, by less than a tie
    first = next(i for i, d in enumerate(per_sample) if d <= min(per_sample) + 1e-7)
    assert got.index == first == 2  # the tie begins at sample 2 (the old argmin said 3)
    assert got.time == t[2]
    assert got.distance == pytest.approx(min(per_sample), abs=1e-12)  # the least, not sample 2's


def test_exempt_pair_is_left_out_and_listed(wb: Workbench) -> None:
    """Twin: the brute force without the exempt pair; the description lists the exemption."""
    qs = np.linspace(Q0, Q1, 5)
    t = np.arange(5.0)
    first = plan_clearance(wb.checker, t, qs)
    assert first.pair is not None
    ex = plan_clearance(wb.checker, t, qs, exempt=[first.pair[::-1]])
    want, pair = _brute_force(wb, qs, {frozenset(first.pair)})
    assert ex.distance == pytest.approx(want, abs=1e-9) and ex.pair == pair
    assert ex.distance >= first.distance
    assert ex.exempt == (tuple(sorted(first.pair)),)
    assert f"exempt: {min(first.pair)} – {max(first.pair)}" in ex.describe()


def test_margin_problem_names_pair_distance_and_time() -> None:
    near = Clearance(0.0012, ("tool", "block"), 1.25, 3, margin=0.002)
    assert not near.keeps_margin
    assert near.problem == (
        "tool comes within 1.2 mm of block at t = 1.25 s, closer than the clearance margin 2.0 mm"
    )
    far = Clearance(0.0025, ("tool", "block"), 1.25, 3, margin=0.002)
    assert far.keeps_margin and far.problem is None


@pytest.mark.parametrize("bad", [float("nan"), -0.001, 0.6, float("inf")])
def test_bad_margin_is_refused_naming_the_field(bad: float) -> None:
    with pytest.raises(InputError, match="margin"):
        CollisionPolicy(margin=bad)


def test_check_motion_reports_the_margin(wb: Workbench, spheres: CollisionEngine) -> None:
    """A free motion closer than the margin keeps `collision_free` but not `keeps_margin`."""
    qs = np.linspace(Q0, Q1, 9)
    t = np.linspace(0.0, 0.8, 9)
    near = plan_clearance(wb.checker, t, qs)
    for margin, keeps in ((near.distance * 0.5, True), (near.distance + 0.001, False)):
        policy = CollisionPolicy(mode="exact", margin=margin, exempt=(("link1", "link5"),))
        rep = check_motion(
            t,
            qs,
            wb.checker,
            policy,
            # the motion is the straight joint segment between samples (no deviation)
            sampler=lambda tt: np.array([np.interp(tt, t, qs[:, j]) for j in range(6)]).T,
            acceleration=np.zeros(6),
        )
        assert rep.collision_free
        assert rep.keeps_margin is keeps
        assert rep.nearest is not None and rep.nearest.pair == near.pair
        if not keeps:
            assert near.pair[0] in rep.message and "closer than the clearance margin" in rep.message
