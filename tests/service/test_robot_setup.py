"""The stored joints are refused by the limit they break, in the controller's values."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.errors import ProjectError
from workbench.kinematics.robot_library import library_robot

ROOT = Path(__file__).resolve().parents[2]


def _open(joints: list[float]) -> Workbench:
    data = json.loads((ROOT / "projects" / "mz07_cell.json").read_text())
    data.pop("program", None)
    data["robot"] = {"preset": "m10ia", "joints": joints}
    return Workbench.from_dict(data, base_dir=ROOT / "projects")


def test_a_fanuc_j3_inside_its_own_range_names_the_coupled_j2_j3_limit() -> None:
    """The report's case: J3 = 264 lies inside the printed [-180, 264]; what it breaks is the
    coupled rule (J3 counted from the horizontal), checked here against the model's box."""
    with pytest.raises(ProjectError) as caught:
        _open([0, -45, 264, 0, 0, 0])
    msg = str(caught.value)
    assert msg.startswith("robot.joints[2]: J3 = 264.000 deg breaks the coupled limit")
    assert "J3 + J2 = 219.000 deg must lie within [-180.000, 180.000] deg" in msg
    robot = library_robot("m10ia").dh_robot()
    q_model = robot.convention.to_model(np.radians([0, -45, 264, 0, 0, 0]))
    assert not robot.limits[2, 0] <= q_model[2] <= robot.limits[2, 1]  # the box it breaks
    _open([0, -45, 100, 0, 0, 0])  # J3 + J2 = 55: inside


def test_a_fanuc_joint_outside_its_own_range_names_that_range() -> None:
    with pytest.raises(
        ProjectError,
        match=r"joints\[2\]: 270.000 deg is outside the joint limits \[-180.000, 264.000\]",
    ):
        _open([0, 0, 270, 0, 0, 0])
    with pytest.raises(
        ProjectError,
        match=r"joints\[1\]: 170.000 deg is outside the joint limits \[-90.000, 160.000\]",
    ):
        _open([0, 170, 0, 0, 0, 0])
