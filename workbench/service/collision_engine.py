"""The open project's conservative collision engine: spheres + signed distance field, confirmed exactly."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


class CollisionService:
    """`Workbench.collision`: fast conservative checks of the robot against the cell (SI units)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
