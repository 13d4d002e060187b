"""The disk cache's size limit and its clearing: the oldest entries go first.

Distance fields, sphere fits and pair tables are cached as `.npz` files (geometry/npz_cache.py)
under `cache_root()`: ``$WORKBENCH_CACHE``, else ``~/.cache/workbench``. After every store, the
entry's folder is pruned to `cache_limit_bytes()` (``$WORKBENCH_CACHE_MAX_BYTES``, default
1 GiB) by removing the entries used longest ago (a read refreshes an entry's time), never the
one just written. `workbench cache clear` removes every entry (`clear`).
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from workbench.env_setting import env_value
from workbench.errors import InputError

CACHE_LIMIT_ENV = "WORKBENCH_CACHE_MAX_BYTES"
DEFAULT_CACHE_LIMIT = 1 << 30  # 1 GiB
_SUFFIXES = (".npz",)


def cache_root() -> Path:
    """Return the workbench's cache folder: $WORKBENCH_CACHE, else ~/.cache/workbench."""
    root = os.environ.get("WORKBENCH_CACHE")
    return Path(root) if root else Path.home() / ".cache" / "workbench"


def cache_limit_bytes() -> int:
    """Return the size limit of one cache folder [bytes] ($WORKBENCH_CACHE_MAX_BYTES, default 1 GiB)."""
    value = env_value(CACHE_LIMIT_ENV, DEFAULT_CACHE_LIMIT, int, "a whole number of bytes")
    if value < 0:
        raise InputError(f"{CACHE_LIMIT_ENV}: {value} must be >= 0 bytes")
    return value


def _entries(folder: Path) -> list[tuple[float, int, Path]]:
    """Return (last use, size, path) of the cache entries in `folder` (regular files only)."""
    out = []
    try:
        it = list(os.scandir(folder))
    except OSError:
        return []
    for e in it:
        if not e.name.endswith(_SUFFIXES) or e.name.startswith("."):
            continue
        try:
            st = e.stat(follow_symlinks=False)
        except OSError:
            continue
        if stat.S_ISREG(st.st_mode):
            out.append((max(st.st_mtime, st.st_atime), st.st_size, Path(e.path)))
    return out


def cache_size(folder: str | os.PathLike[str]) -> int:
    """Return the bytes the cache entries in `folder` take."""
    return sum(size for _, size, _ in _entries(Path(folder)))


def prune(
    folder: str | os.PathLike[str], *, limit: int | None = None, keep: Path | None = None
) -> list[Path]:
    """Remove the least recently used entries of `folder` until it fits `limit`; return them.

    `keep` (the entry just written) is never removed.
    """
    cap = cache_limit_bytes() if limit is None else limit
    entries = sorted(_entries(Path(folder)))
    total = sum(size for _, size, _ in entries)
    removed = []
    for _, size, path in entries:
        if total <= cap:
            break
        if keep is not None and path == keep:
            continue
        try:
            path.unlink()
        except OSError:
            continue
        total -= size
        removed.append(path)
    return removed


def touch(path: Path) -> None:
    """Mark the entry at `path` as just used (its place in the eviction order)."""
    try:
        os.utime(path)
    except OSError:
        pass


def clear(root: str | os.PathLike[str] | None = None) -> tuple[int, int]:
    """Remove every cache entry (and left-over temporary file) under `root`; return (files, bytes).

    Only the cache's own files are removed (``*.npz`` and ``.*.tmp``), never anything else
    someone put there. Default root: `cache_root()`.
    """
    base = Path(root) if root is not None else cache_root()
    count = freed = 0
    if not base.is_dir():
        return 0, 0
    for folder, _dirs, files in os.walk(base):
        for name in files:
            if not (name.endswith(_SUFFIXES) or (name.startswith(".") and name.endswith(".tmp"))):
                continue
            p = Path(folder) / name
            try:
                st = p.lstat()
                if not stat.S_ISREG(st.st_mode):
                    continue
                p.unlink()
            except OSError:
                continue
            count += 1
            freed += st.st_size
    return count, freed
