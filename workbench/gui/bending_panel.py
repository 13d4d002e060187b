"""The "Bending" tab: the part flat and folded at the die, sequence, grasp, OBB tree levels, Plan;
with a press brake, the sequence search and the planned cycle on the timeline."""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING, Any

import numpy as np
import viser
import viser.uplot as uplot
from numpy.typing import NDArray

from workbench.errors import InputError, WorkbenchError
from workbench.geometry.transforms import make_transform
from workbench.gui.bending_cycle import CycleFollower
from workbench.gui.fields import NumberField, format_number
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded, notify
from workbench.gui.program_download import ProgramDownload
from workbench.gui.progress import busy
from workbench.gui.scene import place
from workbench.gui.sequence_search import SequenceSearch
from workbench.gui.timeline import SECONDS

if TYPE_CHECKING:
    import trimesh

    from workbench.gui.app import WorkbenchApp
    from workbench.service.bending import BendingResult, CheckCost, DiePlacement, OBBTree

MM_PER_M = 1e3  # m -> mm for display
PART_COLOR = (120, 170, 230)
LEVEL_COLORS = ((40, 160, 60), (240, 150, 20), (150, 60, 200), (20, 150, 190), (200, 200, 40))
HIT_COLOR = (230, 30, 30)
UNTESTED_COLOR = (150, 150, 150)


class BendingPanel:
    """Controls of the bending workflow; built inside its tab, removed when the project changes."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        self.server = app.server
        self.handles: list[Removable] = []
        self.nodes: list[Any] = []
        self.box_nodes: list[Any] = []
        self._lock = threading.RLock()
        self._placements: tuple[DiePlacement, ...] | None = None
        self._tree: OBBTree | None = None
        self._check: tuple[tuple[int, ...], tuple[int, ...]] | None = None  # tested, hit nodes
        self._animating = threading.Event()
        self._quiet = False
        self.plots: list[Any] = []
        self.search: SequenceSearch | None = None
        self.follower: CycleFollower | None = None  # the timeline's view of the last cycle
        self._press_moved = False  # the press's bodies left their parked poses
        g = app.server.gui
        if not app.wb.bending.available:
            self.handles.append(g.add_markdown("This project has no `bending` section."))
            return
        self._build()

    # -- widgets --------------------------------------------------------------------------
    def _build(self) -> None:
        s, g = self.server, self.server.gui
        svc = self.app.wb.bending
        part = svc.part
        nb = len(part.bends)
        self.info = g.add_markdown(self._describe())
        self.look = g.add_button("Look at die and part", icon=viser.Icon.FOCUS_2)
        self.look.on_click(guarded(s, "View")(lambda e: self.app.views.frame_bending(e.client)))
        self.sequence = g.add_text(
            "Sequence", ",".join(svc.sequence), hint="Bend names in order, comma-separated"
        )
        self.apply_sequence = g.add_button("Apply sequence", icon=viser.Icon.ARROWS_SORT)
        self._step = float(nb)  # the fold step shown [bends]
        self.step_field = NumberField(
            s,
            "Fold step",
            get=lambda: self._step,
            put=self._set_step,
            allowed=lambda: f"[0, {len(self.app.wb.bending.part.bends)}] bends",
            changed=self.redraw,
            slider=(0.0, float(nb), 0.05),
            hint="bends folded so far (fractions fold partway)",
        )
        self.step = self.step_field.slider
        self.animate = g.add_button("Animate folds", icon=viser.Icon.PLAYER_PLAY)
        flanges = tuple(f.name for f in part.flanges)
        self.grasp = g.add_dropdown("Grasp flange", options=flanges, initial_value=svc.grasp_flange)
        self.offset_fields = [
            NumberField(
                s,
                f"Grasp {axis} [mm]",
                get=lambda i=i: float(self.app.wb.bending.grasp_offset()[i] * MM_PER_M),  # type: ignore[misc]
                put=lambda v, i=i: self._set_offset(i, v),  # type: ignore[misc]
                allowed=lambda: (
                    f"a point on flange '{self.app.wb.bending.grasp_flange}'"
                    " (its polygon frame) [mm]"
                ),
                changed=self._reset,
                decimals=2,
            )
            for i, axis in enumerate("xy")
        ]
        self.offset_x, self.offset_y = (f.text for f in self.offset_fields)
        self.levels = []
        depth = svc.tree_depth()
        self.levels_folder = g.add_folder("OBB tree levels")  # kept: `remove` removes it
        with self.levels_folder:
            for lvl in range(depth):
                name = "root" if lvl == 0 else ("flanges" if lvl == depth - 1 else f"split {lvl}")
                cb = g.add_checkbox(f"Level {lvl} ({name})", initial_value=lvl == 0)
                cb.on_update(guarded(s, "OBB levels")(lambda _: self._show_levels()))
                self.levels.append(cb)
            self.tree_info = g.add_markdown("")
        self.has_press = svc.si().press is not None
        if self.has_press:
            self.search = SequenceSearch(
                self.app, on_used=self._sequence_changed, on_planned=self._show_plan
            )
        self.plan_button = g.add_button("Plan", icon=viser.Icon.ROUTE)
        self.progress = g.add_progress_bar(0.0, visible=False, animated=True)
        self.result = g.add_markdown("")
        self.export = ProgramDownload(s, lambda: self.app.wb, "bending")  # the plan's programs
        self.plot_folder = g.add_folder(
            "Per-frame checks: tree vs flat loop", visible=not self.has_press
        )
        self.handles += [
            self.info,
            self.look,
            self.sequence,
            self.apply_sequence,
            *self.step_field.handles,
            self.animate,
            self.grasp,
            *(h for f in self.offset_fields for h in f.handles),
            *self.levels,
            self.tree_info,
            self.plan_button,
            self.progress,
            self.result,
            *self.export.handles,
            self.plot_folder,
            self.levels_folder,  # after its checkboxes and markdown
        ]
        self.apply_sequence.on_click(guarded(s, "Bend sequence")(self._on_sequence))
        self.step.on_update(guarded(s, "Fold step")(self._on_step_set))
        self.animate.on_click(guarded(s, "Animate")(self._on_animate))
        self.grasp.on_update(guarded(s, "Grasp")(self._on_grasp_flange))
        self.plan_button.on_click(guarded(s, "Plan bending")(self._on_plan))
        self.part_frame = s.scene.add_frame("/bending/part", show_axes=False)
        self.grasp_frame = s.scene.add_frame("/bending/part/obb", show_axes=False)
        self.nodes += [self.part_frame, self.grasp_frame]
        self.mesh: Any = None
        self.mesh_step: float | None = None  # the fold step of the drawn mesh [bends]
        try:
            self.redraw()
        except WorkbenchError as exc:
            self.result.content = f"**Problem:** {exc}"

    def _describe(self) -> str:
        svc = self.app.wb.bending
        part = svc.part
        return (
            f"**Part `{svc.part_spec().name}`**: {len(part.flanges)} flanges, {len(part.bends)} "
            f"bends, t = {part.thickness * MM_PER_M:g} mm, blank area {part.blank_area() * 1e6:.0f} mm²"
        )

    def remove(self) -> None:
        """Remove the tab's widgets and scene nodes."""
        self._animating.clear()
        if self.follower is not None:
            self.follower.close()
        if self.search is not None:
            self.search.remove()
        for h in self.plots:
            h.remove()
        for h in self.handles:
            h.remove()
        for n in self.box_nodes:
            n.remove()
        for n in reversed(self.nodes):
            n.remove()
        self.plots.clear()
        self.handles.clear()
        self.box_nodes.clear()
        self.nodes.clear()

    # -- scene ----------------------------------------------------------------------------
    def _die_placements(self) -> tuple[DiePlacement, ...] | None:
        if self._placements is None:
            try:
                self._placements = self.app.wb.bending.placements()[0]
            except WorkbenchError as exc:
                self.result.content = f"**Problem:** {exc}"
                return None
        return self._placements

    def redraw(self) -> None:
        """Show the part folded to the slider's step, on the die for its next bend, robot holding it."""
        with self._lock:
            svc = self.app.wb.bending
            nb = len(svc.part.bends)
            step = float(np.clip(self._step, 0.0, nb))
            state = svc.fold(step)
            k = svc.bend_on_die(step)
            self._draw_mesh(state.solid(), step)
            place(self.part_frame, svc.die_part_pose(k))
            if self._press_moved:  # a cycle moved the ram: the die view shows it parked
                self.app.scene.park_bodies()
                self._press_moved = False
            placements = self._die_placements()
            if placements is not None:
                self.app.scene.show(placements[k].q)
            self._tree = state.obb_tree(svc.grasp_flange)
            self._check = None
            self._draw_boxes(state.T_part_flange[self._tree.grasp_flange])

    def _draw_mesh(self, mesh: trimesh.Trimesh, step: float) -> None:
        """Draw the part's mesh (in the part frame) for fold step `step` [bends]."""
        with self._lock:
            if self.mesh is not None:
                self.mesh.remove()
                self.nodes.remove(self.mesh)
            self.mesh = self.server.scene.add_mesh_simple(
                "/bending/part/mesh",
                np.asarray(mesh.vertices, np.float32),
                np.asarray(mesh.faces, np.uint32),
                color=PART_COLOR,
                side="double",
            )
            self.mesh_step = step
            self.nodes.append(self.mesh)

    def show_fold(self, step: float) -> None:
        """Draw the part folded to `step` [bends] where it is (a cycle on the timeline); the
        OBB tree, drawn for the fold step on the die, is taken down until that is shown again."""
        with self._lock:
            self._draw_mesh(self.app.wb.bending.fold(step).solid(), step)
            self._press_moved = True
            if self._tree is not None:
                for n in self.box_nodes:
                    n.remove()
                self.box_nodes.clear()
                self._tree, self._check = None, None
                self.tree_info.content = (
                    "The tree is drawn for the fold step above; the cycle's checks are in its"
                    " summary."
                )

    def _draw_boxes(self, T_part_grasp: NDArray[np.float64]) -> None:
        for n in self.box_nodes:
            n.remove()
        self.box_nodes.clear()
        tree = self._tree
        assert tree is not None
        place(self.grasp_frame, T_part_grasp)  # the boxes are given in the tree's (grasp) frame
        for i in range(len(tree.flanges)):
            h = self.server.scene.add_box(
                f"/bending/part/obb/n{i}",
                color=LEVEL_COLORS[int(tree.level[i]) % len(LEVEL_COLORS)],
                dimensions=tuple(2 * tree.boxes.half_extents[i]),
                wireframe=True,
            )
            place(h, make_transform(tree.boxes.rotation[i], tree.boxes.center[i]))
            self.box_nodes.append(h)
        self._show_levels()

    def _show_levels(self) -> None:
        tree = self._tree
        if tree is None:
            return
        on = [bool(cb.value) for cb in self.levels]
        tested, hit = self._check or ((), ())
        for i, h in enumerate(self.box_nodes):
            lvl = int(tree.level[i])
            h.visible = lvl < len(on) and on[lvl]
            if self._check is None:
                h.color = LEVEL_COLORS[lvl % len(LEVEL_COLORS)]
            elif i in hit:
                h.color = HIT_COLOR
            elif i in tested:
                h.color = LEVEL_COLORS[lvl % len(LEVEL_COLORS)]
            else:
                h.color = UNTESTED_COLOR
        names = self.app.wb.bending.part.flanges
        rows = [
            f"L{int(tree.level[i])}: {{{', '.join(names[f].name for f in fl)}}}"
            + (" **hit**" if i in hit else (" tested" if i in tested else ""))
            for i, fl in enumerate(tree.flanges)
            if int(tree.level[i]) < len(on) and on[int(tree.level[i])]
        ]
        self.tree_info.content = f"{len(tree.flanges)} nodes. " + "; ".join(rows)

    # -- callbacks ------------------------------------------------------------------------
    def _sequence_changed(self) -> None:
        """Show the project's sequence (a search's plan was put into the project)."""
        svc = self.app.wb.bending
        self.sequence.value = ",".join(svc.sequence)  # type: ignore[misc]
        self._placements = None
        self.result.content = ""
        self.info.content = self._describe()

    def _reset(self) -> None:
        self._placements = None
        self.result.content = ""
        self.info.content = self._describe()
        self.redraw()

    def _on_sequence(self, event: viser.GuiEvent) -> None:
        names = [n for n in str(self.sequence.value).replace(";", ",").split(",") if n.strip()]
        self.app.wb.bending.set_sequence(names)
        self.sequence.value = ",".join(self.app.wb.bending.sequence)  # type: ignore[misc]
        self._reset()
        notify(self.server, event.client, "Bend sequence", "Applied.", color="green")

    def _on_grasp_flange(self, event: viser.GuiEvent) -> None:
        svc = self.app.wb.bending
        if event.client is None or self.grasp.value == svc.grasp_flange:
            return
        try:
            svc.set_grasp(str(self.grasp.value))
        finally:
            self.grasp.value = svc.grasp_flange  # type: ignore[misc]  # the flange in use
            for f in self.offset_fields:
                f.refresh()
        self._reset()

    def _set_offset(self, i: int, value_mm: float) -> None:
        """Move the grasp point's coordinate i (0: x, 1: y) [mm]; the service refuses off the flange."""
        svc = self.app.wb.bending
        off = np.array(svc.grasp_offset(), float)
        off[i] = value_mm / MM_PER_M
        svc.set_grasp(svc.grasp_flange, off)

    def _set_step(self, v: float) -> None:
        nb = len(self.app.wb.bending.part.bends)
        if not 0.0 <= v <= nb:
            raise InputError(f"Fold step: {format_number(v)} is outside [0, {nb}] bends")
        self._step = v

    def _on_step_set(self, event: Any) -> None:
        if event.client is not None:
            return  # the field commits what a page sends (or refuses it)
        self._step = float(self.step.value)  # animation and Plan move the slider from here
        self.step_field.refresh()
        self.redraw()

    def _on_animate(self, event: viser.GuiEvent) -> None:
        if self._animating.is_set():
            self._animating.clear()
            return
        self._animating.set()
        nb = float(len(self.app.wb.bending.part.bends))

        def run() -> None:
            v = 0.0
            while self._animating.is_set() and v <= nb + 1e-9:
                self.step.value = round(v, 2)  # type: ignore[misc]  # fires redraw
                v += 0.1
                time.sleep(0.05)
            self._animating.clear()

        threading.Thread(target=run, name="bending-animate", daemon=True).start()

    def _on_plan(self, event: viser.GuiEvent) -> None:
        svc = self.app.wb.bending
        try:
            with busy(
                self.progress, [self.plan_button], self.result, what="planning the bending"
            ) as progress:
                plan = svc.plan(progress=progress)
        except Exception:
            self.export.disabled = svc.last_plan is None  # a refused plan: nothing to export
            raise
        self._show_plan(plan)

    def _show_plan(self, plan: BendingResult) -> None:
        """Show a plan's summary, and its motion on the timeline."""
        head = "**OK:** " if plan.ok else "**Collision:** "
        self.result.content = head + plan.summary()
        self.export.disabled = False  # the export writes this plan (or says why not)
        cost = self.app.wb.bending.check_cost(plan)  # measured on request, not by the plan
        if cost is not None:  # one OBB tree checks the part throughout (no press)
            nb = float(len(self.app.wb.bending.part.bends))
            self.step.value = nb  # type: ignore[misc]  # redraws the folded tree
            self._show_plots(plan, cost)
            self._load_timeline(plan)
        else:
            self._load_cycle(plan)

    def _show_plots(self, plan: BendingResult, cost: CheckCost) -> None:
        for h in self.plots:
            h.remove()
        x = np.arange(1, len(plan.times) + 1, dtype=float)
        fx = uplot.Series(label="frame")
        with self.plot_folder:
            self.plots = [
                self.server.gui.add_uplot(
                    data=(x, cost.tree_tests.astype(float), cost.flat_tests.astype(float)),
                    series=(
                        fx,
                        uplot.Series(label="tree", stroke="#2ca02c", width=2),
                        uplot.Series(label="flat loop", stroke="#d62728", width=2),
                    ),
                    title="OBB tests per frame",
                    aspect=1.6,
                    scales=SECONDS,
                ),
                self.server.gui.add_uplot(
                    data=(x, cost.tree_seconds * 1e6, cost.flat_seconds * 1e6),
                    series=(
                        fx,
                        uplot.Series(label="tree [µs]", stroke="#2ca02c", width=2),
                        uplot.Series(label="flat loop [µs]", stroke="#d62728", width=2),
                    ),
                    title="Check time per frame [µs]",
                    aspect=1.6,
                    scales=SECONDS,
                ),
            ]

    def _load_timeline(self, plan: BendingResult) -> None:
        svc = self.app.wb.bending
        robot = self.app.wb.robot

        def follow(t: float) -> None:
            place(self.part_frame, svc.part_pose_at(plan, t))
            self._check = plan.tree_check_at(t)
            self._show_levels()

        self.app.timeline.load(
            svc.playback(plan),
            robot=robot,
            follow=follow,
        )
        first = plan.first_problem_time
        if first is not None:
            self.app.timeline.time.value = round(first, 4)  # type: ignore[misc]

    def _load_cycle(self, plan: BendingResult) -> None:
        """Play a press-brake cycle: the robot, the part folded and carried, the ram and the
        back-gauge; the timeline starts at the first colliding frame when there is one."""
        svc = self.app.wb.bending
        if self.follower is not None:
            self.follower.close()
        self.follower = CycleFollower(
            self.app, plan, part_frame=self.part_frame, show_fold=self.show_fold
        )
        self.app.timeline.load(svc.playback(plan), robot=self.app.wb.robot, follow=self.follower)
        first = plan.first_problem_time
        if first is not None:
            self.app.timeline.time.value = round(first, 4)  # type: ignore[misc]
