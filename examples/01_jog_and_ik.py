"""Jog and inverse kinematics: move the MZ07 by joints and by TCP pose, headless.

Opens the example MZ07 cell, jogs two joints, prints the TCP pose, lists every arm
configuration that reaches a pose 50 mm lower, moves there in another configuration and
reports the collision status of each pose, as the Robot tab does in the browser.

    python examples/01_jog_and_ik.py [PROJECT]
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from workbench import Workbench

PROJECT = Path(__file__).resolve().parents[1] / "projects" / "mz07_cell.json"


def _pose_mm(T: np.ndarray) -> str:
    x, y, z = T[:3, 3] * 1000.0
    return f"x {x:7.1f}  y {y:7.1f}  z {z:7.1f} mm"


def _deg(q: np.ndarray, digits: int) -> list[float]:
    """Return joints [rad] as rounded degrees (+ 0.0: no -0.0)."""
    return (np.round(np.degrees(q), digits) + 0.0).tolist()


def _collision(wb: Workbench) -> str:
    report = wb.collision_status()
    if report.in_collision:
        return "in collision: " + ", ".join(f"{a} - {b}" for a, b in report.colliding)
    closest = " - ".join(report.closest_pair or ())
    return f"collision-free, clearance {report.min_distance * 1000:.1f} mm ({closest})"


def main(project: str | Path = PROJECT) -> None:
    wb = Workbench.open(project)
    print(f"project: {wb.project.name}")

    # Jog: the robot takes the model's joints [rad]; the controller's values (the pendant's,
    # the project file's, the GUI's) map to them through the robot's joint convention.
    conv = wb.robot.convention
    wb.set_joints(conv.to_model(np.radians([20.0, 100.0, -5.0, 0.0, -30.0, 0.0])))
    print(f"joints [deg]: {_deg(conv.to_controller(wb.joints), 2)} (controller)")
    T = wb.tcp_pose()
    print(f"TCP:  {_pose_mm(T)}")
    print(f"      {_collision(wb)}")

    # Inverse kinematics: every configuration that puts the TCP 50 mm lower, nearest first.
    target = T.copy()
    target[2, 3] -= 0.050
    solutions = wb.ik_solutions(target)
    print(f"{len(solutions)} configurations reach the pose 50 mm lower:")
    for k, s in enumerate(solutions):
        print(f"  {k}: {s.label:24s} joints [deg] {_deg(conv.to_controller(s.q), 1)}")

    # Move there in the nearest configuration, then in the second one: the TCP stays put.
    for configuration in (None, solutions[-1].label):
        wb.move_tcp(target, configuration=configuration)
        error = np.abs(wb.tcp_pose() - target).max()
        name = configuration or solutions[0].label
        print(f"moved in {name}: TCP {_pose_mm(wb.tcp_pose())} (error {error:.1e})")
        print(f"      {_collision(wb)}")


if __name__ == "__main__":
    main(*sys.argv[1:2])
