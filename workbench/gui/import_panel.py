"""The Project tab's "Import" folder: bring your own cell into the open project.

- **Robot**: a robot of the library (ABB, KUKA, FANUC, Universal Robots, NACHI); **Use robot**
  puts it at the project's robot base in its home posture. The dropdown shows the robot in
  use; exports default to its vendor's language.
- **Part (STEP or DXF)**: a STEP of the bent sheet-metal part, or a DXF flat pattern with its
  bend lines on the named layer; recognised into the bending section's part (stored inline,
  so the project keeps it without the file). A DXF needs the sheet thickness; a bend radius
  the file does not state comes from "Inner radius" (blank: none given). Both boxes are
  checked as typed against the project's bounds (`bending.part_import`).
- **Obstacle**: a STEP, STL, OBJ or PLY file placed in the cell at the position given; kept in
  an upload folder until a save copies it beside the project (`service.project_save`).

Every import validates the whole project first: on an error (a notification naming the field
or the face) nothing changes. The service does the work (`service.project_imports`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar

import viser

from workbench.errors import WorkbenchError
from workbench.gui import project_upload
from workbench.gui.fields import NumberField, schema_range
from workbench.gui.notify import guarded, notify
from workbench.gui.uploads import safe_name
from workbench.service.project_imports import (
    PartImportSpec,
    Pose,
    add_cell_file,
    import_bending_part,
    import_settings,
    obstacle_coordinate,
    robot_choices,
    use_robot,
)

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp

T = TypeVar("T")


class ImportPanel:
    """Robot, part and obstacle imports; each rebuilds the tabs on the new project."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        s = self.server = app.server
        g = s.gui
        self.choices = robot_choices()
        with g.add_folder("Import", expand_by_default=True):
            labels = tuple(c.label for c in self.choices)
            self.robot = g.add_dropdown("Robot", options=labels, initial_value=labels[0])
            self.use = g.add_button("Use robot", hint="the library robot at the same base")
            # The next part import's settings (bending.part_import's fields, mm): checked by
            # the project's bounds as they are typed; a blank box is "not given".
            self.numbers: dict[str, float] = {}
            self.bend_layer = "BEND"
            self.fields = [
                self._field("Sheet thickness [mm]", "thickness", "a DXF's (a STEP states its own)"),
                self._field("Inner radius [mm]", "inner_radius", "for bends the file gives none"),
            ]
            self.layer = g.add_text("Bend layer (DXF)", initial_value="BEND")
            self.layer.on_update(self._on_layer)
            self.part = g.add_upload_button(
                "Import part (STEP or DXF)",
                icon=viser.Icon.UPLOAD,
                hint="a STEP of the bent part, or a DXF flat pattern with its bend lines",
            )
            # three strict boxes (viser's vector box reads "12,5" as 125: fields.py)
            self.at_mm = [800.0, 0.0, 0.0]
            self.at_fields = [self._at_field(i, axis) for i, axis in enumerate("xyz")]
            self.obstacle = g.add_upload_button(
                "Import obstacle", icon=viser.Icon.UPLOAD, hint="a STEP, STL, OBJ or PLY file"
            )
            self.info = g.add_markdown("")
        self.use.on_click(guarded(s, "Use robot")(self._on_use_robot))
        self.part.on_upload(guarded(s, "Import part")(self._on_part))
        self.obstacle.on_upload(guarded(s, "Import obstacle")(self._on_obstacle))
        self.refresh()

    def refresh(self) -> None:
        """Show the robot in use in the dropdown and say what it is."""
        robot = self.app.wb.project.robot
        names = [c.name for c in self.choices]
        if robot.preset in names:
            choice = self.choices[names.index(robot.preset)]
            self.robot.value = choice.label  # type: ignore[misc]
            self.info.content = (
                f"Robot in use: **{choice.title}** (exports default to {choice.program_format})"
            )
        else:
            kind = "DH rows" if robot.dh is not None else "a URDF"
            self.info.content = f"Robot in use: **{robot.name}** ({kind}: no vendor)"

    def _field(self, label: str, key: str, hint: str) -> NumberField:
        def put(value: float | None) -> None:
            given = {k: v for k, v in self.numbers.items() if k != key}
            if value is not None:
                given[key] = value
            import_settings(dict(given), "part.dxf")  # raises naming part_import.<key>
            self.numbers = given

        return NumberField(
            self.server,
            label,
            get=lambda: self.numbers.get(key),
            put=put,
            allowed=lambda: "blank (not given) or " + schema_range(PartImportSpec(), key, "mm"),
            clear=lambda: put(None),
            hint=hint,
        )

    def _at_field(self, i: int, axis: str) -> NumberField:
        def put(v: float) -> None:
            self.at_mm[i] = obstacle_coordinate(i, v)

        return NumberField(
            self.server,
            f"Obstacle at {axis} [mm]",
            get=lambda: self.at_mm[i],
            put=put,
            allowed=lambda: schema_range(Pose(), "xyz", "mm"),
            decimals=2,
            hint=f"{axis} of the next imported obstacle's position in the world [mm]",
        )

    def settings(self) -> dict[str, float | str]:
        """Return the next part import's settings (`bending.part_import`'s fields, mm)."""
        return {**self.numbers, "bend_layer": self.bend_layer}

    def _on_layer(self, event: viser.GuiEvent) -> None:
        try:
            import_settings({"bend_layer": str(self.layer.value)}, "part.dxf")
            self.bend_layer = str(self.layer.value)
        except WorkbenchError as exc:
            notify(self.server, event.client, "Bend layer (DXF): refused", str(exc))
        finally:
            self.layer.value = self.bend_layer  # type: ignore[misc]  # the value in use

    def _choice(self) -> str:
        labels = [c.label for c in self.choices]
        return self.choices[labels.index(str(self.robot.value))].name

    def _apply(self, what: str, work: Callable[[], T], event: viser.GuiEvent, done: str) -> T:
        """Run `work` as the session's job and rebuild the tabs on its project; return its result.

        A refused import changes nothing; either way the panel shows what is in use.
        """
        try:
            with self.app.jobs.job(what):
                result = work()
                self.app.rebuild()
        finally:
            self.refresh()  # a refused robot: the dropdown shows the one still in use
        notify(self.server, event.client, "Imported", done, color="green")
        return result

    def _on_use_robot(self, event: viser.GuiEvent) -> None:
        name = self._choice()
        self._apply(
            "changing the robot", lambda: use_robot(self.app.wb, name), event, f"robot {name}"
        )

    def _on_part(self, event: viser.GuiEvent) -> None:
        up = self.part.value
        name = safe_name(up.name, "part.step")
        summary = self._apply(
            "importing a part",
            lambda: import_bending_part(self.app.wb, name, up.content, self.settings()),
            event,
            name,
        )
        self.info.content = f"Part **{name}**: {summary}"

    def _on_obstacle(self, event: viser.GuiEvent) -> None:
        up = self.obstacle.value
        name = safe_name(up.name, "obstacle.step")
        folder = project_upload.new_folder()
        path = folder / name
        path.write_bytes(up.content)
        wb = self.app.wb
        try:
            wb.folders = wb.folders.with_session(folder)
            xyz = list(self.at_mm)
            added = self._apply(
                "importing an obstacle",
                lambda: add_cell_file(wb, path, xyz_mm=xyz),
                event,
                name,
            )
        except BaseException:
            wb.folders = wb.folders.without(folder)
            project_upload.remove_folder(folder)
            raise
        self.info.content = f"Obstacle **{added}** from `{name}` in the cell"
