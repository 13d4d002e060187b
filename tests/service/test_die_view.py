"""The bending tab's die view agrees with what Plan plans (issue 30 part 4 a).

The press cells' die view once placed every bend on the section's old `die` with the
section's grasp, which is not where the cycle puts it (the project's steps: their grasps and
stations), and said "unreachable" although Plan succeeded. It now shows each bend against its
stop as the cycle's own inverse kinematics holds it.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.pressbrake.cycle_path import T_part_tcp
from workbench.service.bending_process import cycle_steps

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests"))
PRESS_CELLS = [
    p
    for p in sorted((ROOT / "projects").glob("*.json"))
    if "press" in json.loads(p.read_text()).get("bending", {})
]


def test_the_press_examples_include_the_u_channel_and_the_pan() -> None:
    assert {p.stem for p in PRESS_CELLS} >= {"u_channel_cell", "pan_cell"}


@pytest.mark.parametrize("path", PRESS_CELLS, ids=lambda p: p.stem)
def test_every_bend_on_the_die_is_held_at_its_steps_grasp(path: Path) -> None:
    """The die view raises nothing on a cell that plans, and each placement is consistent
    by forward kinematics: the joints put the TCP where the step's grasp holds the part."""
    wb = Workbench.open(path)
    svc = wb.bending
    placed, label = svc.placements()  # raised UnreachableError before the fix
    steps = cycle_steps(svc)
    assert [p.bend for p in placed] == [b.name for b in svc.part.bends]
    for k, p in enumerate(placed):
        # the twin: forward kinematics of the joints, composed by hand
        T_fk = wb.setup.T_world_base @ wb.robot.fk(p.q) @ wb.setup.T_flange_tcp
        np.testing.assert_allclose(T_fk, p.T_world_tcp, atol=1e-6)
        T_held = p.T_world_part @ T_part_tcp(svc.part, steps[k].grasp, k)
        np.testing.assert_allclose(T_held, p.T_world_tcp, atol=1e-9)
        np.testing.assert_allclose(svc.die_part_pose(k), p.T_world_part, atol=1e-12)
        lo, hi = wb.robot.limits[:, 0], wb.robot.limits[:, 1]
        assert np.all((lo - 1e-9 <= p.q) & (p.q <= hi + 1e-9)), (p.bend, p.q)
    assert label


@pytest.mark.slow
def test_the_die_view_shows_the_joints_the_plan_stops_at() -> None:
    """The planned cycle stops at each bend's stop with the die view's joints (u_channel)."""
    from example_plans import bending_plan

    wb, plan = bending_plan("u_channel_cell.json")
    assert plan.ok
    placed, _ = wb.bending.placements()
    stops = {ph.bend: ph.start for ph in plan.path.phases if ph.kind == "bend"}
    for k, p in enumerate(placed):
        np.testing.assert_allclose(plan.q[stops[k]], p.q, atol=1e-9)
        np.testing.assert_allclose(plan.path.waypoints[stops[k]].T_world_tcp, p.T_world_tcp)
