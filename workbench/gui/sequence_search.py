"""The Bending tab's "Find sequences" folder (projects with a press brake): the ranked search
of bend order, grasps and tool stations (`wb.bending.find_sequences`) as the session's job,
with a Cancel button; its table, rejected branches and figures; "Use plan" puts the chosen
plan into the project (`wb.bending.use_plan`) and plans its cycle."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import viser

from workbench.errors import InputError, WorkbenchError
from workbench.gui.fields import NumberField, format_number
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded, notify
from workbench.gui.progress import busy

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp
    from workbench.service.bending import BendingResult, SearchResult, SequencePlan

ENGINES = ("serial", "ray")
MAX_TIME_LIMIT = 3600.0  # [s] the longest search the box takes
REJECTED_SHOWN = 5  # rejected branches listed under the table
NO_PLAN = "(none)"  # the Plan dropdown before a search found one


def _cell(text: str) -> str:
    """Return `text` safe inside a markdown table cell."""
    return text.replace("|", "\\|").replace("\n", " ")


def sequence_text(names: tuple[str, ...] | list[str]) -> str:
    """Return bend names as the Sequence box writes them ('bB,bA')."""
    return ",".join(names)


def results_table(result: SearchResult) -> str:
    """Return the ranked plans as a markdown table (a line saying none when there is none)."""
    if not result.plans:
        return "**No feasible sequence.**"
    rows = [
        "| Rank | Sequence | Regrips | Flips | Cycle time [s] | Verified |",
        "|---:|---|---:|---:|---:|---|",
    ]
    for rank, p in enumerate(result.plans, 1):
        time_s = f"{p.cycle_time:.1f}" + (" (estimate)" if p.estimated else "")
        rows.append(
            f"| {rank} | {_cell(sequence_text(p.sequence))} | {p.regrips} | {p.flips} "
            f"| {time_s} | {'yes' if p.verified else 'no'} |"
        )
    return "\n".join(rows)


def rejected_text(result: SearchResult) -> str:
    """Return the note and the first rejected branches (markdown lines)."""
    lines = [f"*{result.note.strip()}*"] if result.note.strip() else []
    if result.rejected:
        lines.append(f"Rejected branches ({len(result.rejected)}), the first:")
        lines += [
            f"- **{_cell(', '.join(prefix))}**: {_cell(reason)}"
            for prefix, reason in result.rejected[:REJECTED_SHOWN]
        ]
    return "\n".join(lines)


def plan_detail(plan: SequencePlan) -> str:
    """Return each bend of `plan` with its grasp, station and the part's orientation (markdown)."""
    return "\n".join(
        f"- **{_cell(b)}**: {_cell(g)}, station {_cell(s)}, {_cell(o)}"
        for b, g, s, o in zip(
            plan.sequence, plan.grasp_labels(), plan.stations, plan.orientations, strict=True
        )
    )


class SequenceSearch:
    """The "Find sequences" folder; `on_used()` after a plan is put into the project (the
    panel shows the new sequence), `on_planned(plan)` with its cycle (summary, timeline)."""

    def __init__(
        self,
        app: WorkbenchApp,
        *,
        on_used: Callable[[], None],
        on_planned: Callable[[BendingResult], None],
    ) -> None:
        self.app = app
        self.server = s = app.server
        self.on_used, self.on_planned = on_used, on_planned
        self._time_limit: float | None = None  # [s] None: no limit
        self._cancel = threading.Event()
        self.result: SearchResult | None = None
        self._by_label: dict[str, SequencePlan] = {}
        g = s.gui
        self.folder = g.add_folder("Find sequences")
        with self.folder:
            self.engine = g.add_dropdown(
                "Engine",
                options=ENGINES,
                initial_value=ENGINES[0],
                hint="serial: in this process; ray: a local Ray started for the search",
            )
            self.limit_field = NumberField(
                s,
                "Time limit [s]",
                get=lambda: self._time_limit,
                put=self._set_limit,
                clear=self._clear_limit,
                allowed=lambda: f"(0, {format_number(MAX_TIME_LIMIT)}] s, or empty for none",
                hint="empty: search to the end; else the best plans found by then",
                decimals=1,
            )
            self.find = g.add_button("Find sequences", icon=viser.Icon.SEARCH)
            self.cancel = g.add_button(
                "Cancel search", icon=viser.Icon.PLAYER_STOP, color="red", visible=False
            )
            self.progress = g.add_progress_bar(0.0, visible=False, animated=True)
            self.status = g.add_markdown("")
            self.table = g.add_markdown("")
            self.rejected = g.add_markdown("")
            self.choice = g.add_dropdown("Plan", options=(NO_PLAN,), disabled=True)
            self.detail = g.add_markdown("")
            self.use = g.add_button("Use plan", icon=viser.Icon.CHECK, disabled=True)
        self.handles: list[Removable] = [
            self.engine,  # the time limit's widgets go with `limit_field.remove` (its timer too)
            self.find,
            self.cancel,
            self.progress,
            self.status,
            self.table,
            self.rejected,
            self.choice,
            self.detail,
            self.use,
        ]
        self.find.on_click(guarded(s, "Find sequences")(self._on_find))
        self.cancel.on_click(guarded(s, "Cancel search")(self._on_cancel))
        self.choice.on_update(guarded(s, "Plan")(lambda _: self._show_detail()))
        self.use.on_click(guarded(s, "Use plan")(self._on_use))

    def remove(self) -> None:
        """Remove the folder and its widgets (a running search is told to stop)."""
        self._cancel.set()
        self.limit_field.remove()
        for h in self.handles:
            h.remove()
        self.folder.remove()
        self.handles.clear()

    # -- the time limit -----------------------------------------------------------------
    @property
    def time_limit(self) -> float | None:
        """Return the search's time limit [s] (None: none)."""
        return self._time_limit

    def _set_limit(self, v: float) -> None:
        if not 0.0 < v <= MAX_TIME_LIMIT:
            raise InputError(
                f"Time limit [s]: {format_number(v)} s is outside (0, "
                f"{format_number(MAX_TIME_LIMIT)}] s; leave the box empty for no limit"
            )
        self._time_limit = v

    def _clear_limit(self) -> None:
        self._time_limit = None

    # -- callbacks ------------------------------------------------------------------------
    @property
    def _buttons(self) -> list[Any]:
        return [self.find, self.use, self.choice, self.engine, self.limit_field.text]

    def _on_find(self, event: viser.GuiEvent) -> None:
        svc = self.app.wb.bending
        self._cancel.clear()
        try:
            with busy(
                self.progress,
                self._buttons,
                self.status,
                verb="Searching",
                what="finding bend sequences",
            ) as progress:
                self.cancel.visible = True
                try:
                    result = svc.find_sequences(
                        engine=str(self.engine.value),
                        time_limit=self._time_limit,
                        progress=progress,
                        cancel=self._cancel.is_set,
                    )
                except WorkbenchError as exc:
                    self.status.content = f"**Cannot search:** {exc}"
                    raise
                finally:
                    self.cancel.visible = False
        finally:
            self._show_detail()  # the job re-enabled Plan and Use plan: only with a plan
        self.show(result)
        if event.client is not None:
            found = len(result.plans)
            notify(
                self.server,
                event.client,
                "Find sequences",
                f"{found} plan(s) found." if found else "No feasible sequence: see the reasons.",
                color="green" if found else "yellow",
            )

    def _on_cancel(self, event: viser.GuiEvent) -> None:
        self._cancel.set()
        self.status.content = "Cancelling: the plans found so far come back shortly."

    def show(self, result: SearchResult) -> None:
        """Show a search's result: table, rejected branches, figures, and the Plan choice."""
        self.result = result
        self.table.content = results_table(result)
        self.rejected.content = rejected_text(result)
        self.status.content = result.stats.describe()
        self._by_label = {
            f"{rank}: {sequence_text(p.sequence)}": p for rank, p in enumerate(result.plans, 1)
        }
        labels = tuple(self._by_label) or (NO_PLAN,)
        self.choice.options = labels
        self.choice.value = labels[0]  # type: ignore[misc]
        self._show_detail()

    def _chosen(self) -> SequencePlan | None:
        return self._by_label.get(str(self.choice.value))

    def _show_detail(self) -> None:
        plan = self._chosen()
        self.detail.content = "" if plan is None else plan_detail(plan)
        self.use.disabled = plan is None
        self.choice.disabled = plan is None

    def _on_use(self, event: viser.GuiEvent) -> None:
        plan = self._chosen()
        if plan is None:
            raise InputError("Use plan: no plan to use; press Find sequences first")
        svc = self.app.wb.bending
        label = str(self.choice.value)
        try:
            with busy(
                self.progress,
                self._buttons,
                self.status,
                verb="Planning",
                what="planning the bending cycle",
            ) as progress:
                svc.use_plan(plan)
                self.on_used()
                try:
                    cycle = svc.plan(progress=progress)
                except WorkbenchError as exc:
                    self.status.content = f"Plan {label} is in use; its cycle: **{exc}**"
                    raise
        finally:
            self._show_detail()  # the job re-enabled Plan and Use plan
        self.status.content = f"Plan {label} is in use; its cycle is planned (summary below)."
        self.on_planned(cycle)
