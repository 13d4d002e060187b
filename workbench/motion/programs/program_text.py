"""The text every reader splits: comments, strings, bracket depth and statement ends, the same
way for every controller language (RAPID, KRL, FANUC LS, URScript, NACHI).

Each language names its own characters: the comment marker (RAPID and LS '!', KRL ';',
URScript '#', NACHI "'"), the statement end (RAPID ';'), the brackets an argument list nests
in. Strings are double-quoted in all five; a marker, separator or bracket inside a string is
text. Line continuation is each language's own (RAPID: a statement runs on to its ';'; LS: a
line starting ':' continues the numbered line before it) and is read where the language is.
"""

from __future__ import annotations

from collections.abc import Iterator

QUOTE = '"'


class Unbalanced(ValueError):
    """Brackets that do not pair: `closing` True when a closing bracket comes first."""

    def __init__(self, closing: bool) -> None:
        super().__init__("unbalanced closing bracket" if closing else "unclosed bracket")
        self.closing = closing


def _outside_strings(text: str) -> Iterator[tuple[int, str, bool]]:
    """Yield (index, character, inside a string) for every character of `text`."""
    in_str = False
    for i, ch in enumerate(text):
        if ch == QUOTE:
            in_str = not in_str
            yield i, ch, True
        else:
            yield i, ch, in_str


def open_string(text: str) -> bool:
    """Return True when `text` ends inside a string (an odd number of quotes)."""
    return text.count(QUOTE) % 2 == 1


def split_comment(line: str, marker: str) -> tuple[str, str | None]:
    """Return (code, comment) of one line: the comment is what follows the first `marker`
    outside a string (None when there is none); neither is stripped."""
    for i, ch, in_str in _outside_strings(line):
        if ch == marker and not in_str:
            return line[:i], line[i + 1 :]
    return line, None


def split_statements(text: str, end: str = ";") -> list[str]:
    """Return the pieces of `text` cut after each `end` outside a string, each stripped and
    keeping its `end` (the last piece has none when the statement runs on); blank pieces dropped."""
    pieces, start = [], 0
    for i, ch, in_str in _outside_strings(text):
        if ch == end and not in_str:
            pieces.append(text[start : i + 1].strip())
            start = i + 1
    rest = text[start:].strip()
    if rest:
        pieces.append(rest)
    return pieces


def split_top(text: str, sep: str = ",", brackets: str = "()", *, strict: bool = True) -> list[str]:
    """Return the parts of `text` between the `sep` characters outside strings and outside
    `brackets` (pairs of opening and closing characters, "()[]{}"), each stripped (empty parts
    kept). `strict`: raise `Unbalanced` when the brackets do not pair."""
    opening, closing = brackets[0::2], brackets[1::2]
    parts, start, depth = [], 0, 0
    for i, ch, in_str in _outside_strings(text):
        if in_str:
            continue
        if ch in opening:
            depth += 1
        elif ch in closing:
            depth -= 1
            if depth < 0 and strict:
                raise Unbalanced(closing=True)
        elif ch == sep and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if depth != 0 and strict:
        raise Unbalanced(closing=False)
    parts.append(text[start:].strip())
    return parts


def numbered_lines(text: str) -> list[tuple[int, str]]:
    """Return the non-blank lines of `text`, stripped, with their line numbers (from 1)."""
    return [(no, t.strip()) for no, t in enumerate(text.splitlines(), start=1) if t.strip()]
