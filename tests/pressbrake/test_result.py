"""`BendingResult`: the transfer-only `BendingPlan` and the press cycle `BendingCycle` offer one
interface, and each method gives what the service computed before it existed.

Twins: the plan's part pose at any time equals the TCP's pose times the grasp's inverse
(`carried_poses`, what the service did); the cycle's part pose, fold step and press poses equal
the frame at or before t read directly; the first problem's time equals the first colliding
frame's (a cycle) or the first collision's frame (a plan); each result's program equals the
program function called by its name.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from example_plans import bending_plan

from workbench import Workbench
from workbench.pressbrake.bend_setup import press_poses
from workbench.pressbrake.cycle import BendingCycle
from workbench.pressbrake.cycle_program import cycle_program
from workbench.pressbrake.plan import BendingPlan, playback
from workbench.pressbrake.program import bending_program
from workbench.pressbrake.result import BendingResult
from workbench.pressbrake.transfer import carried_poses
from workbench.project.program_io import program_settings

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def plan_wb() -> Workbench:
    return Workbench.open(ROOT / "projects" / "bending_cell.json")


@pytest.fixture(scope="module")
def cycle_wb() -> Workbench:
    return bending_plan("u_channel_cell.json")[0]  # shared: the tests only read it


@pytest.fixture(scope="module")
def plan(plan_wb: Workbench) -> BendingPlan:
    p = plan_wb.bending.plan()
    assert isinstance(p, BendingPlan)
    return p


@pytest.fixture(scope="module")
def cycle(cycle_wb: Workbench) -> BendingCycle:
    c = bending_plan("u_channel_cell.json")[1]  # the service's plan, shared
    assert isinstance(c, BendingCycle)
    return c


def test_both_results_are_bending_results(plan: BendingPlan, cycle: BendingCycle) -> None:
    assert isinstance(plan, BendingResult) and isinstance(cycle, BendingResult)
    assert plan.duration == pytest.approx(plan.trajectory.duration)
    assert cycle.duration == cycle.cycle_time
    assert plan.grasp_frames is plan.T_world_grasp and cycle.grasp_frames is None


def test_the_plans_part_pose_at_any_time_is_the_carried_pose(
    plan_wb: Workbench, plan: BendingPlan
) -> None:
    svc = plan_wb.bending
    for t in np.linspace(0.0, plan.duration, 7):
        q = plan.trajectory.at([t])[0][0]
        twin = carried_poses(svc.world_tcp(q), svc.part, svc.grasp)[1]
        np.testing.assert_allclose(plan.part_pose_at(float(t), svc.world_tcp), twin, atol=1e-12)
    # at the checked frames it is the plan's own part pose
    for f in (0, len(plan.times) // 2, len(plan.times) - 1):
        got = plan.part_pose_at(float(plan.times[f]), svc.world_tcp)
        np.testing.assert_allclose(got, plan.T_world_part[f], atol=1e-9)
    assert plan.part_step_at(0.3) == float(len(svc.part.bends))
    assert plan.press_poses_at(0.3, None) == {}


def test_the_cycles_part_and_press_at_t_are_those_of_the_last_frame_before(
    cycle_wb: Workbench, cycle: BendingCycle
) -> None:
    press = cycle_wb.bending.si().press
    assert press is not None
    for t in np.linspace(0.0, cycle.duration, 11):
        n = int(np.searchsorted(cycle.frames.times, t, side="right") - 1)
        n = min(max(n, 0), len(cycle.frames.times) - 1)
        np.testing.assert_array_equal(cycle.part_pose_at(float(t)), cycle.frames.T_world_part[n])
        assert cycle.part_step_at(float(t)) == float(cycle.frames.step[n])
        k = int(cycle.frames.stop[n])
        twin = press_poses(
            press, float(cycle.frames.punch_z[n]), cycle.path.stops[k] if k >= 0 else None
        )
        got = cycle.press_poses_at(float(t), press)
        assert got.keys() == twin.keys()
        for name, T in twin.items():
            np.testing.assert_array_equal(got[name], T)
    assert cycle.tree_check_at(1.0) is None


def test_first_problem_time_and_tree_check(plan: BendingPlan, cycle: BendingCycle) -> None:
    assert plan.first_problem_time is None and cycle.first_problem_time is None  # both free
    rep = plan.part_report.frame(plan.nearest_frame(0.2))
    assert plan.tree_check_at(0.2) == (rep.nodes_tested, rep.nodes_hit)


def test_playback_and_programs_are_those_of_the_named_functions(
    plan_wb: Workbench, plan: BendingPlan, cycle_wb: Workbench, cycle: BendingCycle
) -> None:
    wtcp = plan_wb.bending.world_tcp
    a, b = plan.playback(wtcp, 0.05), playback(plan, wtcp, 0.05)
    np.testing.assert_array_equal(a.joints, b.joints)
    np.testing.assert_array_equal(a.colliding, b.colliding)
    s = program_settings(plan_wb.project)
    si = plan_wb.bending.si()
    got = plan.robot_program(plan_wb.setup, si, s, plan_wb.joints)
    assert _text(got) == _text(bending_program(plan, plan_wb.setup, si, s, plan_wb.joints))
    s = program_settings(cycle_wb.project)
    got = cycle.robot_program(cycle_wb.setup, cycle_wb.bending.si(), s, cycle_wb.joints)
    assert _text(got) == _text(cycle_program(cycle, cycle_wb.setup, s, cycle_wb.joints))


def _text(program: object) -> str:
    """Return the program's full repr, every array in full and to the last digit."""
    with np.printoptions(threshold=sys.maxsize, precision=17):
        return repr(program)
