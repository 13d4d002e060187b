"""The "Motion" tab: the program table and its editor, plan the program, see the checks, export
robot programs; the last plan's TCP path in 3D."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import viser

from workbench.gui import jobs
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded, notify
from workbench.gui.program_download import ProgramDownload
from workbench.gui.program_editor import ProgramEditorPanel, table_markdown
from workbench.gui.progress import busy
from workbench.gui.timeline import Timeline
from workbench.service import Workbench
from workbench.service.program_import import program_files


class MotionPanel:
    """The program table and editor, Plan with progress, the plan's summary, program export.

    `scene` (the `RobotScene`, optional) draws the last plan's TCP path and lets the TCP
    gizmo follow its playback."""

    def __init__(
        self,
        server: viser.ViserServer,
        wb: Workbench,
        timeline: Timeline,
        on_replaced: Callable[[], None] = lambda: None,
        scene: Any = None,
    ) -> None:
        self.server, self.wb, self.timeline = server, wb, timeline
        self.on_replaced = on_replaced
        self.scene = scene
        g = server.gui
        self.program = g.add_markdown("")
        self.editor = ProgramEditorPanel(server, wb, on_changed=self.refresh)
        self.plan_button = g.add_button("Plan", icon=viser.Icon.ROUTE)
        self.progress = g.add_progress_bar(0.0, visible=False, animated=True)
        self.result = g.add_markdown("")
        self.export = ProgramDownload(
            server,
            lambda: self.wb,
            "motion",
            stem=lambda: f"{self.wb.project.program.name}_{self.format.value}",  # type: ignore[union-attr]
            after=lambda _: self.refresh(),  # a stale plan was planned again for the export
        )
        self.format, self.download = self.export.format, self.export.button
        self.upload = g.add_upload_button(
            "Import program",
            icon=viser.Icon.UPLOAD,
            hint="A RAPID .mod, a KRL .zip of .src + .dat, a FANUC .ls, a URScript .script or a"
            " NACHI program: it replaces the project's program",
        )
        self.upload.on_upload(guarded(server, "Import program")(self._on_import))
        self.plan_button.on_click(guarded(server, "Plan")(self._on_plan))
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
        self.editor.remove()
        for h in self.handles:
            h.remove()

    def refresh(self) -> None:
        """Show the project's program with the last plan's durations (stale after an edit)."""
        if not hasattr(self, "plan_button"):
            return  # the editor's first refresh, before the panel is complete
        self.program.content = table_markdown(self.wb, self.editor.selected)
        self.plan_button.disabled = self.wb.project.program is None

    def _on_plan(self, event: viser.GuiEvent) -> None:
        with busy(
            self.progress, [self.plan_button], self.result, what="planning motion"
        ) as progress:
            plan = self.wb.plan_motion(progress=progress)
        self.result.content = ("**OK:** " if plan.ok else "**Problems:** ") + plan.summary()
        self.download.disabled = False
        self.refresh()
        if self.scene is not None:
            self.scene.show_plan(plan.samples)  # the TCP path; the gizmo follows its playback
        self.timeline.load(
            plan.samples,
            robot=self.wb.robot,
        )

    def _on_import(self, event: viser.GuiEvent) -> None:
        up = self.upload.value
        # a job like a plan: refused (Busy) while another runs, nothing changed then
        with jobs.of(self.server).job("importing a program"):
            notes = self.wb.import_program(program_files(up.name, up.content))
            self.on_replaced()  # the program, tool and work objects changed: rebuild the tabs
        body = f"{up.name}: {len(self.wb.project.program.moves)} items"  # type: ignore[union-attr]
        notify(self.server, event.client, "Program imported", body, color="green")
        if notes:  # lines the reader did not understand, values taken differently: stay open
            text = "\n".join(f"- {n}" for n in notes[:20])
            more = f"\n- … and {len(notes) - 20} more" if len(notes) > 20 else ""
            notify(self.server, event.client, "Import notes", text + more, color="yellow")
