"""The "Polishing" tab: workpiece upload, fitted surface, path planning, force-control simulation."""

from __future__ import annotations

import functools
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import viser
import viser.uplot as uplot
from numpy.typing import NDArray

from workbench.errors import InputError, WorkbenchError
from workbench.gui.fields import NumberField, format_number, schema_range
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded, notify
from workbench.gui.polishing_faces import FacesChecklist
from workbench.gui.program_download import ProgramDownload
from workbench.gui.progress import busy
from workbench.gui.uploads import WORKPIECES, safe_name
from workbench.service.polishing import PolishingPath, PolishingSimulation

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp

MM = 1e-3
SURFACE_COLOR = (120, 170, 220)
SOLID_COLOR = (150, 150, 150)  # the rest of a STEP solid whose faces are polished
PATH_COLOR = (30, 60, 200)
AXIS_COLOR = (240, 140, 20)
LEAD_IN_COLOR = (20, 170, 60)
LEAD_OUT_COLOR = (200, 30, 160)
GAP_COLOR = (220, 30, 30)
#: Most tool axes drawn along a path, and most samples sent per plot series.
MAX_AXES = 250
MAX_PLOT_POINTS = 4000
MESH_TYPES = (".stl", ".obj", ".ply", ".step", ".stp")


def _segments(points: NDArray[np.float64]) -> NDArray[np.float32]:
    return np.stack([points[:-1], points[1:]], axis=1).astype(np.float32)


def _stride(n: int) -> int:
    return max(1, int(np.ceil(n / MAX_PLOT_POINTS)))


class PolishingPanel:
    """Controls of the polishing workflow; built inside its tab, removed when the project changes."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        self.server = app.server
        self.handles: list[Removable] = []
        self.nodes: dict[str, Removable] = {}
        self.plots: list[Removable] = []
        self.fields: list[NumberField] = []
        self._motion: Any = None  # the samples this tab put on the timeline
        g = app.server.gui
        if app.wb.project.polishing is None:
            self.handles.append(g.add_markdown("This project has no `polishing` section."))
            return
        self.svc = app.wb.polishing
        spec = self.svc.spec
        # The parent of the tab's scene nodes, made explicitly so `remove` can remove it.
        self.root: Removable | None = app.server.scene.add_frame("/polishing", show_axes=False)
        guard = guarded(app.server, "Polishing")
        self.workpiece_info = g.add_markdown("")
        self.upload = g.add_upload_button(
            "Upload workpiece", icon=viser.Icon.UPLOAD, mime_type=",".join(MESH_TYPES)
        )
        self.units = g.add_dropdown(
            "Units", options=self.svc.mesh_units, initial_value=spec.units, hint="of the mesh file"
        )
        # A STEP solid's faces to polish (none listed for a mesh file).
        self.faces = FacesChecklist(app.server, self.svc, guard, self._on_faces)
        self.pattern = g.add_dropdown(
            "Pattern", options=self.svc.patterns, initial_value=spec.pattern
        )
        # Path and process values: typed, set through the service, shown from its section.
        s = app.server
        self.fields = [
            NumberField(
                s,
                "Step [mm]",
                get=lambda: float(self.svc.spec.step),
                put=lambda v: self.svc.set_parameters(step=v * MM),
                allowed=lambda: (
                    schema_range(self.svc.spec, "step", "mm") + ", below the workpiece's size"
                ),
                changed=self._clear_results,
            ),
            NumberField(
                s,
                "Spacing [mm]",
                get=lambda: float(self.svc.spec.spacing),
                put=lambda v: self.svc.set_parameters(spacing=v * MM),
                allowed=lambda: (
                    schema_range(self.svc.spec, "spacing", "mm") + ", below the workpiece's size"
                ),
                changed=self._clear_results,
            ),
            NumberField(
                s,
                "Force [N]",
                get=lambda: float(self.svc.spec.force),
                put=lambda v: self.svc.set_parameters(force=v),
                allowed=lambda: (
                    f"[0.001, {format_number(self.svc.spec.max_force)}] N (the tool's max_force)"
                ),
                changed=self._clear_results,
            ),
            NumberField(
                s,
                "Feed [mm/s]",
                get=lambda: float(self.svc.spec.feed),
                put=lambda v: self.svc.set_parameters(feed=v * MM),
                allowed=lambda: (
                    schema_range(self.svc.spec, "feed", "mm/s")
                    + f", at most the controller's {format_number(self.svc.spec.controller.max_speed)}"
                    " mm/s"
                ),
                changed=self._clear_results,
            ),
        ]
        self.step, self.spacing, self.force, self.feed = (f.text for f in self.fields)
        self.plan_button = g.add_button("Plan path", icon=viser.Icon.ROUTE)
        self.sim_button = g.add_button("Simulate", icon=viser.Icon.PLAYER_PLAY, disabled=True)
        self.progress = g.add_progress_bar(0.0, visible=False, animated=True)
        self.path_info = g.add_markdown("")
        self.sim_info = g.add_markdown("")
        self.export = ProgramDownload(app.server, lambda: self.app.wb, "polishing")
        self.format, self.download = self.export.format, self.export.button
        self.plot_folder = g.add_folder("Force control", expand_by_default=True)
        self.handles += [
            self.workpiece_info,
            self.upload,
            self.units,
            self.pattern,
            self.plan_button,
            self.sim_button,
            self.progress,
            self.path_info,
            self.sim_info,
            self.format,
            self.download,
            self.plot_folder,
        ]
        self.upload.on_upload(guard(self._on_upload))
        self.pattern.on_update(guard(self._on_parameter))
        self.plan_button.on_click(guard(self._on_plan))
        self.sim_button.on_click(guard(self._on_simulate))
        try:
            self.svc.load_workpiece()
        except WorkbenchError as exc:
            self.workpiece_info.content = f"**Workpiece not loaded:** {exc}"
            self.plan_button.disabled = True
            return
        self._show_workpiece()

    # -- scene ---------------------------------------------------------------------------
    def _set_node(self, name: str, make: Callable[[], Removable] | None) -> None:
        # Remove the old node first: viser replaces a node of the same name, and removing
        # the old handle afterwards would remove the new node.
        old = self.nodes.pop(name, None)
        if old is not None:
            old.remove()
        if make is not None:
            self.nodes[name] = make()

    def _clear_path_nodes(self) -> None:
        for name in ("path", "leads_in", "leads_out", "axes", "gaps"):
            self._set_node(name, None)

    def _show_workpiece(self) -> None:
        rep = self.svc.report
        warn = "; ".join(rep.warnings) if rep.warnings else "no defects found"
        self.workpiece_info.content = (
            f"**Workpiece** `{Path(rep.path).name}` ({rep.units}): {rep.n_faces} triangles, "
            f"diagonal {rep.bbox_diagonal / MM:.0f} mm, {rep.n_holes} holes, "
            f"{rep.n_nonmanifold_edges} non-manifold edges; {warn}."
        )
        vertices, faces = self.svc.surface_mesh()
        self._set_node(
            "surface",
            lambda: self.server.scene.add_mesh_simple(
                "/polishing/surface",
                vertices.astype(np.float32),
                faces.astype(np.uint32),
                color=SURFACE_COLOR,
                side="double",
                cast_shadow=False,
                receive_shadow=False,
            ),
        )
        solid = self.svc.solid_mesh()  # a STEP solid: drawn whole, the picked faces over it
        self._set_node(
            "solid",
            None
            if solid is None
            else lambda: self.server.scene.add_mesh_simple(
                "/polishing/solid",
                solid[0].astype(np.float32),
                solid[1].astype(np.uint32),
                color=SOLID_COLOR,
                opacity=0.6,
                cast_shadow=False,
                receive_shadow=False,
            ),
        )
        self._clear_path_nodes()

    def _show_path(self, pp: PolishingPath) -> None:
        p = pp.path
        scene = self.server.scene
        proc = p.points[p.is_process]
        self._set_node(
            "path",
            lambda: scene.add_line_segments(
                "/polishing/path", _segments(proc), PATH_COLOR, thickness=0.0015
            ),
        )
        for name, mask, color in (
            ("leads_in", p.is_lead_in, LEAD_IN_COLOR),
            ("leads_out", p.is_lead_out, LEAD_OUT_COLOR),
        ):
            self._set_node(
                name,
                functools.partial(
                    scene.add_point_cloud,
                    f"/polishing/{name}",
                    p.points[mask].astype(np.float32),
                    color,
                    point_size=0.008,
                    point_shape="circle",
                ),
            )
        idx = np.flatnonzero(p.is_process)[:: max(1, int(p.is_process.sum()) // MAX_AXES)]
        base = p.points[idx]
        tip = base - 0.03 * p.tool_z[idx]  # the tool axis, drawn 30 mm above the surface
        self._set_node(
            "axes",
            lambda: scene.add_line_segments(
                "/polishing/axes",
                np.stack([tip, base], axis=1).astype(np.float32),
                AXIS_COLOR,
                thickness=0.001,
            ),
        )
        cov = pp.coverage
        gaps = cov.samples[cov.distance > cov.tool_radius]
        self._set_node(
            "gaps",
            lambda: scene.add_point_cloud(
                "/polishing/gaps",
                gaps.astype(np.float32) if len(gaps) else np.zeros((1, 3), np.float32),
                GAP_COLOR,
                point_size=0.003,
                visible=bool(len(gaps)),
            ),
        )

    # -- callbacks -----------------------------------------------------------------------
    def _on_upload(self, event: viser.GuiEvent) -> None:
        up = self.upload.value
        name = safe_name(up.name, "workpiece.stl")
        if Path(name).suffix.lower() not in MESH_TYPES:
            raise InputError(
                f"workpiece {name!r}: give an STL, OBJ, PLY or STEP file (the face to polish)"
            )
        picked = None
        with WORKPIECES.new_file(self.app.wb, name, up.content) as path:
            try:
                self.svc.load_workpiece(path, units=str(self.units.value))
            except WorkbenchError as exc:
                if exc.field != "polishing.faces":
                    raise
                picked = self.svc.suggested_faces(path)  # a closed solid: a first pick
                self.svc.set_faces(picked, path)
        self.faces.rebuild()
        if picked is not None:
            notify(
                self.server,
                event.client,
                "Polishing",
                f"{name} is a solid: face {picked[0]} (its largest) is picked; tick the faces"
                " to polish under Faces to polish",
                color="blue",
            )
        self._show_workpiece()
        self.path_info.content = ""
        self.sim_info.content = ""
        self.sim_button.disabled = True
        self.download.disabled = True

    def _on_faces(self) -> None:
        """The service took new faces to polish: show the new surface, drop old results."""
        self._show_workpiece()
        self._clear_results()
        self.plan_button.disabled = False

    def _on_parameter(self, event: viser.GuiEvent) -> None:
        if event.client is None:
            return
        try:
            self.svc.set_parameters(pattern=str(self.pattern.value))
        finally:
            self.pattern.value = self.svc.spec.pattern  # type: ignore[misc]  # the value in use
        self._clear_results()

    def _clear_results(self) -> None:
        """Drop what no longer matches the parameters: path, plots, summaries, the timeline's motion."""
        self._clear_path_nodes()
        for p in self.plots:
            p.remove()
        self.plots = []
        self.path_info.content = ""
        self.sim_info.content = ""
        self.sim_button.disabled = True
        self.download.disabled = True
        if self._motion is not None and self.app.timeline.motion is self._motion:
            self.app.timeline.clear()
        self._motion = None

    def _on_plan(self, event: viser.GuiEvent) -> None:
        buttons = [self.plan_button, self.sim_button]
        with busy(self.progress, buttons, what="planning the polishing path") as progress:
            pp = self.svc.plan_path(progress=progress)
        self._show_path(pp)
        self.path_info.content = (
            f"**Path** {pp.summary()}. Lead-in points green, lead-out magenta, tool axes "
            "orange, uncovered surface red."
        )
        self.sim_info.content = ""
        self.sim_button.disabled = False

    def _on_simulate(self, event: viser.GuiEvent) -> None:
        buttons = [self.plan_button, self.sim_button]
        with busy(self.progress, buttons, what="simulating the polishing") as progress:
            motion = self.svc.plan_motion(progress=lambda f, m: progress(0.7 * f, m))
            sim = self.svc.simulate(progress=lambda f, m: progress(0.7 + 0.3 * f, m))
        self._show_plots(sim)
        self.sim_info.content = (
            f"**Simulation** {sim.summary()}.\n\n**Robot** ({self.svc.configuration}): "
            f"{motion.summary()}."
        )
        self.download.disabled = False
        robot = self.app.wb.robot
        self._motion = motion.samples
        self.app.timeline.load(
            motion.samples,
            robot=robot,
        )

    def _show_plots(self, sim: PolishingSimulation) -> None:
        for p in self.plots:
            p.remove()
        r = sim.result
        k = _stride(len(r.t))
        t = r.t[::k]
        x = uplot.Series(label="t [s]")
        g = self.server.gui
        with self.plot_folder:
            self.plots = self._plots(g, sim, t, x, k)

    def _plots(
        self, g: Any, sim: PolishingSimulation, t: NDArray[np.float64], x: Any, k: int
    ) -> list[Removable]:
        r = sim.result
        return [
            g.add_uplot(
                data=(t, r.force[::k], r.force_measured[::k], np.full_like(t, sim.target_force)),
                series=(
                    x,
                    uplot.Series(label="contact force [N]", stroke="#1f77b4", width=1.5),
                    uplot.Series(label="measured [N]", stroke="#9ecae1", width=1),
                    uplot.Series(label="target [N]", stroke="#d62728", dash=(6.0, 4.0), width=1),
                ),
                title="Contact force vs target [N]",
                scales={"x": uplot.Scale(time=False)},
                aspect=1.6,
            ),
            g.add_uplot(
                data=(t, r.tracking_error[::k] / MM),
                series=(x, uplot.Series(label="tracking error [mm]", stroke="#2ca02c", width=1.5)),
                title="Tracking error [mm]",
                scales={"x": uplot.Scale(time=False)},
                aspect=1.6,
            ),
            g.add_uplot(
                data=(t, np.degrees(r.orientation_error[::k])),
                series=(
                    x,
                    uplot.Series(label="tool axis vs normal [deg]", stroke="#9467bd", width=1.5),
                ),
                title="Orientation error [deg]",
                scales={"x": uplot.Scale(time=False)},
                aspect=1.6,
            ),
        ]

    def remove(self) -> None:
        """Remove the tab's widgets and scene nodes."""
        for f in self.fields:
            f.remove()
        self.fields.clear()
        if getattr(self, "faces", None) is not None:
            self.faces.remove()
        for h in [*self.plots, *self.nodes.values(), *self.handles]:
            h.remove()
        if getattr(self, "root", None) is not None:
            assert self.root is not None
            self.root.remove()
            self.root = None
        self.handles.clear()
        self.plots.clear()
        self.nodes.clear()
