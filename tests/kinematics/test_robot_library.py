"""The robot library (issue 23): each robot against its published data and independent twins.

- reach: the DH rows' reach to the wrist centre (a1 + c2 + |(a2, c3)| for OPW arms) is the
  data sheet's (ABB IRB 1200-7/0.7 703 mm, KUKA KR 6 R900-2 901 mm, FANUC M-10iA 1420 mm);
- FK at the controller's home/zero posture is the published flange position: ABB's URDF
  tool0 (433, 0, 791.1) mm at zero, KUKA's (535, 0, 880) at HOME (0, -90, 90, 0, 0, 0) and
  (990, 0, 425) at zero, FANUC's URDF tool0 (890, 0, 1250) at zero, UR's (-817.2, -232.9,
  62.8) at zero (UR's DH table: x = a2 + a3, y = -(d4 + d6), z = d1 - d5);
- FK of the DH rows equals opw_kinematics' own forward kinematics (written here from the
  paper and that library: sign corrections, offsets, c1..c4, a1, a2, b) at random ROS joints,
  and pinocchio's at random joints;
- IK round trip on 1,000 seeded poses per robot: every solution within limits with
  fk == T (1e-9) and the original joints among them (modulo turns);
- the conventions put the vendors' documented postures where the vendors say.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pinocchio as pin
import pytest
from mesh_overlap import fcl_overlap

from workbench.errors import InputError
from workbench.kinematics import IK_TOL, JointConvention
from workbench.kinematics.arm_configuration import arm_configuration
from workbench.kinematics.robot_library import LIBRARY, ROBOT_NAMES, library_robot, preset_robot
from workbench.motion.programs.fanuc import config_text
from workbench.motion.programs.krl import status_turn
from workbench.motion.programs.rapid import confdata

DEG = math.pi / 180.0
# (a1, a2, b, c1, c2, c3, c4) [m], offsets [rad], sign corrections: the ROS-I OPW files
OPW = {
    "irb1200_7_70": (
        (0.0, -0.042, 0.0, 0.3991, 0.350, 0.351, 0.082),
        (0, 0, -math.pi / 2, 0, 0, 0),
        (1, 1, 1, 1, 1, 1),
    ),
    "kr6_r900_2": (
        (0.025, -0.025, 0.0, 0.400, 0.455, 0.420, 0.090),
        (0, -math.pi / 2, 0, 0, 0, 0),
        (-1, 1, 1, -1, 1, -1),
    ),
    "m10ia": (
        (0.150, -0.200, 0.0, 0.450, 0.600, 0.640, 0.100),
        (0, 0, -math.pi / 2, 0, 0, math.pi),
        (1, 1, -1, -1, -1, -1),
    ),
}
REACH_MM = {"irb1200_7_70": 703.0, "kr6_r900_2": 901.0, "m10ia": 1420.0}
FLANGE_AT = {  # controller joints [deg] -> flange position [mm] (sources in the docstring)
    "irb1200_7_70": [((0, 0, 0, 0, 0, 0), (433.0, 0.0, 791.1))],
    "kr6_r900_2": [((0, -90, 90, 0, 0, 0), (535.0, 0.0, 880.0)), ((0,) * 6, (990.0, 0, 425.0))],
    "m10ia": [((0, 0, 0, 0, 0, 0), (890.0, 0.0, 1250.0))],
    "ur5e": [((0, 0, 0, 0, 0, 0), (-817.2, -232.9, 62.8))],
    "mz07": [((0, 90, 0, 0, 0, 0), (468.0, 0.0, 730.0))],  # 50+340+78, 355+330+45
}


def opw_forward(params, offsets, signs, q_ros) -> np.ndarray:  # noqa: ANN001
    """Return base -> flange (4, 4) of ROS joints: opw_kinematics' forward(), re-derived."""
    a1, a2, b, c1, c2, c3, c4 = params
    q = [s * x - o for s, x, o in zip(signs, q_ros, offsets, strict=True)]
    psi3, k = math.atan2(a2, c3), math.hypot(a2, c3)
    cx1 = c2 * math.sin(q[1]) + k * math.sin(q[1] + q[2] + psi3) + a1
    cz1 = c2 * math.cos(q[1]) + k * math.cos(q[1] + q[2] + psi3)
    s1, co1 = math.sin(q[0]), math.cos(q[0])
    c = np.array([cx1 * co1 - b * s1, cx1 * s1 + b * co1, cz1 + c1])
    s23, c23 = math.sin(q[1] + q[2]), math.cos(q[1] + q[2])
    R0c = np.array([[co1 * c23, -s1, co1 * s23], [s1 * c23, co1, s1 * s23], [-s23, 0, c23]])
    s4, c4_, s5, c5, s6, c6 = (f(q[j]) for j in (3, 4, 5) for f in (math.sin, math.cos))
    Rce = np.array(
        [
            [c4_ * c5 * c6 - s4 * s6, -c4_ * c5 * s6 - s4 * c6, c4_ * s5],
            [s4 * c5 * c6 + c4_ * s6, -s4 * c5 * s6 + c4_ * c6, s4 * s5],
            [-s5 * c6, s5 * s6, c5],
        ]
    )
    T = np.eye(4)
    T[:3, :3] = R0c @ Rce
    T[:3, 3] = c + c4 * T[:3, 2]
    return T


def ros_to_controller(name: str, q_ros: np.ndarray) -> np.ndarray:
    """Return the controller's joints of ROS-I joints (FANUC: ctrl J3 = ros J3 - ros J2)."""
    q = np.array(q_ros, float)
    if name == "m10ia":
        q[2] -= q[1]
    return q


@pytest.mark.parametrize("name", ROBOT_NAMES)
def test_fk_at_the_published_postures(name: str) -> None:
    robot = preset_robot(name)
    for q_deg, xyz in FLANGE_AT[name]:
        q = robot.convention.to_model(np.radians(q_deg))
        assert np.allclose(robot.fk(q)[:3, 3] * 1000, xyz, atol=0.05), (name, q_deg)
    if name in REACH_MM:
        a1, a2, _, _, c2, c3, _ = OPW[name][0]
        assert abs((a1 + c2 + math.hypot(a2, c3)) * 1000 - REACH_MM[name]) < 1.0
        g = robot.opw
        assert g is not None and abs((g.a1 + g.a2 + g.K) * 1000 - REACH_MM[name]) < 1.0


@pytest.mark.parametrize("name", sorted(OPW))
def test_fk_is_opw_kinematics_forward(name: str) -> None:
    params, offsets, signs = OPW[name]
    robot = preset_robot(name)
    rng = np.random.default_rng(1)
    for q_ros in rng.uniform(-math.pi, math.pi, (200, 6)):
        q_model = robot.convention.to_model(ros_to_controller(name, q_ros))
        assert np.allclose(
            robot.fk(q_model), opw_forward(params, offsets, signs, q_ros), atol=1e-12
        )


@pytest.mark.parametrize("name", ROBOT_NAMES)
def test_fk_matches_pinocchio_and_meshes_are_sane(name: str) -> None:
    robot = preset_robot(name)
    model, data = robot.pinocchio_model()
    fid = model.getFrameId("flange")
    rng = np.random.default_rng(2)
    qs = rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (200, 6))
    batch = robot.fk(qs)
    for q, T in zip(qs, batch, strict=True):
        pin.forwardKinematics(model, data, q)
        assert np.allclose(pin.updateFramePlacement(model, data, fid).homogeneous, T, atol=1e-12)
    meshes = robot.link_meshes()
    reach = LIBRARY[name].reach_mm / 1000
    assert len(meshes) == 7 and all(m.is_watertight for m in meshes)
    assert all(0.02 * reach < max(m.extents) < 1.2 * reach for m in meshes)


@pytest.mark.parametrize("name", ROBOT_NAMES)
def test_ik_round_trip_1000_poses(name: str) -> None:
    robot = preset_robot(name)
    rng = np.random.default_rng(3)
    lo, hi = robot.limits[:, 0], robot.limits[:, 1]
    qs = rng.uniform(lo, hi, (3000, 6))
    qs = qs[robot.within_limits(qs)][:1000]
    assert len(qs) == 1000
    worst, t0 = 0.0, time.perf_counter()
    for q in qs:
        T = robot.fk(q)
        sols = robot.ik(T, q_near=q)
        assert np.all(robot.within_limits(sols))
        worst = max(worst, float(np.abs(robot.fk(sols) - T).max()))
        wrapped = (sols - q + math.pi) % (2 * math.pi) - math.pi
        assert np.abs(wrapped).max(axis=1).min() < 1e-7, (name, np.degrees(q))
    assert worst < IK_TOL
    print(f"{name}: worst |fk - T| {worst:.1e}, {(time.perf_counter() - t0) / 1e3 * 1e6:.0f} us")


@pytest.mark.parametrize("name", ROBOT_NAMES)
def test_link_shapes_touch_neighbours_and_keep_two_apart_at_home(name: str) -> None:
    robot = preset_robot(name)
    q = robot.convention.to_model(np.radians(LIBRARY[name].home_deg))
    frames = robot.link_transforms(q)
    world = [m.copy().apply_transform(F) for m, F in zip(robot.link_meshes(), frames, strict=True)]
    for i in range(robot.dof):
        assert fcl_overlap(world[i], world[i + 1]), (name, i, i + 1)
    # pairs two or more apart in contact at home: the collision checker disables the pairs in
    # contact at its reference posture, as MoveIt's "default" collisions. The generated shapes
    # touch there only where the real arms are compact: FANUC's wrist (a 100 mm flange
    # distance), UR's shoulder on its base and its offset wrist.
    touching = [
        (i, j) for i in range(7) for j in range(i + 2, 7) if fcl_overlap(world[i], world[j])
    ]
    assert touching == {"m10ia": [(4, 6)], "ur5e": [(0, 2), (3, 5)]}.get(name, []), name


def test_ur5e_has_the_closed_form_ik_checked_by_pinocchio() -> None:
    robot = preset_robot("ur5e")
    assert robot.ur is not None and not robot.is_analytic
    model, data = robot.pinocchio_model()
    fid = model.getFrameId("flange")
    rng = np.random.default_rng(4)
    counts = []
    for q in rng.uniform(-math.pi, math.pi, (200, 6)):
        T = robot.fk(q)
        sols = robot.ik(T)
        counts.append(len(sols))
        for s in sols:
            pin.forwardKinematics(model, data, s)
            assert np.allclose(pin.updateFramePlacement(model, data, fid).homogeneous, T, atol=1e-9)
    assert max(counts) == 8


def test_conventions_put_the_vendors_postures_where_the_vendors_say() -> None:
    # ABB: tool0 at the calibration position points forward, x down: quaternion
    # [0.707107, 0, 0.707107, 0] (RAPID's home robtargets); J5 = +90 points it down.
    abb = preset_robot("irb1200_7_70")
    R = abb.fk(np.zeros(6))[:3, :3]
    assert np.allclose(R, [[0, 0, 1], [0, 1, 0], [-1, 0, 0]], atol=1e-12)
    assert np.allclose(abb.fk(np.radians([0, 0, 0, 0, 90, 0]))[:3, 2], [0, 0, -1], atol=1e-12)
    # KUKA: A1 positive turns the arm clockwise seen from above (towards -y); A5 positive
    # points the flange down at HOME.
    kuka = preset_robot("kr6_r900_2")
    conv = kuka.convention
    assert kuka.fk(conv.to_model(np.radians([30, -90, 90, 0, 0, 0])))[1, 3] < -0.2
    T = kuka.fk(conv.to_model(np.radians([0, -90, 90, 0, 90, 0])))
    assert np.allclose(T[:3, 2], [0, 0, -1], atol=1e-12)
    # FANUC: J3 counts from the horizontal, so J2 alone leaves the forearm's direction;
    # J5 = -90 points the flange down.
    fanuc = preset_robot("m10ia")
    for j2 in (-40.0, 0.0, 60.0):
        F = fanuc.link_transforms(fanuc.convention.to_model(np.radians([0, j2, 0, 0, 0, 0])))
        assert np.allclose(F[3, :3, 2], [1, 0, 0], atol=1e-12)  # axis 4 horizontal, forward
    T = fanuc.fk(fanuc.convention.to_model(np.radians([0, 0, 0, 0, -90, 0])))
    assert np.allclose(T[:3, 2], [0, 0, -1], atol=1e-12)
    # UR: "home" (0, -90, 0, -90, 0, 0) stands the arm upright
    ur = preset_robot("ur5e")
    F = ur.link_transforms(np.radians([0, -90, 0, -90, 0, 0]))
    assert np.allclose(F[3, :2, 3], F[1, :2, 3], atol=1e-12) and F[3, 2, 3] > 0.9


def test_fanuc_coupling_is_exact_and_limits_are_the_controllers() -> None:
    fanuc = preset_robot("m10ia")
    conv, lim = fanuc.convention, fanuc.controller_limits
    assert lim is not None
    rng = np.random.default_rng(5)
    q = rng.uniform(-3, 3, (1000, 6))
    assert np.abs(conv.to_model(conv.to_controller(q)) - q).max() < 1e-14
    # controller J2 = 60, J3 = 100 deg is inside (model J3 = -(J3 + J2) = -160 deg); model
    # J2 = 100, J3 = 120 deg lies in the model's box but is controller J3 = -220 deg: refused
    ok = conv.to_model(np.radians([0, 60, 100, 0, 0, 0]))
    bad = np.radians([0, 100, 120, 0, 0, 0])
    assert np.isclose(conv.to_controller(bad)[2], -220 * DEG)
    assert fanuc.within_limits(ok) and not fanuc.within_limits(bad)
    assert np.all((bad >= fanuc.limits[:, 0]) & (bad <= fanuc.limits[:, 1]))
    with pytest.raises(InputError, match="strictly lower triangular"):
        JointConvention(offset=np.zeros(2), sign=np.ones(2), coupling=[[0, 1], [0, 0]])


def test_configuration_data_follow_the_vendors_rules() -> None:
    abb = preset_robot("irb1200_7_70")
    for q_deg, want in (
        ((0, 0, 0, 0, 30, 0), (0, 0, 0, 0)),  # the usual pose: ABB's cfx 0
        ((0, 0, 0, 0, -30, 0), (0, 0, 0, 1)),  # axis 5 negative
        ((0, 60, -130, 0, 30, 0), (0, 0, 0, 2)),  # forearm past stretched (J3 < -96.8 deg)
        ((0, 0, -120, 0, 30, 0), (0, 0, 0, 6)),  # ... and the wrist centre behind axis 1
        ((0, -90, 30, 0, 30, 0), (0, 0, 0, 4)),  # behind axis 1, in front of the lower arm
        ((100, 0, 0, 200, 30, -100), (1, 2, -2, 0)),  # quadrants of axes 1, 4, 6
    ):
        q = np.radians(q_deg)
        assert confdata(q, arm_configuration(abb, q)) == want, q_deg
    kuka = preset_robot("kr6_r900_2")
    for q_deg, want in (
        ((0, -90, 90, 0, 30, 0), (2, 2)),  # HOME: S 'B010', T 'B000010' (A2 < 0)
        ((0, -90, 90, 0, -30, 0), (6, 18)),  # A5 negative: S bit 2, T bit 4
        ((0, -30, -30, 0, 30, 0), (0, 6)),  # A3 below the stretched arm: S bit 1 clear
        ((0, -30, 30, 0, 30, 0), (2, 2)),
        ((0, -90, -30, 0, 30, 0), (1, 6)),  # wrist centre behind A1 (overhead): S bit 0
    ):
        q = kuka.convention.to_model(np.radians(q_deg))
        assert status_turn(arm_configuration(kuka, q), np.radians(q_deg)) == want, q_deg


def test_fanuc_configuration_strings() -> None:
    fanuc = preset_robot("m10ia")
    for q_deg, want in (
        ((0, 0, 0, 0, -90, 0), "N U T, 0, 0, 0"),  # the usual tool-down posture
        ((0, 0, 0, 0, 30, 0), "F U T, 0, 0, 0"),  # J5 positive: flipped
        ((0, 30, 100, 0, -30, 0), "N D T, 0, 0, 0"),  # forearm above the stretched arm
        ((0, -80, 100, 0, -30, 0), "N U B, 0, 0, 0"),  # wrist centre behind J1
        ((170, 0, 0, -185, -90, 200), "N U T, 0, -1, 1"),  # turn numbers of J1, J4, J6
    ):
        q = fanuc.convention.to_model(np.radians(q_deg))
        assert config_text(arm_configuration(fanuc, q), np.radians(q_deg)) == want, q_deg


def test_preset_names_and_errors() -> None:
    assert preset_robot("mz07").name == preset_robot("mz07").name == "NACHI MZ07"
    assert np.array_equal(preset_robot("mz07").dh, preset_robot("mz07").dh)
    with pytest.raises(InputError) as err:
        library_robot("irb6700")
    assert all(n in str(err.value) for n in ROBOT_NAMES)
    from workbench.project.models import PRESETS, PresetName

    assert PresetName.__args__ == PRESETS == ROBOT_NAMES  # type: ignore[attr-defined]
