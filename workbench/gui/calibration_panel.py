"""The Project tab's "Calibration" folder: readings measured on the real robot -> tool, work
object or robot base as built, shown in the 3D view, applied with undo.

- **Calibrate**: the tool's TCP, a work object (named; `3point`: origin, x, y; `fit`: points
  to known positions) or the robot's base in the cell (points to known positions).
- **Readings** and **Known points**: CSV pasted into the box or uploaded into it
  (`label,j1..j6` [deg, controller] or `label,x,y,z` [mm, robot base]; docs/calibration.md).
- **Compute** runs the service's calibration (`wb.calibration`): its summary (mean and max
  error) in the panel; the measured points labelled with their residuals and the fitted
  frame in the 3D view (`fit_marks.py`). Nothing changes in the project yet.
- **Apply** puts the result into the project (`wb.calibration.apply`), rebuilds the tabs and
  shows the value now in use; **Undo** puts the project before it back (`project_undo.py`).

Every error is a notification naming the field and the fix; a refused computation keeps the
last result (and its marks) as they were.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import viser

from workbench.errors import InputError
from workbench.gui.csv_box import CsvBox
from workbench.gui.fit_marks import FitMarks
from workbench.gui.notify import guarded, notify

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp

KINDS = {"Tool (TCP)": "tcp", "Work object": "work_object", "Robot base": "base"}
METHODS = ("3point", "fit")
READINGS_HINT = "label,j1,j2,j3,j4,j5,j6 [deg, controller] or label,x,y,z [mm, robot base]"
FRAME_NAMES = {"tcp": "TCP of {}", "work_object": "{}", "base": "base of {}"}
KNOWN_HINT = "label,x,y,z [mm]: where each measured point is on the part or in the cell"


def _fmt(values: Any) -> str:
    return ", ".join(f"{float(v):.2f}" for v in values)


class CalibrationPanel:
    """Readings in, a calibration result shown, applied and undone (see the module doc)."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        s = self.server = app.server
        g = s.gui
        self.result: Any = None
        self.basis: Any = None  # the project the result was computed on
        self.marks = FitMarks(s)
        with g.add_folder("Calibration", expand_by_default=False):
            labels = tuple(KINDS)
            self.kind = g.add_dropdown("Calibrate", options=labels, initial_value=labels[0])
            self.name = g.add_text("Work object name", initial_value="", hint="new or existing")
            self.method = g.add_dropdown("Method", options=METHODS, initial_value=METHODS[0])
            self.readings = CsvBox(s, "Readings (CSV)", "label,j1,j2,j3,j4,j5,j6\n", READINGS_HINT)
            # in a folder of its own: viser 1.1.1's upload button ignores `visible`, a folder not
            self.known_folder = g.add_folder("Known points", expand_by_default=True)
            with self.known_folder:
                self.known = CsvBox(s, "Known points (CSV)", "label,x,y,z\n", KNOWN_HINT)
            self.compute = g.add_button("Compute", hint="fit the readings; the project stays")
            self.summary = g.add_markdown("")
            self.apply = g.add_button("Apply to project", disabled=True)
            self.undo = g.add_button("Undo", disabled=True)
            self.in_use = g.add_markdown("")
        self.kind.on_update(lambda _: self._layout())
        self.method.on_update(lambda _: self._layout())
        self.compute.on_click(guarded(s, "Calibration")(self._on_compute))
        self.apply.on_click(guarded(s, "Apply calibration")(self._on_apply))
        self.undo.on_click(guarded(s, "Undo")(self._on_undo))
        app.undo.listeners.append(self.refresh)
        self._layout()
        self.refresh()

    @property
    def wb(self):  # type: ignore[no-untyped-def]  # the app's workbench (one per server)
        return self.app.wb

    def _what(self) -> str:
        return KINDS[str(self.kind.value)]

    def _layout(self) -> None:
        what = self._what()
        self.name.visible = self.method.visible = what == "work_object"
        self.known_folder.visible = what == "base" or (
            what == "work_object" and self.method.value == "fit"
        )

    def refresh(self) -> None:
        """Show the values in use (tool TCP, work objects, robot base) and the undo's target."""
        p = self.wb.project
        lines = [
            f"Tool **{p.tool.name}** TCP [mm, deg]: xyz ({_fmt(p.tool.tcp.xyz)}),"
            f" rpy ({_fmt(p.tool.tcp.rpy)})",
            f"Robot base [mm, deg]: xyz ({_fmt(p.robot.base.xyz)}), rpy ({_fmt(p.robot.base.rpy)})",
        ]
        for w in p.work_objects or ():
            lines.append(
                f"Work object **{w.name}** [mm, deg]: xyz ({_fmt(w.pose.xyz)}),"
                f" rpy ({_fmt(w.pose.rpy)})"
            )
        self.in_use.content = "In use:  \n" + "  \n".join(lines)
        last = self.app.undo.last
        self.undo.disabled = last is None
        self.undo.label = f"Undo {last}" if last else "Undo"

    # -- compute --------------------------------------------------------------------------
    def _on_compute(self, event: viser.GuiEvent) -> None:
        cal = self.wb.calibration
        readings, what = self.readings.text, self._what()
        boxes = {"source": self.readings.label}
        if what == "tcp":
            result = cal.tcp(readings, **boxes)
        elif what == "work_object":
            name = str(self.name.value).strip()
            if not name:
                raise InputError(
                    "type the work object's name (a new one is added)", field=self.name.label
                )
            fit = self.method.value == "fit"
            result = cal.work_object(
                readings,
                name=name,
                method=str(self.method.value),
                known_csv=self.known.text if fit else None,
                known_source=self.known.label,
                **boxes,
            )
        else:
            result = cal.base(
                readings, known_csv=self.known.text, known_source=self.known.label, **boxes
            )
        self.result, self.basis = result, self.wb.project
        self.summary.content = "  \n".join(result.summary().splitlines())  # lines that wrap
        self.apply.disabled = False
        self.marks.show(
            dict(zip(result.labels, result.points_world, strict=True)),
            frame=result.T_world_frame,
            frame_name=FRAME_NAMES[result.kind].format(result.name),
            residuals_m=result.residual_by_label,
            outliers=result.dropped,
        )

    # -- apply and undo -------------------------------------------------------------------
    def _on_apply(self, event: viser.GuiEvent) -> None:
        result = self.result
        if result is None:
            raise InputError("nothing computed yet; paste the readings and press Compute")
        if self.wb.project is not self.basis:
            raise InputError(
                "the project changed since Compute (another apply, an import or a load); press"
                " Compute again",
                field="Apply to project",
            )
        with self.app.jobs.job("applying a calibration"):
            previous = self.wb.calibration.apply(result)
            what = "calibration: " + FRAME_NAMES[result.kind].format(result.name)
            self.app.undo.push(what, previous)
            self.app.rebuild()
        self.result = None
        self.apply.disabled = True
        notify(self.server, event.client, "Calibration applied", what, color="green")

    def _on_undo(self, event: viser.GuiEvent) -> None:
        what = self.app.undo_last()
        notify(self.server, event.client, "Undone", what, color="green")

    def clear(self) -> None:
        """Forget the result and take its marks down (another project was opened)."""
        self.result = self.basis = None
        self.summary.content = ""
        self.apply.disabled = True
        self.marks.clear()
