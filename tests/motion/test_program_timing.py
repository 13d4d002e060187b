"""How the workflows time the moves their plans do not (issue 12: the read-back program planned
again takes the planned time): the motion planner's own durations, the fitted speed of a
straight move, polishing's blend radii, a near-zero first move, NACHI's file names per robot."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from program_round_trip import sample_program

from workbench.kinematics import DHRobot
from workbench.kinematics.robot_library import preset_robot
from workbench.motion import Move, Program, plan_program, time_program
from workbench.motion.programs.formats import write_programs
from workbench.motion.programs.from_plan import (
    FIT_TOLERANCE,
    fit_linear_speed,
    planner_durations,
)
from workbench.motion.programs.nachi import unit_name
from workbench.motion.programs.names import controller_model, nachi_file_name
from workbench.motion.trajectory import DUPLICATE_TOL
from workbench.polishing.program import BLEND_LEVELS, BLEND_ZONE, corner_zones

DEG = np.pi / 180.0
Q0 = np.array([0.0, 10.0, 20.0, 0.0, -60.0, 0.0]) * DEG


def _line_target(model: DHRobot, dx: float) -> np.ndarray:
    T = model.fk(Q0).copy()
    T[0, 3] += dx
    return T


def test_planner_durations_are_the_plans_arrivals() -> None:
    model = preset_robot("mz07")
    q1 = Q0 + np.array([30.0, -10.0, 5.0, 20.0, 10.0, -40.0]) * DEG
    prog = Program(
        "p", (Move.joint(q1, speed=0.5), Move.linear(_line_target(model, 0.05), speed=0.1))
    )
    got = planner_durations(model, prog, Q0, np.eye(4))
    path = plan_program(model, prog, Q0, model.max_velocity)
    traj = time_program(path, model.max_acceleration, model.max_jerk, position_limits=model.limits)
    assert got.sum() == pytest.approx(traj.duration, abs=1e-12)
    end0 = np.flatnonzero(path.move_index == 0)[-1]
    assert got[0] == pytest.approx(traj.waypoint_times[end0], abs=1e-12)


def test_fit_linear_speed_gives_the_duration_at_the_slowest_speed() -> None:
    model = preset_robot("mz07")
    T = _line_target(model, 0.08)

    def took(v: float) -> float:
        prog = Program("p", (Move.linear(T, speed=v),))
        return float(planner_durations(model, prog, Q0, np.eye(4))[0])

    wanted = took(0.12)  # a duration the planner takes at 120 mm/s
    v = fit_linear_speed(model, np.eye(4), Q0, T, wanted, 2.0)
    assert wanted <= took(v) <= wanted * (1 + FIT_TOLERANCE)
    assert v == pytest.approx(0.12, rel=0.01)
    assert took(0.98 * v) > wanted  # slower would take longer: the slowest that takes it
    # shorter than the planner can at the top speed: the top speed
    assert fit_linear_speed(model, np.eye(4), Q0, T, 1e-3, 2.0) == 2.0


def test_fit_linear_speed_on_the_joint_limited_plateau_is_the_slowest_speed() -> None:
    """A duration the joints' limits set (the top speed's time): every speed above some v*
    takes it within the tolerance. Twin: a scan of 150 speeds on a log grid; the fit is the
    slowest speed within the tolerance (the scan's first, to one grid step), the same for a
    duration off by a last bit (the bisection met some speed of the plateau before)."""
    model = preset_robot("mz07")
    T = _line_target(model, -0.3)

    def took(v: float) -> float:
        prog = Program("p", (Move.linear(T, speed=v),))
        return float(planner_durations(model, prog, Q0, np.eye(4))[0])

    wanted = took(2.0)
    most = wanted * (1 + FIT_TOLERANCE)
    grid = np.geomspace(0.05, 2.0, 150)
    within = [v for v in grid if took(float(v)) <= most]
    assert len(within) > 15  # a plateau: many speeds take the time
    v = fit_linear_speed(model, np.eye(4), Q0, T, wanted, 2.0)
    step = grid[1] / grid[0]
    assert within[0] / step <= v <= within[0]
    assert took(v) <= most < took(v * (1 - 1e-6))
    again = fit_linear_speed(model, np.eye(4), Q0, T, wanted * (1 + 1e-15), 2.0)
    assert again == pytest.approx(v, rel=1e-8)


def test_corner_zones_keep_the_blend_within_the_tolerance() -> None:
    tol = 0.05e-3
    straight = np.array([[0, 0, 0], [0.01, 0, 0], [0.02, 0, 0]], float)
    right = np.array([[0, 0, 0], [0.01, 0, 0], [0.01, 0.01, 0]], float)
    slight = np.array([[0, 0, 0], [0.01, 0, 0], [0.02, 0.0002, 0]], float)
    assert corner_zones(straight, tol)[0] == BLEND_ZONE
    # 90 deg: r <= 2 tol / sin(45 deg) = 0.1414 mm -> the 0.1 mm level
    assert corner_zones(right, tol)[0] == pytest.approx(0.1e-3)
    # a 0.02 rad turn: 2 tol / sin(0.01) = 10 mm -> the largest, 2 mm; the blend leaves the
    # corner by r sin(a/2) / 2 = 0.01 mm < tol
    r = corner_zones(slight, tol)[0]
    assert r == BLEND_ZONE and r * np.sin(0.01) / 2 < tol
    assert set(
        corner_zones(np.cumsum(np.random.default_rng(1).normal(size=(50, 3)), 0), tol)
    ) <= set(BLEND_LEVELS)


def test_a_first_move_shorter_than_the_tolerance_is_no_move() -> None:
    model = preset_robot("mz07")
    q1 = Q0 + np.array([20.0, 0, 0, 0, 0, 0]) * DEG
    prog = Program("p", (Move.joint(Q0 + 1e-8, speed=1.0), Move.joint(q1, speed=1.0)))
    near = planner_durations(model, prog, Q0, np.eye(4))  # ruckig refused this micro-move once
    twin = planner_durations(model, Program("p", (Move.joint(q1, speed=1.0),)), Q0, np.eye(4))
    assert 1e-8 < DUPLICATE_TOL
    assert near[0] == 0.0 and near[1] == pytest.approx(twin[0], rel=1e-6)


def test_nachi_files_are_named_model_unit_a_number() -> None:
    """An FD controller lists programs as <model>-<unit>-A.<nnn>: the model, not the robot's
    or the library's title (NACHI MZ07 and MZ07 are both MZ07); a cell's robots are units 01,
    02, ... of one export, program 001 in every workflow."""
    assert unit_name("MZ07") == "MZ07-01-A" == unit_name("NACHI MZ07")
    assert unit_name("MZ07", 2) == "MZ07-02-A"
    assert unit_name("robot 2") == "robot2-01-A"
    assert nachi_file_name(controller_model("NACHI MZ07"), 1, 1) == "MZ07-01-A.001"
    prog, _ = sample_program(name="assembly_MZ07")
    other = dataclasses.replace(prog, name="assembly_MZ07_B", robot="MZ07_B")
    files = write_programs("nachi", [prog, other], models=["MZ07", "MZ07"]).files
    assert sorted(files) == ["MZ07-01-A.001", "MZ07-02-A.001"]
