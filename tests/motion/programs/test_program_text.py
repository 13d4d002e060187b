"""The readers' shared splitter against the per-reader loops it replaced (kept here as twins),
on random text, and its handling of strings."""

from __future__ import annotations

import random

import pytest

from workbench.motion.programs.program_text import (
    Unbalanced,
    numbered_lines,
    open_string,
    split_comment,
    split_statements,
    split_top,
)


def _twin_split_top(text: str, opening: str, closing: str) -> tuple[list[str], str | None]:
    """The old character loop (no strings): parts and the first imbalance ('close'/'open')."""
    parts, cur, depth, err = [], [], 0, None
    for ch in text:
        if ch in opening:
            depth += 1
        elif ch in closing:
            depth -= 1
            if depth < 0 and err is None:
                err = "close"
        if ch == "," and depth == 0:
            parts.append("".join(cur).strip())
            cur = []
        else:
            cur.append(ch)
    parts.append("".join(cur).strip())
    if err is None and depth != 0:
        err = "open"
    return parts, err


def _twin_comment(line: str, marker: str) -> tuple[str, str | None, bool]:
    in_str = False
    for i, ch in enumerate(line):
        if ch == '"':
            in_str = not in_str
        elif ch == marker and not in_str:
            return line[:i], line[i + 1 :], False
    return line, None, in_str


def _twin_semicolons(line: str) -> list[str]:
    pieces, cur, in_str = [], "", False
    for ch in line:
        cur += ch
        if ch == '"':
            in_str = not in_str
        elif ch == ";" and not in_str:
            pieces.append(cur.strip())
            cur = ""
    if cur.strip():
        pieces.append(cur.strip())
    return pieces


def _random_text(rng: random.Random, alphabet: str, n: int) -> str:
    return "".join(rng.choice(alphabet) for _ in range(rng.randint(0, n)))


@pytest.mark.parametrize("brackets", ["()", "()[]", "{}"])
def test_split_top_matches_the_old_loops(brackets: str) -> None:
    rng = random.Random(7)
    opening, closing = brackets[0::2], brackets[1::2]
    for _ in range(3000):
        text = _random_text(rng, "a1 ," + brackets, 14)
        want, err = _twin_split_top(text, opening, closing)
        if err is None:
            assert split_top(text, ",", brackets) == want, text
        else:
            with pytest.raises(Unbalanced) as exc:
                split_top(text, ",", brackets)
            assert exc.value.closing == (err == "close"), text
        if err != "close":  # lenient: the same split as long as depth never went below 0
            assert split_top(text, ",", brackets, strict=False) == want, text


def test_comments_and_statements_match_the_old_loops() -> None:
    rng = random.Random(11)
    for _ in range(3000):
        line = _random_text(rng, 'ab ;!"#', 16)
        for marker in "!;#":
            code, comment, still_open = _twin_comment(line, marker)
            assert split_comment(line, marker) == (code, comment), line
            assert (comment is None and open_string(code)) == still_open, line
        assert split_statements(line, ";") == _twin_semicolons(line), line


def test_strings_hide_separators_markers_and_brackets() -> None:
    assert split_top('a, "b, (c", d', ",", "()") == ["a", '"b, (c"', "d"]
    assert split_comment('x := "a!b" ! note', "!") == ('x := "a!b" ', " note")
    assert split_statements('TPWrite "a;b"; x := 1;') == ['TPWrite "a;b";', "x := 1;"]
    assert open_string('TPWrite "open')


def test_numbered_lines_skip_blanks_and_count_from_one() -> None:
    assert numbered_lines("a\n\n  b  \n") == [(1, "a"), (3, "b")]
