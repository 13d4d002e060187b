"""Numeric IK (pinocchio CLIK) for DH robots outside the OPW family."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.errors import InputError, UnreachableError
from workbench.kinematics import DHRobot

# A UR5-like arm: offset wrist (a != 0 after joint 3, d4, d5, d6), not OPW.
UR5_DH = np.array(
    [
        [0.0, 0.089159, 0.0, math.pi / 2],
        [0.0, 0.0, -0.425, 0.0],
        [0.0, 0.0, -0.39225, 0.0],
        [0.0, 0.10915, 0.0, math.pi / 2],
        [0.0, 0.09465, 0.0, -math.pi / 2],
        [0.0, 0.0823, 0.0, 0.0],
    ]
)


@pytest.fixture(scope="module")
def ur5() -> DHRobot:
    return DHRobot(UR5_DH, np.tile([-2 * math.pi, 2 * math.pi], (6, 1)), name="ur5-like")


def test_non_opw_robot_uses_numeric_ik(ur5: DHRobot) -> None:
    assert not ur5.is_analytic
    rng = np.random.default_rng(0)
    for q in rng.uniform(-math.pi, math.pi, (4, 6)):
        T = ur5.fk(q)
        sols = ur5.ik(T, q_near=q + 0.05)
        assert len(sols) >= 1
        np.testing.assert_allclose(ur5.fk(sols), np.broadcast_to(T, (len(sols), 4, 4)), atol=1e-8)
        assert np.all(sols >= ur5.limits[:, 0]) and np.all(sols <= ur5.limits[:, 1])
        # Seeded near the original, the nearest solution is the original.
        np.testing.assert_allclose(sols[0], q, atol=1e-6)


def test_numeric_unreachable_and_batch_refused(ur5: DHRobot) -> None:
    T = np.eye(4)
    T[:3, 3] = [3.0, 0.0, 0.0]
    with pytest.raises(UnreachableError, match="numeric IK"):
        ur5.ik(T)
    with pytest.raises(InputError, match="OPW"):
        ur5.ik_batch(T[None])
