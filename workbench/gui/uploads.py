"""Uploaded files on disk: each upload in its own temporary folder, removed when replaced or at exit.

An upload that loads replaces the previous one of its slot (whose folder is removed); one that
fails is removed at once. Whatever is left is removed when the process exits, on SIGTERM too
(`workbench serve` turns it into a normal exit). A folder is named for the process that made it
(``workbench-<kind>-<pid>-*`` in the system's temporary folder), so a server that starts removes
the folders that a crashed or killed one left behind (`remove_stale`). The folder is allowed in
the workbench's `folders` while it exists, so the path rule lets the service read it; a save
copies what the project needs from it beside the project (`service.project_save`).
"""

from __future__ import annotations

import atexit
import os
import re
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from workbench.errors import InputError
from workbench.service import Workbench

MAX_NAME = 120
_LIVE: set[Path] = set()
_OURS = re.compile(r"workbench-(project|workpiece)-(?:(\d+)-)?")  # an upload folder's name


def new_folder(kind: str) -> Path:
    """Return a fresh upload folder for `kind` ("project", "workpiece"), removed at exit."""
    folder = Path(tempfile.mkdtemp(prefix=f"workbench-{kind}-{os.getpid()}-"))
    _LIVE.add(folder)
    return folder


def _gone(pid: int) -> bool:
    """Return whether no process `pid` runs (the GUI layer does not import atomic_file's)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    except OSError:  # another user's process
        return False
    return False


def remove_stale(started: float) -> list[Path]:
    """Remove the upload folders that servers no longer running left behind; return them.

    A folder counts as left behind when the process named in it is gone, or when it names none
    (made before the names carried one) and is older than `started` [s, epoch], this server's
    start. Another running server's folders stay.
    """
    root = Path(tempfile.gettempdir())
    gone = []
    for folder in root.glob("workbench-*"):
        match = _OURS.match(folder.name)
        if match is None or not folder.is_dir() or folder.is_symlink() or folder in _LIVE:
            continue
        pid = match.group(2)
        try:
            stale = _gone(int(pid)) if pid else folder.stat().st_mtime < started
        except OSError:
            continue
        if stale:
            shutil.rmtree(folder, ignore_errors=True)
            gone.append(folder)
    return gone


def _remove(folder: Path | None) -> None:
    if folder is not None:
        _LIVE.discard(folder)
        shutil.rmtree(folder, ignore_errors=True)


@atexit.register
def remove_all() -> None:
    """Remove every upload folder of this process still on disk (run at exit)."""
    for folder in list(_LIVE):
        _remove(folder)
    for folder in Path(tempfile.gettempdir()).glob(f"workbench-*-{os.getpid()}-*"):
        match = _OURS.match(folder.name)
        if match is not None and match.group(2) == str(os.getpid()) and not folder.is_symlink():
            shutil.rmtree(folder, ignore_errors=True)


def safe_name(name: str, default: str) -> str:
    """Return `name` as a plain file name: no folders, NUL or control characters, at most 120 chars."""
    base = Path(str(name).replace("\\", "/")).name
    base = re.sub(r"[\x00-\x1f\x7f/]", "", base).strip().lstrip(".")
    if not base:
        return default
    stem, dot, ext = base.rpartition(".")
    if len(base) > MAX_NAME:
        if not dot or len(ext) > 10:
            raise InputError(
                f"upload name: {len(base)} characters; rename the file (at most {MAX_NAME})"
            )
        base = stem[: MAX_NAME - len(ext) - 1] + "." + ext
    return base


class UploadSlot:
    """Where one kind of upload (the polishing workpiece) lives on disk; see the module doc."""

    def __init__(self, kind: str) -> None:
        self.kind = kind
        self.folder: Path | None = None

    @contextmanager
    def new_file(self, wb: Workbench, name: str, content: bytes) -> Iterator[Path]:
        """Write `content` to a fresh folder and yield its path; keep it only if the block succeeds."""
        folder = new_folder(self.kind)
        path = folder / name
        path.write_bytes(content)
        wb.folders = wb.folders.with_session(folder)
        try:
            yield path
        except BaseException:
            wb.folders = wb.folders.without(folder)
            _remove(folder)
            raise
        old, self.folder = self.folder, folder
        if old is not None:
            wb.folders = wb.folders.without(old)
            _remove(old)

    def clear(self, wb: Workbench | None = None) -> None:
        """Remove the slot's folder (and its allowance in `wb.folders`)."""
        if self.folder is not None and wb is not None:
            wb.folders = wb.folders.without(self.folder)
        _remove(self.folder)
        self.folder = None


WORKPIECES = UploadSlot("workpiece")  # the Polishing tab's uploaded workpiece
