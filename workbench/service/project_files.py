"""The files a project names, and switching a workbench to a project whose files all exist.

`named_files` lists every file path a project names (meshes, URDF, part file, workpiece) with
its field; `check_named_files` reads or checks each through the path rule (docs/security.md),
so a project whose `bending.part_file` or a mesh is missing is refused before anything changes;
`switch_project` replaces a workbench's project, its folders and its file together, or nothing.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

from workbench.errors import InputError
from workbench.project import Project, load_project, parse_project_json
from workbench.project.paths import ProjectFolders

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


def named_files(project: Project) -> list[tuple[str, str]]:
    """Return (field, path) of every file `project` names, in the order of the file."""
    return [(where, path) for where, path, _, _ in named_fields(project)]


def named_fields(project: Project) -> list[tuple[str, str, Any, str]]:
    """Return (field, path, model, attribute) of every file path in `project`, in the order of
    the file: `model`'s `attribute` holds the path (a list's index for the link meshes)."""
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

    Every file the project names is checked first (by the load); on any error `wb` stays as
    it was.
    """
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


def open_into(
    wb: Workbench,
    path: Path,
    *,
    allowed: tuple[Path, ...] = (),
    session: tuple[Path, ...] = (),
    unsaved: bool = False,
) -> None:
    """Switch `wb` to the project file `path`, its files in its folder, `allowed` ones and the
    `session` ones (uploads: see `ProjectFolders`).

    `wb.path` becomes `path`, or None when `unsaved` (an upload: "Save" needs a name). On any
    error (the file, a file it names, the load) `wb` stays as it was.
    """
    project = read_project(path)
    folders = ProjectFolders(Path(path).resolve().parent, allowed, session)
    switch_project(wb, project, folders, None if unsaved else Path(path))
