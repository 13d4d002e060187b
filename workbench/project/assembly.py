"""The project file's `assembly` section: virtual assembly (seed 003): parts, start and goal poses, planner."""

from __future__ import annotations

from workbench.project.common import StrictModel


class AssemblySpec(StrictModel):
    """The `assembly` section (mm, deg)."""
