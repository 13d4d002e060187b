"""Turn selection against brute-force enumeration of q + 2 pi k."""

from __future__ import annotations

import math

import numpy as np

from workbench.kinematics.ik_report import branch_name
from workbench.kinematics.joint_turns import all_turns, joint_turn, wrap_to_pi
from workbench.kinematics.robot_library import preset_robot

TWO_PI = 2 * math.pi


def brute(q: float, lo: float, hi: float, ref: float) -> float | None:
    cands = [q + TWO_PI * k for k in range(-4, 5) if lo - 1e-10 <= q + TWO_PI * k <= hi + 1e-10]
    return min(cands, key=lambda c: abs(c - ref)) if cands else None


def test_joint_turn_matches_brute_force() -> None:
    rng = np.random.default_rng(0)
    limits = [
        (-math.pi, math.pi),
        (-2 * math.pi, 2 * math.pi),
        (math.radians(-190), math.radians(190)),
        (0.5, 5.0),
        (-0.3, 0.4),
    ]
    for lo, hi in limits:
        q = rng.uniform(-3 * math.pi, 3 * math.pi, 400)
        ref = rng.uniform(lo, hi, 400)
        got, ok = joint_turn(q, lo, hi, ref)
        for qi, ri, gi, oi in zip(q, ref, got, ok, strict=True):
            want = brute(qi, lo, hi, ri)
            assert oi == (want is not None)
            if want is not None:
                assert abs(gi - want) < 1e-12 or abs(abs(gi - ri) - abs(want - ri)) < 1e-12


def test_all_turns_enumerates_every_variant() -> None:
    limits = np.array([[-math.pi, math.pi], [-2 * math.pi, 2 * math.pi], [-0.5, 0.5]])
    rows = all_turns(np.array([1.0, 1.0, 0.2]), limits)
    assert rows.shape == (2, 3)
    np.testing.assert_allclose(sorted(rows[:, 1]), [1.0 - TWO_PI, 1.0])
    assert np.all(np.abs(wrap_to_pi(np.array([3 * math.pi + 0.1]))) <= math.pi)


def test_branch_names_say_configuration_and_turns() -> None:
    robot = preset_robot("mz07")
    conv = robot.convention
    # Straight up, elbow bent forward: the twin is the controller's own reading of the joints
    # (J5 sign for the flip, J6 between 180 and 540 deg for +1 turn).
    q_ctrl = np.radians([0.0, 0.0, 0.0, 0.0, 30.0, 200.0])
    name = branch_name(robot, conv.to_model(q_ctrl))
    assert name.endswith("/no flip, J6 +1 turn")
    q_ctrl[4], q_ctrl[5] = np.radians(-30.0), np.radians(-190.0)
    assert branch_name(robot, conv.to_model(q_ctrl)).endswith("/flip, J6 -1 turn")
    q_ctrl[5] = np.radians(180.0)  # exactly +180 deg is still turn 0
    assert ", J6" not in branch_name(robot, conv.to_model(q_ctrl))
    assert "elbow A" not in name and "elbow B" not in name
