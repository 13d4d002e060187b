"""The Motion tab and the shared timeline in a real Chromium: plan, play, scrub, export."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from browser_helpers import (
    canvas_png,
    set_slider,
    steady_picture,
    wait_for,
    wait_for_new_picture,
    wait_for_timeline,
)

from workbench.gui.app import WorkbenchApp

pytestmark = pytest.mark.e2e


def test_plan_play_scrub_and_export(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name="Motion").click()
    plots_before = app.timeline.plots
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(lambda: app.wb.last_plan is not None, timeout=90, what="the plan on the server")
    plan = app.wb.last_plan
    assert plan is not None and plan.cycle_time > 0
    # The cycle time the page shows is the server's.
    page.get_by_text(f"{plan.cycle_time:.3f} s").first.wait_for()
    wait_for_timeline(app, plots_before, what="the plan on the timeline")
    assert app.timeline.motion is not None
    assert app.timeline.motion.duration == pytest.approx(plan.cycle_time, abs=1e-9)
    # The joint plot shows the controller's values (as the sliders and the programs do).
    shown = np.array(app.timeline.plots[0].data[1:], float).T  # (N, dof) [deg]
    ctrl = np.degrees(app.wb.robot.convention.to_controller(plan.positions))
    assert np.allclose(shown, ctrl, atol=1e-9)

    # Scrub: typing a time poses the robot at the plan's joints for that time.
    before = steady_picture(lambda: canvas_png(page))
    t = round(plan.cycle_time / 2, 2)
    set_slider(page, "Time [s]", t)
    wait_for(lambda: abs(app.timeline.time.value - t) < 1e-6, what="the timeline at the typed time")
    q_expected = app.timeline.motion.at(t)
    T = app.wb.link_poses(q_expected)[3]
    wait_for(
        lambda: np.allclose(app.scene.links["link3"].position, T[:3, 3], atol=1e-6),
        what="link 3 at the planned pose",
    )
    wait_for_new_picture(lambda: canvas_png(page), before, what="when scrubbing")

    # Play at 4x from the middle: the time runs to the end by itself and playback stops.
    page.get_by_role("combobox", name="Speed").click()
    page.get_by_role("option", name="4x").click()
    wait_for(lambda: app.timeline.speed.value == "4x", what="speed 4x on the server")
    page.get_by_role("button", name="Play").click()
    # At 4x the rest of the motion plays in well under a second: wait for its end.
    wait_for(
        lambda: app.timeline.time.value >= plan.cycle_time - 0.02 and not app.timeline.playing,
        what="playback to run to the end and stop",
    )
    assert app.timeline.time.value == pytest.approx(plan.cycle_time, abs=0.02)
    page.get_by_role("button", name="Play").wait_for()  # the button reads Play again

    # Export: the downloaded program is the server's export in the format the dropdown shows,
    # by default the robot's vendor's (NACHI FD for the MZ07).
    assert app.motion.format.value == "nachi" == app.wb.default_program_format()
    with page.expect_download() as dl:
        page.get_by_role("button", name="Download program").click()
    text = Path(dl.value.path()).read_text()
    assert text == app.wb.export_program("nachi").text
    assert text.startswith("' PROGRAM ") and "M1J,L" in text
