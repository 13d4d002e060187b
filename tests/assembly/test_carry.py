"""`carry_ik`: the carrying robot's joints along a TCP path, one configuration, against FK and per-pose IK."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.assembly.carry import MAX_JOINT_STEP, carry_ik
from workbench.errors import UnreachableError
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.kinematics.robot_library import preset_robot

ROBOT = preset_robot("mz07")
BASE = xyz_rpy_to_transform([0.1, -0.2, 0.3], [0, 0, np.radians(30)])
TOOL = xyz_rpy_to_transform([0, 0, 0.15], [0, 0, 0])


def _line(p0, p1, n=60):  # type: ignore[no-untyped-def]
    """TCP poses pointing down (z = -world z) on a straight line, turning 90 deg about z."""
    return np.stack(
        [
            BASE @ xyz_rpy_to_transform(p0 + u * (p1 - p0), [np.pi, 0, u * np.pi / 2])
            for u in np.linspace(0, 1, n)
        ]
    )


def test_joints_follow_the_path_in_one_configuration():
    T = _line(np.array([0.45, -0.2, 0.2]), np.array([0.45, 0.25, 0.35]))
    q_home = np.array([0, 0, 0, 0, -np.pi / 2, 0])
    r = carry_ik(ROBOT, BASE, TOOL, T, q_home)
    # Twin: the robot's FK reproduces every TCP pose.
    np.testing.assert_allclose(BASE @ ROBOT.fk(r.q) @ TOOL, T, atol=1e-9)
    assert np.all(r.q >= ROBOT.limits[:, 0] - 1e-9) and np.all(r.q <= ROBOT.limits[:, 1] + 1e-9)
    assert r.max_step <= MAX_JOINT_STEP
    assert r.max_step == pytest.approx(np.abs(np.diff(r.q, axis=0)).max())
    # Twin: at every pose the chosen row is one of the robot's own IK solutions (up to turns).
    for Ti, qi in zip(T, r.q, strict=True):
        sols = ROBOT.ik(np.linalg.inv(BASE) @ Ti @ np.linalg.inv(TOOL), q_near=qi)
        d = np.angle(np.exp(1j * (sols - qi)))
        assert np.min(np.abs(d).max(axis=1)) < 1e-6
    # One arm configuration all along: the branch is valid at every pose.
    qb, valid = ROBOT.ik_batch(np.linalg.inv(BASE) @ T @ np.linalg.inv(TOOL), q_near=q_home)
    assert valid[:, r.branch].all()


def test_a_path_leaving_the_workspace_names_the_first_unreachable_pose():
    T = _line(np.array([0.45, 0.0, 0.3]), np.array([1.6, 0.0, 0.3]), n=50)
    with pytest.raises(UnreachableError, match=r"pose (\d+) of 50") as info:
        carry_ik(ROBOT, BASE, TOOL, T, np.zeros(6), what="test path")
    named = int(str(info.value).split("pose ")[1].split(" of")[0]) - 1
    # Twin: the first pose with no IK solution at all, by the robot's own per-pose IK.
    first = None
    for i, Ti in enumerate(T):
        try:
            ROBOT.ik(np.linalg.inv(BASE) @ Ti @ np.linalg.inv(TOOL))
        except UnreachableError:
            first = i
            break
    assert first is not None and named == first
    assert "test path" in str(info.value) and "mm" in str(info.value)
