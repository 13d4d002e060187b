"""Bend notes of a DXF flat pattern: TEXT/MTEXT such as "UP 90° R1.5" or "DOWN 45", per bend line.

A note is a direction (UP, DOWN or DN; optional, before or after the angle), the bend angle in
degrees (the deflection from flat as SolidWorks writes it: 90 for a right angle; "°", "%%d" or
"DEG" optional) and optionally "R" with the inner radius in drawing units, case-insensitive,
optionally led by "BEND". Any other text is not a note. Each note belongs to the bend line
nearest to it; a line with several takes the one nearest its midpoint.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

_NUM = r"(?:\d+(?:[.,]\d*)?|[.,]\d+)"
NOTE = re.compile(
    rf"^(?:BEND\s*)?(?P<d1>UP|DOWN|DN)?\s*(?P<a>{_NUM})\s*(?:°|DEG(?:REES?)?)?\s*"
    rf"(?P<d2>UP|DOWN|DN)?\s*(?:R\s*=?\s*(?P<r>{_NUM})\s*(?:MM|IN|\")?)?\s*$",
    re.IGNORECASE,
)


@dataclass(frozen=True, eq=False)
class BendNote:
    """A parsed note: `text`, position `at` (2,) [m], `angle` [rad], `direction` (+1, -1 or
    None: not written), `inner_radius` [m] or None."""

    text: str
    at: NDArray[np.float64]
    angle: float
    direction: int | None
    inner_radius: float | None


def _number(s: str) -> float:
    return float(s.replace(",", "."))


def parse_note(text: str, at: NDArray[np.float64], scale: float) -> BendNote | None:
    """Return the note `text` at `at` [m] parsed (radius: drawing units x `scale` m), or None."""
    clean = re.sub(r"%%d|º", "°", text, flags=re.IGNORECASE)
    clean = " ".join(clean.split())
    m = NOTE.match(clean)
    if m is None:
        return None
    words = {m["d1"], m["d2"]} - {None}
    if len(words) > 1:
        return None
    direction = None if not words else (1 if words.pop().upper() == "UP" else -1)
    r = _number(m["r"]) * scale if m["r"] else None
    return BendNote(clean, np.asarray(at, float), float(np.radians(_number(m["a"]))), direction, r)


def read_notes(entities: list[Any], scale: float) -> list[BendNote]:
    """Return the bend notes among TEXT and MTEXT `entities` (`scale` m per drawing unit)."""
    notes = []
    for e in entities:
        kind = e.dxftype()
        if kind not in ("TEXT", "MTEXT"):
            continue
        at = e.dxf.insert
        if kind == "TEXT" and (e.dxf.get("halign", 0) or e.dxf.get("valign", 0)):
            at = e.dxf.get("align_point", at)
        note = parse_note(e.plain_text(), np.array([at.x, at.y]) * scale, scale)
        if note is not None:
            notes.append(note)
    return notes


def _segment_distance(
    p: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]
) -> float:
    ab = b - a
    s = float(np.clip(np.dot(p - a, ab) / max(float(np.dot(ab, ab)), 1e-300), 0.0, 1.0))
    return float(np.linalg.norm(p - (a + s * ab)))


def assign_notes(
    notes: list[BendNote], segments: list[tuple[NDArray[np.float64], NDArray[np.float64]]]
) -> list[BendNote | None]:
    """Return per segment (start, end) [m] its note (nearest to its midpoint among those
    nearest to it), or None."""
    mine: list[list[BendNote]] = [[] for _ in segments]
    for note in notes:
        if segments:
            d = [_segment_distance(note.at, a, b) for a, b in segments]
            mine[int(np.argmin(d))].append(note)
    out: list[BendNote | None] = []
    for (a, b), own in zip(segments, mine, strict=True):
        mid = 0.5 * (a + b)
        out.append(min(own, key=lambda n: float(np.linalg.norm(n.at - mid))) if own else None)
    return out
