"""The open project's virtual assembly (seed 003): parts, start and goal poses, planners, carried parts."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench


class AssemblyService:
    """`Workbench.assembly`: the assembly workflow of the open project (SI units)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
