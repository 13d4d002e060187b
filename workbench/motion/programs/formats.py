"""The export formats: robot programs (each vendor's post, `write_<fmt>(RobotProgram)`), joint
samples (CSV, JSON), and the readers that parse programs back (`read_<fmt>(files)`).

`write_programs(fmt, programs)` is the one dispatch every workflow uses: one `RobotProgram`
per robot in, one `ExportedProgram` (every robot's files and the posts' notes) out.
`write_samples` writes timed joint samples. `post(fmt)` and `reader(fmt)` return a format's
functions.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.kinematics.joint_convention import JointConvention
from workbench.motion.programs.controller_program import ReadProgram, RobotProgram
from workbench.motion.programs.exported import ExportedProgram, merge_exports
from workbench.motion.programs.fanuc import write_ls
from workbench.motion.programs.fanuc_read import read_ls
from workbench.motion.programs.krl import write_krl
from workbench.motion.programs.krl_read import read_krl
from workbench.motion.programs.nachi import unit_name, write_nachi
from workbench.motion.programs.nachi_read import read_nachi
from workbench.motion.programs.rapid import write_rapid
from workbench.motion.programs.rapid_read import read_rapid
from workbench.motion.programs.samples import csv_text, json_text
from workbench.motion.programs.urscript import write_urscript
from workbench.motion.programs.urscript_read import read_urscript

FloatArray = NDArray[np.float64]

#: Robot-program formats and the extension of their (main) file.
PROGRAM_FORMATS = {
    "rapid": ".mod",
    "krl": ".src",
    "ls": ".ls",
    "urscript": ".script",
    "nachi": ".prg",
}
#: Joint-sample formats and their extension.
SAMPLE_FORMATS = {"csv": ".csv", "json": ".json"}
#: Every export format and the file extension it is written with.
EXPORT_FORMATS = {**PROGRAM_FORMATS, **SAMPLE_FORMATS}

_POSTS: dict[str, Callable[[RobotProgram], ExportedProgram]] = {
    "rapid": write_rapid,
    "krl": write_krl,
    "ls": write_ls,
    "urscript": write_urscript,
    "nachi": write_nachi,
}
_READERS: dict[str, Callable[[dict[str, str]], ReadProgram]] = {
    "rapid": read_rapid,
    "krl": read_krl,
    "ls": read_ls,
    "urscript": read_urscript,
    "nachi": read_nachi,
}


def check_format(fmt: str, formats: dict[str, str] = EXPORT_FORMATS) -> str:
    """Return `fmt` if it is one of `formats`; InputError naming the formats there are."""
    if fmt not in formats:
        raise InputError(f"format: {fmt!r} is not one of {', '.join(formats)}")
    return fmt


def post(fmt: str) -> Callable[[RobotProgram], ExportedProgram]:
    """Return the post `write_<fmt>(RobotProgram) -> ExportedProgram` of a robot-program format."""
    return _POSTS[check_format(fmt, PROGRAM_FORMATS)]


def reader(fmt: str) -> Callable[[dict[str, str]], ReadProgram]:
    """Return the reader `read_<fmt>(files) -> ReadProgram` of a robot-program format."""
    return _READERS[check_format(fmt, PROGRAM_FORMATS)]


def write_programs(
    fmt: str, programs: Sequence[RobotProgram], *, models: Sequence[str] | None = None
) -> ExportedProgram:
    """Return the robot programs (one per robot) written as `fmt` (rapid, krl, ls, urscript,
    nachi): every program's files, and the posts' notes. Posts refuse (InputError naming the
    move) what the robot cannot be told. NACHI files are named as the controller lists them,
    ``<model>-<unit>-A.001`` (`names.nachi_file_name`): `models` the robots' model names
    (default: `names.controller_model` of each program's robot), units 01, 02, ... in the
    programs' order, program number 001 in every workflow."""
    check_format(fmt, PROGRAM_FORMATS)
    if not programs:
        raise InputError("there is no robot program to write")
    if fmt == "nachi":
        names = list(models) if models is not None else [p.robot for p in programs]
        return merge_exports(
            [
                write_nachi(p, unit=unit_name(m, k), number=1)
                for k, (p, m) in enumerate(zip(programs, names, strict=True), 1)
            ]
        )
    write = post(fmt)
    return merge_exports([write(p) for p in programs])


def write_samples(
    fmt: str,
    samples: Sequence[tuple[str, FloatArray, FloatArray]],
    conventions: Sequence[JointConvention] | None = None,
) -> ExportedProgram:
    """Return joint samples as `fmt` (csv, json): one file `<name>.<fmt>` per (name, times (N,)
    [s], model joints (N, dof) [rad]) triple, written in the controller's convention of the
    same position in `conventions` (None: as given)."""
    check_format(fmt, SAMPLE_FORMATS)
    text = csv_text if fmt == "csv" else json_text
    convs = list(conventions) if conventions is not None else [None] * len(samples)
    return merge_exports(
        [
            ExportedProgram({name + SAMPLE_FORMATS[fmt]: text(t, q, convention=c)})
            for (name, t, q), c in zip(samples, convs, strict=True)
        ]
    )


# File endings of each robot-program format's files, for telling a file's format by its name.
_ENDINGS = {
    "rapid": (".mod", ".modx", ".prg", ".sys"),
    "krl": (".src", ".dat"),
    "ls": (".ls",),
    "urscript": (".script", ".urscript"),
}


def format_of(names: Sequence[str]) -> str:
    """Return the robot-program format of files by their names (.mod RAPID, .src/.dat KRL, .ls
    FANUC, .script URScript, .001-style numbers NACHI); InputError when they do not tell one."""
    found = set()
    for name in names:
        low = name.lower()
        ext = "." + low.rsplit(".", 1)[-1] if "." in low else ""
        kinds = [f for f, ends in _ENDINGS.items() if ext in ends]
        if not kinds and ext[1:].isdigit():
            kinds = ["nachi"]
        if not kinds:
            raise InputError(
                f"{name!r}: not a robot program this workbench reads (.mod RAPID, .src/.dat KRL,"
                " .ls FANUC, .script URScript, .001 NACHI); give the format"
            )
        found.update(kinds)
    if len(found) != 1:
        raise InputError(
            f"files {list(names)}: they are of {len(found)} formats; import one program at a time"
        )
    return found.pop()
