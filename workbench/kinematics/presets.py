"""Robot data: the NACHI MZ07 (the real MZ07F's frames), with seed 003's table as a variant.

Every number below cites its document. [P] is the published teach-pendant data of a real
NACHI MZ07F and the chain fitted to it: gstorm-b/RobotKinematics,
docs/preset_references/nachi-mz07f.md (commit ac638be4083e), "Kinematics verification
(2026-09-30)" table and "Joint limits", https://github.com/gstorm-b/RobotKinematics/blob/main/
docs/preset_references/nachi-mz07f.md; the same repository's presets/Nachi/MZ07F/
nachi_mz07f.json encodes that table as joint origins (tests/data/robot_descriptions/
nachi_mz07f.urdf holds them). [S] is seed 003, Table 2.

The preset (``MZ07_DH``, standard DH, mm and deg; theta column = offsets):

    row   theta   d      a    alpha   source
    0-1   0       355    50   90      [P] J1 row: J2 axis 355 mm above the base, 50 mm forward
    1-2   90      0      330  0       [P] J2 row (a = 330)
    2-3   0       0      45   90      [P] J3 row (a = 45)
    3-4   0       340    0    90      [P] J4 row (d = 340: J3 to the wrist centre)
    4-5   90      0      0    90      [P] J5 row
    5-6   0       -78    0    180     [P] J6 row: wrist centre to flange 78 mm

The theta offsets and the signs of rows 3-6 are the seed's parameterisation of the same arm
(its model convention below); [P] writes the chain with the pendant's own joint values
(rows 0 355 50 90 / 0 0 330 0 / 0 0 45 90 / 0 340 0 -90 / 0 0 0 90 / 0 78 0 0). The two give
the same flange frame at every posture (tests/kinematics/test_robot_descriptions.py), and
both reproduce the six pendant poses of [P] within 0.065 mm and 0.013 deg
(tests/kinematics/test_joint_convention.py).

Seed 003's table ([S], ``MZ07_SEED_DH``, kept as a documented variant):

    row   theta   d       a    alpha
    0-1   0       340     50   90
    1-2   90      0       330  0
    2-3   0       0       45   90
    3-4   0       340     0    90
    4-5   90      0       0    90
    5-6   0       -516.9  0    0

It differs from the real MZ07F in two numbers: J2 axis 340 mm above the base (real 355 mm),
and it ends at the tip of the authors' end effector, 516.9 mm from the wrist centre. With
the real 78 mm flange that end effector is flange -> TCP Tz(438.9 mm): ``MZ07_SEED_TOOL``.

The controller's joint convention (``MZ07_CONVENTION``). The NACHI controller (FD/CFD teach
pendant) shows the upright posture -- upper arm vertical, forearm horizontal, wrist straight,
flange facing forward -- as J = (0, 90, 0, 0, 0, 0) deg ([P], "meshToLink from the STEP
assembly": the reference posture q_ref = (0, 90, 0, 0, 0, 0)); J2 grows as the upper arm leans
back, J3 as the forearm rises. The model reaches that posture at q = (0, 0, 0, 0, -90, 0) deg,
and its J5 and J6 axes point the other way than the controller's, so

    q_ctrl = sign * q_model + offset,  sign = (+1, +1, +1, +1, -1, -1),
    offset = (0, 90, 0, 0, -90, 0) deg.

tests/kinematics/test_joint_convention.py maps the six pendant joint readings of [P] through
this convention and reproduces the pendant's flange poses within 0.1 mm and 0.02 deg.

Joint limits, in the controller's convention (``MZ07_CONTROLLER_LIMITS_DEG``; the model's
``MZ07_LIMITS`` are derived from them): J1 +-170, J2 -45..+170, J3 -65..+190, J4 +-190,
J5 +-120, J6 +-360 deg: [P], "Joint limits (actual limits of the reference robot)".

Maximum joint speeds 450, 380, 520, 550, 550, 1000 deg/s: the ROS description of an MZ07 by
Nishida-Lab, nachi_description/robots/mz07/mz07.urdf.xacro (commit 2b1a2264e0b7),
J1..J6_velocity_limit, https://github.com/Nishida-Lab/nachi_project/blob/master/
nachi_description/robots/mz07/mz07.urdf.xacro. [P] gives no speeds; NACHI's own data sheet
was not available to check them against.
"""

from __future__ import annotations

import numpy as np

from workbench.geometry.transforms import make_transform
from workbench.kinematics.joint_convention import JointConvention

_DEG = np.pi / 180.0

MZ07_SEED_DH_MM_DEG = np.array(  # [S] seed 003, Table 2 (see the module docstring)
    [
        [0.0, 340.0, 50.0, 90.0],
        [90.0, 0.0, 330.0, 0.0],
        [0.0, 0.0, 45.0, 90.0],
        [0.0, 340.0, 0.0, 90.0],
        [90.0, 0.0, 0.0, 90.0],
        [0.0, -516.9, 0.0, 0.0],
    ]
)

MZ07_SEED_DH = np.column_stack(
    [
        MZ07_SEED_DH_MM_DEG[:, 0] * _DEG,
        MZ07_SEED_DH_MM_DEG[:, 1] / 1000.0,
        MZ07_SEED_DH_MM_DEG[:, 2] / 1000.0,
        MZ07_SEED_DH_MM_DEG[:, 3] * _DEG,
    ]
)
"""The seed's table in SI units (rad, m), ending at the seed's tool tip."""

MZ07_BASE_D = 0.355
"""d of the J1 row [m]: the J2 axis 355 mm above the base ([P], J1 row; seed 003: 340 mm)."""

MZ07_FLANGE_D = -0.078
"""d of the flange row [m]: wrist centre to flange 78 mm along -z5 ([P], J6 row d = 78)."""

MZ07_DH = MZ07_SEED_DH.copy()
MZ07_DH[0, 1] = MZ07_BASE_D
MZ07_DH[5] = [0.0, MZ07_FLANGE_D, 0.0, np.pi]
"""The preset: the real MZ07F's chain in the seed's parameterisation (module docstring)."""

MZ07_SEED_TIP_FROM_WRIST = 0.5169
"""The seed's end effector tip from the wrist centre [m] ([S], last row d = -516.9 mm)."""

MZ07_SEED_TOOL = make_transform(np.eye(3), [0.0, 0.0, MZ07_SEED_TIP_FROM_WRIST + MZ07_FLANGE_D])
"""Flange -> TCP of the seed's end effector: Tz(0.4389 m), TCP z pointing out of the tool.

The seed's own tip frame has z pointing back into the wrist (its last alpha is 0), and its
base is 15 mm lower than the real robot's J2 axis would put it, so
``fk_seed(q) == Tz(-0.015) @ fk(q) @ MZ07_SEED_TOOL @ Rx(pi)``.
"""

MZ07_CONVENTION_OFFSET_DEG = np.array([0.0, 90.0, 0.0, 0.0, -90.0, 0.0])
MZ07_CONVENTION_SIGN = np.array([1.0, 1.0, 1.0, 1.0, -1.0, -1.0])
MZ07_CONVENTION = JointConvention(
    offset=MZ07_CONVENTION_OFFSET_DEG * _DEG, sign=MZ07_CONVENTION_SIGN
)
"""The NACHI controller's joint values against the seed model's (see the module docstring)."""

MZ07_CONTROLLER_UPRIGHT_DEG = np.array([0.0, 90.0, 0.0, 0.0, 0.0, 0.0])
"""The upright posture (upper arm vertical, forearm horizontal, wrist straight) on the pendant."""

MZ07_CONTROLLER_LIMITS_DEG = np.array(  # [P], "Joint limits" (J1..J6)
    [
        [-170.0, 170.0],
        [-45.0, 170.0],
        [-65.0, 190.0],
        [-190.0, 190.0],
        [-120.0, 120.0],
        [-360.0, 360.0],
    ]
)
"""Joint limits [deg] as the controller shows them (the model's are `MZ07_LIMITS`)."""

MZ07_LIMITS_DEG = JointConvention(
    offset=MZ07_CONVENTION_OFFSET_DEG, sign=MZ07_CONVENTION_SIGN
).limits_to_model(MZ07_CONTROLLER_LIMITS_DEG)  # the map is linear: mapped in whole degrees
MZ07_LIMITS = MZ07_LIMITS_DEG * _DEG
"""Joint limits [rad] in the model's convention: J2 -135..80, J3 -65..190, J5 -210..30 deg, ..."""

MZ07_MAX_VELOCITY_DEG_S = np.array([450.0, 380.0, 520.0, 550.0, 550.0, 1000.0])  # Nishida-Lab
MZ07_MAX_VELOCITY = MZ07_MAX_VELOCITY_DEG_S * _DEG
"""Joint speed limits [rad/s] (450, 380, 520, 550, 550, 1000 deg/s; sources in the docstring)."""

ACCELERATION_TIME = 0.25
"""Default time [s] to reach full speed: max_acceleration = max_velocity / 0.25 s."""

JERK_TIME = 0.05
"""Default time [s] to reach full acceleration: max_jerk = max_acceleration / 0.05 s."""

DEFAULT_MAX_VELOCITY = np.pi  # rad/s for robots given without speeds
