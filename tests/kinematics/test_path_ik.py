"""`follow_path`: one arm configuration along a pose sequence, against per-pose IK and pinocchio FK."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from workbench.errors import PlanningError, UnreachableError
from workbench.geometry.transforms import make_transform, rpy_to_matrix
from workbench.kinematics import PathIK, RobotModel, URDFRobot, branch_name, follow_path
from workbench.kinematics.robot_library import preset_robot

ROBOT = preset_robot("mz07")
Q0 = np.radians([0.0, 10.0, 10.0, 0.0, -70.0, 0.0])


def _line(n: int = 30, x: float = 0.45, turn: float = 0.0) -> np.ndarray:
    """Flange poses (n, 4, 4) along a 200 mm line, flange z down, turning `turn` rad about z."""
    return np.stack(
        [
            make_transform(rpy_to_matrix([np.pi, 0.0, u * turn]), [x, -0.1 + 0.2 * u, 0.25])
            for u in np.linspace(0.0, 1.0, n)
        ]
    )


def _pin_fk(q: np.ndarray) -> np.ndarray:
    model, data = ROBOT.pinocchio_model()
    fid = model.getFrameId("flange")
    out = []
    for qi in q:
        pin.forwardKinematics(model, data, qi)
        out.append(pin.updateFramePlacement(model, data, fid).homogeneous)
    return np.array(out)


def test_both_robot_classes_are_robot_models() -> None:
    assert isinstance(ROBOT, RobotModel)
    members = ("is_analytic", "ik_batch", "link_meshes", "ik", "fk", "link_transforms")
    assert all(hasattr(URDFRobot, m) for m in members)


def test_one_configuration_reproduces_the_poses_and_matches_brute_force() -> None:
    T = _line(turn=3.0)
    r = follow_path(ROBOT, T, Q0, max_joint_step=0.2)
    assert isinstance(r, PathIK) and r.configuration == branch_name(ROBOT, r.q[0])
    # Twin 1: pinocchio's FK of the joints is the target pose.
    np.testing.assert_allclose(_pin_fk(r.q), T, atol=1e-9)
    assert r.max_step == pytest.approx(np.abs(np.diff(r.q, axis=0)).max())
    # Twin 2 (brute force): per pose, every turn variant of every solution; the path's row
    # is one of them, and the branch is the one whose first-pose solution is nearest Q0
    # among the branches valid at every pose.
    for Ti, qi in zip(T, r.q, strict=True):
        sols = ROBOT.ik_all(Ti)
        assert np.min(np.abs(sols - qi).max(axis=1)) < 1e-9
    qb, valid = ROBOT.ik_batch(T, q_near=Q0)
    ok = np.flatnonzero(valid.all(axis=0))
    d0 = [np.linalg.norm(qb[0, b] - Q0) for b in ok]
    assert r.branch == ok[int(np.argmin(d0))]
    # Continuous: the wrist turns 3 rad without a 2 pi jump.
    assert np.abs(np.diff(r.q, axis=0)).max() < 0.2


def test_total_cost_picks_the_branch_nearest_over_all_poses() -> None:
    T = _line(n=5)
    r = follow_path(ROBOT, T, Q0, cost="total")
    qb, valid = ROBOT.ik_batch(T, q_near=Q0)
    ok = np.flatnonzero(valid.all(axis=0))
    total = [np.linalg.norm(qb[:, b] - Q0, axis=1).sum() for b in ok]
    assert r.branch == ok[int(np.argmin(total))]


def test_nearest_tracking_equals_per_pose_ik() -> None:
    T = _line()
    r = follow_path(ROBOT, T, Q0, track="nearest")
    prev = Q0
    for Ti, qi in zip(T, r.q, strict=True):
        sols = ROBOT.ik(Ti, q_near=prev)
        prev = sols[np.argmin(np.linalg.norm(sols - prev, axis=1))]
        np.testing.assert_array_equal(qi, prev)
    assert r.branch == -1 and r.configuration == "nearest solution"


def test_unreachable_pose_is_named_with_label_and_position() -> None:
    T = _line()
    T[7, :3, 3] = [2.0, 0.0, 0.25]
    labels = [f"process point {i + 1}" for i in range(len(T))]
    with pytest.raises(
        UnreachableError, match=r"my path: process point 8 at \[2000.0, 0.0, 250.0\]"
    ):
        follow_path(ROBOT, T, Q0, labels=labels, what="my path")
    with pytest.raises(UnreachableError, match=r"pose 8 of 30 at \[1.0, 2.0, 3.0\] mm.*; fix it"):
        follow_path(ROBOT, T, Q0, points=np.full((30, 3), 1e-3) * [1, 2, 3], hint="fix it")
    # Twin: the named pose is the first with no per-pose IK solution at all.
    first = next(i for i, Ti in enumerate(T) if _unreachable(Ti))
    assert first == 7


def _unreachable(T: np.ndarray) -> bool:
    try:
        ROBOT.ik(T)
    except UnreachableError:
        return True
    return False


def test_a_joint_jump_is_refused_naming_the_point() -> None:
    with pytest.raises(PlanningError, match=r"pose 2 of 3 .* joint jump"):
        follow_path(ROBOT, _line(n=3), Q0, max_joint_step=1e-4)


class _Numeric:
    """The MZ07 seen as a numeric model: same `ik`, no branches."""

    is_analytic = False

    def __getattr__(self, name: str) -> object:
        return getattr(ROBOT, name)


def test_numeric_models_follow_the_nearest_solution() -> None:
    T = _line()
    r = follow_path(_Numeric(), T, Q0)  # type: ignore[arg-type]
    np.testing.assert_allclose(ROBOT.fk(r.q), T, atol=1e-9)
    assert r.branch == -1 and r.max_step < 0.2
    T[3, :3, 3] = [2.0, 0.0, 0.25]
    with pytest.raises(UnreachableError, match=r"pose 4 of 30 at \[2000.0"):
        follow_path(_Numeric(), T, Q0)  # type: ignore[arg-type]


def test_bad_input_says_the_shape() -> None:
    from workbench.errors import InputError

    with pytest.raises(InputError, match=r"\(N, 4, 4\)"):
        follow_path(ROBOT, np.eye(4), Q0)
    with pytest.raises(InputError, match="q_near"):
        follow_path(ROBOT, _line(n=2), np.zeros(5))
