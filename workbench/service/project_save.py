"""The one save routine: every Save, Save as, `sweep --use`, `import --out`, `Workbench.save`
and the project's .zip (`to_zip`).

A saved project must open and plan from a fresh process, wherever it was written. The user
chooses what happens to the files the project names (`project_files.named_fields`):

``files="rebase"`` (the default) keeps naming the same files, in order:

1. a file inside the new project's folder is named relative to it;
2. a relative path that leads to the same file from the new folder is kept as it is (a save in
   place changes no path); any other relative path to a file the saved project may read (its
   own folder, the workbench's bundled assets, a folder allowed at start) is rebased: it names
   the same file from the new folder; an absolute path stays;
3. a file in a temporary folder (this run's uploads, `ProjectFolders.session`, or anything under
   the system's temporary folder) is copied beside the project (as in 5): the folder goes
   when the server stops;
4. a file in a folder allowed at start (`--allow-dir`, `allowed_dirs=`) is named by its
   absolute path, which the same `--allow-dir` reads again (a note says so);
5. anything else (the old project's folder seen from elsewhere: the saved project may not read
   it, by the path rule) is copied beside the project: under the same relative path where it
   lay in the old project's folder (``parts/pan.json``), else into ``files/``; a note says so.

``files="copy"`` makes the saved folder whole: every file not already inside it is copied
beside the project (the same places as in 5), absolute paths included, so the folder can be
moved or zipped as it is. A URDF is not copied (it names its meshes relative to itself).

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

from workbench.atomic_file import atomic_write_text
from workbench.errors import InputError, WorkbenchError
from workbench.project import Project, project_to_json
from workbench.project.file_copies import copy_files, remove_made, same_bytes
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


FILE_MODES = ("rebase", "copy")  # Save's `files=`: see the module docstring


def check_mode(files: str) -> str:
    """Return `files` if it is a save mode; InputError naming the choices otherwise."""
    if files not in FILE_MODES:
        raise InputError(
            f"save: files={files!r} is not a mode; give 'rebase' (name the same files from the"
            " new folder) or 'copy' (copy them beside the project)",
            field="files",
        )
    return files


@dataclass
class _Placer:
    """Decides, file by file, the path a saved project names and the copies it needs."""

    old: ProjectFolders
    folder: Path  # the new project's folder, real
    kept: tuple[Path, ...]  # folders allowed at start, real: they hold for the saved project
    readable: list[Path]  # every root the saved project may read from
    copies: dict[Path, Path]  # destination -> source
    mode: str = "rebase"

    def place(self, where: str, given: str) -> tuple[str, str | None]:
        """Return (the path to save, a note or None) for file `given` of field `where`."""
        kind = {"robot.urdf": "urdf", "bending.part_file": "part"}.get(where, "mesh")
        src = self.old.check_file(given, where, kind=kind)  # there, a regular file: names the field
        if _inside(src, self.folder):  # 1
            return Path(os.path.relpath(src, self.folder)).as_posix(), None
        session = [_real(f) for f in self.old.session]
        temporary = any(_inside(src, f) for f in session) or (
            _inside(src, temporary_root()) and not _bundled(src)  # a checkout may lie in /tmp
        )
        if self.mode == "rebase":
            kept = self._rebased(where, given, src, temporary)
            if kept is not None:
                return kept
        if where == "robot.urdf":
            raise InputError(
                f"save: robot.urdf: {shown_path(given)!r} lies outside the folder saved to, and"
                " a URDF names its meshes relative to itself, so it is not copied; save the"
                " project in a folder that holds the URDF's folder, or allow that folder"
                " (--allow-dir) and save with files='rebase'"
            )
        old_base = _real(self.old.base)
        if _inside(src, old_base):  # 3 and 5: where it lay beside the old project
            rel = Path(os.path.relpath(src, old_base))
        else:  # 3 and 5 outside the old project's folder
            rel = Path(COPY_FOLDER) / src.name
        rel = self._free(rel, src)
        self.copies[self.folder / rel] = src
        return rel.as_posix(), None

    def _rebased(
        self, where: str, given: str, src: Path, temporary: bool
    ) -> tuple[str, str | None] | None:
        """Return rules 2 and 4's path and note for `src`, or None where it must be copied."""
        absolute = os.path.isabs(given) or given.startswith("~")
        readable = any(_inside(src, r) for r in self.readable)
        if readable and not absolute and _real(self.folder / given) == src:
            return given, None  # 2: the same file from the new folder, as given
        if temporary:
            return None  # 3
        home = next((a for a in self.kept if _inside(src, a)), None)
        if home is not None and not _bundled(src):  # 4
            note = (
                f"{where}: named by its absolute path in {home}; open the project with that"
                " folder allowed (--allow-dir)"
            )
            return str(src), note
        if not readable:
            return None  # 5: the saved project could not read it
        if absolute:
            return given, None
        return Path(os.path.relpath(src, self.folder)).as_posix(), None

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
            if planned is None and dst.is_file() and same_bytes(dst, src):
                return rel
            n += 1
            rel = rel.with_name(f"{stem}_{n}{suffix}")


def _bundled(path: Path) -> bool:
    """Return whether `path` is one of the workbench's bundled assets (its place differs
    between a checkout and an install, so a saved project does not name it absolutely)."""
    return any(_inside(path, _real(a)) for a in (BUNDLED_ASSETS, INSTALLED_ASSETS))


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


def save_project_file(
    wb: Workbench, target: PathArg | None, *, overwrite: bool = True, files: str = "rebase"
) -> SavedProject:
    """Save `wb`'s project to `target` (None: its file) so that it opens and plans from there,
    its files rebased or copied (`files`); make `target` its file (see the module docstring).
    InputError or ProjectError naming the field, and nothing written, if the saved project
    would not open; `overwrite` False refuses an existing file."""
    target = target if target is not None else wb.path
    if target is None:
        raise InputError("save: no path given and the project was not opened from a file")
    saved, paths = write_project(wb.project, wb.folders, target, overwrite=overwrite, files=files)
    _set_paths(named_fields(wb.project), paths)
    wb.folders = wb.folders.moved_to(saved.path.parent)
    wb.base_dir = wb.folders.base
    wb.path = saved.path
    return saved


def write_project(
    project: Project,
    folders: ProjectFolders,
    target: PathArg,
    *,
    overwrite: bool = True,
    files: str = "rebase",
) -> tuple[SavedProject, list[str]]:
    """Write `project` (its files in `folders`) to `target` as `save_project_file` does, the
    project itself unchanged; return the save and the paths the written file names."""
    check_mode(files)
    target = Path(os.path.abspath(target))
    _check_target(target, overwrite)
    folder = _real(target.parent)
    kept = tuple(_real(a) for a in folders.allowed)
    new_folders = ProjectFolders(folder, kept)  # what the saved project may read
    placer = _Placer(folders, folder, kept, new_folders.roots(), {}, files)
    fields = named_fields(project)
    placed = [placer.place(where, given) for where, given, _, _ in fields]
    notes = [note for _, note in placed if note is not None]
    saved = project.model_copy(deep=True)
    paths = [path for path, _ in placed]
    _set_paths(named_fields(saved), paths)
    text = project_to_json(saved)  # refuses fields the loader would refuse
    made = copy_files(placer.copies)
    try:
        check_named_files(saved, new_folders)  # from the new folder, as the saved file will
    except WorkbenchError as exc:
        remove_made(made)
        raise type(exc)(
            f"save refused, nothing written: the saved project would not open: {exc}"
        ) from None
    except BaseException:
        remove_made(made)
        raise
    try:
        atomic_write_text(target, text)
    except OSError as exc:
        remove_made(made)
        raise InputError(f"save: {target}: cannot write ({exc.strerror})") from None
    copied = tuple(dst for dst in placer.copies if dst in made)
    # by file name only: the source may lie in the server's upload folders
    notes += [f"copied {placer.copies[dst].name} to {dst.relative_to(folder)}" for dst in copied]
    return SavedProject(target, tuple(notes), copied), paths


def _set_paths(fields: list[tuple[str, str, Any, str]], paths: list[str]) -> None:
    for (_, _, model, attr), path in zip(fields, paths, strict=True):
        if isinstance(model, list):
            model[int(attr)] = path
        else:
            setattr(model, attr, path)
