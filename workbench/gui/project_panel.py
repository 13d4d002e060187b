"""The "Project" tab: upload a project JSON, download the current one, save it on the server."""

from __future__ import annotations

from collections.abc import Callable

import viser

from workbench.errors import ProjectError
from workbench.gui.notify import guarded, notify
from workbench.service import Workbench


class ProjectPanel:
    """Upload / download / save of the whole project; `on_replaced` rebuilds the scene."""

    def __init__(
        self, server: viser.ViserServer, wb: Workbench, on_replaced: Callable[[], None]
    ) -> None:
        s = server
        self.server, self.wb, self.on_replaced = server, wb, on_replaced
        self.info = s.gui.add_markdown("")
        self.upload = s.gui.add_upload_button(
            "Load project JSON", icon=None, mime_type="application/json"
        )
        self.download = s.gui.add_button("Download project JSON")
        self.save = s.gui.add_button(
            "Save on server",
            disabled=wb.path is None,
            hint="Write the project back to its file (atomic)",
        )
        self.upload.on_upload(guarded(s, "Load project")(self._on_upload))
        self.download.on_click(guarded(s, "Download project")(self._on_download))
        self.save.on_click(guarded(s, "Save project")(self._on_save))
        self.refresh()

    def refresh(self) -> None:
        """Show the project's name and file."""
        wb = self.wb
        where = f"`{wb.path}`" if wb.path else "not saved to a file"
        self.info.content = f"**{wb.project.name}**  \n{where}"

    def _on_upload(self, event: viser.GuiEvent) -> None:
        file = self.upload.value
        if not file.name.lower().endswith(".json"):
            raise ProjectError(f"{file.name}: expected a .json project file")
        project = self.wb.replace_from_json(file.content, source=file.name)
        self.on_replaced()
        self.refresh()
        notify(
            self.server,
            event.client,
            "Project loaded",
            f"{file.name}: {project.name}",
            color="green",
        )

    def _on_download(self, event: viser.GuiEvent) -> None:
        if event.client is None:
            return
        name = (self.wb.project.name or "project").replace(" ", "_") + ".json"
        event.client.send_file_download(name, self.wb.to_json().encode(), save_immediately=True)

    def _on_save(self, event: viser.GuiEvent) -> None:
        path = self.wb.save()
        notify(self.server, event.client, "Saved", str(path), color="green")
