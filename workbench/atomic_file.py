"""Atomic file writes: a crash mid-write never leaves a broken or empty file behind.

A save keeps the file as it was: its mode and owner are carried over, a symlink stays a
symlink (the write goes to the file it points to), and only a regular file is ever replaced
(a folder, device node or pipe at the path is refused). Temporary files left by an interrupted
save (kill -9, power loss) are removed by the next save of the same file.
"""

from __future__ import annotations

import os
import re
import stat
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import IO, Any

from workbench.errors import InputError

STALE_TEMP_SECONDS = 600.0  # a temporary file of a live process older than this is stale
_NAME_IN_TEMP = 100  # characters of the file name kept in its temporary file's name


def _temp_prefix(name: str) -> str:
    return f".{name[:_NAME_IN_TEMP]}."


def pid_alive(pid: int) -> bool:
    """Return whether process `pid` runs (another user's counts as running)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def remove_stale_temporaries(target: Path) -> list[Path]:
    """Remove the temporary files an interrupted save of `target` left in its folder; return them.

    A temporary file is stale when the process that wrote it is gone, or when it is older than
    `STALE_TEMP_SECONDS` (a concurrent save of a live process is left alone).
    """
    prefix = _temp_prefix(target.name)
    pattern = re.compile(re.escape(prefix) + r"(?:(\d+)\.)?[A-Za-z0-9_]+\.tmp")
    removed = []
    try:
        entries = list(os.scandir(target.parent))
    except OSError:
        return []
    now = time.time()
    for entry in entries:
        m = pattern.fullmatch(entry.name)
        if m is None:
            continue
        try:
            st = entry.stat(follow_symlinks=False)
        except OSError:
            continue
        if not stat.S_ISREG(st.st_mode):
            continue
        pid = int(m.group(1)) if m.group(1) else None
        old = now - st.st_mtime > STALE_TEMP_SECONDS
        if old or (pid is not None and pid != os.getpid() and not pid_alive(pid)):
            try:
                os.unlink(entry.path)
                removed.append(Path(entry.path))
            except OSError:
                pass
    return removed


def _target(path: Path) -> tuple[Path, os.stat_result | None]:
    """Return the file a write of `path` replaces (through symlinks) and its stat, if it exists."""
    real = Path(os.path.realpath(path)) if path.is_symlink() else path
    try:
        st = os.stat(real)
    except FileNotFoundError:
        return real, None
    if not stat.S_ISREG(st.st_mode):
        kind = "a folder" if stat.S_ISDIR(st.st_mode) else "not a regular file (a device or pipe)"
        raise InputError(f"{path}: is {kind}; refusing to replace it, give the path of a file")
    return real, st


def _umask_mode() -> int:
    """Return the mode `open` gives a new file under the process's umask (read without setting it)."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return 0o666 & ~int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)  # no /proc: the classic dance (briefly process-wide)
    os.umask(mask)
    return 0o666 & ~mask


def _carry_over(fd: int, st: os.stat_result | None) -> None:
    """Give the temporary file `fd` the mode and owner of the file it replaces."""
    os.fchmod(fd, stat.S_IMODE(st.st_mode) if st is not None else _umask_mode())
    if st is None:
        return
    try:
        os.fchown(fd, st.st_uid, st.st_gid)
    except PermissionError:  # not ours to give away: keep at least the group if we may
        try:
            os.fchown(fd, -1, st.st_gid)
        except PermissionError:
            pass


def atomic_write(
    path: str | os.PathLike[str],
    write: Callable[[IO[Any]], object],
    *,
    binary: bool,
    durable: bool = True,
) -> None:
    """Write `path` atomically with write(file): temporary file in the same folder, fsync, rename.

    The temporary file has a unique name, so two writers of the same path never mix their
    bytes; the last rename wins and the folder is synced after it. The file keeps its mode and
    owner (a new one gets the umask's mode, as `open` would give it); a symlink is followed and
    kept; anything but a regular file at the path raises InputError. durable=False skips
    the two fsyncs (still atomic for readers): for cache entries, which are checked on load,
    so one lost or torn by a power cut is only rebuilt.
    """
    p = Path(path)
    real, st = _target(p)
    folder = real.parent if str(real.parent) else Path(".")
    folder.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(real)
    fd, tmp = tempfile.mkstemp(
        prefix=f"{_temp_prefix(real.name)}{os.getpid()}.", suffix=".tmp", dir=folder
    )
    try:
        fh: IO[Any] = os.fdopen(fd, "wb") if binary else os.fdopen(fd, "w", encoding="utf-8")
        with fh:
            _carry_over(fh.fileno(), st)
            write(fh)
            fh.flush()
            if durable:
                os.fsync(fh.fileno())
        os.replace(tmp, real)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    if not durable:
        return
    try:
        dir_fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(dir_fd)
    finally:
        os.close(dir_fd)


def atomic_write_text(path: str | os.PathLike[str], text: str) -> None:
    """Write `text` to `path` atomically (see `atomic_write`)."""
    atomic_write(path, lambda fh: fh.write(text), binary=False)
