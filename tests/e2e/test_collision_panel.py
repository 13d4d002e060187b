"""The collision-engine controls in the Robot tab, in a real Chromium: spheres and Check."""

from __future__ import annotations

import numpy as np
import pytest
from browser_helpers import (
    canvas_png,
    save_screenshot,
    steady_picture,
    type_number,
    wait_for,
    wait_for_new_picture,
)

from workbench.gui.app import WorkbenchApp

pytestmark = pytest.mark.e2e


def test_show_spheres_and_check(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name="Robot").click()
    before = steady_picture(lambda: canvas_png(page))
    page.get_by_label("Show spheres").check()
    wait_for(
        lambda: app.collision.sphere_node is not None, timeout=90, what="spheres on the server"
    )
    centres, radii, _ = app.wb.collision.spheres(None)
    assert np.allclose(app.collision.sphere_node.batched_positions, centres, atol=1e-6)
    wait_for_new_picture(lambda: canvas_png(page), before, what="showing the spheres")

    page.get_by_role("button", name="Check", exact=True).click()
    wait_for(lambda: hasattr(app.collision, "last"), timeout=60, what="the check on the server")
    c = app.collision.last
    expected = app.wb.collision.check()
    assert c.colliding == expected.colliding and c.clearance == pytest.approx(expected.clearance)
    text = f"{c.link} hits {c.obstacle}" if c.colliding else "Collision-free at these joints"
    page.get_by_text(text).first.wait_for()
    steady_picture(lambda: canvas_png(page))
    save_screenshot(page, "collision.png")


def test_plan_collision_mode_control_sets_the_next_plans_mode(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    """The Robot tab's "Plan collision mode" sets the project's field; the next plan uses it."""
    page.get_by_role("tab", name="Robot").click()
    assert app.wb.collision.mode == "spheres"
    page.get_by_role("combobox", name="Plan collision mode").click()
    page.get_by_role("option", name="exact", exact=True).click()
    wait_for(lambda: app.wb.collision.mode == "exact", what="mode exact on the server")
    assert app.wb.project.collision is not None and app.wb.project.collision.mode == "exact"

    page.get_by_role("tab", name="Motion").click()
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(lambda: app.wb.last_plan is not None, timeout=90, what="the plan on the server")
    rep = app.wb.last_plan.collision_report  # type: ignore[union-attr]
    assert rep.mode == "exact" and rep.fallback is not None
    page.get_by_text("collision mode is exact").first.wait_for(timeout=15_000)

    # A refused value (set from Python as a stale client would) puts the widget back.
    app.collision.mode.value = "voxels"  # type: ignore[misc]
    wait_for(lambda: app.collision.mode.value == "exact", what="the widget back on exact")
    assert app.wb.collision.mode == "exact"


def test_clearance_margin_field_is_what_the_next_plan_keeps(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    """The Robot tab's "Clearance margin [mm]" sets collision.margin; the next Motion plan is
    measured against it, names the pair closer than it, and the one clearance figure says so."""
    page.get_by_role("tab", name="Robot").click()
    type_number(page, "Clearance margin [mm]", "40")
    wait_for(
        lambda: abs(app.wb.collision.margin - 0.040) < 1e-12, what="margin 40 mm on the server"
    )
    assert app.wb.project.collision is not None and app.wb.project.collision.margin == 40.0
    page.get_by_role("tab", name="Motion").click()
    page.get_by_role("button", name="Plan", exact=True).click()
    wait_for(lambda: app.wb.last_plan is not None, timeout=120, what="the plan on the server")
    plan = app.wb.last_plan
    assert plan is not None and not plan.ok and plan.collision_report.collision_free
    near = plan.collision_report.nearest
    assert near is not None and near.margin == 0.040 and near.pair is not None
    assert near.distance < 0.040  # the example plans 11.7 mm from link4 – link6
    page.get_by_text("closer than the clearance margin 40.0 mm").first.wait_for(timeout=15_000)
    page.get_by_role("tab", name="Robot").click()
    app.jog.refresh()
    page.get_by_text("closer than the margin").first.wait_for(timeout=15_000)
    # A refused value keeps the margin in use.
    type_number(page, "Clearance margin [mm]", "-3")
    page.get_by_text("collision.margin").first.wait_for(timeout=15_000)
    assert app.wb.collision.margin == 0.040
    save_screenshot(page, "clearance_margin.png")
