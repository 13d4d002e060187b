"""What a post writes (`ExportedProgram`: files and notes) and what a reader returns (`ReadProgram`)."""

from __future__ import annotations

import io
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from workbench.atomic_file import atomic_write_text
from workbench.errors import InputError
from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.motion.programs.model import Action, MoveKind, ToolData, WorkObject

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ExportedProgram:
    """The files of an exported program (name -> text, in writing order) and the post's notes
    (renamed identifiers, settings that applied), which posts also write as comments."""

    files: dict[str, str]
    notes: tuple[str, ...] = ()

    @property
    def text(self) -> str:
        """Return the one file's text (InputError when the program has several files)."""
        if len(self.files) != 1:
            raise InputError(
                f"this export has {len(self.files)} files ({', '.join(self.files)}); use .files,"
                " write_to(folder) or zip_bytes()"
            )
        return next(iter(self.files.values()))

    def write_to(self, folder: str | Path) -> list[Path]:
        """Write every file into `folder` (created if missing), each atomically; return the paths."""
        root = Path(folder)
        root.mkdir(parents=True, exist_ok=True)
        out = []
        for name, text in self.files.items():
            if Path(name).name != name or name in ("", ".", ".."):
                raise InputError(f"export file name {name!r} must be a plain file name")
            path = root / name
            atomic_write_text(path, text)
            out.append(path)
        return out

    def zip_bytes(self) -> bytes:
        """Return the files as one zip archive."""
        buf = io.BytesIO()
        with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
            for name, text in self.files.items():
                zf.writestr(name, text)
        return buf.getvalue()


def merge_exports(parts: list[ExportedProgram]) -> ExportedProgram:
    """Return one export holding the files and notes of several (one per robot); names must differ."""
    files: dict[str, str] = {}
    notes: list[str] = []
    for p in parts:
        for name, text in p.files.items():
            if name in files:
                raise InputError(
                    f"two programs write the file {name!r}; give the robots distinct names"
                )
            files[name] = text
        notes.extend(p.notes)
    return ExportedProgram(files, tuple(notes))


@dataclass(frozen=True, eq=False)
class ReadTarget:
    """A target as a program states it: controller `joints` (dof,) [rad] for a joint target, or
    a TCP pose `T_wobj_tcp` (4, 4) [m] with its `configuration` and the controller joint ranges
    (dof, 2) [rad] its turn data allow (None: not stated)."""

    name: str
    joints: FloatArray | None = None
    T_wobj_tcp: FloatArray | None = None
    configuration: ArmConfiguration | None = None
    controller_ranges: FloatArray | None = None


@dataclass(frozen=True, eq=False)
class ReadMove:
    """A move as read: kind, target (and `via` for circular), `speed` (joint: fraction of max,
    linear/circular: TCP m/s; None when the program gives only a time), `zone` [m], `tool`
    and `wobj` names, `duration` [s] when the program states one (RAPID \\T), source `line`."""

    kind: MoveKind
    target: ReadTarget
    speed: float | None
    zone: float
    tool: str
    wobj: str
    duration: float | None = None
    via: ReadTarget | None = None
    line: int = 0

    @property
    def name(self) -> str:
        """Return the target's name."""
        return self.target.name


@dataclass(frozen=True, eq=False)
class ReadProgram:
    """A program read back: name, tools, work objects (as declared in the file), instructions
    (moves and low-level actions, in order), and the lines the reader did not understand
    (`unknown`: (line number, text)), never dropped silently."""

    name: str
    tools: tuple[ToolData, ...]
    work_objects: tuple[WorkObject, ...]
    instructions: tuple[ReadMove | Action, ...]
    unknown: tuple[tuple[int, str], ...] = ()
    notes: tuple[str, ...] = field(default=())

    @property
    def moves(self) -> tuple[ReadMove, ...]:
        """Return the moves, in order."""
        return tuple(i for i in self.instructions if isinstance(i, ReadMove))

    def actions(self) -> tuple[Action, ...]:
        """Return the actions, in order."""
        return tuple(i for i in self.instructions if not isinstance(i, ReadMove))
