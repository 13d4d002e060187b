"""The open project's press-brake bending (seed 000): the part, its bend sequence, the grasp, OBB-tree checks and the plan."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


class BendingService:
    """`Workbench.bending`: the bending workflow of the open project (SI units)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
