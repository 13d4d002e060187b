"""Browser-test fixtures: a real workbench server on a free port and headless Chromium.

Playwright drives Debian's /usr/bin/chromium (`playwright install` cannot download here).
With CI=true a missing browser fails the run instead of skipping. A failing test saves a
screenshot and the page HTML under tests/e2e/artifacts/.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest
from browser_helpers import PAGE_TIMEOUT_MS, free_port, wait_for

from workbench.gui.app import WorkbenchApp, start_server
from workbench.gui.server_guard import AccessPolicy, new_token
from workbench.service import Workbench

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = os.environ.get("WORKBENCH_CHROMIUM", "/usr/bin/chromium")
ARTIFACTS = Path(__file__).resolve().parent / "artifacts"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo) -> Iterator[None]:
    outcome = yield
    rep = outcome.get_result()  # type: ignore[attr-defined]
    setattr(item, f"rep_{rep.when}", rep)


@pytest.fixture(scope="session")
def browser() -> Iterator[object]:
    if not Path(CHROMIUM).is_file():
        if os.environ.get("CI") == "true":
            pytest.fail(f"{CHROMIUM} is missing; .ci/run installs Debian's chromium")
        pytest.skip(f"{CHROMIUM} is missing (apt-get install chromium)")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        yield b
        b.close()


@pytest.fixture
def launch(browser: object, request: pytest.FixtureRequest) -> Iterator[object]:
    """Return `launch(project_path) -> (app, page)`: a server on a free port and a page on it.

    Everything launched is stopped after the test; a failing test saves a screenshot and the
    page HTML of every page under tests/e2e/artifacts/.
    """
    opened: list[tuple[WorkbenchApp, object, object]] = []

    def _launch(project: Path) -> tuple[WorkbenchApp, object]:
        wb = Workbench.open(project)
        access = AccessPolicy(new_token())  # the page opens the URL `workbench serve` prints
        server = start_server("127.0.0.1", free_port(), access=access)
        application = WorkbenchApp(server, wb)
        context = browser.new_context(viewport={"width": 1280, "height": 800})  # type: ignore[attr-defined]
        # Every action and wait of the page has this limit unless a test says otherwise.
        context.set_default_timeout(PAGE_TIMEOUT_MS)
        context.set_default_navigation_timeout(PAGE_TIMEOUT_MS)
        pg = context.new_page()
        opened.append((application, context, pg))
        pg.goto(
            f"http://127.0.0.1:{server.get_port()}/?hideViserLogo"
            "&initialCameraPosition=1.9,-1.6,1.3&initialCameraLookAt=0.3,0,0.45"
            f"&token={access.token}"
        )
        wait_for(lambda: len(server.get_clients()) > 0, what="the page to connect")
        pg.get_by_role("tab", name="Robot").wait_for()
        return application, pg

    yield _launch
    rep = getattr(request.node, "rep_call", None)
    for k, (application, context, pg) in enumerate(opened):
        if rep is not None and rep.failed:
            ARTIFACTS.mkdir(exist_ok=True)
            pg.screenshot(path=str(ARTIFACTS / f"{request.node.name}-{k}.png"))  # type: ignore[attr-defined]
            (ARTIFACTS / f"{request.node.name}-{k}.html").write_text(pg.content())  # type: ignore[attr-defined]
        context.close()  # type: ignore[attr-defined]
        application.timeline.close()
        application.server.stop()


@pytest.fixture
def opened(launch) -> tuple[WorkbenchApp, object]:  # type: ignore[no-untyped-def]
    """The example MZ07 cell, served and opened in Chromium."""
    return launch(ROOT / "projects" / "mz07_cell.json")  # type: ignore[no-any-return]


@pytest.fixture
def app(opened: tuple[WorkbenchApp, object]) -> WorkbenchApp:
    return opened[0]


@pytest.fixture
def page(opened: tuple[WorkbenchApp, object]) -> object:
    return opened[1]
