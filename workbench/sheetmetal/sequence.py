"""The bend-sequence rule: a sequence names every bend of the part exactly once.

The one definition of the rule. `SheetMetalPart.from_spec` applies it to the part's
sequence; the project file's models call `sequence_problem` to refuse a bad file at load
(naming the field), and the service calls `check_sequence` on a sequence given through the API.
"""

from __future__ import annotations

from collections.abc import Sequence

from workbench.errors import InputError


def sequence_problem(sequence: Sequence[str], bends: Sequence[str] | None = None) -> str | None:
    """Return what is wrong with `sequence` against the part's bend names, or None if nothing.

    With `bends` None (the part is not known yet) only repeated names are found.
    """
    seq = [str(s) for s in sequence]
    dup = sorted({s for s in seq if seq.count(s) > 1})
    if bends is None:
        return f"must name every bend exactly once; repeated {dup}" if dup else None
    names = [str(b) for b in bends]
    missing = [n for n in names if n not in seq]
    unknown = [s for s in seq if s not in names]
    if not (dup or missing or unknown):
        return None
    found = [
        f"{what} {which}"
        for what, which in (("repeated", dup), ("missing", missing), ("unknown", unknown))
        if which
    ]
    return f"must name every bend exactly once; {', '.join(found)} (bends are {names})"


def check_sequence(
    sequence: Sequence[str], bends: Sequence[str], where: str = "sequence"
) -> list[str]:
    """Return `sequence` as a list of names; InputError naming `where` if it breaks the rule."""
    problem = sequence_problem(sequence, bends)
    if problem is not None:
        raise InputError(f"{where}: {problem}")
    return [str(s) for s in sequence]
