"""Nothing saved is lost, in a real Chromium against a real `workbench serve`: an obstacle, a
part and a workpiece uploaded through the GUI, Save, the server stopped with SIGTERM (as
`docker stop` does) and started again: the saved project opens and plans, and the upload folders
are gone.

The server runs as its own process (the SIGTERM is real); what it saved is opened again by
`workbench serve` and planned by a fresh Python process.
"""

from __future__ import annotations

import json
import shutil
import signal
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
import trimesh
from browser_helpers import PAGE_TIMEOUT_MS, close_notifications, free_port, wait_for

pytestmark = pytest.mark.e2e

ROOT = Path(__file__).resolve().parents[2]
TOKEN = "e2e-saved-uploads-token"


@contextmanager
def served(project: Path) -> Iterator[subprocess.Popen[str]]:
    """Run `workbench serve project` (working folder: the project's) until the block ends."""
    port = free_port()
    proc = subprocess.Popen(
        [sys.executable, "-m", "workbench", "serve", str(project), "--port", str(port)]
        + ["--token", TOKEN],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        cwd=project.parent,
    )
    try:
        assert proc.stdout is not None
        lines = []
        for line in proc.stdout:
            lines.append(line)
            if "serving" in line:
                break
        else:
            pytest.fail("the server did not start:\n" + "".join(lines))
        proc.port = port  # type: ignore[attr-defined]
        yield proc
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(timeout=30)


def _page(browser, port: int):  # type: ignore[no-untyped-def]
    context = browser.new_context(viewport={"width": 1280, "height": 800})
    context.set_default_timeout(PAGE_TIMEOUT_MS)
    page = context.new_page()
    page.goto(f"http://127.0.0.1:{port}/?hideViserLogo&token={TOKEN}")
    page.get_by_role("tab", name="Robot").wait_for()
    return context, page


def _upload(page, button: str, path: Path) -> None:  # type: ignore[no-untyped-def]
    with page.expect_file_chooser() as fc:
        page.get_by_role("button", name=button, exact=True).click()
    fc.value.set_files(str(path))


def _uploads_of(pid: int) -> list[Path]:
    return sorted(Path(tempfile.gettempdir()).glob(f"workbench-*-{pid}-*"))


def _stop(proc: subprocess.Popen[str]) -> None:
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(timeout=60) == 128 + signal.SIGTERM


def _plans_from_a_fresh_process(project: Path) -> str:
    script = (
        "import sys\n"
        "from workbench import Workbench\n"
        "from workbench.service.programs import plan_workflow\n"
        "wb = Workbench.open(sys.argv[1])\n"
        "for wf in wb.project.workflows():\n"
        "    print('planned', wf, plan_workflow(wb, wf).ok, flush=True)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script, str(project)], capture_output=True, text=True, timeout=600
    )
    assert done.returncode == 0, done.stdout + done.stderr[-3000:]
    return done.stdout


def _far_box(path: Path) -> None:
    """A 50 mm cube 2 m to the side of where it is placed (clear of every example's cell)."""
    box = trimesh.creation.box((50.0, 50.0, 50.0))
    box.apply_translation((0.0, -2000.0, 25.0))
    path.write_bytes(box.export(file_type="stl"))


def test_uploads_saved_then_sigterm_then_the_project_opens_and_plans(
    browser, tmp_path: Path
) -> None:  # type: ignore[no-untyped-def]
    mine = tmp_path / "mine"  # the user's own files, uploaded from the browser's machine
    mine.mkdir()
    _far_box(mine / "crate.stl")
    shutil.copyfile(ROOT / "projects" / "parts" / "u_channel.step", mine / "channel.step")
    shutil.copyfile(ROOT / "web_assets" / "workpieces" / "panel.stl", mine / "my_panel.stl")

    # 1. A press-brake cell: an obstacle and a part (STEP) through the Import folder.
    work = tmp_path / "bend"
    shutil.copytree(ROOT / "projects" / "parts", work / "parts")
    shutil.copyfile(ROOT / "projects" / "u_channel_cell.json", work / "cell.json")
    # 2. A polishing cell: an obstacle and a workpiece through the Polishing tab.
    polish = tmp_path / "polish"
    polish.mkdir()
    data = json.loads((ROOT / "projects" / "polishing_cell.json").read_text())
    data["polishing"]["workpiece"] = "panel.stl"
    shutil.copyfile(ROOT / "web_assets" / "workpieces" / "panel.stl", polish / "panel.stl")
    (polish / "cell.json").write_text(json.dumps(data))

    obstacle = ("Import obstacle", "crate.stl", "in the cell")
    part = ("Import part (STEP or DXF)", "channel.step", "3 flanges, 2 bends")
    workpiece = ("Upload workpiece", "my_panel.stl", "triangles")
    for project, uploads in (
        (work / "cell.json", [obstacle, part]),
        (polish / "cell.json", [obstacle, workpiece]),
    ):
        with served(project) as proc:
            context, page = _page(browser, proc.port)  # type: ignore[attr-defined]
            for button, name, shown in uploads:
                tab = "Polishing" if button == "Upload workpiece" else "Project"
                page.get_by_role("tab", name=tab).click()
                _upload(page, button, mine / name)
                page.get_by_text(shown).first.wait_for()  # the panel shows it in use
                close_notifications(page)
            page.get_by_role("tab", name="Project").click()
            before = project.read_text()
            page.get_by_role("button", name="Save to cell.json", exact=True).click()
            # the notification's own title (a bare "Saved" also matches the File name field's
            # hint "saved in the working folder"), then the file the save replaced (atomic: old
            # or new, never half): nothing is read before the save has written
            page.get_by_text("Saved", exact=True).first.wait_for()
            wait_for(
                lambda p=project, b=before: p.read_text() != b, what="the save to write the file"
            )
            assert _uploads_of(proc.pid), "the uploads wait in the server's upload folders"
            saved = json.loads(project.read_text())
            context.close()
            _stop(proc)
            assert _uploads_of(proc.pid) == []  # SIGTERM: removed like a normal exit
        paths = [o.get("path") for o in saved["cell"]["objects"] if o.get("shape") == "mesh"]
        assert "files/crate.stl" in paths
        assert (project.parent / "files" / "crate.stl").read_bytes() == (
            mine / "crate.stl"
        ).read_bytes()
        if "polishing" in saved:
            assert saved["polishing"]["workpiece"] == "files/my_panel.stl"
        else:
            assert saved["bending"]["part"]["thickness"] > 0  # the STEP part, stored inline
        # Restarted on the saved file: it opens; a fresh process plans every workflow.
        with served(project) as proc:
            context, page = _page(browser, proc.port)  # type: ignore[attr-defined]
            context.close()
            _stop(proc)
        out = _plans_from_a_fresh_process(project)
        for wf in ("polishing",) if "polishing" in saved else ("bending",):
            assert f"planned {wf}" in out
