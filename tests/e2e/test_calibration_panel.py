"""The Project tab's Calibration folder in a real Chromium: bad readings pasted and refused, TCP
readings uploaded into the box, the fit shown (mean and max error, the points with their
residuals in the 3D view), applied, undone.

What the page shows is what the server uses: after Apply the server's tool TCP is the fitted
one and the folder's "In use" line shows it; after Undo both are back. The readings are made by
the project's own kinematics from a known TCP (the tip held on one point in five orientations,
joints in the controller's convention with 0.005 deg of noise), so the fit must recover it.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from browser_helpers import close_notifications, save_screenshot, wait_for

from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.gui.app import WorkbenchApp
from workbench.service import Workbench

pytestmark = pytest.mark.e2e
ROOT = Path(__file__).resolve().parents[2]
PROJECT = ROOT / "projects" / "mz07_cell.json"
NOTIFICATION = ".mantine-Notification-root"
TRUE_TCP_MM = (4.0, -3.0, 152.0)  # the project says (0, 0, 150)
POINT_M = (0.45, 0.05, 0.30)  # the fixed point the tip is held on [m, world]
TILTS_DEG = ((180, 0, 0), (155, 0, 30), (180, 25, -40), (200, -10, 90), (170, -20, -120))


def tcp_readings(noise_deg: float = 0.005, seed: int = 28) -> str:
    """Return `label,j1..j6` readings [deg, controller] of the tool with TCP `TRUE_TCP_MM` held
    on `POINT_M` in the orientations `TILTS_DEG` (the project's robot, IK then noise)."""
    data = json.loads(PROJECT.read_text())
    data["tool"]["tcp"] = {"xyz": list(TRUE_TCP_MM), "rpy": [0, 0, 0]}
    wb = Workbench.from_dict(data, base_dir=PROJECT.parent)
    rng = np.random.default_rng(seed)
    rows = ["label,j1,j2,j3,j4,j5,j6"]
    for k, rpy in enumerate(TILTS_DEG):
        q = wb.ik_solutions(xyz_rpy_to_transform(POINT_M, np.radians(rpy)))[0].q
        deg = np.degrees(wb.robot.convention.to_controller(q)) + rng.normal(0, noise_deg, 6)
        rows.append(f"r{k + 1}," + ",".join(f"{v:.4f}" for v in deg))
    return "\n".join(rows) + "\n"


def _box(page, label: str):  # type: ignore[no-untyped-def]
    """Return the text area of the viser text box labelled `label`."""
    row = page.locator(".mantine-Flex-root").filter(has=page.get_by_text(label, exact=True))
    return row.locator("textarea").last


def _notification(page, *texts: str):  # type: ignore[no-untyped-def]
    """Return the first notification that shows every one of `texts`."""
    found = page.locator(NOTIFICATION)
    for t in texts:
        found = found.filter(has_text=t)
    return found.first


def _button(page, name: str):  # type: ignore[no-untyped-def]
    return page.get_by_role("button", name=name, exact=True).filter(visible=True)


def _open_folder(page) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name="Project").click()
    page.get_by_text("Calibration", exact=True).click()
    _box(page, "Readings (CSV)").wait_for()


def _look_at(app: WorkbenchApp, point: tuple[float, float, float]) -> None:
    """Point every page's camera at `point` [m] from 0.9 m away (for the screenshot)."""
    for client in app.server.get_clients().values():
        with client.atomic():
            client.camera.position = np.add(point, (0.45, -0.65, 0.4))
            client.camera.look_at = point  # after the position, which moves look_at with it


def _paste(page, app: WorkbenchApp, text: str) -> None:  # type: ignore[no-untyped-def]
    _box(page, "Readings (CSV)").fill(text)
    wait_for(lambda: app.calibration.readings.text == text, what="the readings on the server")


def test_tcp_readings_pasted_fitted_applied_and_undone(
    page, app: WorkbenchApp, tmp_path: Path
) -> None:  # type: ignore[no-untyped-def]
    _open_folder(page)
    panel, wb = app.calibration, app.wb

    # Bad readings: refused by a notification naming the box and the fix; nothing computed.
    _paste(page, app, "label,j1,j2\nr1,5,6\n")
    _button(page, "Compute").click()
    _notification(page, "Readings (CSV)", "label,j1,j2,j3").wait_for()
    assert panel.result is None and _button(page, "Apply to project").is_disabled()
    close_notifications(page)

    # Good readings uploaded from a file: the box shows them, the server holds them; then the
    # fit, its errors on the page, its points and frame in the 3D view.
    text = tcp_readings()
    readings = tmp_path / "tcp_readings.csv"
    readings.write_text(text.replace("\n", "\r\n"))  # as a Windows pendant export writes it
    with page.expect_file_chooser() as fc:
        _button(page, "Upload readings").click()
    fc.value.set_files(str(readings))
    wait_for(lambda: app.calibration.readings.text == text, what="the uploaded readings")
    wait_for(lambda: _box(page, "Readings (CSV)").input_value() == text, what="the box filled")
    _button(page, "Compute").click()
    wait_for(lambda: panel.result is not None, what="the TCP fit")
    result = panel.result
    mean = next(line for line in result.summary().splitlines() if "mean error" in line)
    page.get_by_text(mean.strip()[:40]).first.wait_for()  # "mean error 0.0xx mm, max error ..."
    assert np.allclose(result.T[:3, 3] * 1000, TRUE_TCP_MM, atol=0.2)
    assert len(panel.marks.labels) == len(TILTS_DEG) + 1  # a label per reading, the frame's
    assert panel.marks.labels[0].startswith("r1  ") and panel.marks.labels[0].endswith(" mm")
    assert wb.project.tool.tcp.xyz == [0.0, 0.0, 150.0]  # computed, not applied
    close_notifications(page)
    _look_at(app, POINT_M)
    page.get_by_text(mean.strip()[:40]).first.scroll_into_view_if_needed()
    save_screenshot(page, "img/calibration_panel.png")

    # Apply: the server's tool is the fitted one, and the folder shows it.
    _button(page, "Apply to project").click()
    wait_for(
        lambda: np.allclose(wb.project.tool.tcp.xyz, result.T[:3, 3] * 1000, atol=1e-3),
        what="the fitted TCP in the project",
    )
    shown = ", ".join(f"{v:.2f}" for v in wb.project.tool.tcp.xyz)
    page.get_by_text(f"xyz ({shown})").first.wait_for()
    assert np.allclose(wb.tcp_pose()[:3, 3], app.scene.tcp_frame.position, atol=1e-9)

    # Undo: the project before the apply is back, on the server and on the page.
    close_notifications(page)
    _button(page, "Undo calibration: TCP of gripper").click()
    wait_for(lambda: wb.project.tool.tcp.xyz == [0.0, 0.0, 150.0], what="the TCP undone")
    page.get_by_text("xyz (0.00, 0.00, 150.00)").first.wait_for()
    page.get_by_text("Undone", exact=True).first.wait_for()
    wait_for(lambda: _button(page, "Undo").is_disabled(), what="nothing left to undo")
