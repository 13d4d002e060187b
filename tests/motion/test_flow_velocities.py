"""Waypoint velocities of flowing trajectories (issue 14 part 5), on random gentle walks.

Twin: validate_trajectory samples every 1 ms plus every profile's critical times and
checks velocity, acceleration and jerk against the limits and each waypoint's position at
its waypoint time; the waypoint velocities themselves are checked against the limits and
against the reversal rule (a joint that turns back at a waypoint passes it at rest).
"""

from __future__ import annotations

import numpy as np

from workbench.motion.trajectory import smooth_joint_path
from workbench.motion.validation import validate_trajectory


def _walk(n, rng):
    d = rng.uniform(-1, 1, 6)
    pts = [rng.uniform(-0.5, 0.5, 6)]
    for _ in range(n - 1):
        d = d / np.linalg.norm(d) + rng.normal(0, 0.15, 6)
        pts.append(pts[-1] + d / np.linalg.norm(d) * rng.uniform(0.05, 0.6))
    return np.array(pts)


def test_random_walk_waypoint_velocities_keep_every_limit_and_pass_every_waypoint():
    rng = np.random.default_rng(14)
    flowing = 0
    for _ in range(60):
        q = _walk(int(rng.integers(2, 26)), rng)
        v, a, j = rng.uniform(0.5, 3, 6), rng.uniform(2, 20, 6), rng.uniform(20, 300, 6)
        stops = [int(i) for i in rng.choice(len(q), size=min(2, len(q)), replace=False)]
        tr = smooth_joint_path(q, v, a, j, exact_stop=stops)
        rep = validate_trajectory(
            tr,
            max_velocity=v,
            max_acceleration=a,
            max_jerk=j,
            dt=0.001,
            tol=1e-9,
            waypoint_tol=1e-7,
        )
        assert rep.ok, rep.violations[:3]
        _, vw, _ = tr.at(tr.waypoint_times)
        assert np.all(np.abs(vw) <= v * (1 + 1e-9))
        assert np.allclose(vw[[0, -1]], 0.0, atol=1e-9) and np.allclose(vw[stops], 0.0, atol=1e-9)
        d = np.diff(q, axis=0)
        turns = np.sign(d[:-1]) * np.sign(d[1:]) < 0  # joint reverses at waypoint i + 1
        assert np.allclose(vw[1:-1][turns], 0.0, atol=1e-9)
        flowing += np.any(np.abs(vw[1:-1]) > 1e-6)
    assert flowing > 40  # most walks flow through their waypoints
