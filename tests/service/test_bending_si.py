"""`wb.bending.si()` converts the project's section to SI once per change: repeated calls (once
per timeline frame during playback) reuse it; each setter's change is seen by the next call."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.pressbrake.sequencing import SequencePlan
from workbench.project.bending import BendingSpec
from workbench.service.bending_process import cycle_steps

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def conversions(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Count `BendingSpec.to_si` calls."""
    calls: list[int] = []
    to_si = BendingSpec.to_si

    def counted(self: BendingSpec, part):  # type: ignore[no-untyped-def]
        calls.append(1)
        return to_si(self, part)

    monkeypatch.setattr(BendingSpec, "to_si", counted)
    return calls


def test_repeated_calls_do_not_convert_again(conversions: list[int]) -> None:
    wb = Workbench.open(ROOT / "projects" / "bending_cell.json")
    conversions.clear()  # the open checks the section once (`check_named_files`)
    svc = wb.bending
    first = svc.si()
    plan = svc.plan()
    for t in np.linspace(0.0, plan.duration, 25):  # what a playback does per frame
        svc.part_pose_at(plan, float(t))
        svc.press_poses_at(plan, float(t))
    assert svc.si() is first
    assert len(conversions) == 1


def test_each_setters_change_is_seen_by_the_next_call(conversions: list[int]) -> None:
    wb = Workbench.open(ROOT / "projects" / "bending_cell.json")
    svc = wb.bending
    before = svc.si()
    order = list(svc.sequence)
    new = [order[1], order[0], *order[2:]]
    svc.set_sequence(new)
    assert list(svc.si().part.sequence) == new != list(before.part.sequence)
    n = len(conversions)
    svc.set_grasp(svc.grasp_flange, [0.1, 0.08], yaw=0.5)
    si = svc.si()
    assert si.grasp.yaw == pytest.approx(0.5) and np.allclose(si.grasp.offset, [0.1, 0.08])
    assert len(conversions) == n + 1
    assert svc.si() is si and len(conversions) == n + 1


def test_use_plan_and_another_project_are_seen(conversions: list[int]) -> None:
    wb = Workbench.open(ROOT / "projects" / "u_channel_cell.json")
    svc = wb.bending
    steps = cycle_steps(svc)
    assert svc.si().steps is not None
    order = tuple(s.bend for s in steps)[::-1]
    plan = SequencePlan(
        sequence=order,
        grasps=tuple(s.grasp for s in steps)[::-1],
        stations=tuple(s.station for s in steps)[::-1],
        orientations=("",) * len(steps),
        regrips=0,
        flips=0,
        cycle_time=0.0,
        cost=0.0,
    )
    svc.use_plan(plan)
    si = svc.si()
    assert si.steps is not None and tuple(s.bend for s in si.steps) == order
    assert tuple(si.part.sequence) == order
    wb.replace_project(Workbench.open(ROOT / "projects" / "u_channel_cell.json").project)
    assert tuple(wb.bending.si().part.sequence) == order[::-1]
