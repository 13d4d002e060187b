"""The touch-up round trip on the project side: the program's moves as the comparison takes
them (`planned_targets`, `work_object_frames`: SI), and a comparison applied back into a new
project dict (mm, deg: `touched_up_project`).

Modes of applying (`TOUCHUP_MODES`):

- "work_object": each work object whose targets share a correction takes it (its pose becomes
  `T_world_wobj @ C`); its targets that agree keep their coordinates in the work object (so
  they move with it in the world); targets that do not agree, targets in the robot base and
  joint targets take the pose (or joints) taught on the pendant.
- "targets": the work objects stay; every moved target takes its taught pose (or joints).
- "both": the work objects take their corrections and every moved target its taught pose.

Moves added or deleted on the pendant are noted, not applied (the Motion tab edits them, or
`import` takes the whole program).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform
from workbench.motion.programs.touchup import PlannedTarget, TouchupReport, TouchupRow
from workbench.project.models import MoveSpec
from workbench.project.program_io import BASE_WOBJ
from workbench.project.units import matrix_to_pose, pose_to_matrix, to_deg

if TYPE_CHECKING:
    from workbench.kinematics.model import RobotModel
    from workbench.project.models import Project

FloatArray = NDArray[np.float64]

TOUCHUP_MODES = ("work_object", "targets", "both")


def work_object_frames(project: Project) -> dict[str, FloatArray]:
    """Return the work objects in the world (4, 4) [m] by name, the robot base as "base"."""
    frames = {BASE_WOBJ: pose_to_matrix(project.robot.base)}
    for w in project.work_objects or ():
        frames[w.name] = pose_to_matrix(w.pose)
    return frames


def base_and_tool(project: Project) -> tuple[FloatArray, FloatArray]:
    """Return the robot base in the world and the tool's TCP in the flange, (4, 4) [m] each."""
    return pose_to_matrix(project.robot.base), pose_to_matrix(project.tool.tcp)


def planned_targets(project: Project, model: RobotModel) -> list[PlannedTarget]:
    """Return the program's moves as `PlannedTarget`s: TCP pose in the world (a joint target's
    through FK and the project's tool), the work object, the index in `program.moves`."""
    if project.program is None:
        return []
    T_world_base = pose_to_matrix(project.robot.base)
    T_flange_tcp = pose_to_matrix(project.tool.tcp)
    out = []
    for k, item in enumerate(project.program.moves):
        if not isinstance(item, MoveSpec):
            continue
        si = item.to_si(model.convention)
        if si.T_world_tcp is not None:
            T, q = si.T_world_tcp, None
        else:
            q = np.asarray(si.joints, float)
            T = T_world_base @ model.fk(q) @ T_flange_tcp
        out.append(PlannedTarget(k, item.name or f"move_{k}", si.type, si.wobj, T, q))
    return out


def _pose(T: FloatArray) -> dict[str, list[float]]:
    p = matrix_to_pose(T)
    return {"xyz": [float(v) for v in p.xyz], "rpy": [float(v) for v in p.rpy]}


def _folded(report: TouchupReport, mode: str, notes: list[str]) -> dict[str, FloatArray]:
    """Return D = T_new @ inv(T_old) of every work object the mode folds a correction into."""
    out: dict[str, FloatArray] = {}
    if mode == "targets":
        return out
    for c in report.corrections:
        if not c.significant(report.settings):
            continue
        if c.wobj == BASE_WOBJ:
            notes.append(
                "base: the moves in the robot base share a correction, but there is no work"
                " object to fold it into; they keep their taught poses (put them in a work"
                " object to correct it as one)"
            )
            continue
        out[c.wobj] = c.T_world_wobj_new @ invert_transform(c.T_world_wobj)
    return out


def _apply_row(
    item: dict[str, Any],
    row: TouchupRow,
    fold: FloatArray | None,
    mode: str,
    convention: Any,
) -> str | None:
    """Change the move `item` (a dict) as `mode` says; return what changed, or None."""
    p, t = row.planned, row.taught
    assert p is not None and t is not None
    if "joints" in item:
        if not row.moved:
            return None
        q = convention.to_controller(t.q) if convention is not None else t.q
        item["joints"] = [float(v) for v in to_deg(q)]
        return "joints as taught"
    if fold is not None and row.agrees and mode == "work_object":
        item["pose"] = _pose(fold @ p.T_world_tcp)
        return f"moves with {row.wobj}"
    if row.moved:
        item["pose"] = _pose(t.T_world_tcp)
        return "pose as taught"
    return None


def touched_up_project(
    project: Project, report: TouchupReport, mode: str, convention: Any = None
) -> tuple[dict[str, Any], tuple[str, ...]]:
    """Return the project dict with `report` applied in `mode` (`TOUCHUP_MODES`) and the notes
    (what changed, what was not applied). `convention`: the robot's joint convention (the
    taught joints, model [rad], are stored as the controller's degrees)."""
    if mode not in TOUCHUP_MODES:
        raise InputError(f"mode: {mode!r} is not one of {', '.join(TOUCHUP_MODES)}", field="mode")
    if project.program is None:
        raise InputError("touch-up: the project has no program to apply it to", field="program")
    notes: list[str] = []
    data = project.model_dump(mode="json", exclude_none=True)
    folds = _folded(report, mode, notes)
    for w in data.get("work_objects", []):
        if w["name"] in folds:
            c = next(c for c in report.corrections if c.wobj == w["name"])
            w["pose"] = _pose(c.T_world_wobj_new)
            notes.append(f"work object {w['name']}: corrected")
    moves = data["program"]["moves"]
    for row in report.rows:
        if row.status == "deleted":
            notes.append(
                f"{row.name}: deleted on the pendant; kept in the project (delete it in the"
                " Motion tab, or import the program to take it whole)"
            )
        elif row.status == "added":
            notes.append(
                f"{row.name}: added on the pendant (line {row.taught.line}); not added to the"  # type: ignore[union-attr]
                " project (teach it in the Motion tab, or import the program to take it whole)"
            )
        else:
            assert row.planned is not None
            what = _apply_row(moves[row.planned.index], row, folds.get(row.wobj), mode, convention)
            if what:
                notes.append(f"{row.name}: {what}")
    return data, tuple(notes)
