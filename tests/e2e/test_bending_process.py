"""The Bending tab with a press brake in a real Chromium: the press drawn, the sequence search,
"Use plan", and the planned cycle on the timeline (the part folded and carried, the ram and the
back-gauge moving)."""

from __future__ import annotations

import json
import logging
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest
from browser_helpers import (
    canvas_png,
    close_notifications,
    save_screenshot,
    set_slider,
    steady_picture,
    type_number,
    wait_for,
    wait_for_new_picture,
    wait_for_timeline,
)

from workbench.gui.app import WorkbenchApp
from workbench.gui.sequence_search import rejected_text, results_table
from workbench.service import Workbench

pytestmark = [pytest.mark.e2e, pytest.mark.slow]

ROOT = Path(__file__).resolve().parents[2]
U_CHANNEL = ROOT / "projects" / "u_channel_cell.json"


def _press_bodies(app: WorkbenchApp) -> list[str]:
    """Return the names of the press's bodies the scene draws (the strokes are not drawn)."""
    return [b.name for b in app.wb.cell if b.group == "press" and b.display]


def _errors(caplog: pytest.LogCaptureFixture) -> list[str]:
    return [r.getMessage() for r in caplog.records if r.levelno >= logging.ERROR]


def _wait_following(app: WorkbenchApp, t: float) -> None:
    """Wait until the part, its fold and the press's moving bodies are those of time `t` [s]."""
    svc, plan = app.wb.bending, app.wb.bending.last_plan
    assert plan is not None
    press = svc.press_poses_at(plan, t)  # type: ignore[arg-type]
    assert {"press punch", "press upper beam"} <= set(press)
    T_part = svc.part_pose_at(plan, t)
    step = svc.part_step_at(plan, t)
    wait_for(
        lambda: all(
            np.allclose(app.scene.bodies[name].position, T[:3, 3], atol=1e-9)
            for name, T in press.items()
            if name in app.scene.bodies
        ),
        what=f"the press's moving bodies at t = {t} s",
    )
    wait_for(
        lambda: np.allclose(app.bending.part_frame.position, T_part[:3, 3], atol=1e-9),
        what=f"the part where the cycle holds it at t = {t} s",
    )
    wait_for(
        lambda: app.bending.mesh_step is not None and abs(app.bending.mesh_step - step) <= 0.01,
        what=f"the part folded to step {step:.3f} at t = {t} s",
    )
    n_vertices = len(svc.fold(app.bending.mesh_step).solid().vertices)
    assert len(app.bending.mesh.vertices) == n_vertices


def _mid_bend_time(app: WorkbenchApp) -> float:
    """Return a time [s] of the last cycle halfway through its first bend."""
    plan = app.wb.bending.last_plan
    steps = plan.frames.step  # type: ignore[union-attr]
    k = int(np.argmin(np.abs(steps - 0.5)))
    assert 0.0 < steps[k] < 1.0
    return round(float(plan.frames.times[k]), 2)  # type: ignore[union-attr]


def test_find_sequences_and_use_plan(launch, caplog: pytest.LogCaptureFixture) -> None:  # type: ignore[no-untyped-def]
    caplog.set_level(logging.INFO)
    with ThreadPoolExecutor(1) as pool:  # the service's own answer, while the page loads
        searched = pool.submit(lambda: Workbench.open(U_CHANNEL).bending.find_sequences())
        app, page = launch(U_CHANNEL)
        expected = searched.result()
    page.get_by_role("tab", name="Bending").click()
    find = page.get_by_role("button", name="Find sequences", exact=True)
    find.wait_for()

    # The press is drawn: its bodies are in the scene, and hiding them changes the picture.
    names = _press_bodies(app)
    assert "press punch" in names and "press upper beam" in names
    assert set(names) <= set(app.scene.bodies)
    with_press = steady_picture(lambda: canvas_png(page))
    for name in names:
        app.scene.bodies[name].visible = False
    wait_for_new_picture(lambda: canvas_png(page), with_press, what="with the press hidden")
    for name in names:
        app.scene.bodies[name].visible = True

    # The time limit takes a positive number or nothing (no limit) and refuses the rest.
    search = app.bending.search
    assert search is not None
    type_number(page, "Time limit [s]", "0")
    page.get_by_text("Time limit [s]: refused").first.wait_for()
    assert search.time_limit is None
    close_notifications(page)
    type_number(page, "Time limit [s]", "120")
    wait_for(lambda: search.time_limit == 120.0, what="the time limit on the server")
    type_number(page, "Time limit [s]", "")
    wait_for(lambda: search.time_limit is None, what="no time limit on the server")

    # The search runs as a job and shows the service's ranking.
    find.click()
    wait_for(lambda: search.result is not None, timeout=180, what="the sequence search")
    got = search.result
    assert [(p.sequence, p.regrips) for p in got.plans] == [
        (p.sequence, p.regrips) for p in expected.plans
    ]
    assert got.rejected == expected.rejected
    assert search.table.content == results_table(expected)
    assert search.rejected.content == rejected_text(expected)
    if not expected.plans:
        # Nothing feasible (the project's cell is being tuned): the page says so with reasons.
        page.get_by_text("No feasible sequence.").first.wait_for()
        page.get_by_text("Rejected branches").first.wait_for()
        prefix, reason = expected.rejected[0]
        page.get_by_text(reason).first.wait_for()
        assert search.use.disabled
        assert not _errors(caplog)
        return
    first = expected.plans[0]
    row = page.locator("table tbody tr").first
    row.wait_for()
    cells = row.locator("td").all_inner_texts()
    assert cells[:3] == ["1", ",".join(first.sequence), str(first.regrips)]

    # Use plan: the project takes the plan, its cycle is planned and on the timeline.
    def service_cycle():  # type: ignore[no-untyped-def]
        wb = Workbench.open(U_CHANNEL)
        wb.bending.use_plan(first)
        return wb.bending.plan()

    plots_before = app.timeline.plots
    with ThreadPoolExecutor(1) as pool:
        planned = pool.submit(service_cycle)
        page.get_by_role("button", name="Use plan").click()
        wait_for_timeline(app, plots_before, what="the cycle on the timeline")
        # the job ends after its callback has shown the plan (and put the time at a hit)
        wait_for(lambda: app.jobs.running is None, what="the end of the job")
        cycle = planned.result()
    head = "**OK:** " if cycle.ok else "**Collision:** "
    assert app.bending.result.content == head + cycle.summary()
    page.get_by_text(cycle.summary()[:60]).first.wait_for()
    assert app.wb.bending.sequence == list(first.sequence)
    assert app.bending.sequence.value == ",".join(first.sequence)

    # Scrub into the first bend: the part folds and rides with the ram.
    t = _mid_bend_time(app)
    set_slider(page, "Time [s]", t)
    wait_for(lambda: abs(app.timeline.time.value - t) < 1e-6, what="the timeline at the time")
    _wait_following(app, t)
    assert not _errors(caplog)
    assert page.get_by_text("internal error").count() == 0
    for client in app.server.get_clients().values():  # the cell from above the robot
        app.views.frame(client, "all", (-0.42, -0.9, 1.48))
    page.mouse.move(300, 700)  # no tooltip over the panel
    steady_picture(lambda: canvas_png(page))
    save_screenshot(page, "img/bending_cycle.png")


# A cell whose cycle plans (the U-channel project's robot, tool, signals and part; the press,
# die, stack, regrip station and pallet pinned here while the project's own cell is tuned).
PINNED_CELL = {
    "robot_joints": [-90, 90, 0, 0, 45, 0],
    "tables": {  # a 300 mm cube at (x, y) [mm] on the floor, its colour; the pose on top
        "blank_stack": ("blank", (250, -450), 90, [150, 150, 160]),
        "pallet": ("pallet", (250, 450), 180, [190, 150, 100]),
        "regrip_table": ("regrip", (-150, -450), 270, [60, 140, 90]),
    },
    "bending": {
        "grasp": {"flange": "base"},
        "die": {"pose": {"xyz": [650, 0, 400], "rpy": [0, 0, -90]}, "length": 800},
        "press": {},
        "transfer": [],
        "approach": [0, -80, 30],
        "lift": 80,
    },
}


def _pinned_cell(tmp_path: Path) -> Path:
    """Return the U-channel project with the cell of `PINNED_CELL`, the part inline."""
    d = json.loads(U_CHANNEL.read_text())
    part = json.loads((U_CHANNEL.parent / d["bending"]["part_file"]).read_text())
    d["robot"]["joints"] = PINNED_CELL["robot_joints"]
    d["bending"] = {**PINNED_CELL["bending"], "part": part}
    d["cell"] = {"objects": []}
    for name, (key, (x, y), yaw, color) in PINNED_CELL["tables"].items():  # type: ignore[attr-defined]
        d["cell"]["objects"].append(
            {
                "name": name,
                "shape": "box",
                "size": [300, 300, 300],
                "pose": {"xyz": [x, y, 150]},
                "color": color,
            }
        )
        d["bending"][key] = {"xyz": [x, y, 302], "rpy": [0, 0, yaw]}
    path = tmp_path / "u_channel_pinned.json"
    path.write_text(json.dumps(d))
    return path


def test_cycle_on_the_timeline(launch, tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:  # type: ignore[no-untyped-def]
    caplog.set_level(logging.INFO)
    project = _pinned_cell(tmp_path)
    with ThreadPoolExecutor(1) as pool:  # the service's own cycle, while the page loads
        planned = pool.submit(lambda: Workbench.open(project).bending.plan())
        app, page = launch(project)
        cycle = planned.result()
    page.get_by_role("tab", name="Bending").click()
    plots_before = app.timeline.plots
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for_timeline(app, plots_before, what="the cycle on the timeline")
    wait_for(lambda: app.jobs.running is None, what="the end of the job")
    head = "**OK:** " if cycle.ok else "**Collision:** "
    wait_for(lambda: app.bending.result.content != "", what="the summary")
    assert app.bending.result.content == head + cycle.summary()
    page.get_by_text(cycle.summary()[:60]).first.wait_for()
    assert app.timeline.motion.duration == pytest.approx(cycle.cycle_time, abs=1e-6)
    _wait_following(app, float(app.timeline.time.value))

    # Scrub into the first bend: the ram is down, the part half folded on the die.
    for client in app.server.get_clients().values():  # the cell from above the robot
        app.views.frame(client, "all", (-0.42, -0.9, 1.48))
    before = steady_picture(lambda: canvas_png(page))
    t = _mid_bend_time(app)
    set_slider(page, "Time [s]", t)
    wait_for(lambda: abs(app.timeline.time.value - t) < 1e-6, what="the timeline at the time")
    _wait_following(app, t)
    punch = next(b for b in app.wb.cell if b.name == "press punch")
    assert not np.allclose(app.scene.bodies["press punch"].position, punch.T_world_body[:3, 3])
    wait_for_new_picture(lambda: canvas_png(page), before, what="when scrubbing the cycle")

    # The fold step slider shows the part on the die again, the press parked.
    page.get_by_role("tab", name="Bending").click()
    set_slider(page, "Fold step", 1)
    wait_for(
        lambda: np.allclose(app.scene.bodies["press punch"].position, punch.T_world_body[:3, 3]),
        what="the press parked for the fold-step view",
    )
    # ...and the timeline takes the cycle up again where it is scrubbed.
    set_slider(page, "Time [s]", t + 0.1)
    wait_for(lambda: abs(app.timeline.time.value - t - 0.1) < 1e-6, what="the time")
    _wait_following(app, round(t + 0.1, 4))
    assert not _errors(caplog)
    assert page.get_by_text("internal error").count() == 0
