"""The example press-brake cells plan (issue 13, part 7 and Done means).

For each example cell with a press: the search's best plan, put into the project by
`use_plan` and replayed by `plan()`, is collision-free through every bend, regrip and the
transfer (every frame for the part; the robot also between samples); serial and Ray give
the same ranked plans. The pan's last walls need the short punch segment: without it they
are rejected with the punch named. A regrip counts only where the robot takes the part on
the station collision-free.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from workbench import Workbench
from workbench.service.bending_process import sweep_context
from workbench.sheetmetal.sequencing import find_sequences

ROOT = Path(__file__).resolve().parents[2]
PRESS_CELLS = [
    p
    for p in sorted((ROOT / "projects").glob("*.json"))
    if "press" in json.loads(p.read_text()).get("bending", {})
]
PAN = ROOT / "projects" / "pan_cell.json"


def test_the_press_examples_are_the_u_channel_and_the_pan() -> None:
    assert {p.stem for p in PRESS_CELLS} >= {"u_channel_cell", "pan_cell"}


def _summary(plans: Any) -> list[tuple[Any, ...]]:
    return [
        (p.sequence, p.grasp_labels(), p.stations, p.regrips, p.flips, round(p.cycle_time, 6))
        for p in plans
    ]


@pytest.mark.slow
@pytest.mark.parametrize("path", PRESS_CELLS, ids=lambda p: p.stem)
def test_the_best_plan_replays_collision_free_and_ray_agrees(path: Path) -> None:
    wb = Workbench.open(path)
    svc = wb.bending
    serial = svc.find_sequences(engine="serial")
    assert serial.plans, (serial.note, serial.rejected[:5])
    best = serial.plans[0]
    assert best.verified
    svc.use_plan(best)
    cycle = svc.plan()
    assert cycle.ok and cycle.first_problem is None, cycle.summary()
    assert not cycle.colliding.any()
    robot = cycle.robot_report
    assert robot.collision_free and robot.certified and not robot.colliding_indices
    assert cycle.regrips == best.regrips
    assert cycle.cycle_time == pytest.approx(best.cycle_time, rel=1e-9)
    assert [s.bend for s in cycle.steps] == list(best.sequence)
    on_ray = svc.find_sequences(engine="ray")
    assert on_ray.stats.engine == "ray"
    assert _summary(on_ray.plans) == _summary(serial.plans)
    assert on_ray.rejected == serial.rejected


@pytest.mark.slow
def test_the_pan_plans_with_regrips_and_the_short_segment() -> None:
    res = Workbench.open(PAN).bending.find_sequences(engine="serial")
    assert res.plans, res.note
    best = res.plans[0]
    assert best.regrips >= 1
    # the walls bent last stand between the first two: only the short punch fits
    assert list(best.stations[2:]) == ["short", "short"], best.stations


def test_without_the_short_segment_the_pans_last_walls_hit_the_punch() -> None:
    data = json.loads(PAN.read_text())
    data["bending"]["press"]["stations"] = [
        s for s in data["bending"]["press"]["stations"] if s["name"] != "short"
    ]
    data["bending"].pop("steps", None)
    wb = Workbench.from_dict(data, base_dir=ROOT / "projects")
    res = wb.bending.find_sequences(engine="serial")
    assert not res.plans
    third = [r for b, r in res.rejected if len(b) == 3]
    assert third and all("hits the punch" in r or "no grasp" in r for r in third), third
    assert any("hits the punch" in r for r in third)


@pytest.mark.slow
def test_a_regrip_counts_only_where_the_robot_takes_the_part_free() -> None:
    """The pan needs regrips; with the robot blocked at the station (and free elsewhere) the
    cheap stage finds no plan and says no regrip is possible."""
    wb = Workbench.open(PAN)
    ctx = sweep_context(wb.bending)
    assert ctx.T_world_regrip is not None
    station = ctx.T_world_regrip

    def free(q: np.ndarray, lying: Any) -> np.ndarray:
        blocked = lying is not None and np.allclose(lying[1], station)
        return np.full(len(q), not blocked)

    open_station = find_sequences(ctx, robot_free=lambda q, lying: np.ones(len(q), bool))
    assert open_station.plans and open_station.plans[0].regrips >= 1
    blocked = find_sequences(ctx, robot_free=free)
    assert not blocked.plans
    assert any("no regrip is possible" in r for _, r in blocked.rejected), blocked.rejected[:5]
