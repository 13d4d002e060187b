"""The Project tab's Touch-up folder in a real Chromium: a program touched up on the pendant
(its fixture moved by a known correction, one target moved further alone) uploaded, the table of
changes and the fitted correction shown, applied to the work object, undone.

What the page shows is what the server uses: the correction on the page is the report's, the
work object after Apply is the project's moved by it, and the target moved alone is named on
the page and keeps its taught pose; after Undo the project is the one before.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from browser_helpers import close_notifications, save_screenshot, wait_for
from touchup_cell import CORRECTION, WOBJ, WOBJ_POSE, cell_data, touched_up_files

from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.gui.app import WorkbenchApp

pytestmark = pytest.mark.e2e
NOTIFICATION = ".mantine-Notification-root"
ALONE = ("pick", xyz_rpy_to_transform([0.004, 0.0, -0.002], [0.0, 0.0, 0.0]))  # 4.5 mm more


def _button(page, name: str):  # type: ignore[no-untyped-def]
    return page.get_by_role("button", name=name, exact=True).filter(visible=True)


def _upload(page, path: Path) -> None:  # type: ignore[no-untyped-def]
    with page.expect_file_chooser() as fc:
        _button(page, "Upload edited program").click()
    fc.value.set_files(str(path))


def _wobj_pose(app: WorkbenchApp) -> tuple[list[float], list[float]]:
    w = next(w for w in app.wb.project.work_objects if w.name == WOBJ)
    return list(w.pose.xyz), list(w.pose.rpy)


def test_touched_up_program_compared_applied_to_the_work_object_and_undone(
    launch, tmp_path: Path
) -> None:  # type: ignore[no-untyped-def]
    project = tmp_path / "cell.json"
    project.write_text(json.dumps(cell_data()))
    (name, text), *_ = touched_up_files("rapid", alone=ALONE).items()
    program = tmp_path / name
    program.write_text(text)
    app, page = launch(project)
    panel, wb = app.touchup, app.wb
    page.get_by_role("tab", name="Project").click()
    page.get_by_text("Touch-up", exact=True).click()

    # A file without moves: refused by a notification naming the file and the fix.
    broken = tmp_path / "broken.mod"
    broken.write_text(
        "MODULE x\n PROC main()\n  MoveL nowhere, v100, fine, tool0;\n ENDPROC\nENDMODULE\n"
    )
    _upload(page, broken)
    page.locator(NOTIFICATION).filter(has_text="broken.mod").filter(
        has_text="is it a rapid program?"
    ).first.wait_for()
    assert panel.report is None and _button(page, "Apply touch-up").is_disabled()
    close_notifications(page)

    _upload(page, program)
    wait_for(lambda: panel.report is not None, what="the comparison")
    report = panel.report
    fit = report.correction
    assert fit.wobj == WOBJ and fit.outliers == ("pick",)
    assert np.allclose(fit.T_correction, CORRECTION, atol=2e-5)  # the fixture's known move
    # the page: the correction as the report has it, the target moved alone named
    xyz = ", ".join(f"{v * 1000:.3f}" for v in fit.T_correction[:3, 3])
    page.get_by_text(f"correction xyz ({xyz}) mm").first.wait_for()
    page.get_by_text("moved alone (not folded into fixture): pick").first.wait_for()
    page.locator("tr").filter(has_text="pick").filter(has_text="alone").first.wait_for()
    assert any(t.startswith("pick (alone)  4.") for t in panel.marks.labels)  # 4.3 mm, red
    assert wb.project.work_objects[0].pose.xyz == WOBJ_POSE["xyz"]  # compared, not applied
    close_notifications(page)
    for client in app.server.get_clients().values():  # the camera on the fixture's targets
        with client.atomic():
            client.camera.position = (0.95, -0.75, 0.95)
            client.camera.look_at = (0.43, 0.0, 0.55)  # after the position, which moves it
    page.get_by_text("correction xyz").first.scroll_into_view_if_needed()
    save_screenshot(page, "img/touchup_panel.png")

    # Apply to the work object: it moves by the correction; "pick" keeps its taught pose.
    before = _wobj_pose(app)
    taught_pick = report.row("pick").taught.T_world_tcp
    _button(page, "Apply touch-up").click()
    wait_for(lambda: _wobj_pose(app) != before, timeout=120, what="the work object corrected")
    want = fit.T_world_wobj_new
    got = xyz_rpy_to_transform(
        np.array(wb.project.work_objects[0].pose.xyz) / 1000,
        np.radians(wb.project.work_objects[0].pose.rpy),
    )
    assert np.allclose(got, want, atol=1e-6)
    pick = next(m for m in wb.project.program.moves if getattr(m, "name", None) == "pick")
    assert np.allclose(np.array(pick.pose.xyz) / 1000, taught_pick[:3, 3], atol=1e-5)
    page.get_by_text("applied (work_object)").first.wait_for()

    # Undo: the work object and the targets as they were.
    close_notifications(page)
    _button(page, "Undo touch-up (work object)").click()
    wait_for(lambda: _wobj_pose(app) == before, what="the touch-up undone")
    assert wb.project.work_objects[0].pose.xyz == WOBJ_POSE["xyz"]
    page.get_by_text("Undone", exact=True).first.wait_for()  # the rebuild ended
