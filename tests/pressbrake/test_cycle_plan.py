"""A press-brake cycle set up for planning (`pressbrake.cycle_plan`): the press checked against
the part, the default steps, the part reordered, and `CycleRobot.check_cycle`.

Twins: the default station of each bend is the first whose die is at least the bend line's
length and whose punch is at most twice the shortfall shorter (a plain loop over the stations);
a reordered part folds as the part built from its spec in that order (`SheetMetalPart.from_spec`);
the robot's cycle equals the service's plan of the same project.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from example_plans import bending_plan

from workbench import Workbench
from workbench.errors import InputError
from workbench.pressbrake.airbend import short_flanges
from workbench.pressbrake.bend_eval import PUNCH_SHORTFALL
from workbench.pressbrake.cycle import BendingCycle
from workbench.pressbrake.cycle_plan import checked_press, default_steps, reordered
from workbench.service.bending_process import cycle_cell, cycle_robot, cycle_steps
from workbench.sheetmetal import SheetMetalPart

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.open(ROOT / "projects" / "u_channel_cell.json")


def test_a_press_whose_v_opening_a_flange_cannot_bridge_is_refused_naming_it(
    wb: Workbench,
) -> None:
    part, press = wb.bending.part, wb.bending.si().press
    assert press is not None
    assert checked_press(part, press) is press and short_flanges(part, press.die.v_opening) == []
    wide = replace(press, die=replace(press.die, v_opening=0.07))
    problems = short_flanges(part, 0.07)
    assert problems
    with pytest.raises(InputError) as err:
        checked_press(part, wide)
    assert str(err.value) == "; ".join(problems)
    assert "flange 'B' reaches 25.0 mm" in str(err.value)


def test_default_steps_take_the_first_station_that_fits(wb: Workbench) -> None:
    part, si = wb.bending.part, wb.bending.si()
    press = si.press
    assert press is not None
    steps = default_steps(part, si.grasp, press)
    assert [s.bend for s in steps] == [b.name for b in part.bends]
    for i, s in enumerate(steps):
        length = float(part.bend_lengths[i])
        first = None
        for st in press.stations:  # the twin: a plain loop
            punch_ok = st.punch_length + 2 * PUNCH_SHORTFALL + 1e-9 >= length
            if st.die_length + 1e-9 >= length and punch_ok:
                first = st.name
                break
        assert s.station == first and s.grasp == si.grasp


def test_a_reordered_part_folds_as_one_built_in_that_order(wb: Workbench) -> None:
    svc = wb.bending
    part, part_si = svc.part, svc.si().part
    order = [b.name for b in part.bends][::-1]
    got = reordered(part, order)
    twin = SheetMetalPart.from_spec(replace(part_si, sequence=tuple(order)))
    assert [b.name for b in got.bends] == [b.name for b in twin.bends] == order
    for step in (0, 1, len(order)):
        np.testing.assert_allclose(
            got.fold(step).T_part_flange, twin.fold(step).T_part_flange, atol=1e-12
        )


def test_the_robots_cycle_is_the_services_plan(wb: Workbench) -> None:
    svc = wb.bending
    cyc = cycle_robot(svc).check_cycle(svc.part, cycle_steps(svc), cycle_cell(svc))
    plan = bending_plan("u_channel_cell.json")[1]  # the service's plan, shared
    assert isinstance(cyc, BendingCycle) and isinstance(plan, BendingCycle)
    np.testing.assert_array_equal(cyc.times, plan.times)
    np.testing.assert_array_equal(cyc.joints, plan.joints)
    assert cyc.summary() == plan.summary() and cyc.ok
