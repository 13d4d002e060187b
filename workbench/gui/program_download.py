"""Program export from a workflow's tab: the format dropdown and the Download button every tab
shows (Motion, Bending, Assembly, Polishing), one helper, `ProgramDownload`.

The download is the service's export (`Workbench.export_program(fmt, workflow)`), so the file is
the one `workbench export` writes. A plan with problems is refused with what a GUI user can do,
and an "Export anyway" button appears beside Download (the GUI's `--force`: the plan's
problems are named again in the notes); a new plan hides it. Notes of
the export come as a notification, and an export of a pressing process in a format without
force control says, and keeps saying until closed, that its targets assume a compliant tool
with D = F/k (`service.programs.contact_note`).
"""

from __future__ import annotations

from collections.abc import Callable

import viser

from workbench.errors import PlanningError
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded, notify
from workbench.service import EXPORT_FORMATS, ExportedProgram, Workbench
from workbench.service.programs import contact_note, latest_plan

#: How a tab's workflow is called in messages.
WORKFLOW_TITLES = {
    "motion": "Motion",
    "bending": "Bending",
    "assembly": "Assembly",
    "polishing": "Polishing",
}


def download_of(exported: ExportedProgram, stem: str) -> tuple[str, bytes]:
    """Return (file name, bytes) to download: the one file, or a zip `stem`.zip of several."""
    if len(exported.files) == 1:
        name, text = next(iter(exported.files.items()))
        return name, text.encode()
    return f"{stem}.zip", exported.zip_bytes()


def refusal(workflow: str, summary: str) -> str:
    """Return why the GUI does not write a plan with problems and what its user can do."""
    tab = WORKFLOW_TITLES.get(workflow, workflow)
    return (
        f"{workflow}: the plan has problems: {summary}. Fix what the summary names (in the"
        f' project, or the {tab} tab\'s settings) and plan again, or press "Export anyway"'
        " to write this plan with its problems."
    )


class ProgramDownload:
    """A tab's "Export format" dropdown and Download button for `workflow`'s robot programs.

    `wb()` returns the open project's Workbench (read at each click); `stem()` names the zip of
    a several-file export; `after(exported)` runs once the file is sent (e.g. a refresh)."""

    def __init__(
        self,
        server: viser.ViserServer,
        wb: Callable[[], Workbench],
        workflow: str,
        *,
        stem: Callable[[], str] | None = None,
        format_label: str = "Export format",
        label: str = "Download program",
        hint: str | None = None,
        disabled: bool = True,
        after: Callable[[ExportedProgram], None] = lambda exported: None,
    ) -> None:
        self.server, self.wb, self.workflow = server, wb, workflow
        self.stem = stem or (lambda: f"{workflow}_{self.format.value}")
        self.after = after
        g = server.gui
        self.format = g.add_dropdown(
            format_label,
            options=tuple(EXPORT_FORMATS),
            initial_value=wb().default_program_format() or "rapid",
        )
        self.button = g.add_button(label, icon=viser.Icon.DOWNLOAD, disabled=disabled, hint=hint)
        self.anyway = g.add_button(
            "Export anyway",
            icon=viser.Icon.ALERT_TRIANGLE,
            color="red",
            visible=False,
            hint="Write the refused plan with its problems (the command line's --force)",
        )
        self.button.on_click(guarded(server, "Export")(self._on_click))
        self.anyway.on_click(guarded(server, "Export anyway")(self._on_anyway))
        self.handles: list[Removable] = [self.format, self.button, self.anyway]

    @property
    def disabled(self) -> bool:
        """Return True while the button is disabled (no plan yet)."""
        return bool(self.button.disabled)

    @disabled.setter
    def disabled(self, value: bool) -> None:
        """Enable (a new plan) or disable (no plan) Download; either hides "Export anyway",
        which belongs to the refused plan."""
        self.button.disabled = value
        self.anyway.visible = False

    def export(self, *, force: bool = False) -> ExportedProgram:
        """Return the workflow's latest plan (planned now if none) exported in the dropdown's
        format; PlanningError with what a GUI user can do when the plan has problems, unless
        `force` (then "Export anyway" shows until the next plan)."""
        wb, fmt = self.wb(), str(self.format.value)
        plan = latest_plan(wb, self.workflow)
        if not plan.ok and not force:
            self.anyway.visible = True
            raise PlanningError(refusal(self.workflow, plan.summary()))
        return wb.export_program(fmt, self.workflow, force=force)

    def _on_click(self, event: viser.GuiEvent) -> None:
        self._send(self.export(), event.client)

    def _on_anyway(self, event: viser.GuiEvent) -> None:
        self._send(self.export(force=True), event.client)
        self.anyway.visible = False

    def _send(self, exported: ExportedProgram, client: viser.ClientHandle | None) -> None:
        if client is not None:
            name, data = download_of(exported, self.stem())
            client.send_file_download(name, data, save_immediately=True)
        fmt = str(self.format.value)
        warning = contact_note(self.wb(), self.workflow, fmt)
        if warning is not None:
            notify(self.server, client, f"{fmt}: no force control", warning, color="yellow")
        others = [n for n in exported.notes if n != warning]
        if others:
            body = "; ".join(others[:12])  # a notification shows plain text, one paragraph
            notify(self.server, client, "Export notes", body, color="blue")
        self.after(exported)

    def remove(self) -> None:
        """Remove the dropdown and the button."""
        for h in self.handles:
            h.remove()
