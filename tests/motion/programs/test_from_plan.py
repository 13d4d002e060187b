"""The robot program of a planned motion (motion.programs.from_plan), against independent twins:
the trajectory sampled at each arrival, the input poses, and the IK of the target itself."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform, make_transform, rpy_to_matrix
from workbench.kinematics.arm_configuration import arm_configuration
from workbench.kinematics.robot_library import preset_robot
from workbench.motion import plan_program, time_program
from workbench.motion.program import motion_program
from workbench.motion.programs import (
    Comment,
    SetOutput,
    Signal,
    ToolData,
    WaitTime,
    WorkObject,
    check_program,
    robot_program,
)
from workbench.motion.programs.from_plan import arrival_indices, wait_holds

DEG = np.pi / 180


@dataclass(frozen=True, eq=False)
class Mv:  # the shape of the project's MoveSI
    name: str
    type: str
    joints: np.ndarray | None
    T_world_tcp: np.ndarray | None
    speed: float
    zone: float
    wobj: str = "base"


def _pose(xyz_mm: list[float]) -> np.ndarray:
    return make_transform(rpy_to_matrix(np.radians([180.0, 0.0, 0.0])), np.array(xyz_mm) / 1000)


@pytest.fixture(scope="module")
def planned():  # noqa: ANN201
    model = preset_robot("mz07")
    T_world_base = make_transform(rpy_to_matrix(np.radians([0, 0, 20])), [0.1, 0.05, 0.0])
    tool = ToolData("gripper", make_transform(np.eye(3), [0, 0, 0.15]), 2.0, np.array([0, 0, 0.06]))
    T_world_table = make_transform(rpy_to_matrix(np.radians([0, 0, 10])), [0.5, 0.0, 0.4])
    wobjs = (
        WorkObject("base", np.eye(4)),
        WorkObject("table", invert_transform(T_world_base) @ T_world_table),
    )
    q0 = np.radians([0, 0, 0, 0, -90, 0])
    grip = Signal("grip", 1)
    T_world_above = T_world_base @ _pose([430, 180, 580])
    items = [
        Comment("go"),
        Mv("above", "joint", None, T_world_above, 0.6, 0.02, "table"),
        Mv("pick", "linear", None, T_world_base @ _pose([430, 180, 495]), 0.15, 0.01, "table"),
        SetOutput(grip, True),  # an action after a blended move: it becomes an exact stop
        WaitTime(0.25),
        Mv("lift", "linear", None, T_world_base @ _pose([430, 180, 580]), 0.25, 0.03),
        Mv("over", "linear", None, T_world_base @ _pose([430, -180, 580]), 0.4, 0.0),
        Mv("home", "joint", q0, None, 0.8, 0.0),
        Mv("home", "joint", q0, None, 1.0, 0.0),
    ]
    prog = motion_program("pp", items, model, T_world_base, tool.T_flange_tcp, q0)
    path = plan_program(model, prog, q0, model.max_velocity, T_flange_tcp=tool.T_flange_tcp)
    traj = time_program(
        path, model.max_acceleration, model.max_jerk, position_limits=model.limits
    ).with_holds(wait_holds(items, path))  # as the service plans: the 0.25 s wait held
    rp = robot_program(
        items, prog, path, traj, model, tool=tool, work_objects=wobjs, T_world_base=T_world_base
    )
    return model, items, prog, path, traj, rp, wobjs, tool, T_world_base


def test_zones_stop_before_actions_and_pose_joint_moves_take_the_nearest_ik(planned) -> None:  # noqa: ANN001
    model, items, prog, *_, tool, T_world_base = planned
    assert [m.zone for m in prog.moves] == [0.02, 0.0, 0.03, 0.0, 0.0, 0.0]
    T_base_flange = (
        invert_transform(T_world_base) @ items[1].T_world_tcp @ invert_transform(tool.T_flange_tcp)
    )
    sols = model.ik(T_base_flange, q_near=np.radians([0, 0, 0, 0, -90, 0]))
    assert np.allclose(prog.moves[0].q, sols[0])
    assert np.allclose(model.fk(prog.moves[0].q), T_base_flange, atol=1e-9)


def test_durations_are_the_times_between_arrivals_and_add_up(planned) -> None:  # noqa: ANN001
    model, items, prog, path, traj, rp, *_ = planned
    durations = [m.duration for m in rp.moves]
    pick = int(arrival_indices(path, len(rp.moves))[1])
    assert wait_holds(items, path) == [(pick, 0.25)]  # held where "pick" arrives
    assert sum(durations) == pytest.approx(traj.duration - 0.25, abs=1e-12)
    assert all(d >= 0 for d in durations)
    # twin: the trajectory itself is at each exact-stop target when its duration (and the
    # wait after "pick", the second move) has elapsed, and still during the wait
    t = np.cumsum(durations) + np.where(np.arange(len(durations)) >= 2, 0.25, 0.0)
    for k, mv in enumerate(rp.moves):
        if mv.zone == 0.0:
            q_at, qd_at, _ = traj.at([t[k]])
            assert np.allclose(q_at[0], mv.target.q, atol=1e-7), mv.name
            assert np.allclose(qd_at[0], 0.0, atol=1e-6), mv.name
    q_wait, qd_wait, _ = traj.at(np.linspace(t[1], t[1] + 0.25, 7))
    assert np.allclose(q_wait, rp.moves[1].target.q, atol=1e-7) and np.abs(qd_wait).max() < 1e-9
    assert rp.cycle_time == pytest.approx(traj.duration)


def test_targets_are_the_given_poses_in_their_work_objects(planned) -> None:  # noqa: ANN001
    model, items, prog, path, traj, rp, wobjs, tool, T_world_base = planned
    moves = [i for i in items if isinstance(i, Mv)]
    names = [m.name for m in rp.moves]
    assert names == ["above", "pick", "lift", "over", "home", "home_2"]
    for src, mv in zip(moves, rp.moves, strict=True):
        assert mv.wobj == src.wobj and mv.tool == "gripper"
        if src.T_world_tcp is None:
            assert not mv.target.cartesian and np.allclose(mv.target.q, src.joints)
            continue
        T_wobj = {w.name: w for w in wobjs}[src.wobj].T_base_wobj
        want = invert_transform(T_world_base @ T_wobj) @ src.T_world_tcp  # from the input pose
        assert np.allclose(mv.target.T_wobj_tcp, want, atol=1e-9), mv.name
        assert mv.target.configuration == arm_configuration(model, mv.target.q)
    # "lift" is blended (30 mm) into "over": the trajectory passes beside it, the target's
    # joints are the IK of the target pose itself, nearest where the planner turned
    lift = rp.moves[2]
    T_flange = (
        invert_transform(T_world_base) @ moves[2].T_world_tcp @ invert_transform(tool.T_flange_tcp)
    )
    assert np.allclose(model.fk(lift.target.q), T_flange, atol=1e-9)
    assert [w.name for w in rp.work_objects] == ["base", "table"]
    check_program(rp, needs_mass=True)  # within the default limits, tool with mass


def test_actions_keep_their_order(planned) -> None:  # noqa: ANN001
    rp = planned[5]
    kinds = [type(i).__name__ for i in rp.instructions]
    assert kinds == [
        "Comment", "MoveInstr", "MoveInstr", "SetOutput", "WaitTime",
        "MoveInstr", "MoveInstr", "MoveInstr", "MoveInstr",
    ]  # fmt: skip


def test_bad_moves_name_their_item() -> None:
    model = preset_robot("mz07")
    q0 = np.radians([0, 0, 0, 0, -90, 0])
    with pytest.raises(
        # Said in the controller's values: model J2 200 deg is the pendant's 290 (offset 90).
        InputError,
        match=r"program.moves\[1\] \(far\).joints\[1\]: 290 deg is outside the joint limits"
        r" \[-45.0, 170.0\] deg",
    ):
        motion_program(
            "p", [Comment("x"), Mv("far", "joint", np.radians([0, 200, 0, 0, 0, 0]), None, 1.0, 0.0)],
            model, np.eye(4), np.eye(4), q0,
        )  # fmt: skip
    with pytest.raises(InputError, match="no moves"):
        motion_program("p", [Comment("x")], model, np.eye(4), np.eye(4), q0)
