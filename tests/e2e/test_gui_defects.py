"""The GUI defects of issue 30 part 4 in Chromium, one page per example (CI time): the
logic behind each fix is unit-tested in tests/gui/test_gui_defect_logic.py and
tests/service/test_die_view.py.

- u_channel: no false "Problem: ... unreachable" on load (the die view is the cycle's), the
  Example dropdown shows the open example, "12,5" in an obstacle coordinate is refused with
  a plain-text notification (no markdown marks) and the box keeps the value in use;
- MZ07: after a plan the Time box's tooltip gives the motion's range.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from browser_helpers import number_box, type_number, wait_for

from workbench.gui.fields import format_number

pytestmark = pytest.mark.e2e
ROOT = Path(__file__).resolve().parents[2]


def test_u_channel_opens_without_false_problems(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(ROOT / "projects" / "u_channel_cell.json")
    page.get_by_role("tab", name="Bending").click()
    page.get_by_role("button", name="Look at die and part").wait_for()
    assert app.bending.result.content == ""  # was "**Problem:** ... unreachable ..."
    assert page.get_by_text("unreachable").count() == 0

    page.get_by_role("tab", name="Project").click()
    assert "(u_channel_cell.json)" in str(app.project_panel.example.value)
    page.locator("input[value*='(u_channel_cell.json)']").first.wait_for()

    label = "Obstacle at x [mm]"
    type_number(page, label, "12,5")
    note = page.locator(".mantine-Notification-root").filter(has_text="decimal comma").first
    note.wait_for()
    text = note.inner_text()
    assert "**" not in text and "`" not in text, text
    wait_for(lambda: number_box(page, label).input_value() == "800", what="the box reverted")
    assert app.import_panel.at_mm == [800.0, 0.0, 0.0]


def test_the_time_tooltip_follows_the_plan(opened) -> None:  # type: ignore[no-untyped-def]
    app, page = opened
    field = app.timeline.time_field
    assert field.text.hint == "allowed none until a motion is planned"
    page.get_by_role("tab", name="Motion").click()
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(lambda: app.wb.last_plan is not None, timeout=90, what="the plan on the server")
    wait_for(lambda: app.timeline.motion is not None, what="the motion on the timeline")
    span = format_number(app.timeline.motion.duration)
    wait_for(lambda: field.text.hint == f"allowed [0, {span}] s", what="the tooltip's range")
