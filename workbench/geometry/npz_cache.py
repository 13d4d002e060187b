"""A disk cache of numpy arrays keyed by the inputs that made them (distance fields, sphere fits).

Entries are `.npz` files named by a SHA-256 of the inputs' bytes, shapes and dtypes and of
the parameters, so a changed mesh or setting never reads a stale entry. Writes go to a
temporary file of a unique name in the same folder, are flushed to disk and renamed over
the entry: two processes filling the same key never see each other's half-written file,
and a crash mid-write leaves the old entry or none. An entry that cannot be read (truncated,
corrupt, missing arrays) counts as a miss: the caller rebuilds and overwrites it.
"""

from __future__ import annotations

import hashlib
import json
import zipfile
from collections.abc import Iterable, Mapping
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from workbench.atomic_file import atomic_write
from workbench.disk_cache import prune, touch

__all__ = ["cache_path", "load_entry", "store_entry"]


def cache_path(
    cache_dir: str | Path,
    prefix: str,
    inputs: Iterable[NDArray],
    params: Mapping[str, object],
) -> Path:
    """Return the entry's path in `cache_dir`: `prefix-<hash>.npz` of the inputs and params."""
    h = hashlib.sha256()
    for a in inputs:
        arr = np.ascontiguousarray(a)
        h.update(f"{arr.dtype.str}{arr.shape};".encode())
        h.update(arr.tobytes())
    h.update(json.dumps(dict(params), sort_keys=True, default=str).encode())
    return Path(cache_dir) / f"{prefix}-{h.hexdigest()[:24]}.npz"


def load_entry(path: Path, required: Iterable[str] = ()) -> dict[str, NDArray] | None:
    """Return the arrays stored at `path`, or None if there is none or it cannot be read.

    required: array names the entry must hold; an entry without one of them is a miss.
    """
    if not path.is_file():
        return None
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {k: np.asarray(data[k]) for k in data.files}
    except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile):
        return None
    if any(k not in arrays for k in required):
        return None
    touch(path)  # recently used: evicted last (disk_cache.prune)
    return arrays


def store_entry(path: Path, arrays: Mapping[str, NDArray]) -> None:
    """Write `arrays` to `path` atomically (unique temporary file, rename).

    No fsync: a reader sees the old entry or the whole new one, and an entry a power cut
    leaves torn fails its zip CRC on load, a miss that is rebuilt (an engine's cold build
    wrote ~30 entries, 56 fsyncs, 0.3-0.5 s). The folder is then pruned to the cache's size
    limit, oldest entries first (disk_cache.py).
    """
    atomic_write(
        path,
        lambda fh: np.savez(fh, **dict(arrays)),  # type: ignore[arg-type]
        binary=True,
        durable=False,
    )
    prune(path.parent, keep=path)
