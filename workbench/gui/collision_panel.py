"""The collision-engine controls in the "Robot" tab: the plan collision mode, spheres,
distance-field slice, check report."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
import trimesh
import viser

from workbench.errors import InputError, WorkbenchError
from workbench.gui.fields import NumberField, format_number
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded, notify

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp


def _colormap(values: np.ndarray, scale: float) -> np.ndarray:
    """Return RGB uint8 (..., 3): red inside (negative), white at the surface, blue far outside."""
    t = np.clip(values / scale, -1.0, 1.0)[..., None]
    red, white, blue = np.array([220, 40, 40]), np.array([250, 250, 250]), np.array([40, 90, 220])
    rgb = np.where(t < 0, white + (red - white) * (-t), white + (blue - white) * t)
    return rgb.astype(np.uint8)


FIELD_SCALE = 0.2  # [m] the distance at which the slice's colours saturate
SLICE_RANGE_MM = (0.0, 2000.0)  # the slice heights offered (a view setting, not the project's)
SLICE_START_MM = 400.0
MM_PER_M = 1000.0  # display only


def colour_bar(width: int = 256, height: int = 14) -> np.ndarray:
    """Return the slice's colour legend as an RGB image (height, width, 3), -scale to +scale."""
    row = _colormap(np.linspace(-FIELD_SCALE, FIELD_SCALE, width), FIELD_SCALE)
    return np.repeat(row[None], height, axis=0)


def legend_text(values: np.ndarray, z: float) -> str:
    """Return the legend of a slice at height `z` [m] with `values` [m]: its range in mm."""
    lo, hi = float(np.min(values)) * MM_PER_M, float(np.max(values)) * MM_PER_M
    s = FIELD_SCALE * MM_PER_M
    return (
        f"Distance field at z = {z * MM_PER_M:.0f} mm: **min {lo:.0f} mm, max {hi:.0f} mm**  \n"
        f"red −{s:.0f} mm (inside) · white 0 (surface) · blue +{s:.0f} mm and beyond"
    )


class CollisionPanel:
    """The plan collision mode (the project's `collision.mode`), toggles for the fitted spheres
    and the SDF slice, and the conservative check's report."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        g = app.server.gui
        self.folder = g.add_folder("Collision engine", expand_by_default=True)
        with self.folder:
            svc = app.wb.collision
            self.mode = g.add_dropdown(
                "Plan collision mode",
                svc.modes,
                initial_value=svc.mode,
                hint="How every plan checks collisions: spheres + SDF confirmed by python-fcl"
                " (default), exact python-fcl at every sample, or capsules",
            )
            self.margin = NumberField(
                app.server,
                "Clearance margin [mm]",
                get=lambda: app.wb.collision.margin * MM_PER_M,
                put=lambda v: app.wb.collision.set_margin(v / MM_PER_M),
                allowed=lambda: f"[0, {format_number(app.wb.collision.max_margin * MM_PER_M)}] mm",
                changed=self._on_margin,
                decimals=1,
                hint="The clearance every plan keeps from the cell and between the robot's"
                " links (the project's collision.margin); closer is a problem and the export"
                " is refused unless forced. The gripper's contacts with the part are exempt",
            )
            self.show_spheres = g.add_checkbox("Show spheres", initial_value=False)
            self.show_field = g.add_checkbox("Show distance field", initial_value=False)
            self._z_mm = SLICE_START_MM  # the slice height in use (the view's own state)
            lo, hi = SLICE_RANGE_MM
            self.height = NumberField(
                app.server,
                "Slice height [mm]",
                get=lambda: self._z_mm,
                put=self._set_height,
                allowed=lambda: f"[{format_number(lo)}, {format_number(hi)}] mm",
                changed=lambda: self._on_field(None),
                decimals=1,
                slider=(lo, hi, 10.0),
                hint="Height of the distance-field slice above the world's floor",
            )
            self.legend_bar = g.add_image(colour_bar(), label="Distance [mm]", visible=False)
            self.legend = g.add_markdown("", visible=False)
            self.check_button = g.add_button("Check", icon=viser.Icon.SHIELD_CHECK)
            self.progress = g.add_progress_bar(0.0, visible=False, animated=True)
            self.report = g.add_markdown("")
        self.handles: list[Removable] = [self.folder]
        self.sphere_node: Any = None
        self.field_node: Any = None
        self.mode.on_update(guarded(app.server, "Plan collision mode")(self._on_mode))
        self.show_spheres.on_update(guarded(app.server, "Show spheres")(self._on_spheres))
        self.show_field.on_update(guarded(app.server, "Show distance field")(self._on_field))
        self.check_button.on_click(guarded(app.server, "Check")(self._on_check))
        # Spheres follow the robot whenever it is posed (jog, timeline).
        app.scene.on_show.append(self.update_spheres)

    def _on_mode(self, event: Any) -> None:
        """Set the project's plan collision mode; a refused value puts the widget back."""
        svc = self.app.wb.collision
        if self.mode.value == svc.mode:
            return
        try:
            svc.set_mode(str(self.mode.value))
        except WorkbenchError as exc:
            self.mode.value = svc.mode  # type: ignore[misc]
            notify(self.app.server, getattr(event, "client", None), "Plan collision mode", str(exc))

    def _on_margin(self) -> None:
        """Show the clearance against the new margin (the jog status holds the one figure)."""
        jog = getattr(self.app, "jog", None)
        if jog is not None:
            jog.refresh()

    def _set_height(self, z_mm: float) -> None:
        lo, hi = SLICE_RANGE_MM
        if not lo <= z_mm <= hi:
            raise InputError(f"Slice height: {format_number(z_mm)} mm is outside the slice range")
        self._z_mm = float(z_mm)

    def _engine(self) -> Any:
        svc = self.app.wb.collision
        if svc.built:
            return svc.engine()
        self.progress.visible = True
        try:
            return svc.engine(progress=lambda f, m: setattr(self.progress, "value", 100.0 * f))
        finally:
            self.progress.visible = False

    def update_spheres(self, q: Any = None) -> None:
        """Move the sphere nodes to the links at joints q [rad] (None: the current joints)."""
        if self.sphere_node is None:
            return
        centres, _, _ = self.app.wb.collision.spheres(q)
        self.sphere_node.batched_positions = centres.astype(np.float32)

    def _on_spheres(self, _event: Any) -> None:
        if not self.show_spheres.value:
            if self.sphere_node is not None:
                self.sphere_node.remove()
                self.sphere_node = None
            return
        self._engine()
        centres, radii, _ = self.app.wb.collision.spheres(None)
        ball = trimesh.creation.icosphere(subdivisions=2, radius=1.0)
        n = len(radii)
        self.sphere_node = self.app.server.scene.add_batched_meshes_simple(
            "/collision/spheres",
            np.asarray(ball.vertices, np.float32),
            np.asarray(ball.faces, np.uint32),
            batched_wxyzs=np.tile(np.array([1.0, 0.0, 0.0, 0.0], np.float32), (n, 1)),
            batched_positions=centres.astype(np.float32),
            batched_scales=radii.astype(np.float32),
            batched_colors=(90, 200, 255),
            opacity=0.35,
        )

    def _on_field(self, _event: Any) -> None:
        if self.field_node is not None:
            self.field_node.remove()
            self.field_node = None
        self.legend_bar.visible = self.legend.visible = bool(self.show_field.value)
        if not self.show_field.value:
            return
        self._engine()
        z = self._z_mm / MM_PER_M
        values, corners = self.app.wb.collision.sdf_slice("z", z, size=96)
        size = corners[1] - corners[0]
        # Image rows run along -y, columns along +x.
        image = _colormap(values.T[::-1], FIELD_SCALE)
        self.legend.content = legend_text(values, z)
        self.field_node = self.app.server.scene.add_image(
            "/collision/field",
            image,
            render_width=float(size[0]),
            render_height=float(size[1]),
            position=((corners[0] + corners[1]) / 2),
        )

    def _on_check(self, _event: Any) -> None:
        self.check_button.disabled = True
        try:
            self._engine()
            c = self.app.wb.collision.check()
            if c.colliding:
                text = (
                    f"**Collision**: {c.link} hits {c.obstacle},"
                    f" penetration {c.penetration * 1e3:.1f} mm"
                )
            else:  # the clearance figure is the status's one (`jog_panel.clearance_text`)
                text = "Collision-free at these joints (spheres checked, flagged pairs confirmed)"
            self.report.content = text
            self.last = c
        finally:
            self.check_button.disabled = False

    def remove(self) -> None:
        """Remove the panel's widgets and scene nodes."""
        if self.update_spheres in self.app.scene.on_show:
            self.app.scene.on_show.remove(self.update_spheres)
        for node in (self.sphere_node, self.field_node):
            if node is not None:
                node.remove()
        self.sphere_node = self.field_node = None
        self.height.remove()
        self.margin.remove()
        for h in self.handles:
            h.remove()
        self.handles.clear()
