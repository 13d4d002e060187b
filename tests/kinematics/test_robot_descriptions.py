"""Every library robot's FK against its published description (data this project did not make).

tests/data/robot_descriptions/ holds one plain URDF per robot, the kinematic chain of the
vendor's or ROS-Industrial's description (repository, path and commit in each file's header;
the MZ07's is the chain fitted to a real MZ07F's teach-pendant readings). Each is built with
pinocchio, independently of the library's DH rows, and its flange pose in the controller's
base frame is compared with the library robot's FK at 50 random controller joints within
limits: within 0.1 mm and 0.01 deg.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from workbench.kinematics.robot_library import ROBOT_NAMES, library_robot

DATA = Path(__file__).resolve().parents[1] / "data" / "robot_descriptions"
DEG = np.pi / 180.0


def _fanuc_j23(q: np.ndarray) -> np.ndarray:
    """ROS-Industrial's joint_3 is the FANUC controller's J3 + J2 (the driver's J23 correction)."""
    q = q.copy()
    q[..., 2] += q[..., 1]
    return q


# preset -> (file, base frame = the controller's base, flange frame, controller -> URDF joints)
DESCRIPTIONS = {
    "irb1200_7_70": ("irb1200_7_70.urdf", "base", "tool0", None),
    "kr6_r900_2": ("kr6r900_2.urdf", "base", "tool0", None),
    "m10ia": ("m10ia.urdf", "base", "tool0", _fanuc_j23),
    "ur5e": ("ur5e.urdf", "base", "tool0", None),
    "mz07": ("nachi_mz07f.urdf", "base_link", "flange", None),
}


def description_flange(name: str, q_ctrl: np.ndarray) -> np.ndarray:
    """Return the description's flange in its controller base frame (n, 4, 4) [m]."""
    file, base, flange, to_urdf = DESCRIPTIONS[name]
    model = pin.buildModelFromUrdf(str(DATA / file))
    data = model.createData()
    q_urdf = to_urdf(q_ctrl) if to_urdf else q_ctrl
    out = []
    for q in q_urdf:
        pin.framesForwardKinematics(model, data, q)
        T_base = data.oMf[model.getFrameId(base)].homogeneous
        T_flange = data.oMf[model.getFrameId(flange)].homogeneous
        out.append(np.linalg.inv(T_base) @ T_flange)
    return np.array(out)


def library_flange(name: str, q_ctrl: np.ndarray) -> np.ndarray:
    """Return the library robot's flange in the controller's base frame (n, 4, 4) [m]."""
    lib = library_robot(name)
    robot = lib.dh_robot()
    return np.linalg.inv(lib.T_base_controller) @ robot.fk(robot.convention.to_model(q_ctrl))


def random_controller_joints(name: str, n: int, seed: int) -> np.ndarray:
    lim = library_robot(name).controller_limits_deg * DEG
    return np.random.default_rng(seed).uniform(lim[:, 0], lim[:, 1], (n, 6))


def pose_errors(Ta: np.ndarray, Tb: np.ndarray) -> tuple[float, float]:
    """Return the largest position [mm] and rotation [deg] differences of two pose stacks."""
    dp = np.linalg.norm(Ta[:, :3, 3] - Tb[:, :3, 3], axis=1).max() * 1000.0
    R = np.einsum("nji,njk->nik", Ta[:, :3, :3], Tb[:, :3, :3])
    cos = np.clip((np.trace(R, axis1=1, axis2=2) - 1.0) / 2.0, -1.0, 1.0)
    return float(dp), float(np.degrees(np.arccos(cos)).max())


def test_every_library_robot_has_a_description() -> None:
    assert set(DESCRIPTIONS) == set(ROBOT_NAMES)
    for file, *_ in DESCRIPTIONS.values():
        head = (DATA / file).read_text()[:900]
        assert "repository:" in head and "commit:" in head, file


@pytest.mark.parametrize("name", ROBOT_NAMES)
def test_fk_equals_the_published_description(name: str) -> None:
    q = random_controller_joints(name, 50, seed=28)
    dp, dr = pose_errors(library_flange(name, q), description_flange(name, q))
    assert dp < 0.1 and dr < 0.01, (name, dp, dr)


@pytest.mark.parametrize("name", ROBOT_NAMES)
def test_the_comparison_can_fail(name: str) -> None:
    """One millimetre on one length of the description, or one joint's sign, is seen."""
    q = random_controller_joints(name, 50, seed=3)
    lib = library_flange(name, q)
    flipped = q.copy()
    flipped[:, 3] *= -1.0  # J4's sign
    dp, dr = pose_errors(lib, description_flange(name, flipped))
    assert dp > 1.0 or dr > 1.0
    moved = lib.copy()
    moved[:, 2, 3] += 0.001  # a base 1 mm higher
    assert pose_errors(moved, description_flange(name, q))[0] > 0.9
