"""The Project tab's Import folder in a real Chromium: a library robot, a STEP part, a DXF part,
a STEP obstacle, and a refused file.

What the page shows is what the server uses: after "Use robot" the dropdown names the robot the
workbench holds (its preset) and the exports' default; an imported part is the part the project
file's own `part_file` route recognises from the same bytes; an imported obstacle is in the
cell; a broken file is refused by a notification that says why, and nothing changes.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from browser_helpers import (
    close_notifications,
    number_box,
    save_screenshot,
    type_number,
    wait_for,
)

from workbench.project.part_import import PartImportSpec, import_part

pytestmark = pytest.mark.e2e

ROOT = Path(__file__).resolve().parents[2]
PARTS = ROOT / "projects" / "parts"


def _upload(page, button: str, path: Path) -> None:  # type: ignore[no-untyped-def]
    with page.expect_file_chooser() as fc:
        page.get_by_role("button", name=button, exact=True).click()
    fc.value.set_files(str(path))


def test_import_a_robot_a_step_part_a_dxf_part_and_an_obstacle(launch, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(ROOT / "projects" / "u_channel_cell.json")
    page.get_by_role("tab", name="Project").click()
    panel = app.import_panel

    # A robot of the library: the server's robot is the one the dropdown shows.
    page.get_by_role("combobox", name="Robot").click()
    page.get_by_role("option", name=panel.choices[1].label, exact=True).click()
    wait_for(lambda: panel.robot.value == panel.choices[1].label, what="the robot chosen")
    page.get_by_role("button", name="Use robot", exact=True).click()
    wait_for(lambda: app.wb.project.robot.preset == "kr6_r900_2", what="the KUKA robot in use")
    page.get_by_text("exports default to krl").first.wait_for()
    assert app.wb.default_program_format() == "krl"

    # A STEP of the bent part: the bending section's part is what the file route recognises.
    close_notifications(page)
    step = (PARTS / "u_channel.step").read_bytes()
    _upload(page, "Import part (STEP or DXF)", PARTS / "u_channel.step")
    twin = import_part(step, "u_channel.step", PartImportSpec())
    wait_for(lambda: app.wb.project.bending.part == twin, what="the STEP part in use")
    page.get_by_text("3 flanges, 2 bends").first.wait_for()
    save_screenshot(page, "img/import_panel.png")

    # A DXF without its thickness is refused by name; with it, it loads.
    close_notifications(page)
    before = app.wb.project.bending.part
    _upload(page, "Import part (STEP or DXF)", PARTS / "pan_flat.dxf")
    page.get_by_text("thickness").first.wait_for()
    assert app.wb.project.bending.part == before
    close_notifications(page)
    type_number(page, "Sheet thickness [mm]", "-2")  # out of bounds: refused, the box reverts
    page.get_by_text("Sheet thickness [mm]: refused").first.wait_for()
    page.get_by_text("kept the box blank").first.wait_for()  # what the box shows
    wait_for(lambda: number_box(page, "Sheet thickness [mm]").input_value() == "", what="revert")
    assert panel.numbers == {}
    close_notifications(page)
    type_number(page, "Sheet thickness [mm]", "1.5")
    type_number(page, "Inner radius [mm]", "1.5")
    wait_for(lambda: panel.numbers == {"thickness": 1.5, "inner_radius": 1.5}, what="numbers")
    _upload(page, "Import part (STEP or DXF)", PARTS / "pan_flat.dxf")
    wait_for(
        lambda: len(app.wb.project.bending.part.flanges) == 5, what="the DXF pan's five flanges"
    )
    assert app.wb.project.bending.part.thickness == 1.5

    # A STEP obstacle lands in the cell; a broken one is refused and the cell stays.
    close_notifications(page)
    n = len(app.wb.project.cell.objects)
    _upload(page, "Import obstacle", ROOT / "web_assets" / "parts" / "fixture_block.step")
    wait_for(lambda: len(app.wb.project.cell.objects) == n + 1, what="the obstacle in the cell")
    assert app.wb.project.cell.objects[-1].name == "fixture_block"
    close_notifications(page)
    broken = tmp_path / "broken.step"
    broken.write_bytes(b"ISO-10303-21;\nHEADER;\n")
    _upload(page, "Import obstacle", broken)
    page.get_by_text("cannot read STEP file").first.wait_for()
    assert len(app.wb.project.cell.objects) == n + 1

    # Each import rebuilt the tabs: the Bending tab shows its widgets once, none left behind.
    page.get_by_role("tab", name="Bending").click()
    page.get_by_text("Level 0 (root)").first.wait_for()
    assert page.get_by_text("OBB tree levels", exact=True).count() == 1


def test_a_step_that_crashes_the_reader_is_refused_and_the_server_answers(  # type: ignore[no-untyped-def]
    launch, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Issue 29: a STEP whose nested list crashes Open CASCADE's parser (its nesting bound lifted
    here, so the file reaches the parser) ended the server with every page; it now crashes the
    CAD worker only. So does a STEP with broken references on the obstacle (mesh) route."""
    from hostile_cad import broken_step, deep_step

    from workbench.cad import step_checks

    app, page = launch(ROOT / "projects" / "u_channel_cell.json")
    page.get_by_role("tab", name="Project").click()
    monkeypatch.setattr(step_checks, "MAX_STEP_NESTING", 10**9)
    deep, broken = tmp_path / "deep.step", tmp_path / "broken.step"
    deep.write_bytes(deep_step())
    broken.write_bytes(broken_step())
    before = app.wb.project.bending.part
    _upload(page, "Import part (STEP or DXF)", deep)
    page.get_by_text("the reader crashed on 'deep.step' (with SIGSEGV)").first.wait_for()
    save_screenshot(page, "img/import_panel_crash.png")
    assert app.wb.project.bending.part == before
    close_notifications(page)
    n = len(app.wb.project.cell.objects)
    _upload(page, "Import obstacle", broken)
    page.get_by_text("does not load whole: 10 entities fail").first.wait_for()
    assert len(app.wb.project.cell.objects) == n
    close_notifications(page)
    _upload(page, "Import part (STEP or DXF)", PARTS / "u_channel.step")  # the same server
    page.get_by_text("3 flanges, 2 bends").first.wait_for()
