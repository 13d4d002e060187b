"""Undo of an applied calibration or touch-up: the project before it, put back by the service.

Each apply of the Project tab's Calibration and Touch-up folders returns the project it
replaced; `ProjectUndo.push` keeps it with what was applied and a print of the project that
resulted. `undo` puts the last previous project back with `wb.replace_project` (a job, then
the tabs rebuilt), but only while the project is still the one that apply made (the robot's
joints aside: a jog does not count): after another change (a program edit, an import, a
load) it is refused with a notification saying why, rather than silently dropping that change.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from workbench.errors import InputError
from workbench.service import Workbench

DEPTH = 10  # applies kept for undo


def _print(project: Any) -> dict[str, Any]:
    """Return the project as data, without the robot's joints (a jog is not an edit)."""
    data: dict[str, Any] = project.model_dump(mode="json", exclude_none=True)
    data.get("robot", {}).pop("joints", None)
    return data


@dataclass(frozen=True)
class Applied:
    """One apply: what it was (for the button and the notification), the project before it,
    and the print of the project it made."""

    what: str
    previous: Any  # the Project before the apply
    after: dict[str, Any]


class ProjectUndo:
    """The applies that can be undone, newest last; `on_change` runs after every push or undo."""

    def __init__(self, wb: Callable[[], Workbench]) -> None:
        self._wb = wb
        self.stack: list[Applied] = []
        self.listeners: list[Callable[[], None]] = []

    def push(self, what: str, previous: Any) -> None:
        """Remember that `what` was applied to the current project, replacing `previous`."""
        self.stack.append(Applied(what, previous, _print(self._wb().project)))
        del self.stack[:-DEPTH]
        self._changed()

    @property
    def last(self) -> str | None:
        """Return what the next undo takes back, or None."""
        return self.stack[-1].what if self.stack else None

    def check(self) -> Applied:
        """Return the apply the next undo takes back; raise InputError naming why it cannot."""
        if not self.stack:
            raise InputError("undo: nothing to undo; apply a calibration or a touch-up first")
        top = self.stack[-1]
        if _print(self._wb().project) != top.after:
            raise InputError(
                f"undo: the project changed after '{top.what}' was applied (an edit, an import"
                " or a load), and undo would drop that change; reload the project or apply"
                " again instead"
            )
        return top

    def undo(self, replace: Callable[[Any], None]) -> str:
        """Put the project before the last apply back through `replace`; return what it undid."""
        top = self.check()
        replace(top.previous)
        self.stack.pop()
        self._changed()
        return top.what

    def clear(self) -> None:
        """Forget every apply (another project was opened)."""
        self.stack.clear()
        self._changed()

    def _changed(self) -> None:
        for listener in self.listeners:
            listener()
