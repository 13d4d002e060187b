"""What the panels need of viser's GUI handles."""

from __future__ import annotations

from typing import Protocol


class Removable(Protocol):
    """A GUI handle that can be removed (every viser GUI handle is)."""

    def remove(self) -> None: ...
