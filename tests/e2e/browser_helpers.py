"""Small Playwright helpers for the viser page.

Every wait here is for a state (of the page or of the server), never for a fixed time:
it returns as soon as the state holds. The limits only decide when a wait that will not
end is reported; they are generous because the browser renders in software on a loaded
2-core machine.
"""

from __future__ import annotations

import os
import socket
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from playwright.sync_api import Error as PlaywrightError

SERVER_TIMEOUT = 60.0  # [s] limit of a wait for a server-side state
PAGE_TIMEOUT_MS = 90_000  # [ms] limit of a Playwright action or wait (the context's default)
NOTIFICATION_CLOSE = "button.mantine-Notification-closeButton"


def free_port() -> int:
    """Return a TCP port on 127.0.0.1 that nothing listens on now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def number_box(page, label: str):  # type: ignore[no-untyped-def]
    """Return the text box of the numeric field labelled `label` (workbench/gui/fields.py)."""
    row = (
        page.locator(".mantine-Flex-root, div")
        .filter(has=page.get_by_text(label, exact=True))
        .filter(has=page.locator("input[type=text], input:not([type])"))
        .last
    )
    return row.locator("input").first


def type_number(page, label: str, text: str) -> None:  # type: ignore[no-untyped-def]
    """Type `text` into the numeric field labelled `label` (committed by the server after a pause)."""
    box = number_box(page, label)
    box.click()
    box.fill(text)
    box.press("Enter")


def set_slider(page, label: str, value: float) -> None:  # type: ignore[no-untyped-def]
    """Type `value` into the text box of the slider field labelled `label`.

    The slider's own number box is hidden (it reads "12,5" as 125); typed values go through
    the field's strict text box, the slider beside it follows.
    """
    type_number(page, label, f"{value}")


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


def wait_for(predicate, *, timeout: float = SERVER_TIMEOUT, what: str = "condition") -> None:  # type: ignore[no-untyped-def]
    """Poll `predicate` until it is true; fail naming `what` after `timeout` seconds."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return
        time.sleep(0.05)
    pytest.fail(f"timed out after {timeout} s waiting for {what}")


def steady_picture(shot: Callable[[], bytes], *, timeout: float = SERVER_TIMEOUT) -> bytes:
    """Return a picture from `shot` once two taken in a row are equal (drawing has settled)."""
    end = time.monotonic() + timeout
    last = shot()
    while time.monotonic() < end:
        now = shot()
        if now == last:
            return now
        last = now
    pytest.fail(f"the 3D view kept changing for {timeout} s")


def wait_for_new_picture(
    shot: Callable[[], bytes], before: bytes, *, what: str, timeout: float = SERVER_TIMEOUT
) -> bytes:
    """Take pictures with `shot` until one differs from `before`, and return it."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        now = shot()
        if now != before:
            return now
    pytest.fail(f"the 3D view did not change within {timeout} s: {what}")


def wait_for_timeline(app, plots_before: object, *, what: str) -> None:  # type: ignore[no-untyped-def]
    """Wait until the shared timeline has loaded a new motion to the end of its `load`.

    `plots_before` is `app.timeline.plots` taken before the action: `load` makes a new list
    of plots last, just before posing the robot at t = 0, so scrubbing after this wait is not
    undone by the load.
    """
    wait_for(
        lambda: app.timeline.plots is not plots_before and app.timeline.motion is not None,
        what=what,
    )


def close_notifications(page, *, timeout: float = SERVER_TIMEOUT) -> None:  # type: ignore[no-untyped-def]
    """Close every notification on the page, one at a time, until none is left.

    Each is clicked, then waited for until it has left the page: closing one re-indexes the
    rest, and one that closes by itself may leave between finding and clicking it.
    """
    closers = page.locator(NOTIFICATION_CLOSE)
    end = time.monotonic() + timeout
    while closers.count() > 0:
        left = end - time.monotonic()
        if left <= 0:
            pytest.fail(f"{closers.count()} notification(s) still open after {timeout} s")
        try:
            button = closers.first.element_handle(timeout=1000)
        except PlaywrightError:
            continue  # it left between counting and finding it
        try:
            button.click(timeout=5000)
        except PlaywrightError:
            # Detached meanwhile, or covered by a neighbour mid-transition: press it directly.
            try:
                button.dispatch_event("click")
            except PlaywrightError:
                pass  # detached: it is gone, which is what we wait for
        button.wait_for_element_state("hidden", timeout=left * 1000)


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
