"""The search of a press-brake cycle with each plan verified as a full cycle
(`pressbrake.cycle_search`): the context, the verification, the robot's free-joints check.

Twins: a plan of the project's own order, grasps and stations verifies with the cycle time and
regrips of the service's planned cycle; the free-joints check equals python-fcl's exact robot
check (`RobotCollisionChecker.check`) joint vector by joint vector.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from example_plans import bending_plan

from workbench import Workbench
from workbench.errors import InputError
from workbench.pressbrake.cycle import BendingCycle
from workbench.pressbrake.cycle_search import robot_free, sweep_context, verify_plan
from workbench.pressbrake.sequencing import Rejected, SequencePlan
from workbench.service.bending_process import cycle_cell, cycle_robot, cycle_steps

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.open(ROOT / "projects" / "u_channel_cell.json")


def _project_plan(wb: Workbench) -> SequencePlan:
    steps = cycle_steps(wb.bending)
    n = len(steps)
    return SequencePlan(
        sequence=tuple(s.bend for s in steps),
        grasps=tuple(s.grasp for s in steps),
        stations=tuple(s.station for s in steps),
        orientations=("",) * n,
        regrips=0,
        flips=0,
        cycle_time=0.0,
        cost=0.0,
    )


def test_the_projects_own_plan_verifies_as_its_cycle(wb: Workbench) -> None:
    svc = wb.bending
    plan = _project_plan(wb)
    got = verify_plan(plan, svc.part, cycle_cell(svc), cycle_robot(svc))
    cyc = bending_plan("u_channel_cell.json")[1]  # the service's plan, shared
    assert isinstance(got, SequencePlan) and isinstance(cyc, BendingCycle)
    assert got.verified and not got.estimated
    assert got.cycle_time == cyc.cycle_time and got.regrips == cyc.regrips
    assert got.sequence == plan.sequence and got.grasps == plan.grasps


def test_a_plan_whose_cycle_cannot_be_built_is_rejected_with_the_reason(wb: Workbench) -> None:
    svc = wb.bending
    plan = _project_plan(wb)
    bad = replace(plan, stations=("nowhere",) * len(plan.stations))
    got = verify_plan(bad, svc.part, cycle_cell(svc), cycle_robot(svc))
    assert isinstance(got, Rejected)
    assert got.reason.startswith("full cycle: ") and "nowhere" in got.reason


def test_robot_free_equals_the_exact_check(wb: Workbench) -> None:
    free = robot_free(cycle_robot(wb.bending))
    model = wb.robot
    rng = np.random.default_rng(7)
    lo, hi = model.limits[:, 0], model.limits[:, 1]
    q = np.vstack([wb.joints, lo + (hi - lo) * rng.random((40, model.dof))])
    got = free(q, None)
    twin = np.array([not wb.checker.check(qi, distance=False).colliding for qi in q])
    np.testing.assert_array_equal(got, twin)
    assert got.any() and not got.all()  # both verdicts occur among the samples


def test_the_context_holds_the_grid_and_names_a_bad_grid(wb: Workbench) -> None:
    svc, si = wb.bending, wb.bending.si()
    press = si.press
    assert press is not None

    def ctx(grid: object) -> object:
        return sweep_context(
            si.part,
            svc.part,
            press,
            cycle_robot(svc),
            wb.joints,
            wb.setup.tool_mesh,
            wb.setup.link_meshes,
            grid,  # type: ignore[arg-type]
            T_world_blank=si.blank,
            T_world_pallet=si.transfer.T_world_pallet,
            lift=si.lift,
            approach=si.approach,
            T_world_regrip=si.regrip,
        )

    c = ctx(si.grasp_grid)
    assert c.press is press and len(c.grasps) > 0  # type: ignore[attr-defined]
    assert c.reach.configuration  # type: ignore[attr-defined]
    with pytest.raises(InputError, match=r"^bending\.grasp_grid: \d+ candidates, above "):
        ctx(replace(si.grasp_grid, spacing=0.005))  # the message's own prefix replaced
