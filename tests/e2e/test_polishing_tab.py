"""The Polishing tab in a real Chromium: set spacing and force, plan the path, simulate."""

from __future__ import annotations

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
    wait_for_timeline,
)

pytestmark = pytest.mark.e2e

ROOT = Path(__file__).resolve().parents[2]


def workpiece_png(page) -> bytes:  # type: ignore[no-untyped-def]
    """Return a PNG of the part of the 3D view around the workpiece (launch's camera)."""
    return page.screenshot(clip={"x": 520, "y": 300, "width": 300, "height": 220})


def test_plan_and_simulate_a_polishing_path(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(ROOT / "projects" / "polishing_cell.json")
    svc = app.wb.polishing
    page.get_by_role("tab", name="Polishing").click()
    page.get_by_text("panel.stl").first.wait_for()
    before = steady_picture(lambda: workpiece_png(page))

    # Change controls: the section on the server follows.
    set_slider(page, "Spacing [mm]", 25)
    set_slider(page, "Force [N]", 30)
    spec = lambda: app.wb.project.polishing  # noqa: E731
    wait_for(lambda: spec().spacing == 25.0 and spec().force == 30.0, what="spacing and force")

    page.get_by_role("button", name="Plan path").click()
    wait_for(lambda: svc.last_path is not None, timeout=60, what="the path on the server")
    pp = svc.last_path
    assert pp.path.spacing == pytest.approx(0.025) and pp.force == 30.0
    assert pp.offset == pytest.approx(30.0 / 5000.0)
    # The page shows the server's coverage, and the path appears in the 3D view.
    page.get_by_text(f"coverage {pp.coverage.fraction * 100:.1f} %").first.wait_for()
    assert "path" in app.polishing.nodes and "leads_in" in app.polishing.nodes
    wait_for_new_picture(lambda: workpiece_png(page), before, what="the path did not appear")

    plots_before = app.timeline.plots
    page.get_by_role("button", name="Simulate").click()
    wait_for(lambda: svc.last_simulation is not None, timeout=120, what="the simulation")
    sim = svc.last_simulation
    assert sim.target_force == 30.0
    assert sim.max_force_error < 4.0
    page.get_by_text(f"±{sim.max_force_error:.2f} N").first.wait_for()
    page.get_by_text("Contact force vs target [N]").first.wait_for()
    # The orientation loop's error is plotted and summed up from the server's figure.
    assert 0 < sim.max_orientation_error < np.arctan(2 * np.pi * 0.3 / 60)
    page.get_by_text(f"within {np.degrees(sim.max_orientation_error):.2f}°").first.wait_for()
    page.get_by_text("Orientation error [deg]").first.wait_for()
    # The robot runs the path on the shared timeline (loaded last by the panel).
    wait_for_timeline(app, plots_before, what="the polishing motion on the timeline")
    motion = app.timeline.motion
    assert motion is not None and svc.last_motion is not None
    assert motion.duration == pytest.approx(svc.last_motion.cycle_time)
    q0 = motion.at(0.0)
    np.testing.assert_allclose(q0, svc.last_motion.trajectory.waypoints[0], atol=1e-9)
    # Scrubbing the timeline moves the robot in the view.
    shot = steady_picture(lambda: canvas_png(page))
    set_slider(page, "Time [s]", round(motion.duration / 2, 2))
    wait_for(lambda: app.timeline.time.value > 1.0, what="the timeline to move")
    wait_for_new_picture(lambda: canvas_png(page), shot, what="the robot with the timeline")

    # A closer view of the tab in action for the docs: the server moves the camera.
    for client in app.server.get_clients().values():
        client.camera.position = (1.0, -0.75, 0.8)
        client.camera.look_at = (0.45, 0.0, 0.33)
    page.get_by_text("Simulation").first.scroll_into_view_if_needed()
    steady_picture(lambda: canvas_png(page))
    save_screenshot(page, "polishing.png")

    # Download the program (NACHI, no force control): the service's export, and a notification
    # that stays says the targets assume a compliant tool with D = F/k (30 N / 5000 N/m = 6 mm).
    assert app.polishing.format.value == "nachi"
    with page.expect_download(timeout=120_000) as dl:
        page.get_by_role("button", name="Download program").click()
    text = Path(dl.value.path()).read_text()
    assert text == app.wb.export_program("nachi", "polishing").text
    assert "NO FORCE CONTROL" in text and "D = F/k = 6.000 mm" in text
    page.get_by_text("nachi: no force control").first.wait_for()
    page.get_by_text("compliant tool of spring rate k = 5000 N/m").first.wait_for()
    save_screenshot(page, "polishing_download.png")


def test_upload_a_workpiece_and_refuse_a_bad_one(launch, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(ROOT / "projects" / "polishing_cell.json")
    svc = app.wb.polishing
    page.get_by_role("tab", name="Polishing").click()
    page.get_by_text("4602 triangles").first.wait_for()

    # An empty file is refused with a notification; the loaded workpiece stays.
    empty = tmp_path / "empty.stl"
    empty.write_bytes(b"")
    with page.expect_file_chooser() as fc:
        page.get_by_role("button", name="Upload workpiece").click()
    fc.value.set_files(str(empty))
    page.get_by_text("is empty").first.wait_for()
    assert svc.report.n_faces == 4602

    # A coarser panel in mm replaces it: the report and the fitted surface follow.
    from workbench.polishing.example_workpiece import make_panel

    mesh = make_panel(21, 15)
    mesh.apply_scale(1000.0)
    coarse = tmp_path / "coarse.stl"
    mesh.export(str(coarse))
    with page.expect_file_chooser() as fc:
        page.get_by_role("button", name="Upload workpiece").click()
    fc.value.set_files(str(coarse))
    wait_for(lambda: svc.report.n_faces == len(mesh.faces), what="the new workpiece")
    page.get_by_text(f"{len(mesh.faces)} triangles").first.wait_for()
    assert app.wb.project.polishing.workpiece.endswith("coarse.stl")


def test_pick_the_faces_of_a_step_solid(launch, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    import json
    import shutil

    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox
    from OCP.gp import gp_Pnt

    from workbench.cad.step import write_step

    box = BRepPrimAPI_MakeBox(gp_Pnt(-100, -60, 0), 200.0, 120.0, 20.0).Shape()
    (tmp_path / "slab.step").write_bytes(write_step(box, "slab"))
    shutil.copy(ROOT / "web_assets/parts/fixture_block.step", tmp_path / "fixture_block.step")
    data = json.loads((ROOT / "projects/step_cell.json").read_text())
    for obj in data["cell"]["objects"]:
        if "path" in obj:
            obj["path"] = "fixture_block.step"
    data["polishing"]["workpiece"] = "slab.step"  # a closed solid, no faces picked yet
    (tmp_path / "slab_cell.json").write_text(json.dumps(data))

    app, page = launch(tmp_path / "slab_cell.json")
    svc = app.wb.polishing
    page.get_by_role("tab", name="Polishing").click()
    page.get_by_text("closed STEP solid").first.wait_for()  # why it is not loaded yet
    page.get_by_text("6 faces; tick the ones to polish").first.wait_for()
    top = page.get_by_text("5: plane, 24000 mm²")
    top.first.click()
    wait_for(lambda: app.wb.project.polishing.faces == [5], what="the picked face")
    page.get_by_text("Workpiece").first.wait_for()
    wait_for(lambda: "solid" in app.polishing.nodes, what="the whole solid drawn")
    page.get_by_role("button", name="Plan path").click()
    wait_for(lambda: svc.last_path is not None, timeout=60, what="the path on the server")
    proc = svc.last_path.path.points[svc.last_path.path.is_process]
    assert np.allclose(proc[:, 2], 0.340 + 0.020, atol=1e-6)  # on the slab's top face
    steady_picture(lambda: canvas_png(page))
    save_screenshot(page, "polishing_faces.png")
