"""The project file's `polishing` section: polishing (seed 004): workpiece, tool path and force control."""

from __future__ import annotations

from workbench.project.common import StrictModel


class PolishingSpec(StrictModel):
    """The `polishing` section (mm, deg)."""
