"""Singularity detection on constructed singular poses of the MZ07."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.kinematics import DHRobot
from workbench.kinematics.robot_library import preset_robot


@pytest.fixture(scope="module")
def robot() -> DHRobot:
    return preset_robot("mz07")


def test_regular_pose_has_none(robot: DHRobot) -> None:
    s = robot.singularities(np.radians([0.0, -10.0, 20.0, 0.0, 30.0, 0.0]))
    assert s.kinds == () and not s.any
    assert s.manipulability > 1e-3


def test_wrist_singular_when_joint5_aligns_joints_4_and_6(robot: DHRobot) -> None:
    # theta5 = q5 + 90 deg = 0 puts the joint-6 axis on the joint-4 axis.
    s = robot.singularities(np.radians([10.0, -20.0, 30.0, 40.0, -90.0, 0.0]))
    assert s.wrist and not s.elbow and not s.shoulder
    assert s.wrist_angle == pytest.approx(0.0, abs=1e-12)
    assert s.manipulability == pytest.approx(0.0, abs=1e-12)
    near = robot.singularities(np.radians([10.0, -20.0, 30.0, 40.0, -87.0, 0.0]))
    assert near.wrist and near.wrist_angle == pytest.approx(math.radians(3.0), abs=1e-12)
    away = robot.singularities(np.radians([10.0, -20.0, 30.0, 40.0, -80.0, 0.0]))
    assert not away.wrist


def test_elbow_singular_when_arm_is_stretched(robot: DHRobot) -> None:
    q = np.radians([0.0, -30.0, 0.0, 0.0, 30.0, 0.0])
    q[2] = math.atan2(0.340, 0.045)  # forearm in line with the upper arm
    s = robot.singularities(q)
    assert s.elbow and s.elbow_angle == pytest.approx(0.0, abs=1e-9)
    assert s.manipulability == pytest.approx(0.0, abs=1e-12)
    q[2] += math.radians(10.0)
    assert not robot.singularities(q).elbow


def test_shoulder_singular_when_wrist_centre_is_on_joint1_axis(robot: DHRobot) -> None:
    # Flange pointing along +x, wrist centre on the joint-1 axis at 0.8 m (q5 = 0).
    T = np.array(
        [[0.0, 0.0, 1.0, 0.078], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.8], [0, 0, 0, 1.0]]
    )
    q = robot.ik(T)[0]
    s = robot.singularities(q)
    assert s.shoulder and s.shoulder_distance == pytest.approx(0.0, abs=1e-9)
    assert s.manipulability == pytest.approx(0.0, abs=1e-9)
    T[0, 3] = 0.2
    assert not robot.singularities(robot.ik(T)[0]).shoulder


def test_manipulability_equals_product_of_singular_values(robot: DHRobot) -> None:
    rng = np.random.default_rng(0)
    for q in rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (20, 6)):
        sv = np.linalg.svd(robot.jacobian(q), compute_uv=False)
        assert robot.singularities(q).manipulability == pytest.approx(
            np.prod(sv), rel=1e-9, abs=1e-15
        )


def test_bad_margins(robot: DHRobot) -> None:
    with pytest.raises(InputError, match="margin"):
        robot.singularities(np.zeros(6), margin=-1.0)
    with pytest.raises(InputError, match="q"):
        robot.singularities(np.zeros((2, 6)))
