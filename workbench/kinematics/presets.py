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

Joint limits and speeds are approximate values from the MZ07 datasheet as remembered, in
the seed's joint convention; check them against the robot's manual before real use. J5 is
±120 deg about the straight wrist; the seed's theta offset of 90 deg puts q5 = 0 at the
flange-down pose and the straight wrist at q5 = -90 deg, so its range is [-210, 30] deg
(q5 > 0 folds the flange back toward the forearm).
"""

from __future__ import annotations

import numpy as np

from workbench.geometry.transforms import make_transform

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

MZ07_LIMITS_DEG = np.array(
    [
        [-170.0, 170.0],
        [-135.0, 80.0],
        [-120.0, 160.0],
        [-190.0, 190.0],
        [-210.0, 30.0],
        [-360.0, 360.0],
    ]
)
MZ07_LIMITS = MZ07_LIMITS_DEG * _DEG

MZ07_MAX_VELOCITY = np.array([450.0, 380.0, 520.0, 550.0, 550.0, 1000.0]) * _DEG
"""Approximate joint speed limits [rad/s] (datasheet figures in deg/s, as remembered)."""

ACCELERATION_TIME = 0.25
"""Default time [s] to reach full speed: max_acceleration = max_velocity / 0.25 s."""

JERK_TIME = 0.05
"""Default time [s] to reach full acceleration: max_jerk = max_acceleration / 0.05 s."""

DEFAULT_MAX_VELOCITY = np.pi  # rad/s for robots given without speeds
