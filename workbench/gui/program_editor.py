"""The program editor in the "Motion" tab: teach targets, edit moves, insert actions, reorder,
undo and redo. The editing is the service's (`service.program_edit.ProgramEditor`); this panel
shows the program and forwards what the user does, then shows the service's state again (a
refused edit leaves the widgets at the program in use and says why)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

import viser

from workbench.errors import InputError
from workbench.gui.fields import NumberField, format_number, parse_number
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded
from workbench.service import Workbench
from workbench.service.program_edit import ProgramEditor, editor

ADD = {"TCP linear": "linear", "TCP joint": "joint", "Joints": "joints"}
"""The "Add current" buttons: what each teaches (`ProgramEditor.add_target` kinds)."""
ACTIONS = {
    "gripper close": "gripper",
    "gripper open": "gripper",
    "set output": "set_output",
    "pulse output": "pulse_output",
    "wait for input": "wait_input",
    "wait time": "wait",
    "comment": "comment",
}
"""The "Action" choices and the program item each inserts."""
ARGUMENT_HINT = "the signal's name (output or input), the seconds to wait, or the comment's text"
NAME_DELAY = 0.6  # [s] quiet time after the last keystroke of a name before it is committed


def action_item(choice: str, argument: str) -> dict[str, Any]:
    """Return the program item of an "Action" choice with its argument (signal, seconds, text)."""
    kind = ACTIONS.get(choice)
    arg = argument.strip()
    if kind is None:
        raise InputError(f"Action: {choice!r} is not one of {', '.join(ACTIONS)}")
    if kind == "gripper":
        return {"type": "gripper", "action": choice.split()[1]}
    if kind == "wait":
        return {"type": "wait", "seconds": parse_number(arg, "wait time [s]")}
    if kind == "comment":
        return {"type": "comment", "text": arg}
    if not arg:
        raise InputError(f"{choice}: type the signal's name in 'Action argument'")
    return {"type": kind, "signal": arg}


def item_label(i: int, item: Any) -> str:
    """Return the dropdown label of item `i` ("3: pick (linear)", "4: gripper close")."""
    if item.type in ("joint", "linear"):
        return f"{i + 1}: {item.name or '-'} ({item.type})"
    return f"{i + 1}: {item.type.replace('_', ' ')} {action_text(item)}".rstrip()


def action_text(item: Any) -> str:
    """Return an action's fields as short text ("close", "grip = False", "0.5 s")."""
    if item.type == "gripper":
        return str(item.action)
    if item.type == "wait":
        return f"{format_number(item.seconds)} s"
    if item.type == "comment":
        return repr(item.text)
    if item.type == "set_output":
        return f"{item.signal} = {item.value}"
    if item.type == "pulse_output":
        return f"{item.signal} for {format_number(item.duration)} s"
    timeout = "" if item.timeout is None else f" (at most {format_number(item.timeout)} s)"
    return f"{item.signal} = {item.value}{timeout}"


def configuration(item: Any) -> str:
    """Return a move's arm configuration as shown ("front/elbow up/no flip, J6 +1 turn"): a
    pose target's stored one, "set by the next plan" before it has one, "-" for joints."""
    if item.joints is not None:
        return "-"
    conf = item.configuration
    return "set by the next plan" if conf is None else conf.label()


def table_markdown(wb: Workbench, selected: int | None) -> str:
    """Return the program as a markdown table with the last plan's durations and cycle time."""
    ed = editor(wb)
    spec = wb.project.program
    if spec is None:
        return "This project has no program: teach a target below to start one."
    try:
        times = ed.planned_times()
    except Exception as exc:  # noqa: BLE001  a plan whose program cannot be written: say so
        times, note = None, f"\n\nPlanned times unavailable: {exc}"
    else:
        note = ""
    rows = []
    for i, it in enumerate(spec.moves):
        mark = "▶ " if i == selected else ""
        d = None if times is None else times.durations[i]
        dur = "" if d is None else f"{d:.3f}"
        if it.type in ("joint", "linear"):
            unit = "%" if it.type == "joint" else "mm/s"
            zone = "fine" if it.zone == 0 else f"{format_number(it.zone)} mm"
            target = "joints" if it.joints is not None else "pose"
            rows.append(
                f"| {mark}{i + 1} | {it.name or '-'} | {it.type} ({target}) | {configuration(it)} |"
                f" {format_number(it.speed)} {unit} | {zone} | {it.wobj or 'base'} | {dur} |"
            )
        else:
            rows.append(f"| {mark}{i + 1} | | {it.type} | | {action_text(it)} | | | |")
    if times is None:
        plan_line = "Not planned yet: **Plan** to see each move's duration and the cycle time."
    elif times.stale:
        plan_line = (
            f"**Stale:** the program changed since the last plan (cycle time then"
            f" {times.cycle_time:.3f} s); **Plan** again for the durations."
        )
    else:
        plan_line = f"Cycle time **{times.cycle_time:.3f} s** (last plan)."
    return (
        f"**Program `{spec.name}`**, tool `{wb.project.tool.name}`\n\n"
        "| # | name | type | configuration | speed | zone | wobj | planned [s] |\n"
        f"|---|---|---|---|---|---|---|---|\n" + "\n".join(rows) + f"\n\n{plan_line}{note}"
    )


class ProgramEditorPanel:
    """Widgets that forward edits to the project's `ProgramEditor`; `on_changed()` after each."""

    def __init__(
        self, server: viser.ViserServer, wb: Workbench, on_changed: Callable[[], None]
    ) -> None:
        self.server, self.wb, self.on_changed = server, wb, on_changed
        self.selected: int | None = None
        self._syncing = False
        self._lock = threading.RLock()
        self._name_timer: threading.Timer | None = None
        g = server.gui
        self.folder = g.add_folder("Program editor", expand_by_default=True)
        with self.folder:
            self.item = g.add_dropdown("Item", options=("(none)",), initial_value="(none)")
            self.add = g.add_button_group("Add current", options=tuple(ADD))
            self.name = g.add_text("Name", "", hint="The target's name in the program")
            self.type = g.add_dropdown("Type", options=("joint", "linear"), initial_value="joint")
            self.speed = NumberField(
                server,
                "Move speed",
                get=lambda: self._move_field("speed", 0.0),
                put=lambda v: self._update(speed=v),
                allowed=lambda: self._allowed("speed"),
                changed=self._changed,
                hint="A joint move's % of the joints' maximum speed; a linear move's mm/s",
            )
            self.zone = NumberField(
                server,
                "Zone [mm]",
                get=lambda: self._move_field("zone", 0.0),
                put=lambda v: self._update(zone=v),
                allowed=lambda: self._allowed("zone") + ", 0 = fine (an exact stop)",
                changed=self._changed,
            )
            self.wobj = g.add_dropdown("Work object", options=("base",), initial_value="base")
            self.tool = g.add_markdown("")
            self.action = g.add_dropdown("Action", options=tuple(ACTIONS))
            self.argument = g.add_text("Action argument", "", hint=ARGUMENT_HINT)
            self.insert = g.add_button("Insert action", icon=viser.Icon.PLUS)
            self.edit = g.add_button_group("Edit", options=("Up", "Down", "Delete"))
            self.history = g.add_button_group("History", options=("Undo", "Redo"))
        self.handles: list[Removable] = [self.folder]
        self.item.on_update(guarded(server, "Program item")(self._on_item))
        self.add.on_click(guarded(server, "Add target")(self._on_add))
        self.name.on_update(guarded(server, "Name")(self._on_name))
        self.type.on_update(guarded(server, "Type")(self._on_field("type", self.type)))
        self.wobj.on_update(guarded(server, "Work object")(self._on_field("wobj", self.wobj)))
        self.insert.on_click(guarded(server, "Insert action")(self._on_insert))
        self.edit.on_click(guarded(server, "Edit program")(self._on_edit))
        self.history.on_click(guarded(server, "Undo/redo")(self._on_history))
        self.refresh()

    @property
    def editor(self) -> ProgramEditor:
        """Return the open project's editor (a new one after the project is replaced)."""
        return editor(self.wb)

    def remove(self) -> None:
        """Remove the widgets."""
        if self._name_timer is not None:
            self._name_timer.cancel()
        self.speed.remove()
        self.zone.remove()
        for h in self.handles:
            h.remove()

    # -- the service's state -> widgets -----------------------------------------------------------
    def _current(self) -> Any:
        items = self.editor.items
        if self.selected is None or not 0 <= self.selected < len(items):
            return None
        return items[self.selected]

    def _move_field(self, field: str, default: float) -> float:
        it = self._current()
        return float(getattr(it, field)) if it is not None and hasattr(it, field) else default

    def _allowed(self, field: str) -> str:
        """Return the selected move's range of `field` as the editor checks it."""
        it = self._current()
        if it is None or getattr(it, "type", "") not in ("joint", "linear"):
            return "a move's value (select a move first)"
        assert self.selected is not None
        return self.editor.allowed(self.selected, field)

    def refresh(self) -> None:
        """Show the program's items and the selected one's fields as the service has them."""
        with self._lock:
            items = self.editor.items
            if self.selected is None and items:
                self.selected = len(items) - 1
            if self.selected is not None and not items:
                self.selected = None
            elif self.selected is not None:
                self.selected = min(self.selected, len(items) - 1)
            labels = [item_label(i, it) for i, it in enumerate(items)] or ["(none)"]
            it = self._current()
            is_move = it is not None and it.type in ("joint", "linear")
            self._syncing = True
            try:
                self.item.options = tuple(labels)
                self.item.value = labels[self.selected] if self.selected is not None else labels[0]  # type: ignore[misc]
                self.name.value = it.name if is_move else ""  # type: ignore[misc]
                self.type.value = it.type if is_move else "joint"  # type: ignore[misc]
                self.wobj.options = tuple(self.editor.work_objects())
                self.wobj.value = (it.wobj or "base") if is_move else "base"  # type: ignore[misc]
            finally:
                self._syncing = False
            for w in (self.name, self.type, self.wobj, self.speed.text, self.zone.text):
                w.disabled = not is_move
            self.speed.refresh()
            self.zone.refresh()
            kind = "" if it is None or not is_move else f" · {it.type} move to its {_target(it)}"
            if is_move and it.joints is None:
                kind += f" in **{configuration(it)}**"
            self.tool.content = f"Tool: **{self.wb.project.tool.name}**{kind}"

    def _changed(self) -> None:
        self.refresh()
        self.on_changed()

    # -- widgets -> the service ---------------------------------------------------------------
    def _update(self, **fields: Any) -> None:
        if self.selected is None:
            raise InputError("select a program item first")
        self.editor.update_item(self.selected, **fields)

    def _after(self, run: Callable[[], Any]) -> None:
        """Run an edit; always show the service's state afterwards (also when it was refused)."""
        try:
            run()
        finally:
            self._changed()

    def _on_item(self, event: viser.GuiEvent) -> None:
        if self._syncing or event.client is None or self.item.value == "(none)":
            return
        self.selected = int(str(self.item.value).split(":", 1)[0]) - 1
        self._changed()

    def _on_add(self, event: viser.GuiEvent) -> None:
        kind = ADD[str(self.add.value)]
        at = None if self.selected is None else self.selected + 1  # after the selected item

        def run() -> None:
            self.selected = self.editor.add_target(kind, at)

        self._after(run)

    def _on_name(self, event: viser.GuiEvent) -> None:
        if self._syncing or event.client is None:
            return
        if self._name_timer is not None:
            self._name_timer.cancel()
        text = str(self.name.value)
        # typing fires per keystroke: commit after a pause, as one edit
        self._name_timer = threading.Timer(
            NAME_DELAY,
            guarded(self.server, "Name")(lambda _: self._commit_name(text)),
            args=(event,),
        )
        self._name_timer.daemon = True
        self._name_timer.start()

    def _commit_name(self, text: str) -> None:
        if str(self.name.value) != text:
            return  # typed on meanwhile
        it = self._current()
        if it is not None and getattr(it, "name", None) != text:
            self._after(lambda: self._update(name=text))

    def _on_field(self, field: str, handle: Any) -> Callable[[viser.GuiEvent], None]:
        def on_update(event: viser.GuiEvent) -> None:
            if self._syncing or event.client is None:
                return
            it = self._current()
            now = getattr(it, field, None) or ("base" if field == "wobj" else None)
            if it is not None and now != handle.value:
                self._after(lambda: self._update(**{field: str(handle.value)}))

        return on_update

    def _on_insert(self, event: viser.GuiEvent) -> None:
        item = action_item(str(self.action.value), str(self.argument.value))
        at = len(self.editor.items) if self.selected is None else self.selected + 1

        def run() -> None:
            self.selected = self.editor.insert_action(at, item)

        self._after(run)

    def _on_edit(self, event: viser.GuiEvent) -> None:
        if self.selected is None:
            raise InputError("select a program item first")
        op, i = str(self.edit.value), self.selected

        def run() -> None:
            if op == "Delete":
                self.editor.delete_item(i)
                self.selected = max(i - 1, 0) if self.editor.items else None
            else:
                self.selected = self.editor.move_item(i, -1 if op == "Up" else +1)

        self._after(run)

    def _on_history(self, event: viser.GuiEvent) -> None:
        op = str(self.history.value)
        self._after(self.editor.undo if op == "Undo" else self.editor.redo)


def _target(item: Any) -> str:
    return "joints" if item.joints is not None else "TCP pose"
