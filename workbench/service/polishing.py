"""The open project's polishing (seed 004): workpiece, fitted surface, tool paths, force control.

`Workbench.polishing` reads the project's `polishing` section through its SI spec
(`PolishingSpec.to_si()`: m, rad, s, N) and works in the world frame: the workpiece is
placed at `polishing.pose`, so paths, TCP poses and the robot motion are all world
coordinates. The path, the robot motion and the simulation are `workbench.polishing`'s.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.errors import InputError, WorkbenchError
from workbench.polishing import (
    MESH_UNITS,
    PATTERNS,
    BezierSurface,
    FittedWorkpiece,
    PolishingPath,
    PolishingSimulation,
    WorkpieceReport,
    fit_workpiece,
    plan_process_motion,
    plan_process_path,
    simulate_process,
    subdivided_surface_mesh,
    tool_frames,
)
from workbench.polishing.force_control import HybridForceParams
from workbench.polishing.process_path import check_path_lengths, point_labels
from workbench.polishing.program import RobotProgram, polishing_program
from workbench.project.cad import step_tolerance
from workbench.project.paths import shown_path
from workbench.project.polishing import PolishingSI, PolishingSpec
from workbench.project.program_io import motion_limits, tool_data
from workbench.service.motion_plan import MotionPlan, plan_from_trajectory
from workbench.service.plan_limits import limited
from workbench.service.polishing_faces import SolidFaces
from workbench.service.section import SectionService

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

__all__ = ["MESH_UNITS", "PATTERNS", "PolishingPath", "PolishingService", "PolishingSimulation"]

Progress = Callable[[float, str], None]
F64 = NDArray[np.float64]


class PolishingService(SectionService[PolishingSpec], SolidFaces):
    """`Workbench.polishing`: the polishing workflow of the open project (SI units)."""

    section = "polishing"
    missing = "add one with at least 'workpiece' (an STL, OBJ, PLY or STEP file)"
    #: The path patterns and workpiece units the section accepts (the GUI's option lists).
    patterns = PATTERNS
    mesh_units = MESH_UNITS

    def __init__(self, wb: Workbench) -> None:
        super().__init__(wb)
        self._fitted: FittedWorkpiece | None = None
        self.last_path: PolishingPath | None = None
        self.last_motion: MotionPlan | None = None
        self.last_simulation: PolishingSimulation | None = None
        self.configuration: str | None = None  # arm configuration of the last motion

    # -- section and workpiece -----------------------------------------------------------
    @property
    def si(self) -> PolishingSI:
        """Return the section in SI, checked as a whole (`InputError` naming the field)."""
        return self.spec.to_si()

    @property
    def T_world_workpiece(self) -> F64:
        """Return the workpiece frame's world pose (4, 4) [m]."""
        return self.si.T_world_workpiece

    def _resolve(self, path: str | Path) -> Path:
        return self.wb.folders.check_file(path, "polishing.workpiece", kind="mesh")

    def load_workpiece(
        self, path: str | Path | None = None, *, units: str | None = None
    ) -> WorkpieceReport:
        """Load and check the workpiece; return its `WorkpieceReport` (lengths in m).

        Default: the section's `workpiece`, `units`, `faces` (a new `path`: the whole file),
        written into the section only when it loads. `MeshError` naming `polishing.workpiece`
        for a missing, empty or non-mesh file, `.units` for wrong units, `.faces` (the field)."""
        spec = self.spec
        file = spec.workpiece if path is None else str(path)
        u = spec.units if units is None else units
        if u not in MESH_UNITS:
            raise InputError(f"polishing.units: must be 'auto', 'mm' or 'm', got {u!r}")
        real = self._resolve(file)  # InputError naming polishing.workpiece if it leaves
        try:
            tol = step_tolerance(self.wb.project.cad)
            faces = spec.faces if path is None else None
            fitted = fit_workpiece(real, u, self.T_world_workpiece, tol, shown_path(file), faces)  # type: ignore[arg-type]
        except WorkbenchError as exc:  # the loader names units and faces; else: the file
            raise exc.within(
                "polishing" if exc.field in ("units", "faces") else "polishing.workpiece"
            ) from exc
        # Commit only what loaded: a bad file leaves the previous workpiece in place.
        if path is not None:
            spec.workpiece, spec.faces = str(path), None
        if units is not None:
            spec.units = u  # type: ignore[assignment]
        self._fitted = fitted
        self.last_path = self.last_motion = self.last_simulation = None
        return fitted.report

    def _ensure(self) -> FittedWorkpiece:
        if self._fitted is None:
            self.load_workpiece()
        assert self._fitted is not None
        return self._fitted

    @property
    def workpiece(self) -> trimesh.Trimesh:
        """Return the workpiece mesh in the world frame [m] (loaded on first use)."""
        return self._ensure().mesh

    @property
    def report(self) -> WorkpieceReport:
        """Return the checks of the loaded workpiece."""
        return self._ensure().report

    @property
    def surface(self) -> BezierSurface:
        """Return the fitted quadratic Bézier surface (world frame, m)."""
        return self._ensure().surface

    def surface_mesh(self) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        """Return (vertices [m], faces) of the fitted surface for display, each patch split in 4."""
        return subdivided_surface_mesh(self.surface)

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
        checked = self.spec.updated(
            pattern=pattern,
            step=step,
            spacing=spacing,
            force=force,
            feed=feed,
            tool_radius=tool_radius,
        )
        if self._fitted is not None:
            si = checked.to_si()
            self._check_lengths(self._fitted.mesh, si.step, si.spacing)
        self.wb.project.polishing = checked
        self.last_path = self.last_motion = self.last_simulation = None

    @staticmethod
    def _check_lengths(mesh: trimesh.Trimesh, step: float, spacing: float) -> None:
        try:
            check_path_lengths(mesh, step, spacing)
        except InputError as exc:
            raise exc.within("polishing") from exc

    def params(self) -> HybridForceParams:
        """Return the controller gains and contact model of the section in SI.

        Raises `InputError` naming `polishing.controller.orientation` for orientation gains
        that make that loop unstable at the control rate and latency, with the change of one
        gain that makes it stable (the section's own check, run again on the live model)."""
        return self.si.control

    # -- path ------------------------------------------------------------------------------
    @limited("the polishing path")
    def plan_path(self, *, progress: Progress | None = None) -> PolishingPath:
        """Return the `PolishingPath` of the section's pattern, step and spacing (world, m).

        The path lies on the fitted surface; its coverage is measured for `tool_radius`.
        Kept as `last_path`; `cancel()` or `planning.time_limit` ends it."""
        report = progress or (lambda f, m: None)
        si = self.si
        report(0.0, "loading and fitting the workpiece")
        w = self._ensure()
        self._check_lengths(w.mesh, si.step, si.spacing)
        try:
            out = plan_process_path(
                w.mesh,
                w.chart,
                w.surface,
                pattern=si.pattern,
                step=si.step,
                spacing=si.spacing,
                lead_height=si.lead_height,
                n_lead=si.n_lead,
                tool_radius=si.tool_radius,
                force=si.force,
                stiffness=si.control.stiffness,
                progress=report,
            )
        except InputError as exc:
            raise exc.within("polishing") from exc
        self.last_path = out
        self.last_motion = self.last_simulation = None
        report(1.0, "done")
        return out

    def _path(self) -> PolishingPath:
        return self.last_path or self.plan_path()

    def tcp_poses(self, path: PolishingPath | None = None) -> F64:
        """Return world TCP poses (N, 4, 4) [m] along the path: z = tool axis into the surface.

        Positions are the commanded points (process points D = F/k into the surface); x is
        the workpiece's x projected onto the tool's plane (the round tool's free turn).
        """
        p = path or self._path()
        return tool_frames(p.commanded, p.path.tool_z, self.T_world_workpiece[:3, 0])

    # -- robot motion ----------------------------------------------------------------------
    @limited("the polishing motion")
    def plan_motion(
        self, *, dt: float | None = None, progress: Progress | None = None
    ) -> MotionPlan:
        """Return the robot's `MotionPlan` along the path at the section's feed (jerk-limited).

        IK in one arm configuration (the one nearest the current joints at the first point);
        unreachable points are named (`UnreachableError`). The trajectory starts at the first
        lead-in point. Samples every `dt` [s] (default: at most ~600 samples) are checked
        for limits and collisions. Kept as `last_motion`; `export_program` writes it."""
        report = progress or (lambda f, m: None)
        pp = self._path()
        setup = self.wb.setup
        report(0.05, "TCP poses and inverse kinematics")
        motion = plan_process_motion(
            self.wb.robot,
            self.tcp_poses(pp),
            setup.T_world_base,
            setup.T_flange_tcp,
            self.wb.setup.q0,
            self.si.feed,
            n_lead=int(pp.path.is_lead_in.sum()),
            labels=point_labels(pp.path),
        )
        report(0.3, "jerk-limited timing")
        plan = plan_from_trajectory(
            motion.program,
            motion.trajectory,
            setup,
            self.plan_checker(),
            policy=self.wb.collision_policy,
            dt=motion.sample_dt(dt),
            validate_dt=motion.validate_dt,
            progress=lambda f, m: report(0.5 + 0.5 * f, m),
        )
        self.configuration = motion.configuration
        self.last_motion = plan
        report(1.0, "done")
        return plan

    def robot_programs(self, plan: MotionPlan | None = None) -> list[RobotProgram]:
        """Return the motion (default: the last) as a robot program (`polishing.program`)."""
        plan, wb = plan or self.last_motion or self.plan_motion(), self.wb
        robot = wb.project.robot
        where = (wb.setup.T_world_base, self.T_world_workpiece, self._path().path.is_process)
        args = (plan.trajectory, wb.robot, tool_data(wb.project.tool), *where, self.si, wb.setup.q0)
        return [polishing_program(*args, robot=robot.name, limits=motion_limits(robot))]

    # -- force control ---------------------------------------------------------------------
    def simulate(self, *, progress: Progress | None = None) -> PolishingSimulation:
        """Return the `PolishingSimulation` of the hybrid force control over the path.

        Process points and normals of the path, the section's force, feed, dwell, gains and
        contact model. Kept as `last_simulation`.
        """
        report = progress or (lambda f, m: None)
        si = self.si  # bad gains are named before any path is planned
        pp = self._path()
        report(0.1, "force/position hybrid control")
        try:
            sim = simulate_process(pp, si.force, si.feed, si.dwell, si.control)
        except InputError as exc:
            raise exc.within("polishing") from exc
        self.last_simulation = sim
        report(1.0, "done")
        return sim
