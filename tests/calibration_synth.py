"""Synthetic calibration readings: a known truth, readings made by the robot's kinematics.

Joint readings come from the project robot's IK at the true poses; each is confirmed by
pinocchio's forward kinematics (the independent twin of the numpy DH chain) before it is
written, in the controller's convention [deg] with noise, as a pendant would show it.
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin
from scipy.spatial.transform import Rotation

from workbench.geometry.transforms import invert_transform, make_transform
from workbench.kinematics.robot_library import library_robot
from workbench.service import Workbench


def _pin_flange(wb: Workbench, q: np.ndarray) -> np.ndarray:
    model, data = wb.robot.pinocchio_model()
    pin.framesForwardKinematics(model, data, q)
    M = data.oMf[model.nframes - 1]
    return make_transform(M.rotation, M.translation)


def joints_at(wb: Workbench, T_base_flange: np.ndarray) -> np.ndarray:
    """Return model joints [rad] putting the flange at T (4, 4) [m], checked by pinocchio."""
    q = wb.robot.ik(T_base_flange, q_near=wb.joints)[0]
    assert np.allclose(_pin_flange(wb, q), T_base_flange, atol=1e-7), "pinocchio disagrees"
    return np.asarray(q)


def joint_csv(
    wb: Workbench,
    labels: list[str],
    flanges: list[np.ndarray],
    rng: np.random.Generator,
    noise_deg: float = 0.0,
) -> str:
    """Return a joint readings CSV [deg, controller] of flange poses in the base, with noise."""
    rows = ["label," + ",".join(f"j{i + 1}" for i in range(wb.robot.dof))]
    for label, T in zip(labels, flanges, strict=True):
        q = wb.robot.convention.to_controller(joints_at(wb, T))
        deg = np.degrees(q) + rng.normal(0.0, noise_deg, q.shape) if noise_deg else np.degrees(q)
        rows.append(label + "," + ",".join(f"{v:.6f}" for v in deg))
    return "\n".join(rows) + "\n"


def touch_flanges(
    wb: Workbench, points_base: np.ndarray, rng: np.random.Generator, tilt: float = 0.3
) -> list[np.ndarray]:
    """Return flange poses that put the project's TCP on each point (n, 3) [m], tool down."""
    T_ft = wb.setup.T_flange_tcp
    out = []
    for p in points_base:
        R = Rotation.from_rotvec(rng.uniform(-tilt, tilt, 3)) * Rotation.from_euler("x", np.pi)
        out.append(make_transform(R.as_matrix(), p) @ invert_transform(T_ft))
    return out


def point_csv(
    wb: Workbench,
    labels: list[str],
    points_base: np.ndarray,
    rng: np.random.Generator,
    noise_mm: float = 0.0,
) -> str:
    """Return a position readings CSV [mm] in the controller's base frame, with noise."""
    preset = wb.project.robot.preset
    T = np.eye(4) if preset is None else library_robot(preset).T_base_controller
    p = (points_base - T[:3, 3]) @ T[:3, :3] * 1e3 + rng.normal(0, noise_mm, points_base.shape)
    rows = ["label,x,y,z"] + [
        f"{a},{x:.5f},{y:.5f},{z:.5f}" for a, (x, y, z) in zip(labels, p, strict=True)
    ]
    return "\n".join(rows) + "\n"


def known_csv(labels: list[str], points: np.ndarray) -> str:
    """Return a known-points CSV [mm] of points (n, 3) [m]."""
    rows = ["label,x,y,z"] + [
        f"{a},{x * 1e3:.6f},{y * 1e3:.6f},{z * 1e3:.6f}"
        for a, (x, y, z) in zip(labels, points, strict=True)
    ]
    return "\n".join(rows) + "\n"
