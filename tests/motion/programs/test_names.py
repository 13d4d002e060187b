"""Tests of workbench/motion/programs/names.py: legal, unique identifiers with a note per rename.

The twin is a brute-force check of the table's promise over many random names: every result is
a legal identifier of the language, no two sources share one, none is reserved, and a name comes
back unchanged exactly when it was already legal, free and short enough.
"""

from __future__ import annotations

import random
import re

from workbench.motion.programs.names import NameTable

_LEGAL = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")


def test_legal_name_is_kept_without_note() -> None:
    t = NameTable("KRL", ["PTP", "LIN"])
    assert t("pick_1", "p") == "pick_1"
    assert t("pick_1", "p") == "pick_1"  # same source, same identifier
    assert t.notes == []


def test_invalid_characters_and_leading_digit() -> None:
    t = NameTable("RAPID", [], prefix="p")
    assert t("approach point", "x") == "approach_point"
    assert t("1st", "x") == "p_1st"
    assert t.notes == [
        "renamed 'approach point' to 'approach_point': not a valid RAPID identifier",
        "renamed '1st' to 'p_1st': not a valid RAPID identifier",
    ]


def test_reserved_word_case_insensitive_unless_told() -> None:
    t = NameTable("KRL", ["LIN"])
    assert t("lin", "x") == "lin_1"
    assert t.notes == ["renamed 'lin' to 'lin_1': a reserved word in KRL"]
    s = NameTable("URScript", ["movel"], case_sensitive=True)
    assert s("MoveL", "x") == "MoveL"
    assert s("movel", "x") == "movel_1"


def test_too_long_and_collisions_get_numbered() -> None:
    t = NameTable("Fanuc", [], max_len=8)
    a = t("abcdefghij", "x")
    b = t("abcdefghXY", "x")
    assert a == "abcdefgh"
    assert b == "abcdef_2" and len(b) == 8
    assert t.notes[0].endswith("Fanuc names have at most 8 characters")
    c = t("abcdef_2", "x")  # legal but already handed out
    assert c == "abcdef_3"
    assert t.notes[-1] == "renamed 'abcdef_2' to 'abcdef_3': taken by another name"


def test_case_insensitive_collision() -> None:
    t = NameTable("RAPID", [])
    assert t("Home", "x") == "Home"
    assert t("HOME", "x") == "HOME_2"


def test_empty_name_uses_fallback_silently() -> None:
    t = NameTable("KRL", [])
    assert t("", "tool_1") == "tool_1"
    assert t("", "9") == "p_9"
    assert t.notes == []  # the user gave no name, so nothing of theirs was renamed


def test_random_names_brute_force() -> None:
    rng = random.Random(3)
    alphabet = "aAbB_1 -.é9zZ"
    reserved = ["aa", "ab", "a_1", "B"]
    for case_sensitive in (False, True):
        t = NameTable("X", reserved, max_len=6, case_sensitive=case_sensitive)

        def key(s: str, cs: bool = case_sensitive) -> str:
            return s if cs else s.lower()

        res = {key(w) for w in reserved}
        given: dict[str, str] = {}
        for _ in range(400):
            name = "".join(rng.choice(alphabet) for _ in range(rng.randint(1, 9)))
            taken = {key(v) for v in given.values()}
            out = t(name, "f")
            if name in given:
                assert out == given[name]
                continue
            assert _LEGAL.match(out) and len(out) <= 6, out
            assert key(out) not in res
            assert key(out) not in taken
            kept = (
                _LEGAL.match(name) is not None
                and len(name) <= 6
                and key(name) not in res
                and key(name) not in taken
            )
            assert (out == name) == kept, (name, out)
            given[name] = out
        assert len(t.notes) == sum(1 for k, v in given.items() if k != v)
