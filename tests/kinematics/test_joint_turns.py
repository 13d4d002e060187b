"""Turn selection against brute-force enumeration of q + 2 pi k."""

from __future__ import annotations

import math

import numpy as np

from workbench.kinematics.ik_report import branch_name
from workbench.kinematics.joint_turns import all_turns, joint_turn, wrap_to_pi

TWO_PI = 2 * math.pi


def brute(q: float, lo: float, hi: float, ref: float) -> float | None:
    cands = [q + TWO_PI * k for k in range(-4, 5) if lo - 1e-10 <= q + TWO_PI * k <= hi + 1e-10]
    return min(cands, key=lambda c: abs(c - ref)) if cands else None


def test_joint_turn_matches_brute_force() -> None:
    rng = np.random.default_rng(0)
    limits = [
        (-math.pi, math.pi),
        (-2 * math.pi, 2 * math.pi),
        (math.radians(-190), math.radians(190)),
        (0.5, 5.0),
        (-0.3, 0.4),
    ]
    for lo, hi in limits:
        q = rng.uniform(-3 * math.pi, 3 * math.pi, 400)
        ref = rng.uniform(lo, hi, 400)
        got, ok = joint_turn(q, lo, hi, ref)
        for qi, ri, gi, oi in zip(q, ref, got, ok, strict=True):
            want = brute(qi, lo, hi, ri)
            assert oi == (want is not None)
            if want is not None:
                assert abs(gi - want) < 1e-12 or abs(abs(gi - ri) - abs(want - ri)) < 1e-12


def test_all_turns_enumerates_every_variant() -> None:
    limits = np.array([[-math.pi, math.pi], [-2 * math.pi, 2 * math.pi], [-0.5, 0.5]])
    rows = all_turns(np.array([1.0, 1.0, 0.2]), limits)
    assert rows.shape == (2, 3)
    np.testing.assert_allclose(sorted(rows[:, 1]), [1.0 - TWO_PI, 1.0])
    assert np.all(np.abs(wrap_to_pi(np.array([3 * math.pi + 0.1]))) <= math.pi)


def test_branch_names() -> None:
    assert branch_name(0) == "front/elbow A/no flip"
    assert branch_name(7) == "back/elbow B/flip"
