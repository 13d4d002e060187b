"""Files in a real Chromium: uploads with their meshes, Save and Save as, the project picker.

Saving after an upload never touches another file: every file of projects/ and web_assets/
has the same checksum before and after. Hostile "Save as" names are refused by name.
"""

from __future__ import annotations

import hashlib
import json
import socket
import zipfile
from pathlib import Path

import pytest
from browser_helpers import PAGE_TIMEOUT_MS, close_notifications, wait_for

from workbench.errors import InputError, ProjectError
from workbench.gui.app import WorkbenchApp, start_server
from workbench.gui.server_guard import AccessPolicy, new_token
from workbench.service import Workbench
from workbench.service.project_files import save_target

ROOT = Path(__file__).resolve().parents[2]
PROJECTS = ROOT / "projects"


def _sums() -> dict[str, str]:
    out = {}
    for folder in (PROJECTS, ROOT / "web_assets"):
        for p in sorted(folder.rglob("*")):
            if p.is_file():
                out[str(p)] = hashlib.sha256(p.read_bytes()).hexdigest()
    return out


def _upload(page, path: Path) -> None:  # type: ignore[no-untyped-def]
    with page.expect_file_chooser() as fc:
        page.get_by_role("button", name="Upload project or its files", exact=True).click()
    fc.value.set_files(str(path))


def _row_input(page, label: str):  # type: ignore[no-untyped-def]
    """Return the input of the viser control labelled `label` (its label is not tied to it)."""
    row = page.locator(".mantine-Flex-root").filter(has=page.get_by_text(label, exact=True))
    return row.locator("input").last


def _save_as(page, app: WorkbenchApp, name: str) -> None:  # type: ignore[no-untyped-def]
    box = _row_input(page, "File name")
    box.fill(name)
    box.press("Enter")
    wait_for(lambda: app.project_panel.name.value == name, what=f"the name {name!r} on the server")
    page.get_by_role("button", name="Save as", exact=True).click()


@pytest.mark.parametrize(
    ("name", "says"),
    [
        ("../x.json", "names a folder"),
        ("/etc/passwd", "names a folder"),
        ("a\x00b.json", "NUL or control character"),
        ("x" * 300, "at most 120"),
        ("notes.txt", "does not end in .json"),
        (".hidden.json", "starts or ends with a space or a dot"),
        ("", "no file name given"),
    ],
)
def test_hostile_save_as_names_are_refused(name: str, says: str, tmp_path: Path) -> None:
    with pytest.raises(InputError, match=says):
        save_target(tmp_path, name)
    assert save_target(tmp_path, "cell") == tmp_path / "cell.json"


def test_a_project_whose_part_file_is_missing_is_refused_whole(tmp_path: Path) -> None:
    data = json.loads((PROJECTS / "bending_cell.json").read_text())
    data["bending"]["part_file"] = "parts/missing.json"
    (tmp_path / "b.json").write_text(json.dumps(data))
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    before, folders = wb.project, wb.folders
    from workbench.service.project_files import open_into

    with pytest.raises(ProjectError, match=r"bending\.part_file: cannot read"):
        open_into(wb, tmp_path / "b.json")
    assert wb.project is before and wb.folders == folders
    assert wb.path == PROJECTS / "mz07_cell.json"


@pytest.mark.e2e
def test_saving_after_uploads_never_touches_another_file(launch, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    sums = _sums()
    app, page = launch(PROJECTS / "mz07_cell.json")
    work = tmp_path / "work"
    work.mkdir()
    app.save_folder = work
    page.get_by_role("tab", name="Project").click()
    save = page.get_by_role("button", name="Save to mz07_cell.json")
    assert save.is_disabled()  # an example: read-only to Save

    # A zip of the bending project whose part differs from the example's: read from the zip.
    part = json.loads((PROJECTS / "parts" / "seed_part.json").read_text())
    part["name"] = "uploaded part"
    zpath = tmp_path / "bending.zip"
    with zipfile.ZipFile(zpath, "w") as z:
        z.writestr("cell/bending_cell.json", (PROJECTS / "bending_cell.json").read_text())
        z.writestr("cell/parts/seed_part.json", json.dumps(part))
    _upload(page, zpath)
    wait_for(lambda: app.wb.bending.available, what="the zipped bending project loaded")
    assert app.wb.bending.part_spec().name == "uploaded part"
    assert app.wb.path is None and app.upload_root is not None
    page.get_by_role("tab", name="Bending").wait_for()

    # A zip that lacks the part file is refused whole: the bending project stays.
    broken = tmp_path / "broken.zip"
    with zipfile.ZipFile(broken, "w") as z:
        z.writestr("bending_cell.json", (PROJECTS / "bending_cell.json").read_text())
    before = app.wb.project
    _upload(page, broken)
    page.get_by_text("lacks files its project names").first.wait_for()
    assert app.wb.project is before

    # The JSON, then the mesh it names: loads once the mesh is there.
    close_notifications(page)
    _upload(page, PROJECTS / "polishing_cell.json")
    page.get_by_text("waits for 1 file(s)").first.wait_for()
    assert app.wb.project is before
    _upload(page, ROOT / "web_assets" / "workpieces" / "panel.stl")
    wait_for(lambda: app.wb.polishing.available, what="the polishing project loaded")
    assert str(app.wb.folders.base).startswith(str(app.upload_root))
    page.get_by_role("button", name="Save", exact=True).wait_for()
    assert page.get_by_role("button", name="Save", exact=True).is_disabled()  # no file yet

    # Hostile names are refused with their reason; nothing is written.
    close_notifications(page)
    for name, says in (("../x.json", "names a folder"), ("/etc/passwd", "names a folder")):
        _save_as(page, app, name)
        page.get_by_text(says).first.wait_for()
        close_notifications(page)
    _save_as(page, app, "x" * 300)
    page.get_by_text("at most 120").first.wait_for()
    close_notifications(page)
    assert list(work.iterdir()) == []

    # Save as: the JSON and the uploaded mesh land in the working folder, and it reopens.
    _save_as(page, app, "mine")
    target = work / "mine.json"
    wait_for(target.exists, what="mine.json saved")
    wait_for(lambda: app.wb.path == target, what="the project's file is mine.json")
    reopened = Workbench.open(target)
    assert reopened.project.polishing is not None
    assert reopened.project.polishing.workpiece == "files/panel.stl"  # copied from the upload
    assert (work / "files" / "panel.stl").read_bytes() == (
        ROOT / "web_assets" / "workpieces" / "panel.stl"
    ).read_bytes()
    page.get_by_role("button", name="Save to mine.json").wait_for()

    # An existing name needs "Overwrite"; with it the file is replaced by a rename (atomic).
    close_notifications(page)
    inode = target.stat().st_ino
    _save_as(page, app, "mine")
    page.get_by_text("tick 'Overwrite'").first.wait_for()
    assert target.stat().st_ino == inode
    close_notifications(page)
    _row_input(page, "Overwrite").check()
    wait_for(lambda: app.project_panel.overwrite.value is True, what="Overwrite ticked")
    _save_as(page, app, "mine")
    wait_for(lambda: target.stat().st_ino != inode, what="mine.json replaced")
    assert sorted(p.name for p in work.iterdir()) == ["files", "mine.json"]  # no temp left
    page.get_by_role("button", name="Save to mine.json").click()
    wait_for(lambda: target.stat().st_mtime_ns > 0, what="saved")
    assert _sums() == sums  # no file of projects/ or web_assets/ changed


@pytest.mark.e2e
def test_a_server_without_a_project_opens_the_picker(browser) -> None:  # type: ignore[no-untyped-def]
    wb = Workbench.from_dict({"schema_version": 1, "name": "no project"})
    access = AccessPolicy(new_token())
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = int(s.getsockname()[1])
    server = start_server("127.0.0.1", port, access=access)
    app = WorkbenchApp(server, wb, picker=True)
    context = browser.new_context(viewport={"width": 1280, "height": 800})
    context.set_default_timeout(PAGE_TIMEOUT_MS)
    try:
        page = context.new_page()
        page.goto(access.url("127.0.0.1", server.get_port()))
        button = page.get_by_role("button", name="Open MZ07", exact=False).first
        button.wait_for()
        assert page.get_by_role("tab", name="Robot").count() == 0  # no empty cell's tabs
        button.click()
        wait_for(lambda: app.wb.path is not None, what="the example opened")
        assert app.wb.path.name == "mz07_cell.json"
        page.get_by_role("tab", name="Robot").wait_for()
        page.get_by_role("button", name="Open MZ07", exact=False).wait_for(state="detached")
    finally:
        context.close()
        app.timeline.close()
        server.stop()


def _named_bytes(wb: Workbench) -> list[bytes]:
    from workbench.service.project_files import named_files

    return [wb.folders.resolve(p, w).read_bytes() for w, p in named_files(wb.project)]


def _without_paths(wb: Workbench) -> dict[str, object]:
    from workbench.service.project_files import named_fields

    project = wb.project.model_copy(deep=True)
    for _, path, model, attr in named_fields(project):
        setattr(model, attr, "file" + Path(path).suffix)
    return project.model_dump(mode="json")


@pytest.mark.e2e
def test_download_the_project_zip_upload_it_back_and_save_as_with_copies(  # type: ignore[no-untyped-def]
    launch, tmp_path: Path
) -> None:
    """Issue 29 part 7: "Download project" gives a .zip of the JSON and every file it names;
    "Upload" takes it back as the same project; Save as says where it writes and copies the
    files beside the project when asked."""
    from browser_helpers import save_screenshot

    sums = _sums()
    app, page = launch(PROJECTS / "step_cell.json")
    work = tmp_path / "work"
    work.mkdir()
    app.save_folder = work
    page.get_by_role("tab", name="Project").click()
    app.project_panel.refresh()
    page.get_by_text(f"Writes in {work}").first.wait_for()
    before, files = _without_paths(app.wb), _named_bytes(app.wb)

    with page.expect_download() as dl:
        page.get_by_role("button", name="Download project (.zip)").click()
    download = dl.value
    assert download.suggested_filename == "step_cell.zip"
    zpath = tmp_path / "step_cell.zip"
    download.save_as(zpath)
    with zipfile.ZipFile(zpath) as z:
        assert z.namelist() == [
            "step_cell.json",
            "files/fixture_block.step",
            "files/panel.step",
        ]

    close_notifications(page)
    _upload(page, zpath)
    wait_for(lambda: app.upload_root is not None, what="the zip uploaded and loaded")
    assert app.wb.path is None
    assert _without_paths(app.wb) == before  # the same project
    assert _named_bytes(app.wb) == files  # with the same files

    # Save as with "copy": the files land beside the project, and it reopens the same.
    close_notifications(page)
    page.get_by_role("combobox", name="Files when saving").click()
    page.get_by_role("option", name="copy: beside the project", exact=True).click()
    wait_for(lambda: app.project_panel._files() == "copy", what="copy chosen on the server")
    _save_as(page, app, "portable")
    target = work / "portable.json"
    wait_for(lambda: app.wb.path == target, what="portable.json saved")
    page.get_by_text("Saved", exact=True).first.wait_for()
    save_screenshot(page, "project_zip.png")
    again = Workbench.open(target)
    assert _without_paths(again) == before and _named_bytes(again) == files
    assert sorted(p.relative_to(work).as_posix() for p in work.rglob("*") if p.is_file()) == [
        "files/fixture_block.step",
        "files/panel.step",
        "portable.json",
    ]
    assert _sums() == sums
