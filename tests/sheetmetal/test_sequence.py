"""The bend-sequence rule (every bend exactly once): one definition, the part and the file use it."""

from __future__ import annotations

import pytest

from workbench.errors import InputError
from workbench.sheetmetal.sequence import check_sequence, sequence_problem

BENDS = ["b1", "b2", "b3"]


def test_a_permutation_is_fine_and_comes_back_as_a_list() -> None:
    assert sequence_problem(["b3", "b1", "b2"], BENDS) is None
    assert check_sequence(("b3", "b1", "b2"), BENDS) == ["b3", "b1", "b2"]
    assert sequence_problem([], []) is None


@pytest.mark.parametrize(
    ("seq", "found"),
    [
        (["b1", "b1", "b2", "b3"], "repeated ['b1'] "),
        (["b1", "b2"], "missing ['b3'] "),
        (["b1", "b2", "b3", "b9"], "unknown ['b9'] "),
        (["b1", "b1", "b9"], "repeated ['b1'], missing ['b2', 'b3'], unknown ['b9'] "),
        ([], "missing ['b1', 'b2', 'b3'] "),
    ],
)
def test_each_problem_is_named_with_the_bends(seq: list[str], found: str) -> None:
    msg = sequence_problem(seq, BENDS)
    assert msg == f"must name every bend exactly once; {found}(bends are {BENDS})"
    with pytest.raises(InputError, match=r"^bending\.sequence: must name every bend exactly once"):
        check_sequence(seq, BENDS, "bending.sequence")


def test_without_the_bends_only_repeats_are_found() -> None:
    assert sequence_problem(["b1", "b9"]) is None
    assert (
        sequence_problem(["b2", "b1", "b2"]) == "must name every bend exactly once; repeated ['b2']"
    )
