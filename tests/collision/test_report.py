"""Tests of workbench/collision/report.py: the certifier's outcome turned into a path report.

Outcomes are made by hand here (no engine), so each field of the report is checked against
what the outcome says; the random test's twin is a brute-force scan for the earliest event
(a colliding sample or a between-samples interval) in time.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.collision.path_oracle import PathOutcome
from workbench.collision.report import ConfigCheck, path_report

T = np.linspace(0.0, 1.0, 11)
Q = np.c_[T, -T]


def _outcome(sample_hits=None, events=(), clearance=0.02) -> PathOutcome:
    return PathOutcome(
        sample_hits=dict(sample_hits or {}),
        flagged=3,
        events=list(events),
        clearance=clearance,
        evaluated=40,
        exact_pairs=7,
    )


def _report(out: PathOutcome, depth: float = 0.004):
    seen = []

    def penetration(q, a, b):
        seen.append((q, a, b))
        return depth

    return path_report(out, Q, T, mode="spheres", pairs_checked=12, penetration=penetration), seen


def test_collision_free_reports_the_clearance() -> None:
    rep, seen = _report(_outcome(clearance=0.0123))
    assert rep.collision_free and rep.certified and seen == []
    assert rep.clearance == rep.min_distance == 0.0123
    assert (rep.samples, rep.evaluated, rep.flagged_samples, rep.exact_pairs) == (11, 40, 3, 7)
    assert rep.first_index is None and rep.first_time is None and rep.link is None
    assert rep.message == (
        "collision-free, including between samples, with clearance of at least 12.3 mm"
        " (11 samples, 40 configurations checked, spheres)"
    )


@pytest.mark.parametrize(
    ("given", "want"), [(-0.001, 0.0), (math.inf, math.inf), (math.nan, math.inf)]
)
def test_collision_free_clearance_is_clipped_or_unbounded(given, want) -> None:
    rep, _ = _report(_outcome(clearance=given))
    assert rep.clearance == want


def test_colliding_sample() -> None:
    rep, seen = _report(_outcome({4: (("link3", "table"),), 7: (("tool", "wall"),)}))
    assert not rep.collision_free
    assert rep.colliding_indices == (4, 7)
    assert rep.first_index == 4 and rep.first_time == pytest.approx(0.4) and not rep.between
    assert (rep.link, rep.obstacle, rep.penetration) == ("link3", "table", 0.004)
    assert np.array_equal(seen[0][0], Q[4]) and seen[0][1:] == ("link3", "table")
    assert rep.first_report is not None and rep.first_report.pairs_checked == 12
    assert rep.first_report.closest_pair == ("link3", "table")
    assert rep.message == (
        "collision at t = 0.400 s (sample 4): link3 hits table, penetration 4.0 mm"
    )


def test_collision_between_samples_comes_first() -> None:
    qm = np.array([0.25, -0.25])
    events = [(0.25, 2, qm, (("link2", "column"),))]
    rep, seen = _report(_outcome({4: (("link3", "table"),)}, events))
    assert rep.between and rep.first_index == 2 and rep.first_time == 0.25
    assert rep.first_q is qm and rep.link == "link2" and rep.between_indices == (2,)
    assert rep.uncertified_indices == ()
    assert "(between samples 2 and 3): link2 hits column" in rep.message


def test_uncertified_interval_is_treated_as_touching() -> None:
    events = [(0.55, 5, np.array([0.55, -0.55]), ())]
    rep, seen = _report(_outcome(events=events))
    assert not rep.collision_free and not rep.certified and seen == []
    assert rep.link is None and rep.uncertified_indices == (5,) and rep.first_index == 5
    assert rep.message == (
        "not certified between samples 5 and 6 near t = 0.550 s (no colliding configuration"
        " found; 1 interval(s) whose clearance is below what the finest subdivision resolves):"
        " treat it as touching"
    )


def test_fallback_messages() -> None:
    rep, _ = _report(_outcome())
    free = type(rep)(**{**rep.__dict__, "fallback": "robot outside the field"})
    assert free.message == (
        "collision-free at every sample (11 samples, exact check; not certified between"
        " samples: robot outside the field)"
    )
    hit, _ = _report(_outcome({2: (("a", "b"),)}))
    hit = type(hit)(**{**hit.__dict__, "fallback": "no field"})
    assert (
        hit.message
        == "collision at t = 0.200 s (sample 2): a hits b (exact check of every sample; no field)"
    )


def test_first_event_matches_brute_force() -> None:
    rng = np.random.default_rng(4)
    for _ in range(200):
        hits = {
            int(i): (("l", f"o{i}"),) for i in rng.choice(11, rng.integers(0, 3), replace=False)
        }
        events = []
        for i in sorted(rng.choice(10, rng.integers(0, 3), replace=False)):
            tm = float(T[i] + rng.uniform(0.001, 0.099))
            pairs = (("l", f"e{i}"),) if rng.random() < 0.6 else ()
            events.append((tm, int(i), np.array([tm, -tm]), pairs))
        rep, _ = _report(_outcome(hits, events))
        # brute force: every candidate with its time; the certifier lists events in time order,
        # and the report takes the earliest of the first sample hit and the first event
        cands = [(float(T[i]), "s", i) for i in hits] + [(e[0], "e", e[1]) for e in events]
        if not cands:
            assert rep.collision_free
            continue
        first_sample = min((c for c in cands if c[1] == "s"), default=None)
        first_event = next((c for c in cands if c[1] == "e"), None)
        tm, kind, idx = min(c for c in (first_sample, first_event) if c is not None)
        assert not rep.collision_free
        assert rep.first_time == pytest.approx(tm) and rep.first_index == idx
        assert rep.between == (kind == "e")
        pairs = hits[idx] if kind == "s" else next(e[3] for e in events if e[1] == idx)
        assert rep.certified == bool(pairs)
        assert rep.obstacle == (pairs[0][1] if pairs else None)
        assert rep.colliding_indices == tuple(sorted(hits))
        assert rep.between_indices == tuple(e[1] for e in events)


def test_config_check_defaults() -> None:
    c = ConfigCheck(colliding=False, flagged=True, clearance=0.01)
    assert (c.link, c.obstacle, c.penetration, c.exact) == (None, None, 0.0, None)
