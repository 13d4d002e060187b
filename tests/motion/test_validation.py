"""Random waypoint sets: every sample within limits, every waypoint passed; the checker itself."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.motion.trajectory import smooth_joint_path
from workbench.motion.validation import critical_times, validate_samples


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
