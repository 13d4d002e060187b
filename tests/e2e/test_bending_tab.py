"""The Bending tab in a real Chromium: reorder the bends, scrub the folds, plan, see the first hit."""

from __future__ import annotations

import json
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

pytestmark = pytest.mark.e2e

ROOT = Path(__file__).resolve().parents[2]


def test_reorder_fold_plan_and_first_collision(launch, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    # The example passes over the flip rack; its first transfer via lowered into the rack
    # (z 355 mm) makes the part's flanges hit a rack cup.
    d = json.loads((ROOT / "projects" / "bending_cell.json").read_text())
    del d["bending"]["part_file"]
    d["bending"]["part"] = json.loads((ROOT / "projects" / "parts" / "seed_part.json").read_text())
    d["bending"]["transfer"][0]["xyz"][2] = 355
    (tmp_path / "bending_hit.json").write_text(json.dumps(d))
    app, page = launch(tmp_path / "bending_hit.json")
    svc = app.wb.bending
    # Look from behind the robot towards the press brake (the fixture's view is from behind it).
    port = app.server.get_port()
    page.goto(
        f"http://127.0.0.1:{port}/?hideViserLogo"
        "&initialCameraPosition=-0.35,-1.5,1.1&initialCameraLookAt=0.42,-0.3,0.35"
    )
    page.get_by_role("tab", name="Bending").click()
    page.get_by_text("seed_000_fig7").first.wait_for()

    # Reorder the sequence in the text field: the server takes it.
    row = page.locator(".mantine-Flex-root").filter(has=page.get_by_text("Sequence", exact=True))
    row.locator("input").last.fill("b45, b23, b14, b12, b17, b16")
    wait_for(
        lambda: app.bending.sequence.value == "b45, b23, b14, b12, b17, b16",
        what="the typed sequence on the server",
    )
    page.get_by_role("button", name="Apply sequence").click()
    wait_for(
        lambda: svc.sequence == ["b45", "b23", "b14", "b12", "b17", "b16"],
        what="the new sequence on the server",
    )
    assert app.wb.project.bending.sequence == svc.sequence

    # Scrub the fold step: the part is drawn half-way through its third bend, on the die.
    before = steady_picture(lambda: canvas_png(page))
    set_slider(page, "Fold step", 2.5)
    wait_for(lambda: abs(app.bending.step.value - 2.5) < 1e-9, what="the fold step on the server")
    T = svc.die_part_pose(2)
    wait_for(
        lambda: np.allclose(app.bending.part_frame.position, T[:3, 3], atol=1e-9),
        what="the part on the die for bend 3",
    )
    n_vertices = len(svc.fold(2.5).solid().vertices)
    wait_for(lambda: len(app.bending.mesh.vertices) == n_vertices, what="the half-folded mesh")
    wait_for_new_picture(lambda: canvas_png(page), before, what="with the fold step")

    # Show the tree's flange level, then plan.
    page.get_by_text("Level 1 (split 1)").click()
    wait_for(lambda: app.bending.levels[1].value, what="OBB level 1 shown")
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(lambda: svc.last_plan is not None, timeout=90, what="the bending plan")
    plan = svc.last_plan
    first = plan.first_collision
    assert first is not None and first.kind == "part"
    assert all(o.startswith("rack_cup") for o in first.obstacles)
    # The page shows the server's verdict and the per-frame plots.
    page.get_by_text(f"First collision: frame {first.frame + 1}").first.wait_for()
    page.get_by_text("OBB tests per frame").first.wait_for()
    # The timeline sits at the first collision with the part in the gripper there.
    t = float(plan.times[first.frame])
    wait_for(lambda: abs(app.timeline.time.value - t) < 1e-3, what="the timeline at the hit")
    T_part = svc.part_pose_at(plan, app.timeline.time.value)
    wait_for(
        lambda: np.allclose(app.bending.part_frame.position, T_part[:3, 3], atol=1e-6),
        what="the part following the gripper",
    )
    hit_nodes = plan.part_report.frame(first.frame).nodes_hit
    assert hit_nodes
    # The tree report follows the timeline after the part is placed: wait for it too.
    wait_for(
        lambda: (
            f"{len(app.bending.box_nodes)} nodes" in app.bending.tree_info.content
            and "**hit**" in app.bending.tree_info.content
        ),
        what="the tree report of the colliding frame",
    )
    steady_picture(lambda: canvas_png(page))
    (ROOT / "docs").mkdir(exist_ok=True)
    save_screenshot(page, "bending.png")

    # Download a colliding plan: refused, the message says what a GUI user can do, and the
    # GUI's own "Export anyway" writes it.
    wait_for(lambda: not app.bending.export.disabled, what="Download enabled by the plan")
    page.get_by_role("button", name="Download program").click()
    page.get_by_text("the plan has problems").first.wait_for()
    page.get_by_text('press "Export anyway"').first.wait_for()
    with page.expect_download() as dl:
        page.get_by_role("button", name="Export anyway").click()
    assert dl.value.suggested_filename
    wait_for(lambda: not app.bending.export.anyway.visible, what="Export anyway hidden again")


def test_plan_and_download_the_bending_program(launch) -> None:  # type: ignore[no-untyped-def]
    # The example's bending plan is collision-free: the Bending tab downloads its program, the
    # service's export in the format the dropdown shows (NACHI FD for the MZ07).
    app, page = launch(ROOT / "projects" / "bending_cell.json")
    page.get_by_role("tab", name="Bending").click()
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(lambda: app.wb.bending.last_plan is not None, timeout=90, what="the bending plan")
    assert app.wb.bending.last_plan.ok
    button = page.get_by_role("button", name="Download program")
    wait_for(lambda: not app.bending.export.disabled, what="Download enabled by the plan")
    assert app.bending.export.format.value == "nachi" == app.wb.default_program_format()
    with page.expect_download() as dl:
        button.click()
    text = Path(dl.value.path()).read_text()
    assert text == app.wb.export_program("nachi", "bending").text
    assert text.startswith("' PROGRAM ") and "M1J,L" in text
    steady_picture(lambda: canvas_png(page))
    save_screenshot(page, "bending_download.png")
