"""The one save routine: every Save, Save as, `sweep --use`, `import --out` and `Workbench.save`.

A saved project must open and plan from a fresh process, wherever it was written. For each
file the project names (`project_files.named_fields`), in order:

1. a file inside the new project's folder is named relative to it;
2. a relative path that leads to the same file from the new folder, inside a folder the saved
   project may read (its own, the workbench's bundled assets, a folder allowed at start), is
   kept as it is: a save in place changes no path;
3. a file in a temporary folder (this run's uploads, `ProjectFolders.session`, or anything under
   the system's temporary folder) is copied beside the project, into ``files/``: the folder
   goes when the server stops;
4. a file in a folder allowed at start (`--allow-dir`, `allowed_dirs=`) is named by its
   absolute path, which the same `--allow-dir` reads again (a note says so);
5. anything else (the old project's folder, the bundled assets seen from elsewhere, whose
   place differs between installs) is copied beside the project: under the same relative path
   where it lay in the old project's folder (``parts/pan.json``), else into ``files/``.

A copy never replaces a different file (its name gets ``_2``, ``_3``, ...). Then the project as
it will be written is validated from its own JSON (`project_to_json`: what is saved is what
loads) and every file it names is checked from the new folder with the folders the saved
project may read (`check_named_files`, part files parsed). Only then is the JSON written,
atomically. A refused save writes nothing: the copies it made are removed and the previous
file stays byte for byte.
"""

from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from workbench.atomic_file import atomic_write, atomic_write_text
from workbench.errors import InputError, WorkbenchError
from workbench.project import project_to_json
from workbench.project.paths import (
    BUNDLED_ASSETS,
    INSTALLED_ASSETS,
    PathArg,
    ProjectFolders,
    shown_path,
)
from workbench.service.project_files import check_named_files, named_fields

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

COPY_FOLDER = "files"  # where copies of files from elsewhere go, beside the saved project


@dataclass(frozen=True)
class SavedProject:
    """A save's result: the file written, notes for the user, the files copied beside it."""

    path: Path
    notes: tuple[str, ...]
    copied: tuple[Path, ...]


def _inside(path: Path, folder: Path) -> bool:
    return path.is_relative_to(folder)  # the folder itself included


def _real(path: PathArg) -> Path:
    return Path(os.path.realpath(path))


def temporary_root() -> Path:
    """Return the system's temporary folder (real path): files under it do not outlive a run."""
    return _real(tempfile.gettempdir())


@dataclass
class _Placer:
    """Decides, file by file, the path a saved project names and the copies it needs."""

    old: ProjectFolders
    folder: Path  # the new project's folder, real
    kept: tuple[Path, ...]  # folders allowed at start, real: they hold for the saved project
    readable: list[Path]  # every root the saved project may read from
    copies: dict[Path, Path]  # destination -> source

    def place(self, where: str, given: str) -> tuple[str, str | None]:
        """Return (the path to save, a note or None) for file `given` of field `where`."""
        kind = {"robot.urdf": "urdf", "bending.part_file": "part"}.get(where, "mesh")
        src = self.old.check_file(given, where, kind=kind)  # there, a regular file: names the field
        if _inside(src, self.folder):  # 1
            return Path(os.path.relpath(src, self.folder)).as_posix(), None
        if not os.path.isabs(given) and not given.startswith("~"):  # 2
            if _real(self.folder / given) == src and any(_inside(src, r) for r in self.readable):
                return given, None
        session = [_real(f) for f in self.old.session]
        temporary = any(_inside(src, f) for f in session) or _inside(src, temporary_root())
        home = next((a for a in self.kept if _inside(src, a)), None)
        if not temporary and home is not None and not _bundled(src):  # 4
            note = (
                f"{where}: named by its absolute path in {home}; open the project with that"
                " folder allowed (--allow-dir)"
            )
            return str(src), note
        if where == "robot.urdf":
            raise InputError(
                f"save: robot.urdf: {shown_path(given)!r} lies outside the folder saved to, and"
                " a URDF names its meshes relative to itself, so it is not copied; save the"
                " project in a folder that holds the URDF's folder, or allow that folder"
                " (--allow-dir)"
            )
        old_base = _real(self.old.base)
        if not temporary and _inside(src, old_base):  # 5
            rel = Path(os.path.relpath(src, old_base))
        else:  # 3, and 5 outside the old project's folder
            rel = Path(COPY_FOLDER) / src.name
        rel = self._free(rel, src)
        self.copies[self.folder / rel] = src
        return rel.as_posix(), None

    def _free(self, rel: Path, src: Path) -> Path:
        """Return `rel`, or `rel` with ``_2``, ``_3``.. added, where no other file lies."""
        stem, suffix = rel.stem, rel.suffix
        n = 1
        while True:
            dst = self.folder / rel
            planned = self.copies.get(dst)
            if planned == src:
                return rel
            if planned is None and not os.path.lexists(dst):
                return rel
            if planned is None and dst.is_file() and _same_bytes(dst, src):
                return rel
            n += 1
            rel = rel.with_name(f"{stem}_{n}{suffix}")


def _bundled(path: Path) -> bool:
    """Return whether `path` is one of the workbench's bundled assets (its place differs
    between a checkout and an install, so a saved project does not name it absolutely)."""
    return any(_inside(path, _real(a)) for a in (BUNDLED_ASSETS, INSTALLED_ASSETS))


def _same_bytes(a: Path, b: Path) -> bool:
    try:
        if a.stat().st_size != b.stat().st_size:
            return False
        return a.read_bytes() == b.read_bytes()
    except OSError:
        return False


def _check_target(target: Path, overwrite: bool) -> None:
    folder = target.parent
    if not folder.is_dir():
        raise InputError(
            f"save: the folder {folder} does not exist; create it first, or save elsewhere"
        )
    if os.path.lexists(target):
        if not target.is_file():
            raise InputError(f"save: {target} exists and is not a file; give another name")
        if not overwrite:
            raise InputError(
                f"save as: {target} exists; tick 'Overwrite' to replace it, or give another name"
            )


def save_project_file(wb: Workbench, target: PathArg, *, overwrite: bool = True) -> SavedProject:
    """Save `wb`'s project to `target` so that it opens and plans from there; make `target` its
    file (see the module docstring). InputError or ProjectError naming the field, and nothing
    written, if the saved project would not open; `overwrite` False refuses an existing file."""
    target = Path(os.path.abspath(target))
    _check_target(target, overwrite)
    folder = _real(target.parent)
    kept = tuple(_real(a) for a in wb.folders.allowed)
    new_folders = ProjectFolders(folder, kept)  # what the saved project may read
    placer = _Placer(wb.folders, folder, kept, new_folders.roots(), {})
    project = wb.project
    fields = named_fields(project)
    placed = [placer.place(where, given) for where, given, _, _ in fields]
    notes = [note for _, note in placed if note is not None]
    saved = project.model_copy(deep=True)
    _set_paths(named_fields(saved), [path for path, _ in placed])
    text = project_to_json(saved)  # refuses fields the loader would refuse
    made = _copy(placer.copies)
    try:
        check_named_files(saved, new_folders)  # from the new folder, as the saved file will
    except WorkbenchError as exc:
        _remove(made)
        raise type(exc)(
            f"save refused, nothing written: the saved project would not open: {exc}"
        ) from None
    except BaseException:
        _remove(made)
        raise
    try:
        atomic_write_text(target, text)
    except OSError as exc:
        _remove(made)
        raise InputError(f"save: {target}: cannot write ({exc.strerror})") from None
    _set_paths(fields, [path for path, _ in placed])
    wb.folders = wb.folders.moved_to(target.parent)
    wb.base_dir = wb.folders.base
    wb.path = target
    copied = tuple(dst for dst in placer.copies if dst in made)
    # by file name only: the source may lie in the server's upload folders
    notes += [f"copied {placer.copies[dst].name} to {dst.relative_to(folder)}" for dst in copied]
    return SavedProject(target, tuple(notes), copied)


def _set_paths(fields: list[tuple[str, str, Any, str]], paths: list[str]) -> None:
    for (_, _, model, attr), path in zip(fields, paths, strict=True):
        if isinstance(model, list):
            model[int(attr)] = path
        else:
            setattr(model, attr, path)


def _copy(copies: dict[Path, Path]) -> list[Path]:
    """Copy each source to its destination (atomically); return the files and folders made."""
    made: list[Path] = []
    try:
        for dst, src in copies.items():
            if dst.is_file() and _same_bytes(dst, src):
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
        _remove(made)
        raise InputError(f"save: cannot copy a file beside the project ({exc.strerror})") from None
    return made


def _remove(made: list[Path]) -> None:
    """Remove what `_copy` made: files first, then the folders it created (deepest first)."""
    for path in reversed(made):
        try:
            if path.is_dir():
                path.rmdir()
            else:
                path.unlink()
        except OSError:
            pass
