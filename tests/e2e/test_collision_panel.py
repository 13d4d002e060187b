"""The collision-engine controls in the Robot tab, in a real Chromium: spheres and Check."""

from __future__ import annotations

import numpy as np
import pytest
from browser_helpers import canvas_png, save_screenshot, wait_for

from workbench.gui.app import WorkbenchApp

pytestmark = pytest.mark.e2e


def test_show_spheres_and_check(page, app: WorkbenchApp) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name="Robot").click()
    before = canvas_png(page)
    page.get_by_label("Show spheres").check()
    wait_for(
        lambda: app.collision.sphere_node is not None, timeout=90, what="spheres on the server"
    )
    centres, radii, _ = app.wb.collision.spheres(None)
    assert np.allclose(app.collision.sphere_node.batched_positions, centres, atol=1e-6)
    page.wait_for_timeout(1500)
    assert canvas_png(page) != before, "the 3D view did not change when showing spheres"

    page.get_by_role("button", name="Check", exact=True).click()
    wait_for(lambda: hasattr(app.collision, "last"), timeout=60, what="the check on the server")
    c = app.collision.last
    expected = app.wb.collision.check()
    assert c.colliding == expected.colliding and c.clearance == pytest.approx(expected.clearance)
    text = (
        f"{c.link} hits {c.obstacle}"
        if c.colliding
        else f"clearance at least {c.clearance * 1e3:.1f} mm"
    )
    page.get_by_text(text).first.wait_for(timeout=15_000)
    page.wait_for_timeout(500)
    save_screenshot(page, "collision.png")
