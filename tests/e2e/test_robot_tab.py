"""The Robot tab in a real Chromium: jog by slider, collision colouring, project upload/download."""

from __future__ import annotations

import json
import zipfile
from pathlib import Path

import numpy as np
import pytest
from browser_helpers import (
    canvas_png,
    save_screenshot,
    set_slider,
    steady_picture,
    wait_for,
    wait_for_new_picture,
)

from workbench.gui.app import WorkbenchApp
from workbench.gui.scene import COLLISION_COLOR, ROBOT_COLOR

pytestmark = pytest.mark.e2e


def test_page_shows_robot_and_jog_moves_it(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    sliders = page.get_by_role("slider")
    assert sliders.count() >= 6
    before = steady_picture(lambda: canvas_png(page))
    save_screenshot(page, "screenshot.png")

    set_slider(page, "J1 [deg]", 35.0)
    wait_for(
        lambda: abs(np.degrees(app.wb.joints[0]) - 35.0) < 1e-6, what="J1 = 35 deg on the server"
    )
    # The link poses in the scene follow the server's joints.
    T = app.wb.link_poses()[1]
    node = app.scene.links["link1"]
    wait_for(lambda: np.allclose(node.position, T[:3, 3], atol=1e-6), what="link 1 at the new pose")
    wait_for_new_picture(lambda: canvas_png(page), before, what="after moving J1")


def test_collision_turns_links_red_and_reports(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    # J2 below 90 (the upright arm on the NACHI pendant) tips the arm forward into the table.
    set_slider(page, "J2 [deg]", 30.0)
    wait_for(lambda: app.wb.collision_status().in_collision, what="a collision on the server")
    hit = app.wb.collision_status().colliding_bodies()
    free = [n for n in app.scene.links if n not in hit and n != "tool"]
    # The scene is recoloured in the jog callback after the joints are set: wait for it.
    wait_for(
        lambda: (
            any(
                tuple(app.scene.links[n].color) == COLLISION_COLOR
                for n in hit
                if n in app.scene.links
            )
            and all(tuple(app.scene.links[n].color) == ROBOT_COLOR for n in free)
        ),
        what="the colliding links red and the free ones in the robot colour",
    )
    page.get_by_text("Collision:").first.wait_for()


def test_upload_bad_project_shows_field_and_keeps_state(
    page, app: WorkbenchApp, tmp_path: Path
) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name="Project").click()
    bad = tmp_path / "bad.json"
    bad.write_text(
        json.dumps(
            {
                "schema_version": 1,
                "cell": {
                    "objects": [
                        {"name": "a", "shape": "box", "size": [1, 2], "pose": {"xyz": [0, 0, 0]}}
                    ]
                },
            }
        )
    )
    name_before = app.wb.project.name
    with page.expect_file_chooser() as fc:
        page.get_by_role("button", name="Upload project or its files", exact=True).click()
    fc.value.set_files(str(bad))
    page.get_by_text("cell.objects[0].size").first.wait_for()
    assert app.wb.project.name == name_before


def test_download_gives_the_current_project(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name="Project").click()
    with page.expect_download() as dl:
        page.get_by_role("button", name="Download project (.zip)").click()
    with zipfile.ZipFile(dl.value.path()) as z:  # the JSON and the files it names (none here)
        assert z.namelist() == [f"{app.wb.path.stem}.json"]
        data = json.loads(z.read(z.namelist()[0]))
    assert data == json.loads(app.wb.to_json())
    assert data["robot"]["preset"] == "mz07"


def test_switching_ik_configuration_keeps_the_tcp(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    # A pose with several configurations within the limits.
    app.wb.set_joints(np.radians([10, -20, 10, 30, -40, -20]))
    app.jog.refresh()
    T = app.wb.tcp_pose()
    labels = [s.label for s in app.wb.ik_solutions(T)]
    assert len(labels) >= 2, labels
    q_before = app.wb.joints
    page.get_by_role("combobox", name="IK configuration").click()
    page.get_by_role("option", name=labels[1], exact=True).click()  # named by branch, no number
    wait_for(
        lambda: not np.allclose(app.wb.joints, q_before), what="the arm to change configuration"
    )
    assert np.allclose(app.wb.tcp_pose(), T, atol=1e-9), (
        "the TCP moved when the configuration changed"
    )
    # The sliders in the page show the new joints, as the controller does (J2 = model + 90).
    j2 = page.get_by_role("slider").nth(1).get_attribute("aria-valuenow")
    j2_ctrl = np.degrees(app.wb.robot.convention.to_controller(app.wb.joints)[1])
    assert abs(j2_ctrl - (np.degrees(app.wb.joints[1]) + 90.0)) < 1e-9
    wait_for(
        lambda: (
            abs(
                float(page.get_by_role("slider").nth(1).get_attribute("aria-valuenow") or "nan")
                - np.degrees(app.wb.robot.convention.to_controller(app.wb.joints)[1])
            )
            < 0.1
        ),
        what=f"slider J2 to show the new joint value (was {j2})",
    )
