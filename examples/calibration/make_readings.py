"""Write the joint readings of docs/calibration.md's worked example from its stated truth.

Run from the repository's root: `python examples/calibration/make_readings.py`. It rewrites
tcp_readings.csv, cell_readings.csv and fixture_3point.csv here; run it again whenever the MZ07
preset's kinematics change (the readings are the controller's joint values, so they depend on
the robot's frames: they were last made with the real MZ07F's, J2 axis 355 mm above the base
and the flange 78 mm from the wrist centre, issue 28).

The truth (docs/calibration.md): the gripper's TCP at (1.8, -0.6, 152.4) mm in the flange, the
robot's base at (2.5, -1.5, 0) mm turned 0.3 deg in the cell, the fixture at (420, -80, 120) mm
turned 15 deg. Each reading is the preset's inverse kinematics of the flange pose that puts
that TCP on the point, checked by its forward kinematics to 1e-6 mm, in the controller's
convention [deg] plus 0.01 deg of normal noise (seeded: the files are reproducible).
fixture_points.csv holds TCP positions, not joints (the pendant's own FK): they do not depend
on the robot's frames and are written by hand from the same truth (0.05 mm noise; hole3
touched 4 mm high).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from workbench import Workbench
from workbench.geometry.transforms import invert_transform, make_transform

HERE = Path(__file__).resolve().parent
PROJECT = HERE.parents[1] / "projects" / "mz07_cell.json"
NOISE_DEG = 0.01
TCP_TRUE = make_transform(np.eye(3), [0.0018, -0.0006, 0.1524])  # flange -> TCP [m]
BASE_TRUE = make_transform(
    Rotation.from_euler("z", 0.3, degrees=True).as_matrix(), [0.0025, -0.0015, 0.0]
)  # world -> robot base [m]
FIXTURE_TRUE = make_transform(
    Rotation.from_euler("z", 15.0, degrees=True).as_matrix(), [0.420, -0.080, 0.120]
)  # world -> fixture [m]
PIN = np.array([0.450, 0.060, 0.180])  # the fixed pin of the TCP readings, in the base [m]
# the TCP readings' tool orientations: tool down, tilted (deg) about the base's x and y, turned
# about the tool's z: at least 30 deg apart about every axis (the calibration's condition)
TCP_TILTS = [
    (0.0, 0.0, 0.0),
    (35.0, 0.0, 40.0),
    (0.0, -35.0, -30.0),
    (-30.0, 25.0, 60.0),
    (20.0, 30.0, -70.0),
]


def _joints(wb: Workbench, T_base_flange: np.ndarray, rng: np.random.Generator) -> str:
    q = wb.robot.ik(T_base_flange, q_near=wb.joints)[0]
    assert np.allclose(wb.robot.fk(q), T_base_flange, atol=1e-9), "IK and FK disagree"
    deg = np.degrees(wb.robot.convention.to_controller(q)) + rng.normal(0.0, NOISE_DEG, 6)
    return ",".join(f"{v:.3f}" for v in deg)


def _touch(p_base: np.ndarray, R_tool: np.ndarray) -> np.ndarray:
    """Return the flange pose putting the true TCP on p_base with tool orientation R_tool."""
    return make_transform(R_tool, p_base) @ invert_transform(TCP_TRUE)


def _down(rng: np.random.Generator) -> np.ndarray:
    """Return a tool-down orientation tilted at random by up to 0.3 rad."""
    R = Rotation.from_rotvec(rng.uniform(-0.3, 0.3, 3)) * Rotation.from_euler("x", np.pi)
    return R.as_matrix()


def _write(name: str, header: list[str], rows: list[str]) -> None:
    text = "\n".join([*header, "label,j1,j2,j3,j4,j5,j6", *rows]) + "\n"
    (HERE / name).write_text(text)


def main() -> None:
    wb = Workbench.open(PROJECT)
    rng = np.random.default_rng(28)
    made = "made by make_readings.py (IK of the MZ07 preset, 0.01 deg noise)"

    rows = []
    for i, (rx, ry, rz) in enumerate(TCP_TILTS):
        R = (
            Rotation.from_euler("xy", [rx, ry], degrees=True)
            * Rotation.from_euler("x", np.pi)
            * Rotation.from_euler("z", rz, degrees=True)
        )
        rows.append(f"p{i + 1}," + _joints(wb, _touch(PIN, R.as_matrix()), rng))
    _write(
        "tcp_readings.csv",
        [
            "# MZ07 joints [deg] as the pendant shows them, the gripper's tip on one fixed pin in "
            f"5 orientations; {made}",
            "# workbench calibrate tcp projects/mz07_cell.json examples/calibration/tcp_readings.csv",
        ],
        rows,
    )

    base_from_world = invert_transform(BASE_TRUE)
    known = np.loadtxt(HERE / "cell_known.csv", delimiter=",", skiprows=2, usecols=(1, 2, 3))
    labels = np.loadtxt(HERE / "cell_known.csv", delimiter=",", skiprows=2, usecols=0, dtype=str)
    rows = []
    for label, p in zip(labels, known / 1000.0, strict=True):
        p_base = base_from_world[:3, :3] @ p + base_from_world[:3, 3]
        rows.append(f"{label}," + _joints(wb, _touch(p_base, _down(rng)), rng))
    _write(
        "cell_readings.csv",
        [
            f"# MZ07 joints [deg], the calibrated TCP on four reference marks of the cell; {made}",
            "# workbench calibrate base CELL.json examples/calibration/cell_readings.csv "
            "--known examples/calibration/cell_known.csv",
        ],
        rows,
    )

    rows = []
    for label, p in [("origin", [0, 0, 0]), ("x", [0.150, 0, 0]), ("y", [0.040, 0.100, 0])]:
        T = base_from_world @ FIXTURE_TRUE
        p_base = T[:3, :3] @ np.asarray(p, float) + T[:3, 3]
        rows.append(f"{label}," + _joints(wb, _touch(p_base, _down(rng)), rng))
    _write(
        "fixture_3point.csv",
        [
            "# MZ07 joints [deg]: the fixture's corner (origin), a point on its +X edge (x), a point "
            f"on its top face, +Y side (y); {made}",
            "# workbench calibrate wobj CELL.json examples/calibration/fixture_3point.csv "
            "--name fixture",
        ],
        rows,
    )


if __name__ == "__main__":
    main()
