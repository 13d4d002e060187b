"""Files copied beside a saved project: all or nothing.

`copy_files` copies each source to its destination atomically (creating folders), returning
what it made; on an error it removes what it made and raises an `InputError`. `remove_made`
takes back what a copy made (a save refused later).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from workbench.atomic_file import atomic_write
from workbench.errors import InputError


def same_bytes(a: Path, b: Path) -> bool:
    """Return whether files `a` and `b` hold the same bytes (False if either cannot be read)."""
    try:
        if a.stat().st_size != b.stat().st_size:
            return False
        return a.read_bytes() == b.read_bytes()
    except OSError:
        return False


def copy_files(copies: dict[Path, Path]) -> list[Path]:
    """Copy each source to its destination (atomically); return the files and folders made."""
    made: list[Path] = []
    try:
        for dst, src in copies.items():
            if dst.is_file() and same_bytes(dst, src):
                continue
            missing = [p for p in reversed(dst.parents) if not p.exists()]
            dst.parent.mkdir(parents=True, exist_ok=True)
            made += missing
            data = src.read_bytes()

            def write(fh: Any, data: bytes = data) -> None:
                fh.write(data)

            atomic_write(dst, write, binary=True)
            made.append(dst)
    except OSError as exc:
        remove_made(made)
        raise InputError(f"save: cannot copy a file beside the project ({exc.strerror})") from None
    return made


def remove_made(made: list[Path]) -> None:
    """Remove what `copy_files` made: files first, then the folders it created (deepest first)."""
    for path in reversed(made):
        try:
            if path.is_dir():
                path.rmdir()
            else:
                path.unlink()
        except OSError:
            pass
