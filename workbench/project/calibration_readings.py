"""Calibration readings files: CSV with a header, in the pendant's units, to SI.

Two kinds of readings, told apart by the header (docs/calibration.md):

- ``label,j1,j2,j3,j4,j5,j6``: the robot's joints [deg] as the controller shows them; one
  column per joint of the project's robot. They go through the robot's joint convention into
  the model's joints [rad].
- ``label,x,y,z``: TCP positions [mm] as the pendant shows them in the robot's base frame
  (the controller's), to metres.

Known points (`parse_known`) have the header ``label,x,y,z`` [mm] too: positions on the part
(a work object's drawing) or in the cell (the robot's place). Blank lines and lines starting
with ``#`` are skipped. Every error names the file, line and column and says what to give.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from pydantic import TypeAdapter, ValidationError

from workbench.errors import InputError
from workbench.kinematics.robot_library import LIBRARY
from workbench.project.models import Robot
from workbench.project.program_io import BASE_WOBJ, Name
from workbench.project.units import DEG, MM

FloatArray = NDArray[np.float64]
MAX_READINGS = 1000
POINT_COLUMNS = ("x", "y", "z")


@dataclass(frozen=True)
class Readings:
    """Readings of one file: `labels` and their `lines` in the file, and either `joints`
    (n, dof) [rad, the model's convention] or `points` (n, 3) [m, the controller's base]."""

    source: str
    labels: tuple[str, ...]
    lines: tuple[int, ...]
    joints: FloatArray | None = None
    points: FloatArray | None = None
    notes: tuple[str, ...] = ()  # joint values outside the robot's ranges (a wrong robot?)

    @property
    def kind(self) -> str:
        """Return "joints" or "points"."""
        return "joints" if self.joints is not None else "points"


def _rows(text: str, source: str) -> list[tuple[int, list[str]]]:
    rows = []
    for number, line in enumerate(text.removeprefix("\ufeff").splitlines(), 1):
        if line.strip() and not line.lstrip().startswith("#"):
            cells = next(csv.reader(io.StringIO(line)))
            rows.append((number, [c.strip() for c in cells]))
    if not rows:
        raise InputError(
            "the file is empty; give a header line and one line per reading", field=source
        )
    if len(rows) > MAX_READINGS + 1:
        raise InputError(f"{len(rows) - 1} readings; at most {MAX_READINGS}", field=source)
    return rows


def _header(number: int, cells: list[str], source: str, dof: int | None) -> tuple[str, int]:
    """Return ("joints" | "points", the number of value columns) of a header line."""
    names = [c.lower() for c in cells]
    joints = [f"j{i}" for i in range(1, len(names))]
    expected = f"label,{','.join(f'j{i}' for i in range(1, (dof or 6) + 1))}"
    if names[:1] == ["label"] and names[1:] == list(POINT_COLUMNS):
        return "points", 3
    if names[:1] == ["label"] and names[1:] == joints and len(joints) > 0:
        if dof is not None and len(joints) != dof:
            raise InputError(
                f"the header has {len(joints)} joint columns but the robot has {dof} joints;"
                f" give {expected}",
                field=f"{source} line {number}",
            )
        return "joints", len(joints)
    separated = next((c for c in (";", "\t") if c in cells[0]), None)
    hint = "" if separated is None else f"; separate the values by commas, not {separated!r}"
    raise InputError(
        f"header {','.join(cells)!r}: give {expected} (joints [deg], as the controller shows"
        f" them) or label,x,y,z (TCP positions [mm] in the robot's base){hint}",
        field=f"{source} line {number}",
    )


def _value(text: str, where: str, unit: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
        if not text:
            raise InputError(f"empty; give a number [{unit}]", field=where) from None
    if not math.isfinite(value):
        raise InputError(f"{text!r} is not a finite number; give a number [{unit}]", field=where)
    return value


def _table(
    text: str, source: str, dof: int | None, kinds: tuple[str, ...]
) -> tuple[str, tuple[str, ...], tuple[int, ...], FloatArray]:
    """Return (kind, labels, line numbers, values (n, k) in the file's units) of a CSV text."""
    rows = _rows(text, source)
    (head_line, head), body = rows[0], rows[1:]
    kind, width = _header(head_line, head, source, dof)
    if kind not in kinds:
        raise InputError(
            f"this file needs label,x,y,z (points [mm]), not {kind}",
            field=f"{source} line {head_line}",
        )
    unit = "deg" if kind == "joints" else "mm"
    labels: list[str] = []
    seen: dict[str, int] = {}
    values = np.zeros((len(body), width))
    for r, (number, cells) in enumerate(body):
        if len(cells) != width + 1:
            raise InputError(
                f"{len(cells) - 1} values after the label but the header names {width}"
                f" ({','.join(head[1:])}); give one per column",
                field=f"{source} line {number}",
            )
        label = cells[0]
        if not label:
            raise InputError(
                "empty label; name each reading", field=f"{source} line {number}, column 1 (label)"
            )
        if label in seen:
            raise InputError(
                f"label {label!r} is also on line {seen[label]}; give each reading its own label",
                field=f"{source} line {number}, column 1 (label)",
            )
        seen[label] = number
        labels.append(label)
        for c in range(width):
            where = f"{source} line {number}, column {c + 2} ({head[c + 1]})"
            values[r, c] = _value(cells[c + 1], where, unit)
    if not labels:
        raise InputError("no readings after the header; give one line per reading", field=source)
    return kind, tuple(labels), tuple(n for n, _ in body), values


def parse_readings(text: str, *, source: str, robot: Robot, dof: int) -> Readings:
    """Return the readings of a CSV `text` (`source` names it in errors) for the project's
    `robot` with `dof` joints: joints [deg, controller] to the model's [rad], points [mm] to m.
    InputError naming the file, line and column for a bad header, value, label or count."""
    kind, labels, lines, values = _table(text, source, dof, ("joints", "points"))
    if kind == "points":
        return Readings(source, labels, lines, points=values * MM)
    convention = robot.convention()
    q = values * DEG
    notes = _outside(values, _controller_limits(robot), labels, lines, source)
    model = q if convention is None else convention.to_model(q)
    return Readings(source, labels, lines, joints=model, notes=notes)


def _controller_limits(robot: Robot) -> FloatArray | None:
    """Return the robot's joint ranges (dof, 2) [deg, the controller's] (None: a URDF's)."""
    if robot.preset is not None:
        return np.asarray(LIBRARY[robot.preset].controller_limits_deg, float)
    if robot.dh is not None:
        return np.array([[r.min, r.max] for r in robot.dh], float)
    return None


def _outside(
    values: FloatArray,
    limits: FloatArray | None,
    labels: tuple[str, ...],
    lines: tuple[int, ...],
    source: str,
) -> tuple[str, ...]:
    """Return a note per joint reading outside the robot's range [deg]: readings of a real
    robot lie within it, so one outside says the robot or its convention is not the real one."""
    if limits is None:
        return ()
    notes = []
    for r, c in zip(*np.nonzero((values < limits[:, 0]) | (values > limits[:, 1])), strict=True):
        lo, hi = limits[c]
        notes.append(
            f"{source} line {lines[r]}: {labels[r]} j{c + 1} = {values[r, c]:.3f} deg lies outside"
            f" the robot's range [{lo:g}, {hi:g}] deg; is the project's robot the one measured?"
        )
    return tuple(notes)


def parse_known(text: str, *, source: str) -> tuple[tuple[str, ...], FloatArray]:
    """Return (labels, points (n, 3) [m]) of a known-points CSV `label,x,y,z` [mm]."""
    _, labels, _, values = _table(text, source, None, ("points",))
    return labels, values * MM


def work_object_name(name: str) -> str:
    """Return `name` checked as a new or existing work object's name (InputError naming it)."""
    try:
        TypeAdapter(Name).validate_python(name)
    except ValidationError:
        raise InputError(
            f"{name!r}: give 1 to 64 printable characters", field="work object name"
        ) from None
    if name == BASE_WOBJ:
        raise InputError(
            f"{name!r} is the robot base; choose another name", field="work object name"
        )
    return name
