"""The "Assembly" tab: pick a part, place its start and goal, plan its path, play the sequence."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np
import viser

from workbench.errors import InputError
from workbench.geometry.transforms import (
    make_transform,
    wxyz_to_matrix,
    xyz_rpy_to_transform,
)
from workbench.gui.fields import NumberField, schema_range
from workbench.gui.handles import Removable
from workbench.gui.notify import guarded
from workbench.gui.program_download import ProgramDownload
from workbench.gui.progress import busy
from workbench.gui.scene import COLLISION_COLOR, _add_mesh, place
from workbench.service.assembly import KEY_POINT_FORMATS, PLANNER_CHOICES, AssemblyPlan

if TYPE_CHECKING:
    from workbench.gui.app import WorkbenchApp

MM = 1e-3
DEG = np.pi / 180.0
PATH_COLOR = (230, 120, 20)
KEY_COLOR = (200, 30, 120)
POSE_COORDINATES = (
    ("x", "mm", "xyz"),
    ("y", "mm", "xyz"),
    ("z", "mm", "xyz"),
    ("roll", "deg", "rpy"),
    ("pitch", "deg", "rpy"),
    ("yaw", "deg", "rpy"),
)
"""The start and goal boxes: coordinate, unit, and the project pose's list that holds it."""


def _validation_text(path: str, exc: ValueError) -> str:
    """Return a pydantic error as the project file's loader says it: '<path>.<loc>: <msg>'."""
    errors: list[Any] = getattr(exc, "errors", list)()
    parts = []
    for e in errors:
        loc = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in e.get("loc", ()))
        parts.append(f"{path}{loc}: {e.get('msg', e)}".replace("Value error, ", ""))
    return "; ".join(parts) or f"{path}: {exc}"


class AssemblyPanel:
    """Controls of the assembly workflow; built inside its tab, removed when the project changes."""

    def __init__(self, app: WorkbenchApp) -> None:
        self.app = app
        self.wb = app.wb
        self.handles: list[Removable] = []
        self.nodes: list[Removable] = []
        self.plan: AssemblyPlan | None = None
        g = app.server.gui
        if not self.wb.assembly.available:
            self.handles.append(g.add_markdown("This project has no `assembly` section."))
            return
        self._build_widgets()
        self._build_scene()
        self._select(self.names[0])

    # -- building ---------------------------------------------------------------------------
    def _build_widgets(self) -> None:
        s = self.app.server
        g = s.gui
        a = self.wb.assembly
        self.names = a.part_names
        spec = a.spec
        self.info = g.add_markdown(
            f"**{len(self.names)} parts**, robots: {', '.join(a.arms)}. Sequence: "
            + " → ".join(t.part for t in a.sequence())
        )
        self.part = g.add_dropdown("Part", options=tuple(self.names), initial_value=self.names[0])
        # The selected part's start and goal: one strict text box per coordinate, showing and
        # setting the project's pose (mm, deg); a refused value reverts to the pose in use.
        self.pose_folders: list[Removable] = []
        self.pose_fields: dict[tuple[str, str], NumberField] = {}
        for which in ("start", "goal"):
            folder = g.add_folder(f"{which.capitalize()} pose", expand_by_default=True)
            self.pose_folders.append(folder)
            with folder:
                for k, (axis, unit, key) in enumerate(POSE_COORDINATES):
                    label = f"{which.capitalize()} {axis} [{unit}]"
                    self.pose_fields[(which, axis)] = NumberField(
                        s,
                        label,
                        get=lambda w=which, c=key, i=k % 3: self._pose_value(w, c, i),  # type: ignore[misc]
                        put=lambda v, w=which, c=key, i=k % 3: self._set_coordinate(w, c, i, v),  # type: ignore[misc]
                        allowed=lambda w=which, c=key, u=unit: schema_range(  # type: ignore[misc]
                            self._pose_spec(w), c, u
                        ),
                        changed=lambda: self._show_poses(str(self.part.value)),
                        decimals=2,
                    )
        self.status = g.add_markdown("")
        self.planner = g.add_dropdown(
            "Planner",
            options=PLANNER_CHOICES,
            initial_value=spec.planner.name,
            hint="ant, rrt_connect: the part's pose (the robot follows by IK); "
            "joint_rrt_connect: the carrying robot's joints, robot and part checked",
        )
        # The planner's numbers live in the section (assembly.planner, mm): the fields show
        # and set them there, checked by the project's bounds; 0 means automatic (None).

        def planner_spec() -> Any:
            return self.wb.assembly.spec.planner

        self.planner_fields = [
            NumberField(
                s,
                "Cell size [mm]",
                get=lambda: float(planner_spec().cell_size or 0.0),
                put=lambda v: self._set_planner("cell_size", None if v == 0 else v),
                allowed=lambda: (
                    "0 (automatic: 1/20 of the part) or "
                    + schema_range(planner_spec(), "cell_size", "mm")
                ),
                hint="Side of the subdivision cells and the motion-check spacing;"
                " 0: automatic (1/20 of the part)",
            ),
            NumberField(
                s,
                "Step (ant)",
                get=lambda: float(planner_spec().step),
                put=lambda v: self._set_planner("step", int(v)),
                allowed=lambda: schema_range(planner_spec(), "step", "segments"),
                integer=True,
            ),
            NumberField(
                s,
                "dis (ant) [mm]",
                get=lambda: float(planner_spec().dis or 0.0),
                put=lambda v: self._set_planner("dis", None if v == 0 else v),
                allowed=lambda: "0 (automatic) or " + schema_range(planner_spec(), "dis", "mm"),
                hint="grid spacing on a cutting plane; 0: automatic",
            ),
        ]
        self.cell, self.step, self.dis = (f.text for f in self.planner_fields)
        self.plan_button = g.add_button("Plan part", icon=viser.Icon.ROUTE)
        self.sequence_button = g.add_button("Plan sequence", icon=viser.Icon.LIST_NUMBERS)
        self.progress = g.add_progress_bar(0.0, visible=False, animated=True)
        self.result = g.add_markdown("")
        self.format = g.add_dropdown(
            "Key points format", options=KEY_POINT_FORMATS, initial_value="csv"
        )
        self.download = g.add_button("Download key points", icon=viser.Icon.DOWNLOAD, disabled=True)
        self.programs = ProgramDownload(
            s,
            lambda: self.wb,
            "assembly",
            format_label="Program format",
            label="Download robot programs",
            hint="One program per robot (a .zip), with the sync points the sequence needs",
        )
        self.prog_format, self.prog_download = self.programs.format, self.programs.button
        self.handles += [
            self.info,
            self.part,
            *(h for f in self.pose_fields.values() for h in f.handles),
            *self.pose_folders,
            self.status,
            self.planner,
            *(h for f in self.planner_fields for h in f.handles),
            self.plan_button,
            self.sequence_button,
            self.progress,
            self.result,
            self.format,
            self.download,
            self.prog_format,
            self.prog_download,
        ]
        self.part.on_update(guarded(s, "Part")(lambda _: self._select(str(self.part.value))))
        self.plan_button.on_click(guarded(s, "Plan part")(lambda e: self._on_plan(e, one=True)))
        self.sequence_button.on_click(
            guarded(s, "Plan sequence")(lambda e: self._on_plan(e, one=False))
        )
        self.download.on_click(guarded(s, "Export key points")(self._on_download))

    def _build_scene(self) -> None:
        s = self.app.server
        a = self.wb.assembly
        self.part_nodes = {}
        for p in a.parts.values():
            h = _add_mesh(s, f"/assembly/parts/{p.name}", p.mesh, p.color, p.start)
            self.part_nodes[p.name] = h
            self.nodes.append(h)
        self.arm_nodes: dict[str, list[viser.MeshHandle]] = {}
        for arm in a.arms.values():
            if arm.main:
                continue
            poses = a.link_poses(arm.name)
            hs = [
                _add_mesh(s, f"/assembly/robots/{arm.name}/link{i}", m, arm.color, T)
                for i, (m, T) in enumerate(zip(arm.setup.link_meshes, poses, strict=True))
            ]
            if arm.setup.tool_mesh is not None:
                hs.append(
                    _add_mesh(
                        s,
                        f"/assembly/robots/{arm.name}/tool",
                        arm.setup.tool_mesh,
                        (230, 180, 60),
                        poses[-1],
                    )
                )
            self.arm_nodes[arm.name] = hs
            self.nodes.extend(hs)
        self.goal_ghost: viser.MeshHandle | None = None
        self.start_gizmo = s.scene.add_transform_controls(
            "/assembly/start_gizmo", scale=0.12, depth_test=False
        )
        self.goal_gizmo = s.scene.add_transform_controls(
            "/assembly/goal_gizmo", scale=0.12, depth_test=False
        )
        self.nodes += [self.start_gizmo, self.goal_gizmo]
        self.start_gizmo.on_update(guarded(s, "Start gizmo")(lambda e: self._on_gizmo(e, "start")))
        self.goal_gizmo.on_update(guarded(s, "Goal gizmo")(lambda e: self._on_gizmo(e, "goal")))
        self.curve: viser.SceneNodeHandle | None = None
        self.keys: viser.SceneNodeHandle | None = None

    def remove(self) -> None:
        """Remove the tab's widgets and scene nodes."""
        fields = [*getattr(self, "planner_fields", ()), *getattr(self, "pose_fields", {}).values()]
        for f in fields:
            f.remove()
        done = {id(h) for f in fields for h in f.handles}
        for h in (*(h for h in self.handles if id(h) not in done), *self.nodes):
            h.remove()
        for extra in (getattr(self, "curve", None), getattr(self, "keys", None)):
            if extra is not None:
                extra.remove()
        ghost = getattr(self, "goal_ghost", None)
        if ghost is not None:
            ghost.remove()
        self.handles.clear()
        self.nodes.clear()

    # -- state -> widgets and scene ------------------------------------------------------------
    def _select(self, name: str) -> None:
        a = self.wb.assembly
        part = a.part(name)
        s = self.app.server
        if self.goal_ghost is not None:
            self.goal_ghost.remove()
        self.goal_ghost = s.scene.add_mesh_simple(
            "/assembly/goal_ghost",
            np.asarray(part.mesh.vertices, np.float32),
            np.asarray(part.mesh.faces, np.uint32),
            color=part.color,
            opacity=0.35,
        )
        self._show_poses(name)

    def _show_poses(self, name: str) -> None:
        a = self.wb.assembly
        part = a.part(name)
        for f in self.pose_fields.values():
            f.refresh()
        place(self.start_gizmo, part.start)
        place(self.goal_gizmo, part.goal)
        place(self.part_nodes[name], part.start)
        assert self.goal_ghost is not None
        place(self.goal_ghost, part.goal)
        self._show_interference(name)

    def _show_interference(self, name: str) -> None:
        a = self.wb.assembly
        part = a.part(name)
        at_start = a.interference(name, part.start)
        at_goal = a.interference(name, part.goal)
        self.part_nodes[name].color = COLLISION_COLOR if at_start else part.color
        if self.goal_ghost is not None:
            self.goal_ghost.color = COLLISION_COLOR if at_goal else part.color
        lines = []
        for which, hit in (("start", at_start), ("goal", at_goal)):
            lines.append(
                f"**{which.capitalize()} interferes** with {', '.join(hit)}"
                if hit
                else f"{which.capitalize()}: interference-free"
            )
        robot = part.robot or "none (moves by itself)"
        self.status.content = f"Carried by **{robot}**. " + "; ".join(lines)

    # -- callbacks --------------------------------------------------------------------------------
    def _set_pose(self, name: str, which: str, T: np.ndarray) -> None:
        try:
            self._put_pose(name, which, T)
        finally:
            self._show_poses(name)  # the pose in use, also when refused

    def _put_pose(self, name: str, which: str, T: np.ndarray) -> None:
        """Set part `name`'s `which` pose [m]; the project's bounds refuse it otherwise."""
        try:
            self.wb.assembly.set_pose(name, which, T)
        except ValueError as exc:  # pydantic's ValidationError: say it as the file would
            i = self.wb.assembly.part_names.index(name)
            raise InputError(_validation_text(f"assembly.parts[{i}].{which}", exc)) from None

    def _pose_spec(self, which: str) -> Any:
        """Return the selected part's `which` pose as the project holds it (mm, deg)."""
        a = self.wb.assembly
        return getattr(a.spec.parts[a.part_names.index(str(self.part.value))], which)

    def _pose_value(self, which: str, key: str, i: int) -> float:
        return float(getattr(self._pose_spec(which), key)[i])

    def _set_coordinate(self, which: str, key: str, i: int, v: float) -> None:
        """Set one coordinate of the selected part's pose (`key` "xyz" [mm] or "rpy" [deg])."""
        name = str(self.part.value)
        held = self._pose_spec(which)
        values = {"xyz": list(held.xyz), "rpy": list(held.rpy)}
        values[key][i] = v
        try:  # the typed pose as the file would hold it: its bounds (an angle wraps otherwise)
            type(held).model_validate(values)
        except ValueError as exc:
            k = self.wb.assembly.part_names.index(name)
            raise InputError(_validation_text(f"assembly.parts[{k}].{which}", exc)) from None
        T = np.array(getattr(self.wb.assembly.part(name), which), dtype=float)
        if key == "xyz":  # the rotation stays exactly as it is
            T[i, 3] = v * MM
        else:
            T = xyz_rpy_to_transform(T[:3, 3], np.asarray(values["rpy"], float) * DEG)
        self._put_pose(name, which, T)

    def _set_planner(self, field: str, value: float | None) -> None:
        """Set assembly.planner.`field` [mm or count]; the section's bounds refuse it otherwise."""
        planner = self.wb.assembly.spec.planner
        try:
            setattr(planner, field, value)  # validated on assignment (the project's bounds)
        except ValueError as exc:  # pydantic's ValidationError: say it as the file would
            raise InputError(_validation_text("assembly.planner", exc)) from None

    def _on_gizmo(self, event: viser.TransformControlsEvent, which: str) -> None:
        if event.phase != "end":
            return
        gz = self.start_gizmo if which == "start" else self.goal_gizmo
        T = make_transform(wxyz_to_matrix(np.asarray(gz.wxyz)), np.asarray(gz.position))
        self._set_pose(str(self.part.value), which, T)

    def _options(self) -> dict[str, object]:
        planner = str(self.planner.value)
        spec = self.wb.assembly.spec.planner  # the values the fields show
        opts: dict[str, object] = {}
        if spec.cell_size is not None:
            opts["cell_size"] = spec.cell_size * MM
        if planner == "ant":
            opts["step"] = int(spec.step)
            if spec.dis is not None:
                opts["dis"] = spec.dis * MM
        return opts

    def _on_plan(self, event: viser.GuiEvent, *, one: bool) -> None:
        name = str(self.part.value)
        buttons = [self.plan_button, self.sequence_button]
        try:
            with busy(
                self.progress, buttons, self.result, what="planning the assembly"
            ) as progress:
                plan = self.wb.assembly.plan_sequence(
                    [name] if one else None,
                    str(self.planner.value),
                    progress=progress,
                    **self._options(),  # type: ignore[arg-type]
                )
        except Exception:
            # a refused plan leaves nothing to download (the service dropped the last plan;
            # a plan refused as Busy never started and keeps it)
            self.result.content = ""
            self.download.disabled = self.wb.assembly.last_part_plan is None
            self.programs.disabled = self.wb.assembly.last_plan is None
            raise
        self.plan = plan
        pp = plan.tasks[0].part_plan if one else plan.tasks[-1].part_plan
        self._show_path(pp.key_points, pp.samples)
        r = pp.path
        head = (
            f"**{name}** ({r.planner}): **{len(r.poses)} key points**, "
            f"length {r.length * 1000:.1f} mm, planned in {r.time_s * 1000:.1f} ms "
            f"({r.checks} poses checked)"
            if one
            else f"**Sequence**: {plan.summary()}"
        )
        state = (
            "collision-free" if plan.ok else f"**{int(plan.colliding.sum())} colliding samples**"
        )
        if plan.contacts:
            state += f" (first contact: {plan.contacts[0].describe()})"
        self.result.content = f"{head}\n\nTimed motion: {plan.duration:.2f} s, {state}"
        self.download.disabled = False
        self.programs.disabled = False
        main = next(arm for arm in self.wb.assembly.arms.values() if arm.main)
        self.app.timeline.load(
            replace(plan.motions[main.name], name="Assembly" if not one else f"Assembly: {name}"),
            robot=main.setup.model,
            follow=self._follow,
        )

    def _show_path(self, keys: np.ndarray, samples: np.ndarray) -> None:
        s = self.app.server
        for h in (self.curve, self.keys):
            if h is not None:
                h.remove()
        self.curve = s.scene.add_spline_catmull_rom(
            "/assembly/path/curve",
            points=np.asarray(samples[:, :3, 3], np.float32),
            curve_type="chordal",
            thickness=0.003,
            color=PATH_COLOR,
        )
        self.keys = s.scene.add_point_cloud(
            "/assembly/path/key_points",
            points=np.asarray(keys[:, :3, 3], np.float32),
            colors=KEY_COLOR,
            point_size=0.012,
            point_shape="circle",
        )

    def _follow(self, t: float) -> None:
        plan = self.plan
        if plan is None:
            return
        a = self.wb.assembly
        i = plan.index_at(t)
        with self.app.server.atomic():
            for name, h in self.part_nodes.items():
                place(h, plan.part_poses[name][i])
                hit = i in plan.part_interference.get(name, ())
                h.color = COLLISION_COLOR if hit else a.part(name).color
            for rname, hs in self.arm_nodes.items():
                poses = a.link_poses(rname, plan.joints_at(rname, t))
                for k, h in enumerate(hs):
                    place(h, poses[min(k, len(poses) - 1)])

    def _on_download(self, event: viser.GuiEvent) -> None:
        fmt = str(self.format.value)
        text = self.wb.assembly.export_key_points(fmt)
        if event.client is not None:
            plan = self.wb.assembly.last_part_plan
            stem = plan.part if plan is not None else "part"
            event.client.send_file_download(
                f"{stem}_key_points.{fmt}", text.encode(), save_immediately=True
            )
