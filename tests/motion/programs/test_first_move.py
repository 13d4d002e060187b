"""The safe first move (first_move.py): what every post writes as a program's first move."""

from __future__ import annotations

import dataclasses

import pytest
from program_round_trip import sample_program

from workbench.motion.programs.controller_program import MoveInstr
from workbench.motion.programs.first_move import (
    FIRST_MOVE_SPEED,
    first_move_index,
    safe_first_move,
    safe_start,
)


def test_the_first_move_becomes_an_untimed_slow_exact_joint_move() -> None:
    prog, _ = sample_program()
    k = first_move_index(prog)
    assert k == 1  # instruction 0 is a comment
    safe = safe_start(prog)
    first = safe.instructions[k]
    assert isinstance(first, MoveInstr)
    assert first.kind == "joint" and first.duration == 0.0 and first.zone == 0.0
    assert first.speed == FIRST_MOVE_SPEED and first.target is prog.instructions[k].target
    # everything after it is the plan's, untouched
    assert safe.instructions[k + 1 :] == prog.instructions[k + 1 :]
    assert safe.instructions[:k] == prog.instructions[:k]


@pytest.mark.parametrize(("kind", "speed", "expected"), [
    ("joint", 0.05, 0.05),  # already slower: kept
    ("joint", 1.0, FIRST_MOVE_SPEED),
    ("linear", 0.25, FIRST_MOVE_SPEED),  # a TCP speed [m/s]: the joint bound instead
    ("circular", 0.1, FIRST_MOVE_SPEED),
])  # fmt: skip
def test_every_kind_of_first_move_is_a_bounded_joint_move(
    kind: str, speed: float, expected: float
) -> None:
    prog, _ = sample_program()
    circ = next(m for m in prog.moves if m.kind == "circular")
    mv = dataclasses.replace(circ, kind=kind, speed=speed, zone=0.02, duration=3.0)  # type: ignore[arg-type]
    safe = safe_first_move(mv)
    assert safe.kind == "joint" and safe.via is None and safe.target is circ.target
    assert safe.speed == pytest.approx(expected) and safe.duration == 0.0 and safe.zone == 0.0


def test_a_program_without_moves_is_left_alone() -> None:
    prog, _ = sample_program()
    empty = dataclasses.replace(prog, instructions=prog.instructions[:1])
    assert first_move_index(empty) is None and safe_start(empty) is empty
