"""JointConvention, and NACHI's convention of the MZ07 preset checked against pendant data."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.kinematics import DHRobot, JointConvention, URDFRobot, presets
from workbench.kinematics.dh_chain import dh_fk, dh_frames
from workbench.kinematics.model import RobotModel
from workbench.kinematics.robot_library import preset_robot

DEG = np.pi / 180.0
RNG = np.random.default_rng(7)


def _random_convention(dof: int) -> JointConvention:
    return JointConvention(
        offset=RNG.uniform(-np.pi, np.pi, dof), sign=RNG.choice([-1.0, 1.0], dof)
    )


# -- the class ----------------------------------------------------------------------------
def test_round_trip_batched() -> None:
    c = _random_convention(6)
    q = RNG.uniform(-3, 3, (4, 5, 6))
    qc = c.to_controller(q)
    assert qc.shape == q.shape
    np.testing.assert_allclose(c.to_model(qc), q, atol=1e-12)
    # element by element, the formula q_ctrl = sign * q_model + offset
    for j in range(6):
        np.testing.assert_allclose(qc[..., j], c.sign[j] * q[..., j] + c.offset[j])


def test_identity() -> None:
    c = JointConvention.identity(7)
    assert c.is_identity and c.dof == 7
    q = RNG.uniform(-3, 3, (3, 7))
    np.testing.assert_array_equal(c.to_controller(q), q)
    np.testing.assert_array_equal(c.to_model(q), q)
    assert not _random_convention(6).is_identity
    assert not JointConvention(np.zeros(2), np.array([1.0, -1.0])).is_identity


def test_limits_sorted_and_mapped_end_to_end() -> None:
    c = JointConvention(offset=np.array([0.5, -0.2, 0.0]), sign=np.array([-1.0, 1.0, -1.0]))
    ctrl = np.array([[-1.0, 2.0], [-0.5, 0.5], [0.1, 0.3]])
    model = c.limits_to_model(ctrl)
    assert np.all(model[:, 0] < model[:, 1])
    # brute force: the model image of many controller values inside the limits
    qc = RNG.uniform(ctrl[:, 0], ctrl[:, 1], (2000, 3))
    qm = c.to_model(qc)
    assert np.all(qm >= model[:, 0] - 1e-12) and np.all(qm <= model[:, 1] + 1e-12)
    np.testing.assert_allclose(model, [[-1.5, 1.5], [-0.3, 0.7], [-0.3, -0.1]])
    np.testing.assert_allclose(c.limits_to_controller(model), ctrl)


def test_bad_input_is_named() -> None:
    with pytest.raises(InputError, match="sign"):
        JointConvention(np.zeros(3), np.array([1.0, 0.5, -1.0]))
    with pytest.raises(InputError, match="offset has 2 entries"):
        JointConvention(np.zeros(2), np.ones(3))
    with pytest.raises(InputError, match="finite"):
        JointConvention(np.array([np.nan]), np.ones(1))
    c = JointConvention.identity(6)
    with pytest.raises(InputError, match=r"q_model: expected shape \(\.\.\., 6\)"):
        c.to_controller(np.zeros(5))
    with pytest.raises(InputError, match="limits"):
        c.limits_to_model(np.zeros((5, 2)))
    with pytest.raises(InputError, match="dof"):
        JointConvention.identity(0)


def test_arrays_are_read_only() -> None:
    c = JointConvention.identity(3)
    with pytest.raises(ValueError):
        c.offset[0] = 1.0


def test_models_carry_a_convention() -> None:
    robot = DHRobot(presets.MZ07_SEED_DH, presets.MZ07_LIMITS)
    assert isinstance(robot, RobotModel)
    assert robot.convention.is_identity and robot.convention.dof == 6
    conv = _random_convention(6)
    assert DHRobot(presets.MZ07_DH, presets.MZ07_LIMITS, convention=conv).convention is conv
    with pytest.raises(InputError, match="convention"):
        DHRobot(presets.MZ07_DH, presets.MZ07_LIMITS, convention=JointConvention.identity(5))
    assert "convention" in URDFRobot.__init__.__code__.co_varnames


# -- NACHI's convention of the MZ07 preset --------------------------------------------------
def test_mz07_upright_posture_from_fk() -> None:
    """FK of to_model(J2 = 90, others 0): upper arm vertical, forearm horizontal, wrist straight."""
    robot = preset_robot("mz07")
    conv = robot.convention
    q = conv.to_model(presets.MZ07_CONTROLLER_UPRIGHT_DEG * DEG)
    np.testing.assert_allclose(q / DEG, [0, 0, 0, 0, -90, 0], atol=1e-12)
    F = robot.link_transforms(q)
    shoulder, elbow, wrist, flange = F[1, :3, 3], F[2, :3, 3], F[4, :3, 3], F[6, :3, 3]
    up = (elbow - shoulder) / np.linalg.norm(elbow - shoulder)
    np.testing.assert_allclose(up, [0, 0, 1], atol=1e-12)  # upper arm vertical
    fore = wrist - F[3, :3, 3]
    assert abs(fore[2]) < 1e-12 and fore[0] > 0.3  # forearm horizontal, forward
    # wrist straight: the flange normal continues the forearm
    z_flange = F[6, :3, 2]
    np.testing.assert_allclose(z_flange, fore / np.linalg.norm(fore), atol=1e-12)
    np.testing.assert_allclose(flange - wrist, 0.078 * z_flange, atol=1e-12)  # [P]: 78 mm


def test_mz07_limits_match_the_controller_limits() -> None:
    robot = preset_robot("mz07")
    ctrl = robot.convention.limits_to_controller(robot.limits) / DEG
    np.testing.assert_allclose(ctrl, presets.MZ07_CONTROLLER_LIMITS_DEG, atol=1e-9)
    np.testing.assert_allclose(ctrl[4], [-120.0, 120.0])  # J5 about the straight wrist
    np.testing.assert_allclose(ctrl[1], [-45.0, 170.0])  # J2, upright = 90


# Teach-pendant pairs of a real NACHI MZ07F (joints deg; flange pose mm and Z-Y-X deg, R =
# Rz(a) Ry(b) Rx(c)), published in gstorm-b/RobotKinematics (commit ac638be4083e),
# docs/preset_references/nachi-mz07f.md, "Joint:" and "Coordinate ..." lists (the note
# under them: the coordinates are the tool-flange pose). The preset is that MZ07F.
PENDANT_J = np.array(
    [
        [21.4862, 64.4801, -41.7744, -180.007, 22.7216, -158.513],
        [18.6965, 68.6763, -39.6996, -158.418, 38.2621, -180.401],
        [4.98917, 73.5581, -44.4732, -189.95, 35.3251, -153.57],
        [-20.077, 72.1081, -41.8598, -0.0550513, -30.2747, -20.0276],
        [-17.8857, 69.2501, -38.4703, -14.4347, -45.5303, -25.5808],
        [-25.4971, 70.7751, -42.0408, 44.0796, -38.9396, -79.9948],
    ]
)
PENDANT_X = np.array(
    [
        [339.525, 133.617, 278.473, 0.000535733, 0.0236197, 179.986],
        [339.486, 133.658, 311.388, 1.99842, 10.7741, -169.478],
        [339.5, 21.8373, 319.019, -13.2406, 3.7502, 172.732],
        [339.503, -124.14, 319.977, -0.00232496, 0.038313, 179.985],
        [339.474, -124.15, 319.966, 19.152, 17.1551, 179.99],
        [339.49, -124.109, 319.939, 14.2266, -16.2692, -159.49],
    ]
)


def _rzyx(a: float, b: float, c: float) -> np.ndarray:
    ca, sa, cb, sb, cc, sc = np.cos(a), np.sin(a), np.cos(b), np.sin(b), np.cos(c), np.sin(c)
    Rz = np.array([[ca, -sa, 0], [sa, ca, 0], [0, 0, 1]])
    Ry = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]])
    Rx = np.array([[1, 0, 0], [0, cc, -sc], [0, sc, cc]])
    return Rz @ Ry @ Rx


def _angle_deg(Ra: np.ndarray, Rb: np.ndarray) -> float:
    return float(np.degrees(np.arccos(np.clip((np.trace(Ra.T @ Rb) - 1) / 2, -1, 1))))


def test_mz07_convention_reproduces_nachi_pendant_poses() -> None:
    """Pendant joints -> to_model -> the preset's FK: the pendant's flange poses within 0.1 mm
    and 0.02 deg (the published chain's own residuals are 0.065 mm and 0.0124 deg)."""
    robot = preset_robot("mz07")
    q = robot.convention.to_model(PENDANT_J * DEG)
    T = robot.fk(q)
    for i, x in enumerate(PENDANT_X):
        R = _rzyx(*(x[3:] * DEG))
        assert _angle_deg(T[i, :3, :3], R) < 0.02, i  # same flange frame, same orientation
        assert np.linalg.norm(T[i, :3, 3] * 1000 - x[:3]) < 0.1, i  # the flange itself


def test_the_old_preset_misses_the_pendant_poses() -> None:
    """The check above can fail: the earlier preset (J2 axis 340 mm up, flange 90 mm from the
    wrist centre) puts the flange 15-25 mm from the pendant's readings."""
    old = presets.MZ07_DH.copy()
    old[0, 1], old[5, 1] = 0.340, -0.090
    T = dh_fk(old, presets.MZ07_CONVENTION.to_model(PENDANT_J * DEG))
    err = np.linalg.norm(T[:, :3, 3] * 1000 - PENDANT_X[:, :3], axis=1)
    assert err.min() > 10.0


def test_the_wrong_convention_fails_the_pendant_check() -> None:
    """The check above can fail: identity, or one sign flipped, misses the pendant poses."""
    robot = preset_robot("mz07")
    c = presets.MZ07_CONVENTION
    for conv in (
        JointConvention.identity(6),
        JointConvention(c.offset, c.sign * np.array([1, 1, 1, -1, 1, 1.0])),
        JointConvention(c.offset, c.sign * np.array([1, 1, 1, 1, 1, -1.0])),
    ):
        T = robot.fk(conv.to_model(PENDANT_J * DEG))
        worst = max(
            _angle_deg(T[i, :3, :3], _rzyx(*(x[3:] * DEG))) for i, x in enumerate(PENDANT_X)
        )
        assert worst > 1.0


def test_pendant_chain_itself_matches_its_poses() -> None:
    """The published MZ07F chain (pendant values used as they are) reproduces its own data."""
    rows = np.array(
        [
            [0, 355, 50, 90],
            [0, 0, 330, 0],
            [0, 0, 45, 90],
            [0, 340, 0, -90],
            [0, 0, 0, 90],
            [0, 78, 0, 0],
        ],
        float,
    )
    dh = np.column_stack([rows[:, 0] * DEG, rows[:, 1] / 1000, rows[:, 2] / 1000, rows[:, 3] * DEG])
    T = dh_fk(dh, PENDANT_J * DEG)
    for i, x in enumerate(PENDANT_X):
        np.testing.assert_allclose(T[i, :3, 3] * 1000, x[:3], atol=0.1)
        assert _angle_deg(T[i, :3, :3], _rzyx(*(x[3:] * DEG))) < 0.02
    # and that chain is upright at the pendant's (0, 90, 0, 0, 0, 0)
    F = dh_frames(dh, presets.MZ07_CONTROLLER_UPRIGHT_DEG * DEG)
    np.testing.assert_allclose(F[2, :3, 3] - F[1, :3, 3], [0, 0, 0.330], atol=1e-12)
    ours = preset_robot("mz07").fk(
        presets.MZ07_CONVENTION.to_model(presets.MZ07_CONTROLLER_UPRIGHT_DEG * DEG)
    )
    np.testing.assert_allclose(ours[:3, :3], F[6, :3, :3], atol=1e-12)


def test_the_coupled_rule_is_the_model_box_in_the_controllers_values() -> None:
    """FANUC's J3 counts from the horizontal: the model's J3 range is a rule on J2 and J3 of the
    controller. Twin: the model box itself, on the model values of random controller joints."""
    from workbench.kinematics.robot_library import library_robot

    robot = library_robot("m10ia").dh_robot()
    conv, box = robot.convention, robot.limits
    rng = np.random.default_rng(0)
    qc = rng.uniform(-np.pi * 1.6, np.pi * 1.6, size=(2000, 6))
    for q in qc:
        text, value, lo, hi = conv.coupled_rule(2, q, box)
        assert text == "J3 + J2"
        assert value == pytest.approx(q[2] + q[1])
        inside = box[2, 0] <= conv.to_model(q)[2] <= box[2, 1]
        assert (lo <= value <= hi) == inside
    assert conv.coupled_rule(1, qc[0], box) is None  # J2 counts on its own
    assert JointConvention.identity().coupled_rule(2, np.zeros(6), box) is None
