"""The transfer-only bending plan (`pressbrake.transfer_plan`) from its inputs, without a project
service: the die placements, the transfer and its checks.

Twins: each placement's joints put the TCP where the die says (forward kinematics); every
transfer frame's part pose is the TCP's pose times the grasp's inverse; the plan made here
equals the service's (`wb.bending.plan`) to the bit; a die moved out of reach is refused
naming the bend and the die field.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.errors import UnreachableError
from workbench.pressbrake.die import die_targets
from workbench.pressbrake.plan import BendingPlan
from workbench.pressbrake.transfer import world_tcp
from workbench.pressbrake.transfer_plan import placements, plan_transfer

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.open(ROOT / "projects" / "bending_cell.json")


def _plan(wb: Workbench, **change: object) -> BendingPlan:
    svc, si = wb.bending, wb.bending.si()
    inputs = dict(
        die=si.die,
        transfer=si.transfer,
        frames=si.frames,
        q_start=wb.joints,
        obstacles=svc.obstacles(),
        checker=wb.checker,
        policy=wb.collision_policy,
    )
    inputs.update(change)
    return plan_transfer(wb.setup, svc.part, svc.grasp, **inputs)  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def plan(wb: Workbench) -> BendingPlan:
    return _plan(wb)


def test_each_placement_holds_its_bend_on_the_die(wb: Workbench) -> None:
    svc, setup = wb.bending, wb.setup
    placed, label = placements(setup, svc.part, svc.si().die, svc.grasp, wb.joints)
    _, T_tcp, names = die_targets(svc.part, svc.si().die, svc.grasp)
    assert len(placed) == len(svc.part.bends) == len(names) and label
    for p, T in zip(placed, T_tcp, strict=True):
        fk = setup.T_world_base @ setup.model.fk(p.q) @ setup.T_flange_tcp
        np.testing.assert_allclose(fk, T, atol=1e-6)


def test_the_part_follows_the_tcp_on_every_frame(wb: Workbench, plan: BendingPlan) -> None:
    setup = wb.setup
    assert plan.T_tcp_part is not None and len(plan.times) == wb.bending.si().frames
    T_tcp = world_tcp(setup.model, setup.T_world_base, setup.T_flange_tcp, plan.joints)
    np.testing.assert_allclose(plan.T_world_part, T_tcp @ plan.T_tcp_part, atol=1e-12)
    assert plan.ok and not plan.colliding.any()


def test_the_plan_is_the_services_plan(wb: Workbench, plan: BendingPlan) -> None:
    svc_plan = wb.bending.plan()
    assert isinstance(svc_plan, BendingPlan)
    np.testing.assert_array_equal(plan.times, svc_plan.times)
    np.testing.assert_array_equal(plan.joints, svc_plan.joints)
    np.testing.assert_array_equal(plan.T_world_grasp, svc_plan.T_world_grasp)
    np.testing.assert_array_equal(plan.colliding, svc_plan.colliding)
    assert plan.summary() == svc_plan.summary()


def test_a_die_out_of_reach_names_the_bend(wb: Workbench) -> None:
    die = wb.bending.si().die
    T = die.T_world_die.copy()
    T[:3, 3] = [2.5, 0.0, 0.35]
    with pytest.raises(UnreachableError, match=r"bending\.die: bend 'b23' \(step 1\)"):
        _plan(wb, die=replace(die, T_world_die=T))
