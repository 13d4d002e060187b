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


@pytest.mark.slow
@pytest.mark.timeout(900)
def test_time_from_serve_to_controls_per_example(browser) -> None:  # type: ignore[no-untyped-def]
    """Measure, per example, the seconds from starting `workbench serve` to the tabs visible in
    Chromium (printed: issue 30 part 4 asks for 3 s; this records what it is here)."""
    import os
    import subprocess
    import sys
    import time

    from browser_helpers import PAGE_TIMEOUT_MS, free_port

    figures = {}
    for project in sorted((ROOT / "projects").glob("*.json")):
        port, token = free_port(), f"serve-timing-{project.stem}"  # 16 characters or more
        env = {**os.environ, "PYTHONPATH": str(ROOT)}
        t0 = time.perf_counter()
        proc = subprocess.Popen(
            [sys.executable, "-m", "workbench", "serve", str(project), "--port", str(port)]
            + ["--token", token],
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )
        try:
            assert proc.stdout is not None
            said = []
            for line in proc.stdout:
                said.append(line)
                if "serving" in line:
                    break
            else:
                pytest.fail(f"{project.name}: the server did not start: {''.join(said)}")
            context = browser.new_context(viewport={"width": 1280, "height": 800})
            page = context.new_page()
            page.goto(f"http://127.0.0.1:{port}/?token={token}", timeout=PAGE_TIMEOUT_MS)
            page.get_by_role("tab", name="Robot").wait_for(timeout=PAGE_TIMEOUT_MS)
            figures[project.stem] = time.perf_counter() - t0
            context.close()
        finally:
            proc.terminate()
            proc.wait(timeout=30)
    print("\nfrom `workbench serve` to the tabs visible [s]:")
    for name, s in figures.items():
        print(f"  {name:24s} {s:5.1f}")
    assert len(figures) == len(list((ROOT / "projects").glob("*.json")))
