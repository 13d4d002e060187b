"""DHRobot: FK against pinocchio and closed forms, the MZ07 preset, Jacobian, bad inputs."""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from workbench.errors import InputError, UnreachableError
from workbench.geometry.transforms import rot_x
from workbench.kinematics import MZ07_SEED_DH, MZ07_SEED_TOOL, DHRobot
from workbench.kinematics.configurations import branch_solutions, pick_solution
from workbench.kinematics.dh_chain import dh_fk, joint_vector
from workbench.kinematics.robot_library import preset_robot

RNG_SEED = 0


@pytest.fixture(scope="module")
def robot() -> DHRobot:
    return preset_robot("mz07")


def random_q(robot: DHRobot, n: int, seed: int = RNG_SEED) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (n, robot.dof))


def naive_fk(dh: np.ndarray, q: np.ndarray) -> np.ndarray:
    """One pose by the textbook product of 4x4 matrices (slow twin)."""
    T = np.eye(4)
    for (off, d, a, al), qi in zip(dh, q, strict=False):
        c, s = math.cos(qi + off), math.sin(qi + off)
        Rz = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])
        Tz = np.eye(4)
        Tz[2, 3] = d
        Tx = np.eye(4)
        Tx[0, 3] = a
        Rx = np.eye(4)
        Rx[:3, :3] = rot_x(al)
        T = T @ Rz @ Tz @ Tx @ Rx
    return T


def test_fk_matches_pinocchio_and_textbook_product(robot: DHRobot) -> None:
    Q = random_q(robot, 300)
    T = robot.fk(Q)
    model, data = robot.pinocchio_model()
    fid = model.getFrameId("flange")
    for q, Tq in zip(Q, T, strict=False):
        pin.framesForwardKinematics(model, data, q)
        np.testing.assert_allclose(Tq, data.oMf[fid].homogeneous, atol=1e-12)
    for q, Tq in zip(Q[:20], T[:20], strict=False):
        np.testing.assert_allclose(Tq, naive_fk(robot.dh, q), atol=1e-12)


def test_link_transforms_match_pinocchio_frames(robot: DHRobot) -> None:
    Q = random_q(robot, 50, seed=1)
    F = robot.link_transforms(Q)
    assert F.shape == (50, 7, 4, 4)
    np.testing.assert_allclose(F[:, 0], np.broadcast_to(np.eye(4), (50, 4, 4)))
    np.testing.assert_allclose(F[:, -1], robot.fk(Q), atol=1e-14)
    model, data = robot.pinocchio_model()
    for q, Fq in zip(Q, F, strict=False):
        pin.framesForwardKinematics(model, data, q)
        for i in range(1, 7):
            oMf = data.oMf[model.getFrameId(f"link_{i}")].homogeneous
            np.testing.assert_allclose(Fq[i], oMf, atol=1e-12)


def test_fk_batch_shapes(robot: DHRobot) -> None:
    Q = random_q(robot, 12).reshape(3, 4, 6)
    T = robot.fk(Q)
    assert T.shape == (3, 4, 4, 4)
    np.testing.assert_allclose(T[2, 1], robot.fk(Q[2, 1]), atol=0)
    assert robot.fk(np.zeros(6)).shape == (4, 4)


def test_mz07_home_pose_by_hand(robot: DHRobot) -> None:
    # q = 0: upper arm vertical (330 mm on top of d1 = 355 mm and a1 = 50 mm), elbow offset
    # 45 mm up, forearm 340 mm along +x, wrist bent down, flange 78 mm below the wrist centre.
    T = robot.fk(np.zeros(6))
    np.testing.assert_allclose(
        T[:3, 3], [0.050 + 0.340, 0.0, 0.355 + 0.330 + 0.045 - 0.078], atol=1e-15
    )
    np.testing.assert_allclose(T[:3, :3], np.diag([1.0, -1.0, -1.0]), atol=1e-15)
    wc = robot.link_transforms(np.zeros(6))[4, :3, 3]
    np.testing.assert_allclose(wc, [0.390, 0.0, 0.730], atol=1e-15)


def test_mz07_reach_to_wrist_centre_is_723_mm(robot: DHRobot) -> None:
    # Stretched elbow (theta3 = atan2(d4, a3)) and a horizontal upper arm (theta2 = 0).
    q = np.zeros(6)
    q[1] = -math.pi / 2
    q[2] = math.atan2(0.340, 0.045)
    wc = robot.link_transforms(q)[4, :3, 3]
    reach = 0.050 + 0.330 + math.hypot(0.340, 0.045)
    np.testing.assert_allclose(wc, [reach, 0.0, 0.355], atol=1e-12)
    assert round(reach * 1000) == 723
    # No random configuration reaches farther from the joint-1 axis.
    wcs = robot.link_transforms(random_q(robot, 20000))[:, 4, :3, 3]
    assert np.hypot(wcs[:, 0], wcs[:, 1]).max() <= reach + 1e-12


def test_seed_table_equals_flange_plus_seed_tool(robot: DHRobot) -> None:
    Q = random_q(robot, 200, seed=2)
    T_seed = dh_fk(MZ07_SEED_DH, Q)
    Rx_pi = np.eye(4)
    Rx_pi[:3, :3] = rot_x(math.pi)
    # the seed's base is 15 mm lower (J2 axis 340 mm above it, the real MZ07F's 355 mm)
    Tz = np.eye(4)
    Tz[2, 3] = -0.015
    np.testing.assert_allclose(T_seed, Tz @ robot.fk(Q) @ MZ07_SEED_TOOL @ Rx_pi, atol=1e-12)
    # Same tip position with the tool alone; 516.9 mm from the wrist centre at home.
    np.testing.assert_allclose(
        T_seed[:, :3, 3], (Tz @ robot.fk(Q) @ MZ07_SEED_TOOL)[:, :3, 3], atol=1e-12
    )
    np.testing.assert_allclose(MZ07_SEED_TOOL[:3, 3], [0, 0, 0.5169 - 0.078], atol=1e-15)
    np.testing.assert_allclose(
        dh_fk(MZ07_SEED_DH, np.zeros(6))[:3, 3], [0.39, 0, 0.715 - 0.5169], atol=1e-15
    )


def test_mz07_limits_and_rates(robot: DHRobot) -> None:
    np.testing.assert_allclose(np.degrees(robot.limits[0]), [-170, 170])
    np.testing.assert_allclose(np.degrees(robot.limits[5]), [-360, 360])
    np.testing.assert_allclose(np.degrees(robot.max_velocity), [450, 380, 520, 550, 550, 1000])
    np.testing.assert_allclose(robot.max_acceleration, robot.max_velocity / 0.25)
    np.testing.assert_allclose(robot.max_jerk, robot.max_acceleration / 0.05)
    assert robot.dof == 6 and robot.is_analytic


def test_jacobian_matches_finite_differences(robot: DHRobot) -> None:
    h = 1e-6
    for q in random_q(robot, 10, seed=3):
        J = robot.jacobian(q)
        assert J.shape == (6, 6)
        T0 = robot.fk(q)
        for j in range(6):
            dq = np.zeros(6)
            dq[j] = h
            Tp, Tm = robot.fk(q + dq), robot.fk(q - dq)
            v = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
            W = (Tp[:3, :3] - Tm[:3, :3]) / (2 * h) @ T0[:3, :3].T
            w = np.array([W[2, 1], W[0, 2], W[1, 0]])
            np.testing.assert_allclose(J[:3, j], v, atol=1e-8)
            np.testing.assert_allclose(J[3:, j], w, atol=1e-8)


@pytest.mark.parametrize(
    ("dh", "limits", "needle"),
    [
        (np.full((6, 4), np.nan), np.zeros((6, 2)), "dh"),
        (np.zeros((6, 3)), np.zeros((6, 2)), "dh: expected shape"),
        (np.zeros((0, 4)), np.zeros((0, 2)), "dh"),
        (np.zeros((6, 4)), np.zeros((5, 2)), "limits: expected shape"),
        (np.zeros((6, 4)), np.tile([1.0, -1.0], (6, 1)), "joint 1 lower limit"),
        (np.zeros((6, 4)), np.tile([0.0, np.inf], (6, 1)), "limits"),
        ("abc", np.zeros((6, 2)), "dh"),
    ],
)
def test_bad_robot_definitions(dh: object, limits: object, needle: str) -> None:
    with pytest.raises(InputError, match=needle):
        DHRobot(dh, limits)  # type: ignore[arg-type]


def test_bad_rates_and_name() -> None:
    lim = np.tile([-1.0, 1.0], (6, 1))
    with pytest.raises(InputError, match="max_velocity"):
        DHRobot(np.zeros((6, 4)), lim, max_velocity=[-1.0] * 6)
    with pytest.raises(InputError, match="max_jerk"):
        DHRobot(np.zeros((6, 4)), lim, max_jerk=[np.nan] * 6)
    with pytest.raises(InputError, match="max_acceleration: expected a number or 6 numbers"):
        DHRobot(np.zeros((6, 4)), lim, max_acceleration=[1.0] * 5)
    with pytest.raises(InputError, match="name"):
        DHRobot(np.zeros((6, 4)), lim, name="")


def test_bad_joint_and_pose_inputs(robot: DHRobot) -> None:
    with pytest.raises(InputError, match=r"q: expected shape \(\.\.\., 6\)"):
        robot.fk(np.zeros(5))
    with pytest.raises(InputError, match="finite"):
        robot.fk([0, 0, np.nan, 0, 0, 0])
    with pytest.raises(InputError, match="T: expected"):
        robot.ik(np.eye(3))
    bad = np.eye(4)
    bad[0, 3] = np.inf
    with pytest.raises(InputError, match="finite"):
        robot.ik(bad)
    skew = np.eye(4)
    skew[0, 1] = 0.1
    with pytest.raises(InputError, match="orthonormal"):
        robot.ik(skew)
    with pytest.raises(InputError, match="q_near"):
        robot.ik(robot.fk(np.zeros(6)), q_near=np.zeros(4))
    with pytest.raises(InputError, match="Ts"):
        robot.ik_batch(np.eye(4))
    with pytest.raises(InputError, match=r"q_near: expected shape \(6,\) or \(2, 6\)"):
        robot.ik_batch(np.stack([np.eye(4)] * 2), q_near=np.zeros((3, 6)))


def test_unreachable_poses_say_why(robot: DHRobot) -> None:
    far = robot.fk(np.zeros(6))
    far[:3, 3] = [2.0, 0.0, 0.5]
    with pytest.raises(UnreachableError, match=r"out of reach by \d+\.\d mm"):
        robot.ik(far)
    # Reachable geometrically, but every configuration needs joint 1 at 30 or -150 deg, and this
    # copy of the MZ07 only allows +-20 deg on every joint.
    narrow = DHRobot(robot.dh, np.tile(np.radians([-20.0, 20.0]), (6, 1)))
    T = narrow.fk(np.array([math.radians(30.0), 0.1, 0.2, 0.0, 0.3, 0.0]))
    with pytest.raises(UnreachableError, match="outside the joint limits") as info:
        narrow.ik(T)
    assert "joint 1 = 30.0 deg outside [-20.0, 20.0] deg" in str(info.value)


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ([0.0] * 5, "expected 6 joint values"),
        ([[0.0] * 6], r"got shape \(1, 6\)"),
        ([0.0, [1.0, 2.0]], "expected joint values"),
        ("abc", "expected 6 joint values"),
        ([float("nan")] * 6, "finite"),
    ],
)
def test_joint_vector_names_the_field_and_what_is_wrong(value, message):
    with pytest.raises(InputError, match=message) as err:
        joint_vector(value, 6, "joints")
    assert str(err.value).startswith("joints: ")


def test_pick_solution_by_index_label_or_nearest():
    sols = [("front/elbow up/no flip", np.zeros(6)), ("back/elbow up/no flip", np.ones(6))]
    assert pick_solution(sols, None) is sols[0][1]
    assert pick_solution(sols, 1) is sols[1][1]
    assert pick_solution(sols, "back/elbow up/no flip") is sols[1][1]
    with pytest.raises(InputError, match="index 2 out of range; 2 solution"):
        pick_solution(sols, 2)
    with pytest.raises(UnreachableError, match="available"):
        pick_solution(sols, "front/elbow down/flip")


def test_branch_solutions_are_the_valid_branches_and_reach_the_pose():
    robot = preset_robot("mz07")
    rng = np.random.default_rng(7)
    lo, hi = robot.limits[:, 0], robot.limits[:, 1]
    for _ in range(50):
        q = rng.uniform(lo, hi)
        T = robot.fk(q)
        rows, branches = branch_solutions(robot, T, q)
        qb, valid = robot.ik_batch(T[None], q_near=q)
        assert branches.tolist() == np.flatnonzero(valid[0]).tolist()
        np.testing.assert_allclose(robot.fk(rows), np.broadcast_to(T, (len(rows), 4, 4)), atol=1e-9)
        assert np.min(np.abs(rows - q).max(axis=1)) < 1e-7, "the original is among them"
    far = np.eye(4)
    far[:3, 3] = [10.0, 0.0, 0.0]
    rows, branches = branch_solutions(robot, far)
    assert rows.shape == (0, 6) and branches.shape == (0,)


def test_labelled_solutions_are_every_configuration_and_turn_stable_across_picks():
    """Twin: brute force over every branch and every turn (`every_solution`), labelled from the
    controller joints; picking any solution leaves the list's labels and joints unchanged."""
    from workbench.kinematics.arm_configuration import arm_configuration, every_solution
    from workbench.kinematics.configurations import labelled_solutions

    robot = preset_robot("mz07")
    rng = np.random.default_rng(11)
    lo, hi = robot.limits[:, 0], robot.limits[:, 1]
    for _ in range(20):
        q = rng.uniform(lo, hi)
        T = robot.fk(q)
        found = labelled_solutions(robot, T, q)
        labels = [name for name, _ in found]
        assert len(set(labels)) == len(labels), labels
        brute = every_solution(robot, T)
        assert len(found) == len(brute)
        for name, qs in found:
            np.testing.assert_allclose(robot.fk(qs), T, atol=1e-9)
            assert name.split(", ")[0] == arm_configuration(robot, qs).label()
            j6 = np.degrees(robot.convention.to_controller(qs)[5])
            turn = int(np.ceil((j6 - 180.0 - 1e-9) / 360.0))
            assert ("J6 +1 turn" in name) == (turn == 1) and ("J6 -1 turn" in name) == (turn == -1)
            assert "elbow A" not in name and "elbow B" not in name
        assert np.abs(found[0][1] - q).max() < 1e-7, "nearest first"
        before = {name: qs for name, qs in found}
        for _name, qs in found[1:3]:
            again = dict(labelled_solutions(robot, T, qs))
            assert again.keys() == before.keys(), "labels do not depend on where the arm is"
            for k in before:
                np.testing.assert_allclose(again[k], before[k], atol=1e-9)
