"""The program editor of the Motion tab in a real Chromium: teach the current TCP, edit its
speed, insert a gripper action, move it up, undo, redo, plan, download RAPID (the server's
export, and the edited program when read back)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from browser_helpers import type_number, wait_for, wait_for_timeline

from workbench.gui.app import WorkbenchApp
from workbench.motion.programs.formats import reader
from workbench.project.units import pose_to_matrix
from workbench.service.program_edit import editor

pytestmark = pytest.mark.e2e


def _types(app: WorkbenchApp) -> list[str]:
    return [it.type for it in editor(app.wb).items]


def test_teach_edit_undo_plan_and_export(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    wb = app.wb
    ed = editor(wb)
    n = len(ed.items)
    page.get_by_role("tab", name="Motion").click()

    # Teach the current TCP as a linear move (after the selected item: the last one).
    page.get_by_role("button", name="TCP linear", exact=True).click()
    wait_for(lambda: len(ed.items) == n + 1, what="the taught target on the server")
    taught = ed.item(n)
    assert taught.type == "linear" and taught.name == "target1"
    assert np.allclose(pose_to_matrix(taught.pose), wb.tcp_pose(), atol=1e-8)
    page.get_by_text("target1").first.wait_for()  # in the table and the item list
    # its arm configuration, the robot's, in the table and under the selected item
    assert taught.configuration is not None
    label = taught.configuration.label()
    page.get_by_text(f"linear move to its TCP pose in {label}").first.wait_for()
    page.get_by_role("cell", name=label).first.wait_for()

    # Its speed, typed: the server's program takes it, and the table shows it.
    type_number(page, "Move speed", "250")
    wait_for(lambda: ed.item(n).speed == 250.0, what="the typed speed in the program")
    page.get_by_text("250 mm/s").first.wait_for()

    # A gripper action after it, then moved up before it.
    page.get_by_role("combobox", name="Action", exact=True).click()
    page.get_by_role("option", name="gripper close", exact=True).click()
    wait_for(lambda: app.motion.editor.action.value == "gripper close", what="the action choice")
    page.get_by_role("button", name="Insert action", exact=True).click()
    wait_for(lambda: len(ed.items) == n + 2, what="the inserted action")
    assert ed.item(n + 1).type == "gripper" and ed.item(n + 1).action == "close"
    page.get_by_role("button", name="Up", exact=True).click()
    wait_for(lambda: _types(app)[n : n + 2] == ["gripper", "linear"], what="the action moved up")

    # Undo puts it back after the target; redo moves it up again.
    page.get_by_role("button", name="Undo", exact=True).click()
    wait_for(lambda: _types(app)[n : n + 2] == ["linear", "gripper"], what="the move undone")
    page.get_by_role("button", name="Redo", exact=True).click()
    wait_for(lambda: _types(app)[n : n + 2] == ["gripper", "linear"], what="the move redone")
    assert ed.item(n + 1).speed == 250.0  # the earlier edits stay

    # Plan: the table shows each move's planned duration and the cycle time.
    plots_before = app.timeline.plots
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(lambda: wb.last_plan is not None, timeout=90, what="the plan on the server")
    plan = wb.last_plan
    assert plan is not None
    wait_for_timeline(app, plots_before, what="the plan on the timeline")
    page.get_by_text(f"Cycle time {plan.cycle_time:.3f} s").first.wait_for()
    times = ed.planned_times()
    assert times is not None and not times.stale
    page.get_by_text(f"{times.durations[n + 1]:.3f}").first.wait_for()
    assert app.scene.path_node is not None  # the TCP path of the plan in 3D

    # Download the program (NACHI FD, the MZ07's vendor's language): the server's export, and
    # the edited program read back.
    with page.expect_download() as dl:
        page.get_by_role("button", name="Download program").click()
    text = Path(dl.value.path()).read_text()
    exported = wb.export_program("nachi")
    assert text == exported.text
    read = reader("nachi")(exported.files)
    assert not read.unknown
    names = [m.name for m in read.moves]
    assert names[-1] == "target1"
    assert read.moves[-1].kind == "linear"
    assert read.moves[-1].speed == pytest.approx(0.250, abs=1e-6)
