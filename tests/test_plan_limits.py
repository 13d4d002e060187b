"""Every plan bounded (issue 29 part 4): the time limit and cancel of every workflow's planning
(`workbench.plan_limit`, the project's `planning.time_limit`) and the work budgets counted
before allocation (a ram speed, the grasp grid's spacing)."""

from __future__ import annotations

import copy
import json
import time
import tracemalloc
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from workbench.errors import InputError, PlanLimitError, PlanningError, ProjectError
from workbench.motion.joint_rrt import plan_joint_rrt_connect
from workbench.plan_limit import TIME_LIMIT_FIELD, PlanLimit
from workbench.pressbrake.grasp_grid import MAX_GRID_POINTS, _grid_points, grasp_grid
from workbench.project.io import project_from_dict
from workbench.project.planning import DEFAULT_TIME_LIMIT_S
from workbench.sheetmetal import SheetMetalPart
from workbench.sheetmetal.part import Flange

ROOT = Path(__file__).resolve().parents[1]
PROJECTS = ROOT / "projects"
LIBRARY = ("irb1200_7_70", "kr6_r900_2", "m10ia", "ur5e", "mz07")
#: The seed cell's limit on each library robot [s]: the UR5e's plan ran past 290 s here (2
#: cores shared by six jobs) in its transits' exact part-solid checks; it must end by it. The
#: other robots plan in 16-29 s here; one that takes longer under load ends by the limit too,
#: which the test accepts as "says why" (a minute proves the bound as well as four did).
LIMIT_S = 60.0


def _example(name: str) -> dict[str, Any]:
    return json.loads((PROJECTS / f"{name}.json").read_text())  # type: ignore[no-any-return]


# -- the limit itself ------------------------------------------------------------------------------
def test_past_the_limit_the_check_names_the_setting_the_plan_and_the_step() -> None:
    limit = PlanLimit(0.5, "the bending plan of project 'x'", start=time.perf_counter() - 1.0)
    with pytest.raises(PlanLimitError) as info:
        limit.check("checking the part in 40 frames")
    err = info.value
    assert err.field == TIME_LIMIT_FIELD == "planning.time_limit"
    assert not err.cancelled and isinstance(err, PlanningError)
    assert "the bending plan of project 'x'" in err.detail
    assert "0.5 s" in err.detail and "while checking the part in 40 frames" in err.detail


def test_within_the_limit_watch_forwards_the_progress_and_cancel_ends_it() -> None:
    seen: list[tuple[float, str]] = []
    stop = {"now": False}
    limit = PlanLimit(60.0, "the motion plan", cancel=lambda: stop["now"])
    report = limit.watch(lambda f, m: seen.append((f, m)))
    report(0.25, "moves through IK")
    assert seen == [(0.25, "moves through IK")]
    stop["now"] = True
    with pytest.raises(PlanLimitError) as info:
        report(0.5, "jerk-limited timing")
    assert info.value.cancelled and "cancelled" in info.value.detail
    assert seen == [(0.25, "moves through IK")]  # not forwarded once ended


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf")])
def test_a_limit_that_is_no_time_is_refused_naming_the_setting(bad: float) -> None:
    with pytest.raises(InputError) as info:
        PlanLimit(bad, "x")
    assert info.value.field == "planning.time_limit"


def test_a_limit_error_keeps_its_setting_when_a_caller_reroots_it() -> None:
    err = PlanLimitError("stopped", field="planning.time_limit").within("assembly.parts[0]")
    assert err.field == "planning.time_limit"
    cancelled = PlanLimitError("cancelled", cancelled=True).within("assembly.parts[0]")
    assert cancelled.field == "assembly.parts[0]" and cancelled.cancelled


def test_the_project_setting_its_default_and_its_range() -> None:
    d = _example("mz07_cell")
    assert project_from_dict(d).planning is None  # absent: the default applies
    assert DEFAULT_TIME_LIMIT_S == 600.0
    assert project_from_dict({**d, "planning": {"time_limit": 2.5}}).planning.time_limit == 2.5  # type: ignore[union-attr]
    for bad in (0, -3, 1e9):
        with pytest.raises(ProjectError, match=r"planning\.time_limit"):
            project_from_dict({**d, "planning": {"time_limit": bad}})


# -- the joint RRT reports its progress, and a limit raising there ends it ---------------------------
class _Wall:
    """A 2-joint space with a wall across the middle but for a gap at the top (a real search)."""

    dof = 2
    limits = np.array([[-1.0, 1.0], [-1.0, 1.0]])

    def distance(self, qa: Any, qb: Any) -> Any:
        return np.abs(np.asarray(qb, float) - np.asarray(qa, float)).sum(axis=-1)

    def valid(self, q: Any) -> bool:
        x, y = np.asarray(q, float)
        return not (abs(x) < 0.05 and y < 0.8)

    def explain(self, q: Any) -> str:
        return "" if self.valid(q) else "the wall"

    def motion_free(self, qa: Any, qb: Any) -> bool:
        u = np.linspace(0.0, 1.0, 50)[:, None]
        return all(self.valid(p) for p in np.asarray(qa) + u * (np.asarray(qb) - np.asarray(qa)))


def test_a_limit_in_the_rrt_ends_it_and_a_silent_watch_changes_nothing() -> None:
    """Twin: the same seed with a progress that never raises gives the very same path."""
    a, b = np.array([-0.5, -0.5]), np.array([0.5, -0.5])
    plain, n_plain = plan_joint_rrt_connect(_Wall(), a, b, seed=4, max_time=np.inf)
    calls: list[str] = []
    watched, n_watched = plan_joint_rrt_connect(
        _Wall(), a, b, seed=4, max_time=np.inf, progress=lambda f, m: calls.append(m)
    )
    assert calls and n_plain == n_watched and np.array_equal(plain, watched)
    limit = PlanLimit(60.0, "the detour", cancel=lambda: True)
    with pytest.raises(PlanLimitError, match="the detour: cancelled"):
        plan_joint_rrt_connect(_Wall(), a, b, seed=4, max_time=np.inf, progress=limit.watch())


# -- work budgets counted before allocation -------------------------------------------------------------
def _peak_bytes(fn: Any) -> int:
    tracemalloc.start()
    try:
        fn()
    finally:
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    return peak


def test_a_ram_crawling_at_a_thousandth_of_a_mm_per_second_is_refused_at_load() -> None:
    """The seed cell's ram closing at 0.001 mm/s: 250 mm in 2.5e5 s, 5e6 frames of each of its
    6 bends (the issue's "20 million samples" that died of MemoryError): refused at load,
    naming the field and the least speed that fits, with a few MB at most."""
    d = _example("seed_part_cell")
    d["bending"]["press"]["ram"]["approach_speed"] = 0.001
    caught: list[ProjectError] = []

    def load() -> None:
        try:
            project_from_dict(d)
        except ProjectError as exc:
            caught.append(exc)

    peak = _peak_bytes(load)
    assert caught, "the crawling ram was accepted"
    text = str(caught[0])
    assert "bending.press.ram.approach_speed" in text
    assert "workbench.motion.trajectory.MAX_SAMPLES" in text and "0.025 mm/s" in text
    assert peak < 20e6, f"{peak / 1e6:.0f} MB before the refusal"
    fits = copy.deepcopy(d)
    fits["bending"]["press"]["ram"]["approach_speed"] = 0.026  # the least that fits, rounded up
    project_from_dict(fits)


def test_a_grasp_grid_finer_than_its_budget_is_refused_before_any_point() -> None:
    """A 0.001 mm grid on a 300 x 200 mm flange (6e10 points, hours of shapely tests) is refused
    in milliseconds with the least spacing; twin: that spacing is within the budget by the same
    count `np.arange` makes, 5 % less is not."""
    poly = np.array([[0.0, 0.0], [0.3, 0.0], [0.3, 0.2], [0.0, 0.2]])
    part = SheetMetalPart(0.002, [Flange("f", poly)], [])
    caught: list[InputError] = []

    def grid() -> None:
        try:
            grasp_grid(part, spacing=1e-6, inset=0.008)
        except InputError as exc:
            caught.append(exc)

    t0 = time.perf_counter()
    peak = _peak_bytes(grid)
    assert caught and caught[0].field == "grasp spacing" and time.perf_counter() - t0 < 1.0
    assert "MAX_GRID_POINTS" in caught[0].detail and peak < 5e6
    least = float(caught[0].detail.split("at least ")[1].split(" mm")[0]) * 1e-3
    ext = np.array([[0.3, 0.2]])
    count = len(np.arange(least / 2, 0.3, least)) * len(np.arange(least / 2, 0.2, least))
    assert _grid_points(ext, least) == count <= MAX_GRID_POINTS
    assert _grid_points(ext, least / 1.06) > MAX_GRID_POINTS


# -- real plans ----------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def mz07() -> Any:
    from workbench import Workbench

    return Workbench.open(PROJECTS / "mz07_cell.json")


@pytest.mark.slow
def test_a_fraction_of_a_second_ends_a_real_plan_and_cancel_too_and_nothing_sticks(
    mz07: Any,
) -> None:
    """A limit of 0.05 s ends the motion plan naming the setting; cancel after three reports
    ends it too; then the same session plans exactly as a fresh one (no engine kept broken)."""
    from workbench.project.planning import PlanningSpec

    mz07.project.planning = PlanningSpec(time_limit=0.05)
    t0 = time.perf_counter()
    with pytest.raises(PlanLimitError) as info:
        mz07.plan_motion()
    assert time.perf_counter() - t0 < 5.0
    assert info.value.field == "planning.time_limit" and "the motion plan" in info.value.detail
    mz07.project.planning = None
    calls: list[str] = []
    with pytest.raises(PlanLimitError) as info2:
        mz07.plan_motion(progress=lambda f, m: calls.append(m), cancel=lambda: len(calls) >= 3)
    assert info2.value.cancelled and len(calls) == 3
    plan = mz07.plan_motion()
    from workbench import Workbench

    fresh = Workbench.open(PROJECTS / "mz07_cell.json").plan_motion()
    assert plan.summary() == fresh.summary()
    assert np.array_equal(plan.samples.joints, fresh.samples.joints)
    assert plan.collision_report.mode == fresh.collision_report.mode  # the engine, not a fallback


@pytest.mark.slow
def test_a_limit_ends_the_press_cycle_inside_its_detours() -> None:
    """The seed part cell's cycle (its transits searched by RRT) under a 3 s limit."""
    from workbench import Workbench

    wb = Workbench.open(PROJECTS / "seed_part_cell.json")
    from workbench.project.planning import PlanningSpec

    wb.project.planning = PlanningSpec(time_limit=3.0)
    t0 = time.perf_counter()
    with pytest.raises(PlanLimitError) as info:
        wb.bending.plan()
    assert time.perf_counter() - t0 < 3.0 + 10.0  # one step of work past the limit at most
    assert info.value.field == "planning.time_limit" and "the bending plan" in info.value.detail


@pytest.mark.slow
@pytest.mark.timeout(300)  # the plan's own limit (60 s) must be what ends a slow one
@pytest.mark.parametrize("preset", LIBRARY)
def test_the_seed_part_cell_plans_on_every_library_robot_within_its_limit(
    preset: str, tmp_path: Path
) -> None:
    """Issue 29's Done-means: a plan (collision-free or not, with its summary) or a
    WorkbenchError saying why, within the project's time limit (plus one step of work)."""
    from workbench import Workbench, WorkbenchError

    d = _example("seed_part_cell")
    d["robot"] = {"name": preset, "preset": preset, "base": d["robot"]["base"]}
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "seed_part.json").write_bytes(
        (PROJECTS / "parts" / "seed_part.json").read_bytes()
    )
    d["planning"] = {"time_limit": LIMIT_S}
    path = tmp_path / f"seed_{preset}.json"
    path.write_text(json.dumps(d))
    t0 = time.perf_counter()
    wb = Workbench.open(path)  # the project itself is sound: only the plan may say why not
    try:
        summary = wb.bending.plan().summary()
    except WorkbenchError as exc:
        summary = f"{type(exc).__name__}: {exc}"
    print(preset, round(time.perf_counter() - t0, 1), "s:", summary)
    assert time.perf_counter() - t0 < LIMIT_S + 60.0, summary
    assert summary
