"""The touch-up tests' cell: the MZ07 example with its pick-and-place targets in a work object
("fixture"), that work object moved by a known correction, and the program of the moved cell
written as a pendant touch-up leaves it: every target re-taught where the moved fixture puts
it, the work object on the controller unchanged.

`touched_up_files(fmt, ...)` writes it in any format the workbench writes; `alone` moves one
target further (re-taught alone), `delete` drops a move, `add` inserts a new one."""

from __future__ import annotations

import copy
import dataclasses
import functools
import json
from pathlib import Path
from typing import Any

import numpy as np

from workbench.geometry.transforms import invert_transform, xyz_rpy_to_transform
from workbench.kinematics.target_configuration import solve_configuration
from workbench.motion.program import is_action, nearest_ik
from workbench.motion.programs.controller_program import MoveInstr, RobotProgram, Target
from workbench.motion.programs.formats import write_programs
from workbench.project import project_from_dict
from workbench.project.program_io import motion_limits, program_items, tool_data, work_objects
from workbench.project.units import matrix_to_pose, pose_to_matrix
from workbench.service import Workbench
from workbench.service.programs import controller_programs, robot_models

ROOT = Path(__file__).resolve().parents[1]
WOBJ = "fixture"
WOBJ_POSE = {"xyz": [430.0, 0.0, 440.0], "rpy": [0.0, 0.0, 5.0]}
#: the fixture's known displacement, in its own frame [m, rad]: taught = C @ planned
CORRECTION = xyz_rpy_to_transform([0.0021, -0.0014, 0.0009], np.radians([0.25, -0.2, 0.6]))


def cell_data(preset: str = "mz07") -> dict[str, Any]:
    """Return the MZ07 cell with its pose targets stated in the work object `fixture`; another
    library robot (`preset`) in its place takes the pose targets without their stored
    configurations (the MZ07's) and without the MZ07's joint targets (home, start)."""
    data = json.loads((ROOT / "projects" / "mz07_cell.json").read_text())
    data["work_objects"] = [{"name": WOBJ, "pose": WOBJ_POSE}]
    for item in data["program"]["moves"]:
        if "pose" in item:
            item["wobj"] = WOBJ
    if preset != "mz07":
        data["robot"] = {"name": preset, "preset": preset, "base": data["robot"]["base"]}
        program = data["program"]
        program.pop("start", None)
        program["moves"] = [m for m in program["moves"] if "joints" not in m]
        for m in program["moves"]:
            m.pop("configuration", None)
    return data


def moved_data(data: dict[str, Any], C: np.ndarray = CORRECTION) -> dict[str, Any]:
    """Return `data` with its work object moved by `C` (in its frame) and its targets with it."""
    out = copy.deepcopy(data)
    w = out["work_objects"][0]
    W = _matrix(w["pose"])
    W_new = W @ C
    D = W_new @ invert_transform(W)
    w["pose"] = _pose(W_new)
    for item in out["program"]["moves"]:
        if item.get("wobj") == WOBJ:
            item["pose"] = _pose(D @ _matrix(item["pose"]))
    return out


def _matrix(pose: dict[str, Any]) -> np.ndarray:
    from workbench.project.common import Pose

    return pose_to_matrix(Pose.model_validate(pose))


def _pose(T: np.ndarray) -> dict[str, list[float]]:
    p = matrix_to_pose(T)
    return {"xyz": [float(v) for v in p.xyz], "rpy": [float(v) for v in p.rpy]}


@functools.cache
def moved_program(preset: str = "mz07") -> tuple[Workbench, RobotProgram]:
    """Return the moved cell's workbench and its program stated in the UNMOVED work object
    (the targets re-taught, the controller's work object as it was): every target's joints by
    IK in its stored configuration (no plan: the posts need targets, speeds and zones)."""
    data = moved_data(cell_data(preset))
    wb = Workbench.from_dict(data, base_dir=ROOT / "projects")
    project, model = wb.project, wb.robot
    tool = tool_data(project.tool)
    orig = {w.name: w for w in work_objects(project_from_dict(cell_data(preset)))}
    q_prev = wb.setup.q0
    T_base_world = invert_transform(pose_to_matrix(project.robot.base))
    instructions: list[Any] = []
    for item in program_items(project, model.convention):
        if is_action(item):
            instructions.append(item)
            continue
        if item.joints is not None:
            target = Target(item.name, np.asarray(item.joints, float))
        else:
            T_base_tcp = T_base_world @ item.T_world_tcp
            T_flange = T_base_tcp @ invert_transform(tool.T_flange_tcp)
            if item.configuration is None:  # another robot: the solution nearest the last
                q = nearest_ik(model, T_flange, q_prev, item.name)
            else:
                q = solve_configuration(model, T_flange, item.configuration, where=item.name)
            q_prev = q
            T_wobj_tcp = invert_transform(orig[item.wobj].T_base_wobj) @ T_base_tcp
            target = Target.planned(item.name, q, model, T_wobj_tcp)
        kind = "joint" if item.type == "joint" else "linear"
        instructions.append(
            MoveInstr(kind, target, item.speed, item.zone, tool.name, item.wobj, duration=1.0)
        )
    used = {i.wobj for i in instructions if isinstance(i, MoveInstr)}
    program = RobotProgram(
        project.program.name,  # type: ignore[union-attr]
        (tool,),
        tuple(w for w in orig.values() if w.name in used),
        tuple(instructions),
        model.convention,
        model.dof,
        project.robot.name,
        motion_limits(project.robot),
    )
    return wb, program


def _shift(wb: Workbench, program: RobotProgram, ins: MoveInstr, T_shift: np.ndarray) -> MoveInstr:
    """Return `ins` with its target moved by `T_shift` in its work object, re-solved."""
    tgt = ins.target
    T_wobj_tcp = T_shift @ tgt.T_wobj_tcp  # type: ignore[operator]
    wobj = program.work_object(ins.wobj).T_base_wobj
    T_flange = wobj @ T_wobj_tcp @ invert_transform(program.tool(ins.tool).T_flange_tcp)
    q = nearest_ik(wb.robot, T_flange, tgt.q, tgt.name)
    return dataclasses.replace(ins, target=Target.planned(tgt.name, q, wb.robot, T_wobj_tcp))


def touched_up_files(
    fmt: str,
    *,
    alone: tuple[str, np.ndarray] | None = None,
    delete: str | None = None,
    add: tuple[str, str, np.ndarray] | None = None,
    joints: tuple[str, np.ndarray] | None = None,
    preset: str = "mz07",
) -> dict[str, str]:
    """Return the touched-up program as `fmt` files. `alone` (name, T in the work object):
    that target moved further; `delete`: that move left out; `add` (new name, after which
    move, T in the work object of that move's target): a move inserted; `joints` (name, dq [rad, model]): that joint target re-taught by dq; `preset`: the cell with that library robot
    (`cell_data`)."""
    wb, program = moved_program(preset)
    out = []
    for ins in program.instructions:
        if isinstance(ins, MoveInstr):
            if ins.name == delete:
                continue
            if alone is not None and ins.name == alone[0]:
                ins = _shift(wb, program, ins, alone[1])
            if joints is not None and ins.name == joints[0]:
                q = ins.target.q + joints[1]
                ins = dataclasses.replace(ins, target=dataclasses.replace(ins.target, q=q))
            out.append(ins)
            if add is not None and ins.name == add[1]:
                new = _shift(wb, program, ins, add[2])
                out.append(
                    dataclasses.replace(new, target=dataclasses.replace(new.target, name=add[0]))
                )
            continue
        out.append(ins)
    edited = dataclasses.replace(program, instructions=tuple(out))
    written = controller_programs(wb, "motion", [edited])
    return dict(write_programs(fmt, written, models=robot_models(wb, written)).files)
