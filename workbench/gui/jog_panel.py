"""The "Robot" tab: joint sliders [deg], the TCP gizmo driving IK, the IK configurations, status.

The sliders show the robot controller's joint values (`RobotModel.convention`), the values the
project file stores and the programs write; the workbench works in the model's.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import viser

from workbench.errors import UnreachableError
from workbench.geometry.transforms import (
    make_transform,
    matrix_to_rpy,
    wxyz_to_matrix,
)
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded
from workbench.gui.scene import place
from workbench.service import Workbench

DEG_PER_RAD = 180.0 / np.pi  # display only
MM_PER_M = 1000.0  # display only


class JogPanel:
    """Jog controls bound to one workbench; `on_moved` redraws the scene after each change."""

    def __init__(
        self, server: viser.ViserServer, wb: Workbench, on_moved: Callable[[], None]
    ) -> None:
        self.server = server
        self.wb = wb
        self.on_moved = on_moved
        self._syncing = False
        self.handles: list[Removable] = []
        self.build()

    def build(self) -> None:
        """Create the sliders, dropdown, gizmo and status for the current project."""
        s, wb = self.server, self.wb
        q = self._controller_deg()
        limits = wb.robot.convention.limits_to_controller(wb.robot.limits) * DEG_PER_RAD
        self.sliders = []
        for j in range(wb.robot.dof):
            lo, hi = limits[j]
            slider = s.gui.add_slider(
                f"J{j + 1} [deg]",
                min=float(np.floor(lo * 10) / 10),
                max=float(np.ceil(hi * 10) / 10),
                step=0.1,
                initial_value=float(np.clip(q[j], lo, hi)),
            )
            slider.on_update(guarded(s, f"Joint {j + 1}")(self._on_slider))
            self.sliders.append(slider)
        self.config = s.gui.add_dropdown(
            "IK configuration",
            options=("current",),
            initial_value="current",
            hint="Arm configurations that reach the current TCP pose",
        )
        self.config.on_update(guarded(s, "IK configuration")(self._on_config))
        self.status = s.gui.add_markdown("")
        self.handles = [*self.sliders, self.config, self.status]
        self.gizmo = s.scene.add_transform_controls("/tcp_gizmo", scale=0.18, depth_test=False)
        self.gizmo.on_update(guarded(s, "Move TCP")(self._on_gizmo))
        self.refresh()

    def remove(self) -> None:
        """Remove every handle (before the project is replaced)."""
        for h in self.handles:
            h.remove()
        self.gizmo.remove()

    # -- callbacks ----------------------------------------------------------------------
    def _on_slider(self, _event: object) -> None:
        if self._syncing:
            return
        q_ctrl = np.array([sl.value for sl in self.sliders]) / DEG_PER_RAD
        self.wb.set_joints(self.wb.robot.convention.to_model(q_ctrl))
        self.refresh()

    def _on_config(self, _event: object) -> None:
        if self._syncing or self.config.value == "current":
            return
        label = str(self.config.value).split(": ", 1)[1]
        self.wb.move_tcp(self.wb.tcp_pose(), configuration=label)
        self.refresh()

    def _on_gizmo(self, event: viser.TransformControlsEvent) -> None:
        # IK is committed on release: during the drag only the gizmo moves.
        if event.phase != "end":
            return
        T = make_transform(
            wxyz_to_matrix(np.asarray(self.gizmo.wxyz)), np.asarray(self.gizmo.position)
        )
        try:
            self.wb.move_tcp(T)
        except UnreachableError:
            self.refresh()  # the arm stays; put the gizmo back on the TCP
            raise
        self.refresh()

    # -- state -> widgets ---------------------------------------------------------------
    def _controller_deg(self) -> np.ndarray:
        """Return the current joints as the controller shows them [deg]."""
        return self.wb.robot.convention.to_controller(self.wb.joints) * DEG_PER_RAD

    def refresh(self) -> None:
        """Put the sliders, gizmo, dropdown and status in line with the workbench's state."""
        wb = self.wb
        q = self._controller_deg()
        T = wb.tcp_pose()
        try:
            sols = wb.ik_solutions(T)
        except UnreachableError:
            sols = []
        labels = [f"{i + 1}: {s.label}" for i, s in enumerate(sols)]
        self._syncing = True
        try:
            for slider, v in zip(self.sliders, q, strict=True):
                if abs(slider.value - v) > 1e-9:
                    slider.value = float(v)  # type: ignore[misc]
            self.config.options = ("current", *labels)
            self.config.value = "current"  # type: ignore[misc]
        finally:
            self._syncing = False
        place(self.gizmo, T)
        self.on_moved()
        self.status.content = self._status_text(T, len(sols))

    def _status_text(self, T: np.ndarray, n_solutions: int) -> str:
        wb = self.wb
        xyz = T[:3, 3] * MM_PER_M
        rpy = matrix_to_rpy(T[:3, :3]) * DEG_PER_RAD
        report = wb.collision_status()
        if report.in_collision:
            pairs = ", ".join(f"{a}–{b}" for a, b in report.colliding)
            coll = f"**Collision:** {pairs}"
        else:
            pair = " – ".join(report.closest_pair) if report.closest_pair else "none"
            coll = f"Collision-free, clearance **{report.min_distance * MM_PER_M:.1f} mm** ({pair})"
        lines = [
            f"TCP [mm]: {xyz[0]:.1f}, {xyz[1]:.1f}, {xyz[2]:.1f}",
            f"RPY [deg]: {rpy[0]:.1f}, {rpy[1]:.1f}, {rpy[2]:.1f}",
            f"IK solutions: {n_solutions}",
            coll,
        ]
        try:
            sing = wb.singularities()
            near = [k for k in ("wrist", "elbow", "shoulder") if getattr(sing, k, False)]
            if near:
                lines.append(f"**Near singularity:** {', '.join(near)}")
        except Exception:  # singularity analysis is advisory
            pass
        return "  \n".join(lines)
