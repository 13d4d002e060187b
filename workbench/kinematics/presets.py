"""Robot data: the NACHI MZ07 of seed 003, with the robot flange and the seed's tool apart.

Seed 003, Table 2 (standard DH, mm and deg; theta column = offsets):

    row   theta   d       a    alpha
    0-1   0       340     50   90
    1-2   90      0       330  0
    2-3   0       0       45   90
    3-4   0       340     0    90
    4-5   90      0       0    90
    5-6   0       -516.9  0    0

The last row reaches the tip of the authors' end effector. The robot flange is modelled as
theta 0, d -0.090 m, a 0, alpha 180 deg (flange z points out of the flange; wrist centre to
flange ~90 mm), and the rest of the seed's 516.9 mm is the tool: ``MZ07_SEED_TOOL``.

The controller's joint convention (``MZ07_CONVENTION``). The NACHI controller (FD/CFD teach
pendant) shows the upright posture -- upper arm vertical, forearm horizontal, wrist straight,
flange facing forward -- as J = (0, 90, 0, 0, 0, 0) deg; J2 grows as the upper arm leans back,
J3 as the forearm rises. The seed's model reaches that posture at q = (0, 0, 0, 0, -90, 0) deg,
and its J5 and J6 axes point the other way than the controller's, so

    q_ctrl = sign * q_model + offset,  sign = (+1, +1, +1, +1, -1, -1),
    offset = (0, 90, 0, 0, -90, 0) deg.

Source: the teach-pendant joint/flange pose pairs of a real MZ07F and the chain they were
fitted with, published in gstorm-b/RobotKinematics,
https://github.com/gstorm-b/RobotKinematics/blob/main/docs/preset_references/nachi-mz07f.md
(six poses, reproduced by that chain to 0.07 mm / 0.013 deg; the MZ04D page of the same
repository shows J(0, 90, 0, 0, 0, 0) as the reference posture of NACHI's manual).
tests/kinematics/test_joint_convention.py maps those pendant values through the convention
and checks this model's flange orientation and wrist centre against the pendant's poses.

Joint limits, in the controller's convention (``MZ07_CONTROLLER_LIMITS_DEG``; the model's
``MZ07_LIMITS`` are derived from them):

- J1 +-170, J2 -45..+170, J4 +-190, J5 +-120, J6 +-360 deg: the limits of the same MZ07F
  (nachi-mz07f.md above); J2 and J5 equal the earlier estimates (-135..+80 deg about the
  vertical, +-120 deg about the straight wrist), J1, J4 and J6 the ROS description of an
  MZ07 by Nishida-Lab,
  https://github.com/Nishida-Lab/nachi_project/blob/master/nachi_description/robots/mz07/mz07.urdf.xacro
- J3 -120..+160 deg: STILL AN ESTIMATE (the value remembered from the datasheet). The MZ07F
  above shows -65..+190 deg and the Nishida-Lab files disagree with each other; check the
  robot's manual before real use.

Maximum joint speeds 450, 380, 520, 550, 550, 1000 deg/s: the Nishida-Lab description above
(and its MoveIt joint_limits.yaml); not yet checked against NACHI's own datasheet.
"""

from __future__ import annotations

import numpy as np

from workbench.geometry.transforms import make_transform
from workbench.kinematics.joint_convention import JointConvention

_DEG = np.pi / 180.0

MZ07_SEED_DH_MM_DEG = np.array(
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

MZ07_FLANGE_D = -0.090
"""d of the flange row [m]: wrist centre to flange along -z5."""

MZ07_DH = MZ07_SEED_DH.copy()
MZ07_DH[5] = [0.0, MZ07_FLANGE_D, 0.0, np.pi]

MZ07_SEED_TOOL = make_transform(np.eye(3), [0.0, 0.0, 0.5169 + MZ07_FLANGE_D])
"""Flange -> TCP of the seed's end effector: Tz(0.4269 m), TCP z pointing out of the tool.

The seed's own tip frame has z pointing back into the wrist (its last alpha is 0), so
``fk_seed(q) == fk(q) @ MZ07_SEED_TOOL @ Rx(pi)``.
"""

MZ07_CONVENTION_OFFSET_DEG = np.array([0.0, 90.0, 0.0, 0.0, -90.0, 0.0])
MZ07_CONVENTION_SIGN = np.array([1.0, 1.0, 1.0, 1.0, -1.0, -1.0])
MZ07_CONVENTION = JointConvention(
    offset=MZ07_CONVENTION_OFFSET_DEG * _DEG, sign=MZ07_CONVENTION_SIGN
)
"""The NACHI controller's joint values against the seed model's (see the module docstring)."""

MZ07_CONTROLLER_UPRIGHT_DEG = np.array([0.0, 90.0, 0.0, 0.0, 0.0, 0.0])
"""The upright posture (upper arm vertical, forearm horizontal, wrist straight) on the pendant."""

MZ07_CONTROLLER_LIMITS_DEG = np.array(
    [
        [-170.0, 170.0],
        [-45.0, 170.0],
        [-120.0, 160.0],  # estimate, see the module docstring
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
"""Joint limits [rad] in the seed model's convention: J2 -135..80, J5 -210..30 deg, ..."""

MZ07_MAX_VELOCITY_DEG_S = np.array([450.0, 380.0, 520.0, 550.0, 550.0, 1000.0])
MZ07_MAX_VELOCITY = MZ07_MAX_VELOCITY_DEG_S * _DEG
"""Joint speed limits [rad/s] (450, 380, 520, 550, 550, 1000 deg/s; sources in the docstring)."""

ACCELERATION_TIME = 0.25
"""Default time [s] to reach full speed: max_acceleration = max_velocity / 0.25 s."""

JERK_TIME = 0.05
"""Default time [s] to reach full acceleration: max_jerk = max_acceleration / 0.05 s."""

DEFAULT_MAX_VELOCITY = np.pi  # rad/s for robots given without speeds
