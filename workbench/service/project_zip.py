"""The project as one .zip: its JSON and every file it names, and back (`Workbench.to_zip`,
`Workbench.from_zip`, the GUI's Download and Upload).

Writing: the project is saved with ``files="copy"`` into a temporary folder (`project_save`:
every file copied beside it, paths rewritten relative to it, the result checked from there as
it will open), and that folder is zipped: the JSON at the top, the files under ``parts/``,
``files/``... as the JSON names them.

Reading: every member is checked first (`project.archive.read_zip`: no absolute names, no
``..``, no links, sizes and ratios bounded); the project is the .json nearest the zip's top
(part files deeper down are its files); every relative path it names must be in the zip, else
the zip is refused whole, naming them. Only then is anything written, into a folder that is new
or empty.
"""

from __future__ import annotations

import os
import posixpath
import re
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

from workbench.errors import InputError
from workbench.project.archive import read_zip, write_zip
from workbench.project.paths import PathArg
from workbench.service.project_files import named_files, parse_project
from workbench.service.project_save import write_project

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


def zip_stem(wb: Workbench) -> str:
    """Return the name of the project's JSON in its zip (no extension): its file's, else its
    name with anything but letters, digits, ``-``, ``_`` and ``.`` made ``_``."""
    if wb.path is not None:
        return wb.path.stem
    stem = re.sub(r"[^A-Za-z0-9_.-]+", "_", wb.project.name or "").strip("._")[:80]
    return stem or "project"


def project_zip(wb: Workbench) -> bytes:
    """Return a .zip (`Workbench.to_zip`) of `wb`'s project and every file it names (see the module docstring);
    `wb` is unchanged. InputError naming the field if a file cannot be packed."""
    with tempfile.TemporaryDirectory(prefix="workbench-zip-") as tmp:
        json_name = zip_stem(wb) + ".json"
        write_project(wb.project, wb.folders, Path(tmp) / json_name, files="copy")
        root = Path(tmp)
        others = sorted(p for p in root.rglob("*") if p.is_file() and p.name != json_name)
        members = [(json_name, root / json_name)]
        members += [(p.relative_to(root).as_posix(), p) for p in others]
        return write_zip(members)


def unpack_project_zip(data: bytes, folder: PathArg, *, source: str = "project.zip") -> Path:
    """Unpack the project .zip `data` into `folder` (new or empty); return its JSON's path.

    InputError or ProjectError naming `source` and the member (or the project's field) if the
    zip is unusable; then nothing is written.
    """
    members = dict(read_zip(data, source))
    jsons = sorted((n.count("/"), n) for n in members if n.lower().endswith(".json"))
    if not jsons:
        raise InputError(f"{source}: holds no project .json file; zip the project with its files")
    top = [n for depth, n in jsons if depth == jsons[0][0]]
    if len(top) > 1:
        raise InputError(f"{source}: holds several project files ({', '.join(top)}); keep one")
    project = parse_project(members[top[0]], source=f"{source}:{top[0]}")
    here = posixpath.dirname(top[0])
    lacking = []
    for _, path in named_files(project):
        if os.path.isabs(path) or path.startswith("~"):
            continue  # absolute: the path rule decides at open (allowed folders only)
        inside = posixpath.normpath(posixpath.join(here, path.replace("\\", "/")))
        if inside not in members:
            lacking.append(path)
    if lacking:
        raise InputError(
            f"{source}: lacks files its project names ({', '.join(lacking)}); add them to the"
            " zip at those paths, relative to the project file"
        )
    root = Path(folder)
    if root.exists() and (not root.is_dir() or any(root.iterdir())):
        raise InputError(f"{source}: unpack into a new or empty folder, not {root}")
    root.mkdir(parents=True, exist_ok=True)
    for name, body in members.items():
        target = root / name
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
            with open(target, "xb") as fh:  # never through a link: the folder was empty
                fh.write(body)
        except OSError as exc:  # a member named like another's folder
            raise InputError(
                f"{source}: the member {name!r} cannot be unpacked ({exc.strerror})"
            ) from None
    return root / top[0]


def open_zip(
    cls: type[Workbench],
    data: bytes,
    folder: PathArg,
    *,
    source: str = "project.zip",
    allowed_dirs: list[PathArg] | tuple[()] = (),
) -> Workbench:
    """Return a workbench (`Workbench.from_zip`) on the project in the .zip `data`, unpacked
    into `folder` (new or empty; see `unpack_project_zip`)."""
    return cls.open(unpack_project_zip(data, folder, source=source), allowed_dirs=allowed_dirs)
