"""The "Robot" tab: joint sliders [deg], the TCP gizmo driving IK, the IK configurations, status.

The sliders show the robot controller's joint values (`RobotModel.convention`), the values the
project file stores and the programs write; the workbench works in the model's.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import viser

from workbench.errors import JointLimitError, UnreachableError
from workbench.geometry.transforms import (
    make_transform,
    matrix_to_rpy,
    wxyz_to_matrix,
)
from workbench.gui.fields import NumberField, format_number
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
        self.limits = wb.robot.convention.limits_to_controller(wb.robot.limits) * DEG_PER_RAD
        self.joint_fields = []
        for j in range(wb.robot.dof):
            lo, hi = self.limits[j]
            self.joint_fields.append(
                NumberField(
                    s,
                    f"J{j + 1} [deg]",
                    get=lambda j=j: float(self._controller_deg()[j]),  # type: ignore[misc]
                    put=lambda v, j=j: self._set_joint(j, v),  # type: ignore[misc]
                    allowed=lambda lo=lo, hi=hi: f"[{format_number(lo)}, {format_number(hi)}] deg",  # type: ignore[misc]
                    changed=self.refresh,
                    slider=(float(np.floor(lo * 10) / 10), float(np.ceil(hi * 10) / 10), 0.1),
                    hint=f"controller joint value [deg], {format_number(lo)} to {format_number(hi)}",
                )
            )
        self.sliders = [f.slider for f in self.joint_fields]
        self.config = s.gui.add_dropdown(
            "IK configuration",
            options=("current",),
            initial_value="current",
            hint="Arm configurations that reach the current TCP pose",
        )
        self.config.on_update(guarded(s, "IK configuration")(self._on_config))
        self.status = s.gui.add_markdown("")
        self.handles = [h for f in self.joint_fields for h in f.handles]
        self.handles += [self.config, self.status]
        self.gizmo = s.scene.add_transform_controls("/tcp_gizmo", scale=0.18, depth_test=False)
        self.gizmo.on_update(guarded(s, "Move TCP")(self._on_gizmo))
        self.refresh()

    def remove(self) -> None:
        """Remove every handle (before the project is replaced)."""
        for h in self.handles:
            h.remove()
        self.gizmo.remove()

    # -- callbacks ----------------------------------------------------------------------
    def _set_joint(self, j: int, value_deg: float) -> None:
        """Move joint j to the controller value [deg]; refused outside its limits (robot stays)."""
        lo, hi = self.limits[j]
        if not lo - 1e-9 <= value_deg <= hi + 1e-9:
            raise JointLimitError(
                f"joint {j + 1}: {format_number(value_deg)} deg is outside its limits"
                f" [{format_number(lo)}, {format_number(hi)}] deg"
            )
        q_ctrl = self._controller_deg()
        q_ctrl[j] = value_deg
        self.wb.set_joints(self.wb.robot.convention.to_model(q_ctrl / DEG_PER_RAD))

    def _on_config(self, event: object) -> None:
        if self._syncing or getattr(event, "client", None) is None:
            return
        label = str(self.config.value)
        if label not in self._labels:
            self.refresh()
            return
        try:
            self.wb.move_tcp(self.wb.tcp_pose(), configuration=label)
        finally:
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
        T = wb.tcp_pose()
        try:
            sols = wb.ik_solutions(T)
        except UnreachableError:
            sols = []
        # The list in a fixed order (by label: the set depends on the pose only), so a pick
        # neither reorders nor renumbers it; the value is the configuration the arm is in.
        self._labels = sorted(s.label for s in sols)
        current = next((s.label for s in sols if np.abs(s.q - wb.joints).max() < 1e-6), "current")
        self._syncing = True
        try:
            for field in self.joint_fields:
                field.refresh()
            options = tuple(self._labels) if current != "current" else ("current", *self._labels)
            if tuple(self.config.options) != options:
                self.config.options = options
            if self.config.value != current:
                self.config.value = current  # type: ignore[misc]
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
            coll = "Collision-free; " + clearance_text(wb)
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


def clearance_text(wb: Workbench) -> str:
    """Return the Robot tab's one clearance figure (markdown): the least distance over the latest
    Motion plan with its pair, else at the current joints, against the margin (mm)."""
    c = wb.collision.clearance()
    if c.pair is None:
        return "clearance: no pair to measure"
    where = "over the plan" if c.time is not None else "at these joints"
    at = f", t = {c.time:.2f} s" if c.time is not None else ""
    verdict = "" if c.keeps_margin else " — **closer than the margin**"
    return (
        f"clearance {where} **{c.distance * MM_PER_M:.1f} mm** ({c.pair[0]} – {c.pair[1]}{at}),"
        f" margin {c.margin * MM_PER_M:.1f} mm{verdict}"
    )
