"""The files a project names, and switching a workbench to a project whose files all exist.

`named_files` lists every file path a project names (meshes, URDF, part file, workpiece) with
its field; `check_named_files` reads or checks each through the path rule (docs/security.md),
so a project whose `bending.part_file` or a mesh is missing is refused before anything changes;
`switch_project` replaces a workbench's project, its folders and its file together, or nothing.
"""

from __future__ import annotations

import os
import re
import shutil
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from workbench.errors import InputError
from workbench.project import Project, load_project, parse_project_json
from workbench.project.paths import ProjectFolders

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


def named_files(project: Project) -> list[tuple[str, str]]:
    """Return (field, path) of every file `project` names, in the order of the file."""
    return [(where, path) for where, path, _, _ in _named(project)]


def _named(project: Project) -> list[tuple[str, str, Any, str]]:
    """Return (field, path, model, attribute) of every file path in `project`."""
    out: list[tuple[str, str, Any, str]] = []
    robot, tool, cell = project.robot, project.tool, project.cell
    if robot.urdf is not None:
        out.append(("robot.urdf", robot.urdf, robot, "urdf"))
    for i, m in enumerate(robot.link_meshes or []):
        if m is not None:
            out.append((f"robot.link_meshes[{i}]", m, robot.link_meshes, str(i)))
    if tool.mesh is not None:
        out.append(("tool.mesh", tool.mesh, tool, "mesh"))
    for i, obj in enumerate(cell.objects):
        if obj.shape == "mesh" and obj.path is not None:
            out.append((f"cell.objects[{i}].path", obj.path, obj, "path"))
    if project.bending is not None and project.bending.part_file is not None:
        out.append(("bending.part_file", project.bending.part_file, project.bending, "part_file"))
    if project.assembly is not None:
        for i, p in enumerate(project.assembly.parts):
            if p.shape == "mesh" and p.path is not None:
                out.append((f"assembly.parts[{i}].path", p.path, p, "path"))
    if project.polishing is not None:
        pol = project.polishing
        out.append(("polishing.workpiece", pol.workpiece, pol, "workpiece"))
    return out


def check_named_files(project: Project, folders: ProjectFolders) -> None:
    """Raise the path rule's error (naming the field) for the first file that cannot be read.

    The workflows' files (part file, workpiece, assembly meshes) are read lazily by the
    services; checking them here refuses a project whole instead of half-way.
    """
    for where, path in named_files(project):
        if where == "bending.part_file":
            assert project.bending is not None
            project.bending.to_si(project.bending.read_part(folders))  # read and validated
        elif where == "robot.urdf":
            folders.check_urdf(path, where)
        else:
            folders.check_file(path, where, kind="mesh")


def switch_project(
    wb: Workbench, project: Project, folders: ProjectFolders, path: Path | None
) -> None:
    """Switch `wb` to `project`, its files in `folders`, opened from `path` (None: unsaved).

    Every file the project names is checked first; on any error `wb` stays as it was.
    """
    check_named_files(project, folders)
    old = wb.folders
    wb.folders = folders  # the load reads the new project's files through it
    try:
        wb.replace_project(project)
    except BaseException:
        wb.folders = old
        raise
    wb.base_dir = folders.base
    wb.path = path


def read_project(path: Path) -> Project:
    """Return the validated project in the file `path` (ProjectError naming the file and field)."""
    return load_project(path)


def parse_project(text: str | bytes, *, source: str) -> Project:
    """Return the validated project in JSON `text` (ProjectError naming `source` and the field)."""
    return parse_project_json(text, source=source)


MAX_NAME = 120  # characters of a file name given in the GUI


def save_target(folder: Path, name: str) -> Path:
    """Return `folder`/`name` for "Save as": InputError unless `name` is a plain .json file name.

    No folders (``/``, ``\\``, ``..``), no NUL or control characters, no leading dot, at most
    `MAX_NAME` characters; ``.json`` is added when the name has no extension.
    """
    shown = repr(name if len(name) <= 60 else name[:57] + "...")
    fix = f"give a plain file name such as my_cell.json (it is saved in {folder})"
    if not name.strip():
        raise InputError(f"save as: no file name given; {fix}")
    if re.search(r"[\x00-\x1f\x7f]", name):
        raise InputError(f"save as: {shown} contains a NUL or control character; {fix}")
    if "/" in name or "\\" in name or name.strip() in (".", ".."):
        raise InputError(f"save as: {shown} names a folder; {fix}")
    if name != name.strip() or name.startswith("."):
        raise InputError(f"save as: {shown} starts or ends with a space or a dot; {fix}")
    if not name.lower().endswith(".json"):
        if "." in name:
            raise InputError(f"save as: {shown} does not end in .json; {fix}")
        name += ".json"
    if len(name) > MAX_NAME:
        raise InputError(f"save as: the name has {len(name)} characters, at most {MAX_NAME}; {fix}")
    return folder / name


def save_as(
    wb: Workbench,
    target: Path,
    *,
    overwrite: bool,
    temporary: Path | Sequence[Path | None] | None = None,
) -> list[str]:
    """Save `wb`'s project atomically to `target` and make `target` its file; return notes.

    The files it names by relative path are kept: a path is rewritten relative to the new
    folder when the file lies inside it, and a file inside `temporary` (an upload folder,
    removed later) is first copied next to the saved project at the same place. A file that
    exists is replaced only when `overwrite`; InputError (nothing written) otherwise.
    """
    folder = target.parent
    real_folder = Path(os.path.realpath(folder))
    if target.exists() and not overwrite:
        raise InputError(
            f"save as: {target} exists; tick 'Overwrite' to replace it, or give another name"
        )
    project = wb.project
    plan: list[tuple[Any, str, str]] = []  # (model, attribute, new path)
    copies: list[tuple[Path, Path]] = []
    notes: list[str] = []
    given_tmp = [temporary] if isinstance(temporary, Path) else list(temporary or [])
    temps = [Path(os.path.realpath(t)) for t in given_tmp if t is not None]
    for where, given, model, attr in _named(project):
        src = wb.folders.resolve(given, where)
        tmp = next((t for t in temps if src.is_relative_to(t)), None)
        if tmp is None and (os.path.isabs(given) or given.startswith("~")):
            continue  # stays as it is: allowed folders are named absolutely
        if tmp is not None:
            dst = real_folder / src.relative_to(tmp)
            if dst.exists() and dst.read_bytes() != src.read_bytes() and not overwrite:
                raise InputError(
                    f"save as: {where}: {dst} exists with other content; tick 'Overwrite'"
                    " to replace it, or save in another folder"
                )
            copies.append((src, dst))
        elif src.is_relative_to(real_folder):
            dst = src
        else:
            notes.append(f"{where}: {src} lies outside {folder}; saved by its absolute path")
            plan.append((model, attr, str(src)))
            continue
        plan.append((model, attr, os.path.relpath(dst, real_folder)))
    for src, dst in copies:
        dst.parent.mkdir(parents=True, exist_ok=True)
        if src != dst:
            shutil.copyfile(src, dst)
    for model, attr, new in plan:
        if isinstance(model, list):
            model[int(attr)] = new
        else:
            setattr(model, attr, new)
    wb.folders = ProjectFolders(folder, wb.folders.allowed)
    wb.base_dir = wb.folders.base
    wb.save(target)
    return notes


def open_into(
    wb: Workbench, path: Path, *, allowed: tuple[Path, ...] = (), unsaved: bool = False
) -> None:
    """Switch `wb` to the project file `path`, its files in its folder and `allowed` ones.

    `wb.path` becomes `path`, or None when `unsaved` (an upload: "Save" needs a name). On any
    error (the file, a file it names, the load) `wb` stays as it was.
    """
    project = read_project(path)
    folders = ProjectFolders(Path(path).resolve().parent, allowed)
    switch_project(wb, project, folders, None if unsaved else Path(path))
