"""Importing a robot program written elsewhere (RAPID, KRL, FANUC LS, URScript, NACHI) into the
project's program: read, every target re-solved through its tool, work object and stored
configuration, then the project's program replaced (the old project stays on any error)."""

from __future__ import annotations

import io
import zipfile
from pathlib import PurePosixPath
from typing import TYPE_CHECKING

from workbench.errors import InputError
from workbench.kinematics.robot_library import library_robot
from workbench.kinematics.target_configuration import target_configuration
from workbench.motion.programs.controller_base import in_model_base
from workbench.motion.programs.formats import format_of, reader
from workbench.motion.programs.readback import solve_moves
from workbench.project.io import project_from_dict
from workbench.project.paths import size_limit
from workbench.project.program_import import imported_project

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


def import_program(wb: Workbench, files: dict[str, str], fmt: str | None = None) -> tuple[str, ...]:
    """Replace the project's program by the one in `files` (name -> text; a KRL .src with its
    .dat) and return the notes: every line the reader did not understand, by line, and every
    value the project took differently. `fmt` defaults to the one the file names tell."""
    if not files:
        raise InputError("import: no program file given")
    limit = size_limit("program")
    for name, text in files.items():
        if len(text) > limit:
            raise InputError(
                f"{name!r}: {len(text)} characters, over the {limit}-byte limit of a robot program"
                " (WORKBENCH_MAX_PROGRAM_BYTES)"
            )
    fmt = fmt or format_of(list(files))
    read_fn = reader(fmt)
    source = ", ".join(files)
    read = read_fn(files)
    preset = wb.project.robot.preset
    if preset is not None:  # work objects as the controller states them: into the model's base
        read = in_model_base(read, library_robot(preset).T_base_controller)
    joints = solve_moves(read, wb.robot)
    configurations = [target_configuration(wb.robot, q) for q in joints]
    result = imported_project(
        wb.project, read, joints, wb.robot.convention, source=source, configurations=configurations
    )
    wb.replace_project(project_from_dict(result.data, source=source))
    return result.notes


def _text(name: str, raw: bytes) -> str:
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")  # controllers write Latin-1 comments


def program_files(name: str, content: bytes) -> dict[str, str]:
    """Return the program files of an upload: the one file, or the members of a .zip (a KRL
    .src with its .dat); each at most the program size limit, plain names only."""
    limit = size_limit("program")
    if not name.lower().endswith(".zip"):
        if len(content) > limit:
            raise InputError(f"{name!r}: over the {limit}-byte limit of a robot program")
        return {PurePosixPath(name).name: _text(name, content)}
    try:
        zf = zipfile.ZipFile(io.BytesIO(content))
    except zipfile.BadZipFile:
        raise InputError(f"{name!r}: not a readable zip archive") from None
    files: dict[str, str] = {}
    with zf:
        members = [m for m in zf.infolist() if not m.is_dir()]
        if not members or len(members) > 16:
            raise InputError(f"{name!r}: expected 1 to 16 program files, found {len(members)}")
        for m in members:
            base = PurePosixPath(m.filename).name
            if m.file_size > limit:
                raise InputError(
                    f"{name!r}: {base} is over the {limit}-byte limit of a robot program"
                )
            files[base] = _text(base, zf.read(m))
    return files
