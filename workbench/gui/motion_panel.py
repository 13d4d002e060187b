"""The "Motion" tab: plan the project's program, see the checks, export robot programs."""

from __future__ import annotations

from collections.abc import Callable

import viser

from workbench.gui.handles import Removable
from workbench.gui.notify import guarded, notify
from workbench.gui.progress import busy
from workbench.gui.timeline import Timeline
from workbench.service import EXPORT_FORMATS, ExportedProgram, Workbench
from workbench.service.program_import import program_files


class MotionPanel:
    """Plan button with progress, the plan's summary, and program export."""

    def __init__(
        self,
        server: viser.ViserServer,
        wb: Workbench,
        timeline: Timeline,
        on_replaced: Callable[[], None] = lambda: None,
    ) -> None:
        self.server, self.wb, self.timeline = server, wb, timeline
        self.on_replaced = on_replaced
        g = server.gui
        self.program = g.add_markdown("")
        self.plan_button = g.add_button("Plan", icon=viser.Icon.ROUTE)
        self.progress = g.add_progress_bar(0.0, visible=False, animated=True)
        self.result = g.add_markdown("")
        self.format = g.add_dropdown(
            "Export format", options=tuple(EXPORT_FORMATS), initial_value="rapid"
        )
        self.download = g.add_button("Download program", icon=viser.Icon.DOWNLOAD, disabled=True)
        self.upload = g.add_upload_button(
            "Import program",
            icon=viser.Icon.UPLOAD,
            hint="A RAPID .mod, a KRL .zip of .src + .dat, a FANUC .ls, a URScript .script or a"
            " NACHI program: it replaces the project's program",
        )
        self.upload.on_upload(guarded(server, "Import program")(self._on_import))
        self.plan_button.on_click(guarded(server, "Plan")(self._on_plan))
        self.download.on_click(guarded(server, "Export")(self._on_download))
        self.handles: list[Removable] = [
            self.program,
            self.plan_button,
            self.progress,
            self.result,
            self.format,
            self.download,
            self.upload,
        ]
        self.refresh()

    def remove(self) -> None:
        """Remove the widgets (before the project is replaced)."""
        for h in self.handles:
            h.remove()

    def refresh(self) -> None:
        """Describe the project's program."""
        spec = self.wb.project.program
        if spec is None:
            self.program.content = (
                "This project has no program. Add a `program` with moves to its JSON."
            )
            self.plan_button.disabled = True
            return
        rows = "\n".join(
            f"| {i + 1} | {m.name or '-'} | {m.type} | {m.speed:g} {'%' if m.type == 'joint' else 'mm/s'}"
            f" | {'fine' if m.zone == 0 else f'{m.zone:g} mm'} |"
            if m.type in ("joint", "linear")
            else f"| {i + 1} | - | {m.type} | {_action_text(m)} | |"
            for i, m in enumerate(spec.moves)
        )
        self.program.content = (
            f"**Program `{spec.name}`**\n\n| # | name | type | speed | zone |\n"
            f"|---|---|---|---|---|\n{rows}"
        )
        self.plan_button.disabled = False

    def _on_plan(self, event: viser.GuiEvent) -> None:
        with busy(
            self.progress, [self.plan_button], self.result, what="planning motion"
        ) as progress:
            plan = self.wb.plan_motion(progress=progress)
        self.result.content = ("**OK:** " if plan.ok else "**Problems:** ") + plan.summary()
        self.download.disabled = False
        self.timeline.load(
            plan.samples,
            robot=self.wb.robot,
        )

    def _on_download(self, event: viser.GuiEvent) -> None:
        fmt = str(self.format.value)
        exported = self.wb.export_program(fmt)  # refused (a notification) if the plan has problems
        if event.client is not None:
            name, data = download_of(exported, f"{self.wb.project.program.name}_{fmt}")  # type: ignore[union-attr]
            event.client.send_file_download(name, data, save_immediately=True)


    def _on_import(self, event: viser.GuiEvent) -> None:
        up = self.upload.value
        notes = self.wb.import_program(program_files(up.name, up.content))
        self.on_replaced()  # the program, tool and work objects changed: rebuild the tabs
        body = f"{up.name}: {len(self.wb.project.program.moves)} items"  # type: ignore[union-attr]
        notify(self.server, event.client, "Program imported", body, color="green")
        if notes:  # lines the reader did not understand, values taken differently: stay open
            text = "\n".join(f"- {n}" for n in notes[:20])
            more = f"\n- … and {len(notes) - 20} more" if len(notes) > 20 else ""
            notify(self.server, event.client, "Import notes", text + more, color="yellow")


def _action_text(item: object) -> str:
    """Return a program action's fields as short text ("action close", "signal grip = True")."""
    fields = {k: v for k, v in vars(item).items() if k != "type"}
    return ", ".join(f"{k} {v}" for k, v in fields.items())


def download_of(exported: ExportedProgram, stem: str) -> tuple[str, bytes]:
    """Return (file name, bytes) to download: the one file, or a zip `stem`.zip of several."""
    if len(exported.files) == 1:
        name, text = next(iter(exported.files.items()))
        return name, text.encode()
    return f"{stem}.zip", exported.zip_bytes()
