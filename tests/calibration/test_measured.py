"""Measured points from joint readings: the TCP by the model's FK against pinocchio's (the
independent twin), and pendant positions moved from the controller's base into the model's."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from workbench.calibration.measured import flange_poses, in_model_base, tcp_positions
from workbench.errors import InputError
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.kinematics.robot_library import library_robot, preset_robot


@pytest.mark.parametrize("name", ["mz07", "m10ia", "irb1200_7_70", "kr6_r900_2", "ur5e"])
def test_tcp_positions_match_pinocchio(name: str) -> None:
    robot = preset_robot(name)
    rng = np.random.default_rng(0)
    q = rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (5, robot.dof))
    T_ft = xyz_rpy_to_transform([0.01, -0.02, 0.15], [0.1, 0.2, 0.3])
    model, data = robot.pinocchio_model()
    twin = []
    for qi in q:
        pin.framesForwardKinematics(model, data, qi)
        M = data.oMf[model.nframes - 1]
        twin.append(M.rotation @ T_ft[:3, 3] + M.translation)
    assert np.allclose(tcp_positions(robot, q, T_ft), twin, atol=1e-9)


def test_pendant_positions_move_into_the_models_base() -> None:
    # FANUC's world frame lies on J1 at the height of J2: a pendant's z is that much lower.
    T = library_robot("m10ia").T_base_controller
    assert T[2, 3] > 0.0
    p = in_model_base([[0.5, 0.1, 0.2]], T)
    assert np.allclose(p, [[0.5, 0.1, 0.2 + T[2, 3]]])


def test_joint_readings_of_the_wrong_width_are_refused() -> None:
    with pytest.raises(InputError, match=r"give \(n, 6\) joints"):
        flange_poses(preset_robot("mz07"), np.zeros((3, 5)))
