"""The project file's `bending` section: press-brake bending (seed 000): part, bend sequence, grasp, cell."""

from __future__ import annotations

from workbench.project.common import StrictModel


class BendingSpec(StrictModel):
    """The `bending` section (mm, deg)."""
