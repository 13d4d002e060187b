"""The collision-engine controls in the "Robot" tab: spheres, distance-field slice, check report."""

from __future__ import annotations

from typing import TYPE_CHECKING

from workbench.gui.handles import Removable

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp


class CollisionPanel:
    """Toggles for the fitted spheres and the SDF slice, and the conservative check's report."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        self.handles: list[Removable] = []

    def remove(self) -> None:
        """Remove the panel's widgets and scene nodes."""
        for h in self.handles:
            h.remove()
        self.handles.clear()
