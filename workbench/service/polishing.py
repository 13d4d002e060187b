"""The open project's polishing (seed 004): workpiece, fitted surface, tool paths, force control.

`Workbench.polishing` reads the project's `polishing` section (mm, deg, N), works in SI
(m, rad, s, N) and in the world frame: the workpiece is placed at `polishing.pose`, so
paths, TCP poses and the robot motion are all world coordinates.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import trimesh
from numpy.typing import NDArray
from pydantic import ValidationError

from workbench.errors import InputError, MeshError, WorkbenchError
from workbench.geometry.transforms import invert_transform
from workbench.motion import Move, Program, smooth_joint_path
from workbench.polishing import (
    Coverage,
    ForceControlResult,
    HybridForceParams,
    ToolPath,
    WorkpieceReport,
    build_chart,
    fit_bezier_triangles,
    force_offset,
    load_workpiece,
    path_coverage,
    raster_toolpath,
    simulate_hybrid_force_control,
    spiral_toolpath,
)
from workbench.polishing.bezier import BezierSurface
from workbench.polishing.chart import SurfaceChart
from workbench.polishing.orientation import instability_message
from workbench.polishing.robot_path import solve_path_ik, tool_frames
from workbench.project.polishing import PolishingSpec
from workbench.service.convert import MM, pose_to_matrix
from workbench.service.motion_plan import MotionPlan, export_text, plan_from_trajectory

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

Progress = Callable[[float, str], None]
F64 = NDArray[np.float64]
PATTERNS = ("spiral", "raster")
ORIENTATION = ("kp", "kd", "ki")  # the section's names of the orientation gains


@dataclass(frozen=True)
class PolishingPath:
    """A planned polishing path in the world frame [m] with its coverage of the fitted surface.

    `path.points`/`path.normals` (N, 3) lie on the fitted surface (process points);
    `commanded` (N, 3) are the TCP targets, process points moved `offset` = F/k [m] into the
    surface; `tool_z` (N, 3) unit tool axes into the surface.
    """

    path: ToolPath
    coverage: Coverage
    force: float  # [N]
    offset: float  # [m] D = F/k
    commanded: F64 = field(repr=False)

    @property
    def length(self) -> float:
        """Return the length [m] of the process part of the path."""
        p = self.path.points[self.path.is_process]
        return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum())

    def summary(self) -> str:
        """Return a one-line human summary (mm, %)."""
        p = self.path
        return (
            f"{p.pattern}: {int(p.is_process.sum())} points, {p.n_passes} passes, "
            f"{self.length * 1000:.0f} mm long; coverage {self.coverage.fraction * 100:.1f} % "
            f"(tool radius {self.coverage.tool_radius / MM:g} mm), largest gap "
            f"{self.coverage.largest_gap / MM:.1f} mm; offset D = F/k = {self.offset / MM:.2f} mm"
        )


@dataclass(frozen=True)
class PolishingSimulation:
    """Force/position hybrid control along the path: the record and its figures.

    `result.t` [s], `result.force` [N], `result.tracking_error` [m],
    `result.orientation_error` [rad]; `max_force_error` [N] is the largest |F - F_target|
    and `max_orientation_error` [rad] the largest tilt of the tool z from the actual surface
    normal, both after `settle_time` [s] (the dwell, when the force has built up) until the
    feed ends; `max_tracking_error` [m] over the whole run.
    """

    result: ForceControlResult
    target_force: float
    feed: float  # [m/s]
    settle_time: float
    max_force_error: float
    max_tracking_error: float
    max_orientation_error: float

    def summary(self) -> str:
        """Return a one-line human summary."""
        return (
            f"target {self.target_force:g} N at {self.feed / MM:g} mm/s over "
            f"{self.result.t[-1]:.1f} s: force within ±{self.max_force_error:.2f} N after "
            f"{self.settle_time:g} s, tracking error ≤ {self.max_tracking_error / MM:.3f} mm, "
            f"tool axis within {np.degrees(self.max_orientation_error):.2f}° of the normal"
        )


class PolishingService:
    """`Workbench.polishing`: the polishing workflow of the open project (SI units)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
        self._mesh: trimesh.Trimesh | None = None
        self._report: WorkpieceReport | None = None
        self._chart: SurfaceChart | None = None
        self._surface: BezierSurface | None = None
        self.last_path: PolishingPath | None = None
        self.last_motion: MotionPlan | None = None
        self.last_simulation: PolishingSimulation | None = None
        self.configuration: str | None = None  # arm configuration of the last motion

    # -- section and workpiece -----------------------------------------------------------
    @property
    def spec(self) -> PolishingSpec:
        """Return the project's `polishing` section; InputError when there is none."""
        spec = self.wb.project.polishing
        if spec is None:
            raise InputError(
                "polishing: the project has no 'polishing' section; add one with at least "
                "'workpiece' (an STL, OBJ or PLY file)"
            )
        return spec

    @property
    def T_world_workpiece(self) -> F64:
        """Return the workpiece frame's world pose (4, 4) [m]."""
        return pose_to_matrix(self.spec.pose)

    def _resolve(self, path: str | Path) -> Path:
        p = Path(path)
        return p if p.is_absolute() else self.wb.base_dir / p

    def load_workpiece(
        self, path: str | Path | None = None, *, units: str | None = None
    ) -> WorkpieceReport:
        """Load and check the workpiece; return its `WorkpieceReport` (lengths in m).

        Default: the section's `workpiece` and `units`. A new `path`/`units` is written into
        the section only when it loads. Raises `MeshError` naming `polishing.workpiece` for a
        missing, empty or non-mesh file and `polishing.units` for a part in the wrong units.
        """
        spec = self.spec
        file = spec.workpiece if path is None else str(path)
        u = spec.units if units is None else units
        if u not in ("auto", "mm", "m"):
            raise InputError(f"polishing.units: must be 'auto', 'mm' or 'm', got {u!r}")
        try:
            mesh, report = load_workpiece(self._resolve(file), units=u)  # type: ignore[arg-type]
        except MeshError as exc:
            where = "polishing.units" if "units" in str(exc) and "1000x" in str(exc) else None
            raise MeshError(f"{where or 'polishing.workpiece'}: {exc}") from None
        mesh.apply_transform(self.T_world_workpiece)
        try:
            chart = build_chart(mesh)
        except WorkbenchError as exc:
            raise type(exc)(f"polishing.workpiece: {exc}") from None
        # Commit only what loaded: a bad file leaves the previous workpiece in place.
        if path is not None:
            spec.workpiece = str(path)
        if units is not None:
            spec.units = u  # type: ignore[assignment]
        self._mesh, self._report, self._chart = mesh, report, chart
        self._surface = fit_bezier_triangles(mesh, vertex_normals=chart.vertex_normals)
        self.last_path = self.last_motion = self.last_simulation = None
        return report

    def _ensure(self) -> tuple[trimesh.Trimesh, SurfaceChart, BezierSurface]:
        if self._mesh is None:
            self.load_workpiece()
        assert self._mesh is not None and self._chart is not None and self._surface is not None
        return self._mesh, self._chart, self._surface

    @property
    def workpiece(self) -> trimesh.Trimesh:
        """Return the workpiece mesh in the world frame [m] (loaded on first use)."""
        return self._ensure()[0]

    @property
    def report(self) -> WorkpieceReport:
        """Return the checks of the loaded workpiece."""
        self._ensure()
        assert self._report is not None
        return self._report

    @property
    def surface(self) -> BezierSurface:
        """Return the fitted quadratic Bézier surface (world frame, m)."""
        return self._ensure()[2]

    # -- parameters ------------------------------------------------------------------------
    def set_parameters(
        self,
        *,
        pattern: str | None = None,
        step: float | None = None,
        spacing: float | None = None,
        force: float | None = None,
        feed: float | None = None,
        tool_radius: float | None = None,
    ) -> None:
        """Set path and process parameters (SI: m, N, m/s) in the section (stored in mm).

        Raises `InputError` naming the field: a step or spacing not in (0, part size), a
        force of 0 or above `max_force`, a feed above the controller's speed limit.
        """
        spec = self.spec
        new = spec.model_dump()
        if pattern is not None:
            if pattern not in PATTERNS:
                raise InputError(f"polishing.pattern: {pattern!r} is not one of {PATTERNS}")
            new["pattern"] = pattern
        for name, val in (
            ("step", step),
            ("spacing", spacing),
            ("feed", feed),
            ("tool_radius", tool_radius),
        ):
            if val is not None:
                if not np.isfinite(val) or val <= 0:
                    raise InputError(f"polishing.{name}: must be > 0, got {val!r} (SI units)")
                new[name] = float(val) / MM
        if force is not None:
            if not np.isfinite(force) or force <= 0:
                raise InputError(f"polishing.force: must be > 0 N, got {force!r}")
            if force > spec.max_force:
                raise InputError(
                    f"polishing.force: {force:g} N is above the tool's limit max_force = "
                    f"{spec.max_force:g} N; give a force in (0, {spec.max_force:g}] N"
                )
            new["force"] = float(force)
        if new["feed"] > spec.controller.max_speed:
            raise InputError(
                f"polishing.feed: {new['feed']:g} mm/s is above controller.max_speed = "
                f"{spec.controller.max_speed:g} mm/s"
            )
        if self._mesh is not None:
            self._check_lengths(new["step"] * MM, new["spacing"] * MM)
        try:
            checked = PolishingSpec.model_validate(new)
        except ValidationError as exc:
            err = exc.errors()[0]
            where = ".".join(str(x) for x in err["loc"])
            raise InputError(f"polishing.{where}: {err['msg']}") from None
        assert self.wb.project.polishing is spec
        self.wb.project.polishing = checked
        self.last_path = self.last_motion = self.last_simulation = None

    def _check_lengths(self, step: float, spacing: float) -> None:
        size = float(np.ptp(np.asarray(self.workpiece.vertices), axis=0).max())
        for name, val in (("step", step), ("spacing", spacing)):
            if val >= size:
                raise InputError(
                    f"polishing.{name}: {val / MM:g} mm is larger than the part (largest extent "
                    f"{size / MM:.1f} mm); give a {name} well below the part size"
                )

    def params(self) -> HybridForceParams:
        """Return the controller gains and contact model of the section in SI.

        Raises `InputError` naming `polishing.controller.orientation` for orientation gains
        that make that loop unstable at the control rate and latency, with the change of one
        gain that makes it stable."""
        s = self.spec
        c, k = s.controller, s.contact
        o = c.orientation
        # The file's section is checked on load; this catches gains changed on the live model
        # (`validate_assignment` checks one field, not the loop it belongs to).
        msg = (
            instability_message(o.kp, o.kd, o.ki, c.control_rate, c.latency * 1e-3, ORIENTATION)
            if o.enabled
            else None
        )
        if msg is not None:
            raise InputError(f"polishing.controller.orientation: {msg}")
        return HybridForceParams(
            control_rate=c.control_rate,
            latency=c.latency * 1e-3,
            kpp=c.kpp,
            kpd=c.kpd,
            kfp=c.kfp * MM,
            kfi=c.kfi * MM,
            stiffness=k.stiffness,
            damping=k.damping,
            friction=k.friction,
            lateral_stiffness=k.lateral_stiffness,
            form_error=k.form_error * MM,
            form_wavelength=k.form_wavelength * MM,
            noise_std=k.noise_std,
            filter_cutoff=k.filter_cutoff,
            max_speed=c.max_speed * MM,
            max_accel=c.max_accel * MM,
            max_force=s.max_force,
            seed=k.seed,
            orientation_loop=c.orientation.enabled,
            kop=c.orientation.kp,
            kod=c.orientation.kd,
            koi=c.orientation.ki,
            max_angular_speed=math.radians(c.orientation.max_speed),
        )

    # -- path ------------------------------------------------------------------------------
    def plan_path(self, *, progress: Progress | None = None) -> PolishingPath:
        """Return the `PolishingPath` of the section's pattern, step and spacing (world, m).

        The path lies on the fitted surface; its coverage is measured for `tool_radius`.
        Kept as `last_path`.
        """
        report = progress or (lambda f, m: None)
        spec = self.spec
        report(0.0, "loading and fitting the workpiece")
        mesh, chart, surface = self._ensure()
        step, spacing = spec.step * MM, spec.spacing * MM
        self._check_lengths(step, spacing)
        report(0.2, f"{spec.pattern} path")
        planner = spiral_toolpath if spec.pattern == "spiral" else raster_toolpath
        try:
            path = planner(
                mesh,
                step,
                spacing,
                surface=surface,
                chart=chart,
                lead_height=spec.lead_height * MM,
                n_lead=spec.n_lead,
            )
        except InputError as exc:
            raise InputError(f"polishing: {exc}") from None
        report(0.7, "coverage")
        cov = path_coverage(surface, path, spec.tool_radius * MM)
        offset = force_offset(spec.force, spec.contact.stiffness)
        commanded = path.pressed_points(spec.force, spec.contact.stiffness)
        out = PolishingPath(path, cov, float(spec.force), offset, commanded)
        self.last_path = out
        self.last_motion = self.last_simulation = None
        report(1.0, "done")
        return out

    def _path(self) -> PolishingPath:
        return self.last_path or self.plan_path()

    def point_labels(self, path: ToolPath) -> list[str]:
        """Return a name per path point: 'lead-in 1', 'process point 17', 'lead-out 2'."""
        names = {0: "lead-in", 1: "process point", 2: "lead-out"}
        count = {0: 0, 1: 0, 2: 0}
        out = []
        for k in path.kind.tolist():
            count[k] += 1
            out.append(f"{names[k]} {count[k]}")
        return out

    def tcp_poses(self, path: PolishingPath | None = None) -> F64:
        """Return world TCP poses (N, 4, 4) [m] along the path: z = tool axis into the surface.

        Positions are the commanded points (process points D = F/k into the surface); x is
        the workpiece's x projected onto the tool's plane (the round tool's free turn).
        """
        p = path or self._path()
        return tool_frames(p.commanded, p.path.tool_z, self.T_world_workpiece[:3, 0])

    # -- robot motion ----------------------------------------------------------------------
    def plan_motion(
        self, *, dt: float | None = None, progress: Progress | None = None
    ) -> MotionPlan:
        """Return the robot's `MotionPlan` along the path at the section's feed (jerk-limited).

        IK in one arm configuration (the one nearest the current joints at the first point);
        unreachable points are named (`UnreachableError`). The trajectory starts at the first
        lead-in point. Samples every `dt` [s] (default: at most ~600 samples) are checked
        for limits and collisions. Kept as `last_motion`; `export_program` writes it.
        """
        report = progress or (lambda f, m: None)
        pp = self._path()
        spec = self.spec
        setup = self.wb.setup
        model = self.wb.robot
        report(0.05, "TCP poses and inverse kinematics")
        T_world_tcp = self.tcp_poses(pp)
        T_base_world = invert_transform(setup.T_world_base)
        T_base_tcp = T_base_world @ T_world_tcp
        T_base_flange = T_base_tcp @ invert_transform(setup.T_flange_tcp)
        q, config = solve_path_ik(
            model, T_base_flange, self.wb.joints, labels=self.point_labels(pp.path)
        )
        report(0.3, "jerk-limited timing")
        feed = spec.feed * MM
        vmax = np.asarray(model.max_velocity, float)
        ds = np.maximum(np.linalg.norm(np.diff(T_world_tcp[:, :3, 3], axis=0), axis=1), 1e-9)
        dq = np.abs(np.diff(q, axis=0))
        seg_v = np.clip(dq * (feed / ds)[:, None], 1e-3 * vmax, vmax)
        n_lead = int(pp.path.is_lead_in.sum())
        traj = smooth_joint_path(
            q,
            seg_v,
            model.max_acceleration,
            model.max_jerk,
            position_limits=model.limits,
            exact_stop=[0, n_lead, len(q) - 1],
        )
        moves = [Move.joint(q[0], speed=0.5, name="approach")]
        moves += [
            Move.linear(T, speed=feed, zone=0.0 if i in (0, len(T_base_tcp) - 2) else 0.5 * MM)
            for i, T in enumerate(T_base_tcp[1:])
        ]
        program = Program("polish", tuple(moves))
        step_t = dt if dt is not None else max(0.02, traj.duration / 600)
        plan = plan_from_trajectory(
            program,
            traj,
            setup,
            self.wb.checker,
            dt=step_t,
            validate_dt=max(0.01, traj.duration / 5000),
            progress=lambda f, m: report(0.5 + 0.5 * f, m),
        )
        self.configuration = config
        self.last_motion = plan
        report(1.0, "done")
        return plan

    def export_program(self, fmt: str) -> str:
        """Return the polishing motion as a robot program or samples (rapid, krl, ls, urscript, csv, json)."""
        return export_text(self.last_motion or self.plan_motion(), fmt)

    # -- force control ---------------------------------------------------------------------
    def simulate(self, *, progress: Progress | None = None) -> PolishingSimulation:
        """Return the `PolishingSimulation` of the hybrid force control over the path.

        Process points and normals of the path, the section's force, feed, dwell, gains and
        contact model. Kept as `last_simulation`.
        """
        report = progress or (lambda f, m: None)
        params = self.params()  # bad gains are named before any path is planned
        pp = self._path()
        spec = self.spec
        proc = pp.path.is_process
        report(0.1, "force/position hybrid control")
        feed = spec.feed * MM
        try:
            res = simulate_hybrid_force_control(
                pp.path.points[proc],
                pp.path.normals[proc],
                spec.force,
                feed,
                params=params,
                dwell=spec.dwell,
            )
        except InputError as exc:
            raise InputError(f"polishing: {exc}") from None
        settle = spec.dwell if spec.dwell > 0 else min(0.5, 0.1 * float(res.t[-1]))
        feed_end = spec.dwell + pp.length / feed
        window = (res.t >= settle) & (res.t <= feed_end)
        ferr = float(np.max(np.abs(res.force[window] - spec.force))) if window.any() else np.nan
        oerr = float(np.max(res.orientation_error[window])) if window.any() else np.nan
        sim = PolishingSimulation(
            result=res,
            target_force=float(spec.force),
            feed=feed,
            settle_time=float(settle),
            max_force_error=ferr,
            max_tracking_error=float(res.tracking_error.max()),
            max_orientation_error=oerr,
        )
        self.last_simulation = sim
        report(1.0, "done")
        return sim

    def summary(self) -> dict[str, Any]:
        """Return the workpiece report and the last results as plain values (for display)."""
        out: dict[str, Any] = {"report": self.report}
        if self.last_path is not None:
            out["path"] = self.last_path.summary()
        if self.last_simulation is not None:
            out["simulation"] = self.last_simulation.summary()
        return out
