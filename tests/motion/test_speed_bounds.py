"""Tests of workbench/motion/speed_bounds.py: closed-form bounds of one jerk-limited joint.

Twins: `max_speed_change` against bisection on the profile's distance (no cubic solved), and
`rest_to_rest_time` against ruckig's time-optimal single-joint trajectory.
"""

from __future__ import annotations

import numpy as np
import pytest
from ruckig import InputParameter, Result, Ruckig, Trajectory

from workbench.motion.speed_bounds import max_speed_change, rest_to_rest_time


def _distance(s0: float, D: float, a: float, j: float) -> float:
    """Distance of the zero-acceleration-ended speed change s0 -> s0 + D (point-symmetric)."""
    t = 2.0 * np.sqrt(D / j) if D <= a * a / j else D / a + a / j
    return (s0 + s0 + D) / 2.0 * t


def _bisect(s0: float, d: float, a: float, j: float) -> float:
    lo, hi = 0.0, 1.0
    while _distance(s0, hi, a, j) < d:
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _distance(s0, mid, a, j) < d else (lo, mid)
    return s0 + 0.5 * (lo + hi)


def test_max_speed_change_matches_bisection() -> None:
    rng = np.random.default_rng(8)
    for _ in range(300):
        s0, d = rng.uniform(0, 3), rng.uniform(1e-4, 3)
        a, j = rng.uniform(0.5, 10), rng.uniform(1, 100)
        got = float(max_speed_change(s0, d, a, j))
        assert got == pytest.approx(_bisect(s0, d, a, j), rel=1e-9, abs=1e-12)
    assert float(max_speed_change(1.5, 0.0, 2.0, 10.0)) == 1.5
    # batched and sign-free in d
    batch = max_speed_change([0.0, 1.0], [-0.5, 0.5], 2.0, 10.0)
    assert np.allclose(batch, [_bisect(0.0, 0.5, 2.0, 10.0), _bisect(1.0, 0.5, 2.0, 10.0)])


def _ruckig_time(d: float, v: float, a: float, j: float) -> float:
    otg = Ruckig(1)
    inp = InputParameter(1)
    inp.current_position, inp.target_position = [0.0], [d]
    inp.max_velocity, inp.max_acceleration, inp.max_jerk = [v], [a], [j]
    traj = Trajectory(1)
    assert otg.calculate(inp, traj) == Result.Working
    return float(traj.duration)


def test_rest_to_rest_time_matches_ruckig() -> None:
    rng = np.random.default_rng(9)
    cases = [(2.0, 1.0, 2.0, 10.0), (0.01, 1.0, 2.0, 10.0), (0.3, 1.0, 2.0, 10.0)]
    cases += [tuple(rng.uniform([1e-3, 0.2, 0.5, 1], [4, 4, 10, 100])) for _ in range(60)]
    for d, v, a, j in cases:
        assert float(rest_to_rest_time(d, v, a, j)) == pytest.approx(
            _ruckig_time(d, v, a, j), rel=1e-6
        ), (d, v, a, j)
    assert float(rest_to_rest_time(0.0, 1.0, 2.0, 10.0)) == 0.0
    assert float(rest_to_rest_time(-2.0, 1.0, 2.0, 10.0)) == float(
        rest_to_rest_time(2.0, 1.0, 2.0, 10.0)
    )
