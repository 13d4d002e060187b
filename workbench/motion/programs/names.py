"""Legal identifiers for robot languages: invalid or reserved names are renamed, with a note."""

from __future__ import annotations

import re
from collections.abc import Iterable

_NOT_IDENT = re.compile(r"[^A-Za-z0-9_]")


class NameTable:
    """Maps program names (targets, tools, work objects, signals) to legal, unique identifiers
    of one language: letters, digits and _, a letter first, at most `max_len` characters, not a
    reserved word (compared case-insensitively where the language is). Every rename is noted."""

    def __init__(
        self,
        language: str,
        reserved: Iterable[str],
        *,
        max_len: int = 24,
        case_sensitive: bool = False,
        prefix: str = "p",
    ) -> None:
        self.language = language
        self.case_sensitive = case_sensitive
        self.reserved = {self._key(w) for w in reserved}
        self.max_len = max_len
        self.prefix = prefix
        self._names: dict[str, str] = {}
        self._used: set[str] = set()
        self.notes: list[str] = []

    def _key(self, s: str) -> str:
        return s if self.case_sensitive else s.lower()

    def __call__(self, name: str, fallback: str) -> str:
        """Return the identifier for `name` (or for `fallback` when `name` is empty)."""
        src = name or fallback
        if src in self._names:
            return self._names[src]
        ident = _NOT_IDENT.sub("_", src)[: self.max_len]
        if not ident or not ident[0].isalpha():
            ident = (self.prefix + "_" + ident)[: self.max_len]
        why = ""
        if self._key(ident) in self.reserved:
            why = f"a reserved word in {self.language}"
            ident = (ident + "_1")[: self.max_len]
        base, k = ident, 1
        while self._key(ident) in self._used or self._key(ident) in self.reserved:
            k += 1
            tail = f"_{k}"
            ident = base[: self.max_len - len(tail)] + tail
        if name and ident != name:
            if not why:
                valid = _NOT_IDENT.sub("_", name) == name and name[0].isalpha()
                if not valid:
                    why = f"not a valid {self.language} identifier"
                elif len(name) > self.max_len:
                    why = f"{self.language} names have at most {self.max_len} characters"
                else:
                    why = "taken by another name"
            self.notes.append(f"renamed {name!r} to {ident!r}: {why}")
        self._names[src] = ident
        self._used.add(self._key(ident))
        return ident


_VENDOR_WORDS = ("NACHI", "ABB", "KUKA", "FANUC", "UNIVERSAL ROBOTS")


def controller_model(title: str) -> str:
    """Return a robot's model name as its controller lists it in file names: the robot's title
    without the vendor's name ('NACHI MZ07' -> 'MZ07', 'MZ07' -> 'MZ07'), spaces dropped and
    any other character that is not a letter, digit or '_' made '_' (so '-' only separates
    the parts of a NACHI file name). An empty or odd name gives 'ROBOT'."""
    text = " ".join(str(title).split())
    for vendor in _VENDOR_WORDS:
        if text.upper().startswith(vendor + " "):
            text = text[len(vendor) + 1 :]
            break
    model = re.sub(r"[^A-Za-z0-9_]", "_", text.replace(" ", ""))
    if not model or not model[0].isalnum():
        model = "ROBOT" + model
    return model


def nachi_file_name(model: str, unit: int, number: int) -> str:
    """Return a NACHI FD program's file name as the controller lists it,
    ``<model>-<unit>-A.<nnn>``: the robot model, the unit (mechanism) number in two digits,
    "A", and the three-digit program number (RoboDK's NACHI posts write ``MZ07L-01-A.001``)."""
    if not 1 <= int(unit) <= 99:
        raise ValueError(f"NACHI unit number {unit} must be 1..99")
    if not 0 <= int(number) <= 999:
        raise ValueError(f"NACHI program number {number} must be 0..999")
    return f"{model}-{int(unit):02d}-A.{int(number):03d}"
