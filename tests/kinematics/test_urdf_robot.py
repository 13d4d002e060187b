"""URDFRobot: the MZ07 written as a URDF (box links) has the same FK as preset_robot("mz07")."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError, MeshError, UnreachableError
from workbench.geometry.transforms import matrix_to_rpy
from workbench.kinematics import DHRobot
from workbench.kinematics.dh_chain import dh_fixed_part
from workbench.kinematics.robot_library import preset_robot
from workbench.kinematics.urdf_robot import URDFRobot


def origin(T: np.ndarray) -> str:
    xyz = " ".join(f"{v:.17g}" for v in T[:3, 3])
    rpy = " ".join(f"{v:.17g}" for v in matrix_to_rpy(T[:3, :3]))
    return f'<origin xyz="{xyz}" rpy="{rpy}"/>'


def mz07_urdf(robot: DHRobot, mesh_file: str | None = None) -> str:
    """Joint i sits at B_(i-1) = Rz(offset) Tz(d) Tx(a) Rx(alpha) of the row before; axis z."""
    B = dh_fixed_part(robot.dh)
    link6_geom = (
        f'<mesh filename="{mesh_file}" scale="1 1 1"/>'
        if mesh_file
        else '<box size="0.05 0.05 0.05"/>'
    )
    parts = [
        '<robot name="mz07_urdf">',
        '<link name="base_link"><collision><geometry>'
        '<cylinder radius="0.1" length="0.2"/></geometry></collision></link>',
    ]
    parent = "base_link"
    for i in range(6):
        geom = link6_geom if i == 5 else '<box size="0.1 0.08 0.06"/>'
        parts.append(
            f'<link name="link_{i + 1}"><collision><geometry>{geom}</geometry></collision></link>'
        )
        place = np.eye(4) if i == 0 else B[i - 1]
        lo, hi = robot.limits[i]
        parts.append(
            f'<joint name="j{i + 1}" type="revolute"><parent link="{parent}"/>'
            f'<child link="link_{i + 1}"/>{origin(place)}<axis xyz="0 0 1"/>'
            f'<limit lower="{lo:.17g}" upper="{hi:.17g}" effort="100" velocity="{robot.max_velocity[i]:.17g}"/></joint>'
        )
        parent = f"link_{i + 1}"
    parts.append('<link name="flange"/>')
    parts.append(
        f'<joint name="flange_joint" type="fixed"><parent link="link_6"/><child link="flange"/>{origin(B[5])}</joint>'
    )
    parts.append("</robot>")
    return "\n".join(parts)


@pytest.fixture(scope="module")
def dh_robot() -> DHRobot:
    return preset_robot("mz07")


@pytest.fixture()
def urdf_path(tmp_path: Path, dh_robot: DHRobot) -> Path:
    trimesh.creation.box(extents=[0.02, 0.03, 0.04]).export(tmp_path / "tool.stl")
    p = tmp_path / "mz07.urdf"
    p.write_text(mz07_urdf(dh_robot, "tool.stl"))
    return p


def test_urdf_fk_equals_dh_fk(urdf_path: Path, dh_robot: DHRobot) -> None:
    robot = URDFRobot.from_file(urdf_path)
    assert robot.dof == 6 and robot.tip_frame == "flange"
    np.testing.assert_allclose(robot.limits, dh_robot.limits, atol=1e-15)
    np.testing.assert_allclose(robot.max_velocity, dh_robot.max_velocity)
    rng = np.random.default_rng(0)
    Q = rng.uniform(dh_robot.limits[:, 0], dh_robot.limits[:, 1], (200, 6))
    np.testing.assert_allclose(robot.fk(Q), dh_robot.fk(Q), atol=1e-12)
    np.testing.assert_allclose(
        robot.fk(Q[:6].reshape(2, 3, 6)), dh_robot.fk(Q[:6]).reshape(2, 3, 4, 4), atol=1e-12
    )
    F = robot.link_transforms(Q[:5])
    assert F.shape == (5, 7, 4, 4)
    np.testing.assert_allclose(F[:, 0], np.broadcast_to(np.eye(4), (5, 4, 4)))
    # Body i's frame is DH frame i-1 turned by q_i: same origin as DH frame i-1.
    np.testing.assert_allclose(
        F[:, 1:, :3, 3], dh_robot.link_transforms(Q[:5])[:, :-1, :3, 3], atol=1e-12
    )


def test_urdf_jacobian_and_ik(urdf_path: Path, dh_robot: DHRobot) -> None:
    robot = URDFRobot.from_file(urdf_path)
    q = np.radians([10.0, -20.0, 30.0, 40.0, -50.0, 60.0])
    np.testing.assert_allclose(robot.jacobian(q), dh_robot.jacobian(q), atol=1e-12)
    T = dh_robot.fk(q)
    sols = robot.ik(T, q_near=q + 0.05)
    np.testing.assert_allclose(sols[0], q, atol=1e-6)
    # Every numeric solution is one of the analytic ones.
    analytic = dh_robot.ik_all(T)
    for s in sols:
        assert np.abs(analytic - s).max(axis=1).min() < 1e-6
    far = np.eye(4)
    far[:3, 3] = [3.0, 0, 0]
    with pytest.raises(UnreachableError, match="numeric IK"):
        robot.ik(far)


def test_urdf_link_meshes(urdf_path: Path) -> None:
    meshes = URDFRobot.from_file(urdf_path).link_meshes()
    assert len(meshes) == 7
    np.testing.assert_allclose(meshes[0].extents, [0.2, 0.2, 0.2], atol=1e-3)
    np.testing.assert_allclose(meshes[1].extents, [0.1, 0.08, 0.06], atol=1e-9)
    np.testing.assert_allclose(meshes[6].extents, [0.02, 0.03, 0.04], atol=1e-9)  # the STL


def test_urdf_bad_inputs(tmp_path: Path, dh_robot: DHRobot) -> None:
    with pytest.raises(InputError, match="does not exist"):
        URDFRobot.from_file(tmp_path / "missing.urdf")
    broken = tmp_path / "broken.urdf"
    broken.write_text("<robot name='x'><link name='a'>")
    with pytest.raises(InputError, match="cannot read URDF"):
        URDFRobot.from_file(broken)
    no_mesh = tmp_path / "no_mesh.urdf"
    no_mesh.write_text(mz07_urdf(dh_robot, "not_there.stl"))
    with pytest.raises(MeshError):
        URDFRobot.from_file(no_mesh).link_meshes()
    good = tmp_path / "good.urdf"
    good.write_text(mz07_urdf(dh_robot))
    with pytest.raises(InputError, match="tip_link"):
        URDFRobot.from_file(good, tip_link="nope")
    robot = URDFRobot.from_file(good)
    with pytest.raises(InputError, match="q"):
        robot.fk(np.zeros(5))
