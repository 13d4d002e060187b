"""Small Playwright helpers for the viser page."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest


def set_slider(page, label: str, value: float) -> None:  # type: ignore[no-untyped-def]
    """Type `value` into the number box beside the viser slider labelled `label`."""
    row = (
        page.locator(".mantine-Flex-root, div")
        .filter(has=page.get_by_text(label, exact=True))
        .filter(has=page.get_by_role("slider"))
        .last
    )
    box = row.locator("input").last
    box.click()
    box.fill(f"{value}")
    box.press("Enter")


def canvas_png(page) -> bytes:  # type: ignore[no-untyped-def]
    """Return a PNG of the 3D view only (clipped left of the GUI panel)."""
    canvas = page.locator("canvas").first
    box = canvas.bounding_box()
    clip = {
        "x": box["x"] + 10,
        "y": box["y"] + 60,
        "width": box["width"] * 0.45,
        "height": box["height"] - 120,
    }
    return page.screenshot(clip=clip)


def wait_for(predicate, *, timeout: float = 15.0, what: str = "condition") -> None:  # type: ignore[no-untyped-def]
    """Poll `predicate` until it is true; fail naming `what` after `timeout` seconds."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return
        time.sleep(0.05)
    pytest.fail(f"timed out after {timeout} s waiting for {what}")


def save_screenshot(page, name: str) -> Path:  # type: ignore[no-untyped-def]
    """Save a screenshot of the page as `name` (e.g. "bending.png") and return its path.

    It goes to docs/ (the README's pictures) when WORKBENCH_UPDATE_SCREENSHOTS=1, else to
    tests/e2e/artifacts/, so an ordinary test run leaves the checkout clean.
    """
    here = Path(__file__).resolve().parent
    folder = (
        here.parents[1] / "docs"
        if os.environ.get("WORKBENCH_UPDATE_SCREENSHOTS") == "1"
        else here / "artifacts"
    )
    folder.mkdir(exist_ok=True)
    path = folder / name
    page.screenshot(path=str(path))
    return path
