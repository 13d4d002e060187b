"""Importing a robot program in a real Chromium: the upload replaces the project's program, the
lines the reader does not understand are listed in a notification that stays, and a bad file
leaves the project as it was."""

from __future__ import annotations

from pathlib import Path

import pytest
from browser_helpers import wait_for

from workbench.gui.app import WorkbenchApp

pytestmark = pytest.mark.e2e

MODULE = """MODULE hand
    CONST robtarget p1:=[[430,180,580],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        MoveJ p1, v500, z10, tool0;
        ConfL \\Off;
        MoveL Offs(p1, 0, 0, -50), v100, fine, tool0;
    ENDPROC
ENDMODULE
"""


def _upload(page, path: Path) -> None:  # type: ignore[no-untyped-def]
    with page.expect_file_chooser() as fc:
        page.get_by_role("button", name="Import program", exact=True).click()
    fc.value.set_files(str(path))


def test_import_a_rapid_module_and_see_its_unknown_line(
    page, app: WorkbenchApp, tmp_path: Path
) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name="Motion").click()
    bad = tmp_path / "broken.mod"
    bad.write_text(
        "MODULE x\n PROC main()\n  MoveL nowhere, v100, fine, tool0;\n ENDPROC\nENDMODULE\n"
    )
    before = app.wb.project
    _upload(page, bad)
    page.get_by_text("no moves the reader understood").first.wait_for()
    assert app.wb.project is before  # refused: nothing changed

    good = tmp_path / "hand.mod"
    good.write_text(MODULE)
    _upload(page, good)
    wait_for(
        lambda: app.wb.project.program is not None and app.wb.project.program.name == "hand",
        what="the imported program on the server",
    )
    page.get_by_text("line 5").first.wait_for()  # ConfL is listed by its line
    items = app.wb.project.program.moves
    assert [m.type for m in items] == ["joint", "linear"]
    # the rebuilt Motion tab lists the imported program and plans it
    page.get_by_role("tab", name="Motion").click()
    page.get_by_text("Program hand").first.wait_for()  # the markdown **Program `hand`**
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(
        lambda: app.wb.last_plan is not None and app.wb.last_plan.program.name == "hand",
        timeout=90,
        what="the imported program planned",
    )
