"""The "Assembly" tab."""

from __future__ import annotations

from typing import TYPE_CHECKING

from workbench.gui.handles import Removable

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp


class AssemblyPanel:
    """Controls of the assembly workflow; built inside its tab, removed when the project changes."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        g = app.server.gui
        self.handles: list[Removable] = [
            g.add_markdown("This project has no `assembly` section.")
        ]

    def remove(self) -> None:
        """Remove the tab's widgets and scene nodes."""
        for h in self.handles:
            h.remove()
        self.handles.clear()
