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

from workbench.errors import InputError
from workbench.project.models import Robot
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

    @property
    def kind(self) -> str:
        """Return "joints" or "points"."""
        return "joints" if self.joints is not None else "points"


def _rows(text: str, source: str) -> list[tuple[int, list[str]]]:
    rows = []
    for number, line in enumerate(text.splitlines(), 1):
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
    raise InputError(
        f"header {','.join(cells)!r}: give {expected} (joints [deg], as the controller shows"
        " them) or label,x,y,z (TCP positions [mm] in the robot's base)",
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
            f"this file needs label,x,y,z (points [mm]), not {kind}", field=f"{source} line 1"
        )
    unit = "deg" if kind == "joints" else "mm"
    labels: list[str] = []
    seen: dict[str, int] = {}
    values = np.zeros((len(body), width))
    for r, (number, cells) in enumerate(body):
        if len(cells) != width + 1:
            raise InputError(
                f"{len(cells)} values but the header has {width + 1} columns ({','.join(head)})",
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
    return Readings(
        source, labels, lines, joints=q if convention is None else convention.to_model(q)
    )


def parse_known(text: str, *, source: str) -> tuple[tuple[str, ...], FloatArray]:
    """Return (labels, points (n, 3) [m]) of a known-points CSV `label,x,y,z` [mm]."""
    _, labels, _, values = _table(text, source, None, ("points",))
    return labels, values * MM
