"""`Workbench.calibration`: the cell as built, from readings taken on the real robot.

Each entry point reads a readings CSV (`project.calibration_readings`: units and the joint
convention), turns joints into flange poses or TCP points (`calibration.measured`), calls the
fit (`calibration.tcp`, `frame_three_point`, `frame_fit`, `robot_place`) and returns a
`CalibrationResult` (SI, the 3D view's points and frame, the summary the CLI and GUI show).
`apply` stores a result in the project (the tool's TCP, a work object, the robot's base) and
returns the project as it was, for undo.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from workbench.calibration import (
    PointsFit,
    calibrate_tcp,
    fit_points,
    fit_robot_base,
    three_point_frame,
)
from workbench.calibration.frame_fit import OUTLIER_TOLERANCE
from workbench.calibration.measured import (
    flange_poses,
    in_model_base,
    tcp_positions,
    transformed,
)
from workbench.errors import InputError
from workbench.kinematics.robot_library import library_robot
from workbench.project import Project, project_from_dict
from workbench.project.calibration_readings import (
    Readings,
    parse_known,
    parse_readings,
    work_object_name,
)
from workbench.project.common import Pose
from workbench.project.units import matrix_to_pose, pose_to_matrix
from workbench.service.calibration_result import (
    CalibrationResult,
    FloatArray,
    fit_lines,
    tcp_lines,
    three_point_lines,
)

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

ELONGATOR_LABELS = ("z", "x")
"""The labels of ABB's Z and X elongator readings in a TCP readings file."""
WOBJ_METHODS = ("3point", "fit")


class CalibrationService:
    """`Workbench.calibration`: TCP, work-object and robot-base calibration (SI results)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb

    # -- readings -------------------------------------------------------------------------
    def _readings(self, csv_text: str, source: str) -> Readings:
        wb = self.wb
        return parse_readings(csv_text, source=source, robot=wb.project.robot, dof=wb.robot.dof)

    def _base_points(self, readings: Readings) -> FloatArray:
        """Return the measured TCP points (n, 3) [m] in the model's base."""
        if readings.joints is not None:
            return tcp_positions(self.wb.robot, readings.joints, self.wb.setup.T_flange_tcp)
        preset = self.wb.project.robot.preset
        T_base_controller = np.eye(4) if preset is None else library_robot(preset).T_base_controller
        return in_model_base(readings.points, T_base_controller)

    # -- TCP ------------------------------------------------------------------------------
    def tcp(self, csv_text: str, *, source: str = "readings") -> CalibrationResult:
        """Return the project tool's TCP fitted from joint readings [deg, controller] with the
        tool tip on one fixed point in 4 or more orientations; readings labelled `z` and `x`
        are ABB's elongator points (the fixed point on the tool's +Z, +X axis): the TCP's
        orientation. InputError for position readings, too few or too alike orientations."""
        readings = self._readings(csv_text, source)
        if readings.joints is None:
            raise InputError(
                "the TCP method needs joint readings (label,j1,...): a TCP position depends on"
                " the TCP being calibrated",
                field=source,
            )
        labels = readings.labels
        approach = [i for i, label in enumerate(labels) if label.lower() not in ELONGATOR_LABELS]
        extra = {label.lower(): i for i, label in enumerate(labels) if i not in approach}
        T = flange_poses(self.wb.robot, readings.joints)
        fit = calibrate_tcp(
            T[approach],
            z_reading=T[extra["z"]] if "z" in extra else None,
            x_reading=T[extra["x"]] if "x" in extra else None,
        )
        T_world_base = self.wb.setup.T_world_base
        tips = fit.tips(T[approach])
        tool = self.wb.project.tool
        T_new = fit.keeping(self.wb.setup.T_flange_tcp)  # unmeasured orientation: kept
        T_world_tcp = T_world_base @ T[approach[-1]] @ T_new
        return CalibrationResult(
            kind="tcp",
            name=tool.name,
            T=T_new,
            T_previous=self.wb.setup.T_flange_tcp,
            T_world_frame=T_world_tcp,
            labels=tuple(labels[i] for i in approach),
            points_world=transformed(tips, T_world_base),
            residuals=fit.residuals,
            dropped=(),
            lines=tcp_lines(fit, T_new, tool.name, tuple(labels[i] for i in approach), tool.tcp)
            + _notes(readings),
        )

    # -- work objects ---------------------------------------------------------------------
    def work_object(
        self,
        csv_text: str,
        *,
        name: str,
        method: str = "3point",
        known_csv: str | None = None,
        source: str = "readings",
        known_source: str = "known",
        tolerance: float = OUTLIER_TOLERANCE,
    ) -> CalibrationResult:
        """Return the work object `name` fitted from measured points (joints through the
        project's tool, or TCP positions [mm] in the robot's base): `method` "3point"
        (labels origin, x, y: KUKA, FANUC; x1, x2, y1: ABB) or "fit" (each label a point of
        `known_csv` `label,x,y,z` [mm] in the work object's frame; outliers above `tolerance`
        [m] dropped and named). The frame is in the world, as the project stores work objects."""
        if method not in WOBJ_METHODS:
            raise InputError(f"method {method!r}: give one of {', '.join(WOBJ_METHODS)}")
        work_object_name(name)
        readings = self._readings(csv_text, source)
        measured = self._base_points(readings)
        T_world_base = self.wb.setup.T_world_base
        stored = self._stored_wobj(name)
        if method == "3point":
            if known_csv is not None:
                raise InputError("the 3-point method takes no known points; use method 'fit'")
            labels = (label.lower() for label in readings.labels)
            frame = three_point_frame(dict(zip(labels, measured, strict=True)))
            T_world = T_world_base @ frame.T
            lines = three_point_lines(frame, name, readings.labels, T_world, stored)
            residuals = np.zeros(len(measured))
            dropped: tuple[str, ...] = ()
        else:
            fit = self._fit(readings, measured, known_csv, known_source, tolerance)
            T_world = T_world_base @ fit.T
            lines = fit_lines(fit, f"work object {name!r}", T_world, stored)
            residuals, dropped = fit.residuals, fit.dropped
        return CalibrationResult(
            kind="work_object",
            name=name,
            T=T_world,
            T_previous=None if stored is None else pose_to_matrix(stored),
            T_world_frame=T_world,
            labels=readings.labels,
            points_world=transformed(measured, T_world_base),
            residuals=residuals,
            dropped=dropped,
            lines=lines + _notes(readings),
        )

    def _stored_wobj(self, name: str) -> Pose | None:
        wobjs = self.wb.project.work_objects or []
        return next((w.pose for w in wobjs if w.name == name), None)

    def _fit(
        self,
        readings: Readings,
        measured: FloatArray,
        known_csv: str | None,
        known_source: str,
        tolerance: float,
        *,
        robot_base: bool = False,
    ) -> PointsFit:
        if known_csv is None:
            raise InputError(
                "give the known points: a CSV label,x,y,z [mm] with every label of the readings",
                field=known_source,
            )
        labels, known = parse_known(known_csv, source=known_source)
        where = dict(zip(labels, known, strict=True))
        for label, line in zip(readings.labels, readings.lines, strict=True):
            if label not in where:
                raise InputError(
                    f"reading {label!r} has no known point; add {label},x,y,z to"
                    f" {known_source} or remove the reading",
                    field=f"{readings.source} line {line}, column 1 (label)",
                )
        ordered = np.array([where[label] for label in readings.labels])
        if robot_base:
            return fit_robot_base(readings.labels, ordered, measured, tolerance=tolerance)
        return fit_points(readings.labels, ordered, measured, tolerance=tolerance)

    # -- the robot's place in the cell ----------------------------------------------------
    def base(
        self,
        csv_text: str,
        *,
        known_csv: str,
        source: str = "readings",
        known_source: str = "known",
        tolerance: float = OUTLIER_TOLERANCE,
    ) -> CalibrationResult:
        """Return the robot's base in the world (T_world_base) fitted from reference points
        measured with the robot (joints through the project's tool, or TCP positions [mm] in
        its base) whose world positions [mm] `known_csv` gives (`label,x,y,z`)."""
        readings = self._readings(csv_text, source)
        measured = self._base_points(readings)
        fit = self._fit(readings, measured, known_csv, known_source, tolerance, robot_base=True)
        robot = self.wb.project.robot
        return CalibrationResult(
            kind="base",
            name=robot.name,
            T=fit.T,
            T_previous=self.wb.setup.T_world_base,
            T_world_frame=fit.T,
            labels=readings.labels,
            points_world=transformed(measured, fit.T),
            residuals=fit.residuals,
            dropped=fit.dropped,
            lines=fit_lines(fit, f"robot {robot.name!r} base in the world", fit.T, robot.base)
            + _notes(readings),
        )

    # -- apply ----------------------------------------------------------------------------
    def apply(self, result: CalibrationResult) -> Project:
        """Store `result` in the project (the tool's TCP, the work object, created if missing,
        or the robot's base) and return the project as it was (for undo: `replace_project`).
        Nothing else of the project changes; on any error the project stays as it was."""
        wb = self.wb
        previous = wb.project.model_copy(deep=True)
        data: dict[str, Any] = wb.project.model_dump(mode="json", exclude_none=True)
        pose = _pose_json(result.T)
        if result.kind == "tcp":
            data["tool"]["tcp"] = pose
        elif result.kind == "base":
            data["robot"]["base"] = pose
        elif result.kind == "work_object":
            wobjs = [w for w in data.get("work_objects", []) if w["name"] != result.name]
            at = next(
                (i for i, w in enumerate(data.get("work_objects", [])) if w["name"] == result.name),
                len(wobjs),
            )
            data["work_objects"] = [*wobjs[:at], {"name": result.name, "pose": pose}, *wobjs[at:]]
        else:
            raise InputError(f"result kind {result.kind!r}: give a calibration result")
        wb.replace_project(project_from_dict(data, source=f"calibration of {result.name}"))
        return previous


def calibration_of(wb: Any) -> CalibrationService:
    """Return the calibration service of Workbench `wb` (its `calibration` property)."""
    return CalibrationService(wb)


def _notes(readings: Readings) -> tuple[str, ...]:
    return tuple(f"  note: {note}" for note in readings.notes)


def _pose_json(T: FloatArray) -> dict[str, list[float]]:
    """Return the project pose (mm, deg) of a transform [m], rounded to 0.1 um and 1e-6 deg."""
    pose = matrix_to_pose(T)
    return {
        "xyz": [round(v, 4) + 0.0 for v in pose.xyz],
        "rpy": [round(v, 6) + 0.0 for v in pose.rpy],
    }
