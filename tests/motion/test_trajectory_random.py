"""1000 random waypoint sets (two seeds of 500): every sample within limits, waypoints passed."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.motion.trajectory import smooth_joint_path
from workbench.motion.validation import validate_trajectory

N_SETS = 500


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
@pytest.mark.parametrize("seed", [0, 1])
def test_random_waypoint_sets_stay_within_limits(seed):
    rng = np.random.default_rng(seed)
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
