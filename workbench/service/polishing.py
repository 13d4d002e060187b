"""The open project's polishing (seed 004): workpiece, fitted surface, tool paths, force control."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


class PolishingService:
    """`Workbench.polishing`: the polishing workflow of the open project (SI units)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
