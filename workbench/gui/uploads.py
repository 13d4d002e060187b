"""Uploaded files on disk: each upload in its own temporary folder, removed when replaced or at exit.

An upload that loads replaces the previous one of its slot (whose folder is removed); one that
fails is removed at once. Whatever is left is removed when the process exits. The folder is
allowed in the workbench's `folders` while it exists, so the path rule lets the service read it.
"""

from __future__ import annotations

import atexit
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


def _remove(folder: Path | None) -> None:
    if folder is not None:
        _LIVE.discard(folder)
        shutil.rmtree(folder, ignore_errors=True)


@atexit.register
def remove_all() -> None:
    """Remove every upload folder still on disk (run at exit)."""
    for folder in list(_LIVE):
        _remove(folder)


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

    def __init__(self, prefix: str) -> None:
        self.prefix = prefix
        self.folder: Path | None = None

    @contextmanager
    def new_file(self, wb: Workbench, name: str, content: bytes) -> Iterator[Path]:
        """Write `content` to a fresh folder and yield its path; keep it only if the block succeeds."""
        folder = Path(tempfile.mkdtemp(prefix=self.prefix))
        _LIVE.add(folder)
        path = folder / name
        path.write_bytes(content)
        wb.folders = wb.folders.with_allowed(folder)
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


WORKPIECES = UploadSlot("workbench-workpiece-")  # the Polishing tab's uploaded workpiece
