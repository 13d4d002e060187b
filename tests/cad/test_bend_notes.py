"""Tests of workbench/cad/bend_notes.py: bend notes parsed and given to their bend lines.

The assignment's twin is brute force: the distance from a note to a segment as the minimum
over 2001 points along the segment, and the note nearest the midpoint among each line's own.
"""

from __future__ import annotations

import math

import ezdxf
import numpy as np
import pytest

from workbench.cad.bend_notes import assign_notes, parse_note, read_notes

AT = np.zeros(2)


@pytest.mark.parametrize(
    ("text", "angle", "direction", "radius"),
    [
        ("UP 90° R1.5", 90.0, 1, 1.5e-3),
        ("down 45", 45.0, -1, None),
        ("DN 30%%d", 30.0, -1, None),
        ("BEND 120 DEG UP", 120.0, 1, None),
        ("90", 90.0, None, None),
        ("  UP   92,5º  R = 2 mm ", 92.5, 1, 2e-3),
        (".5 degrees", 0.5, None, None),
    ],
)
def test_notes_are_parsed(text, angle, direction, radius) -> None:
    n = parse_note(text, AT, 1e-3)
    assert n is not None
    assert n.angle == pytest.approx(math.radians(angle))
    assert n.direction == direction
    assert n.inner_radius == (pytest.approx(radius) if radius else None)


@pytest.mark.parametrize("text", ["UP 90 DOWN", "PART 17", "UP", "R1.5", "90 R", "", "1.2.3"])
def test_other_text_is_not_a_note(text) -> None:
    assert parse_note(text, AT, 1e-3) is None


def test_read_notes_takes_text_and_mtext_at_their_anchor() -> None:
    msp = ezdxf.new().modelspace()
    msp.add_text("UP 90 R2", dxfattribs={"insert": (10, 20)})
    msp.add_mtext("DOWN 45", dxfattribs={"insert": (30, 40)})
    msp.add_text("ORDER 4711", dxfattribs={"insert": (0, 0)})
    msp.add_line((0, 0), (1, 1))
    notes = read_notes(list(msp), 1e-3)
    assert [(n.text, n.direction) for n in notes] == [("UP 90 R2", 1), ("DOWN 45", -1)]
    assert np.allclose(notes[0].at, [0.01, 0.02]) and np.allclose(notes[1].at, [0.03, 0.04])
    assert notes[0].inner_radius == pytest.approx(2e-3)


def _brute(notes, segments):
    s = np.linspace(0.0, 1.0, 2001)[:, None]
    own = [[] for _ in segments]
    for n in notes:
        d = [np.linalg.norm(a + s * (b - a) - n.at, axis=1).min() for a, b in segments]
        own[int(np.argmin(d))].append(n)
    return [
        min(o, key=lambda n, a=a, b=b: np.linalg.norm(n.at - (a + b) / 2)) if o else None
        for (a, b), o in zip(segments, own, strict=True)
    ]


def test_assignment_matches_brute_force() -> None:
    rng = np.random.default_rng(2)
    for _ in range(100):
        segments = [tuple(rng.uniform(0, 1, (2, 2))) for _ in range(rng.integers(1, 5))]
        notes = [
            parse_note("UP 90", rng.uniform(-0.2, 1.2, 2), 1e-3) for _ in range(rng.integers(0, 6))
        ]
        got = assign_notes(notes, segments)
        want = _brute(notes, segments)
        assert [id(n) for n in got] == [id(n) for n in want]
    assert assign_notes([parse_note("90", AT, 1e-3)], []) == []
