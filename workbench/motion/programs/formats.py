"""The export formats: robot programs (each vendor's post, `write_<fmt>(RobotProgram)`), joint
samples (CSV, JSON), and the readers that parse programs back (`read_<fmt>(files)`).

`write_programs(fmt, programs)` is the one dispatch every workflow uses: one `RobotProgram`
per robot in, one `ExportedProgram` (every robot's files and the posts' notes) out.
`write_samples` writes timed joint samples. `post(fmt)` and `reader(fmt)` return a format's
functions, or None while that post or reader does not exist in this build.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.motion.program import Move, Program
from workbench.motion.programs.exported import ExportedProgram, ReadProgram, merge_exports
from workbench.motion.programs.model import RobotProgram
from workbench.motion.programs.samples import csv_text, json_text

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

# Where each format's post and reader live: (module in this package, function), first found wins.
_POSTS: dict[str, tuple[tuple[str, str], ...]] = {
    "rapid": (("rapid", "write_rapid"),),
    "krl": (("krl", "write_krl"),),
    "ls": (("fanuc", "write_ls"), ("ls", "write_ls"), ("fanuc", "write_fanuc")),
    "urscript": (("urscript", "write_urscript"),),
    "nachi": (("nachi", "write_nachi"),),
}
_READERS: dict[str, tuple[tuple[str, str], ...]] = {
    "rapid": (("rapid_read", "read_rapid"),),
    "krl": (("krl_read", "read_krl"),),
    "ls": (("fanuc_read", "read_ls"), ("ls_read", "read_ls"), ("fanuc_read", "read_fanuc")),
    "urscript": (("urscript_read", "read_urscript"),),
    "nachi": (("nachi_read", "read_nachi"),),
}
# The first posts (motion.Program in, text out): used where a format's new post is missing.
_LEGACY = {"rapid": "to_rapid", "krl": "to_krl", "ls": "to_ls", "urscript": "to_urscript"}
_LEGACY_MODULE = {"rapid": "rapid", "krl": "krl", "ls": "fanuc", "urscript": "urscript"}


def _find(table: dict[str, tuple[tuple[str, str], ...]], fmt: str) -> Callable | None:
    for module, name in table.get(fmt, ()):
        try:
            mod = importlib.import_module(f"workbench.motion.programs.{module}")
        except ModuleNotFoundError as exc:
            if exc.name != f"workbench.motion.programs.{module}":
                raise
            continue
        fn = getattr(mod, name, None)
        if fn is not None:
            return fn  # type: ignore[no-any-return]
    return None


def check_format(fmt: str, formats: dict[str, str] = EXPORT_FORMATS) -> str:
    """Return `fmt` if it is one of `formats`; InputError naming the formats there are."""
    if fmt not in formats:
        raise InputError(f"format: {fmt!r} is not one of {', '.join(formats)}")
    return fmt


def post(fmt: str) -> Callable[[RobotProgram], ExportedProgram] | None:
    """Return the post `write_<fmt>(RobotProgram) -> ExportedProgram` of a robot-program
    format, or None while this build has none."""
    return _find(_POSTS, check_format(fmt, PROGRAM_FORMATS))


def reader(fmt: str) -> Callable[[dict[str, str]], ReadProgram] | None:
    """Return the reader `read_<fmt>(files) -> ReadProgram` of a robot-program format, or None."""
    return _find(_READERS, check_format(fmt, PROGRAM_FORMATS))


def _legacy_program(program: RobotProgram) -> Program:
    moves = []
    for mv in program.moves:
        if mv.kind == "joint":
            moves.append(Move.joint(mv.target.q, speed=mv.speed, zone=mv.zone, name=mv.name))
        else:
            T = program.work_object(mv.wobj).T_base_wobj @ np.asarray(mv.target.T_wobj_tcp)
            moves.append(Move.linear(T, speed=mv.speed, zone=mv.zone, name=mv.name))
    return Program(program.name, tuple(moves))


def _write_one(fmt: str, program: RobotProgram) -> ExportedProgram:
    fn = post(fmt)
    if fn is not None:
        return fn(program)
    if fmt not in _LEGACY:
        raise InputError(f"format {fmt!r}: this build has no post for it yet")
    legacy = getattr(
        importlib.import_module(f"workbench.motion.programs.{_LEGACY_MODULE[fmt]}"), _LEGACY[fmt]
    )
    note = (
        f"{fmt}: the first post (no tool, work object or I/O); the full post is not in this build"
    )
    return ExportedProgram(
        {program.name + PROGRAM_FORMATS[fmt]: str(legacy(_legacy_program(program)))}, (note,)
    )


def write_programs(fmt: str, programs: Sequence[RobotProgram]) -> ExportedProgram:
    """Return the robot programs (one per robot) written as `fmt` (rapid, krl, ls, urscript,
    nachi): every program's files, and the posts' notes. Posts refuse (InputError naming the
    move) what the robot cannot be told."""
    check_format(fmt, PROGRAM_FORMATS)
    if not programs:
        raise InputError("there is no robot program to write")
    return merge_exports([_write_one(fmt, p) for p in programs])


def write_samples(
    fmt: str, samples: Sequence[tuple[str, FloatArray, FloatArray]]
) -> ExportedProgram:
    """Return joint samples as `fmt` (csv, json): one file `<name>.<fmt>` per (name, times (N,)
    [s], joints (N, dof) [rad]) triple."""
    check_format(fmt, SAMPLE_FORMATS)
    text = csv_text if fmt == "csv" else json_text
    return merge_exports(
        [ExportedProgram({name + SAMPLE_FORMATS[fmt]: text(t, q)}) for name, t, q in samples]
    )


def export(fmt: str, program: Program, times: FloatArray, joints: FloatArray) -> str:
    """Return a motion `Program` as `fmt` text through the first posts (rapid, krl, ls,
    urscript), or its timed joint samples `times` (N,) [s], `joints` (N, dof) [rad] as csv or
    json: the workflows that do not build a `RobotProgram` yet use it.

    Raises InputError naming the format and the formats there are.
    """
    check_format(fmt, {k: v for k, v in EXPORT_FORMATS.items() if k != "nachi"})
    if fmt == "csv":
        return csv_text(times, joints)
    if fmt == "json":
        return json_text(times, joints)
    module = importlib.import_module(f"workbench.motion.programs.{_LEGACY_MODULE[fmt]}")
    return str(getattr(module, _LEGACY[fmt])(program))


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
        raise InputError(f"files {list(names)}: they are of {len(found)} formats; import one program at a time")
    return found.pop()
