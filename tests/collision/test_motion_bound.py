"""Tests of workbench/collision/motion_bound.py: joint levers bound how far link points move.

Twin: forward kinematics of random points fixed on each link along random joint steps, the
travel summed over fine steps (moved here from test_engine.py, and run on an offset-wrist UR
as well as the MZ07).
"""

from __future__ import annotations

import numpy as np
import pytest

from workbench.collision.motion_bound import JointLevers
from workbench.kinematics.robot_library import preset_robot


@pytest.mark.parametrize("name", ["mz07", "ur5e"])
def test_levers_bound_the_motion_of_link_points(name: str) -> None:
    """Twin: forward kinematics of random points for random joint steps."""
    robot = preset_robot(name)
    lev = JointLevers(robot)
    rng = np.random.default_rng(0)
    lim = robot.limits
    for frame in range(1, 7):
        pts = rng.normal(0, 0.2, (20, 3))
        L = lev.levers(frame, pts)
        assert np.all(L[frame:] == 0)
        for _ in range(40):
            q = rng.uniform(lim[:, 0], lim[:, 1])
            dq = rng.normal(0, 0.05, 6)
            # Travel along the straight joint segment, by fine steps.
            qs = np.linspace(q, q + dq, 30)
            T = robot.link_transforms(qs)[:, frame]
            p = np.einsum("nij,pj->npi", T[:, :3, :3], pts) + T[:, None, :3, 3]
            travel = np.linalg.norm(np.diff(p, axis=0), axis=2).sum(axis=0)
            assert np.all(travel <= np.abs(dq) @ L + 1e-12)


def test_levers_are_not_loose() -> None:
    """The bound is a distance to a point on the axis: for a point on joint j's axis in the
    frame of j, the lever of joint j is zero; points far out get levers of their distance."""
    robot = preset_robot("mz07")
    lev = JointLevers(robot)
    for frame in range(1, 7):
        on_axis = lev.in_own[frame][None]
        assert lev.levers(frame, on_axis)[frame - 1] == pytest.approx(0.0, abs=1e-9)
        far = on_axis + [[2.0, 0.0, 0.0]]
        assert lev.levers(frame, far)[frame - 1] == pytest.approx(2.0)
    assert np.all(lev.levers(0, np.ones((3, 3))) == 0)
