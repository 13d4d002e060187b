"""Random waypoint sets: every sample within limits, every waypoint passed; the checker itself."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.motion.trajectory import smooth_joint_path
from workbench.motion.validation import critical_times, validate_samples, validate_trajectory

# 1000 random sets in all: 500 here (seed 0), 500 in test_trajectory_random.py (seed 1),
# split so that each file stays under ~15 s.
N_SETS = 500
SEED = 0


def _random_problem(rng):
    dof = 6
    n = int(rng.integers(2, 51))
    lim = np.stack([-rng.uniform(1.0, 3.0, dof), rng.uniform(1.0, 3.0, dof)], axis=1)
    if rng.random() < 0.5:  # wandering path with gentle turns
        steps = rng.normal(0, 1, (n - 1, dof)).cumsum(axis=0) * 0.05 + rng.normal(0, 0.2, dof)
        q = np.clip(
            np.concatenate([np.zeros((1, dof)), steps.cumsum(axis=0)]), lim[:, 0], lim[:, 1]
        )
    else:  # anywhere within the limits: many reversals
        q = rng.uniform(lim[:, 0], lim[:, 1], (n, dof))
    v, a, j = rng.uniform(0.3, 3, dof), rng.uniform(1, 20, dof), rng.uniform(5, 500, dof)
    return q, v, a, j, lim


@pytest.mark.slow
def test_random_waypoint_sets_stay_within_limits():
    rng = np.random.default_rng(SEED)
    worst = {
        "position": -np.inf,
        "velocity": 0.0,
        "acceleration": 0.0,
        "jerk": 0.0,
        "waypoint": 0.0,
    }
    n_flowing = 0
    for _ in range(N_SETS):
        q, v, a, j, lim = _random_problem(rng)
        tr = smooth_joint_path(q, v, a, j, position_limits=lim)
        rep = validate_trajectory(
            tr,
            max_velocity=v,
            max_acceleration=a,
            max_jerk=j,
            position_limits=lim,
            dt=0.05,
            tol=1e-9,
            waypoint_tol=1e-6,
        )
        assert rep.ok, rep.violations[:3]
        for k in worst:
            worst[k] = max(worst[k], rep.worst[k])
        n_flowing += len(tr.stop_indices) < q.shape[0]
    assert worst["velocity"] <= 1 + 1e-9 and worst["acceleration"] <= 1 + 1e-9
    assert worst["jerk"] <= 1 + 1e-9 and worst["waypoint"] <= 1e-6 and worst["position"] <= 1e-9
    assert n_flowing > N_SETS // 4  # most sets flow through some waypoint


def test_validate_samples_flags_scaled_motion():
    rng = np.random.default_rng(1)
    q = np.cumsum(rng.uniform(-0.4, 0.4, (6, 6)), axis=0)
    v, a, j = np.full(6, 1.0), np.full(6, 4.0), np.full(6, 40.0)
    tr = smooth_joint_path(q, v, a, j)
    t, p, vel, acc = tr.sample(0.002)
    ok = validate_samples(t, p, vel, acc, max_velocity=v, max_acceleration=a, max_jerk=j)
    assert ok.ok and ok.worst["jerk"] <= 1 + 1e-9
    # The same path played s times faster scales velocity by s, acceleration s^2, jerk s^3:
    # pick s so that all three exceed their limits.
    w = ok.worst
    s = 1.05 / min(w["velocity"], np.sqrt(w["acceleration"]), np.cbrt(w["jerk"]))
    fast = validate_samples(
        t / s, p, vel * s, acc * s * s, max_velocity=v, max_acceleration=a, max_jerk=j
    )
    kinds = {x.kind for x in fast.violations}
    assert kinds == {"velocity", "acceleration", "jerk"}
    assert fast.worst["velocity"] == pytest.approx(ok.worst["velocity"] * s, rel=1e-9)
    assert fast.worst["acceleration"] == pytest.approx(ok.worst["acceleration"] * s * s, rel=1e-9)
    lim = np.array([[-10, 10]] * 6, float)
    lim[2] = [p[:, 2].min() + 0.01, 10]
    pos = validate_samples(
        t, p, vel, acc, max_velocity=v, max_acceleration=a, max_jerk=j, position_limits=lim
    )
    assert {x.kind for x in pos.violations} == {"position"}
    assert all(x.joint == 3 for x in pos.violations)


def test_critical_times_find_velocity_peaks_that_a_grid_misses():
    q = np.array([[0.0] * 6, [0.05] * 6, [3.0] * 6])
    v, a, j = np.full(6, 2.0), np.full(6, 5.0), np.full(6, 10.0)
    tr = smooth_joint_path(q, v, a, j)
    crit = critical_times(tr)
    dense = np.linspace(0, tr.duration, 200_001)
    _, vd, _ = tr.at(dense)
    _, vc, _ = tr.at(crit)
    # The exact peak is at a critical time and is at least the densest grid's peak.
    assert np.abs(vc).max() >= np.abs(vd).max() - 1e-15
    assert np.abs(vc).max() == pytest.approx(np.abs(vd).max(), abs=1e-9)
