"""Read-back programs turned into joints: each target re-solved through its tool, work object and
stored configuration, as the controller's own IK would, and the program model rebuilt from them."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.arm_configuration import arm_configuration, select_solution
from workbench.kinematics.model import RobotModel
from workbench.motion.programs.controller_program import (
    Instruction,
    MotionLimits,
    MoveInstr,
    ReadMove,
    ReadProgram,
    ReadTarget,
    RobotProgram,
    Target,
    ToolData,
    WorkObject,
)

FloatArray = NDArray[np.float64]


def _find(items: tuple, name: str, what: str, line: int) -> object:
    for it in items:
        if it.name == name:
            return it
    raise InputError(
        f"line {line}: the move uses {what} {name!r}, which the program does not declare;"
        f" declared: {[i.name for i in items]}"
    )


def target_joints(
    target: ReadTarget,
    tool: ToolData,
    wobj: WorkObject,
    model: RobotModel,
    *,
    where: str,
    q_near: FloatArray | None = None,
) -> FloatArray:
    """Return the joints (dof,) [rad, model] a controller reaches for a read target.

    Joint targets: the stated controller joints, converted. Cartesian targets: the IK solution
    of T_base_flange = T_base_wobj @ T_wobj_tcp @ inv(T_flange_tcp) that the stored
    configuration and turn ranges select (`select_solution`).
    """
    if target.joints is not None:
        return np.asarray(model.convention.to_model(target.joints), float)
    if target.T_wobj_tcp is None or target.configuration is None:
        raise InputError(
            f"{where}: target {target.name!r} has neither joints nor a pose with its configuration"
        )
    T = wobj.T_base_wobj @ target.T_wobj_tcp @ invert_transform(tool.T_flange_tcp)
    return select_solution(
        model, T, target.configuration, target.controller_ranges, q_near=q_near, where=where
    )


def solve_moves(read: ReadProgram, model: RobotModel) -> list[FloatArray]:
    """Return the controller's joints (dof,) [rad, model] at every move's target, in order
    (a linear or circular move's from its configuration data and the previous target's joints)."""
    out: list[FloatArray] = []
    for mv in read.moves:
        tool = _find(read.tools, mv.tool, "tool", mv.line)
        wobj = _find(read.work_objects, mv.wobj, "work object", mv.line)
        # a linear or circular move runs on from the previous target's joints
        near = out[-1] if out and mv.kind != "joint" else None
        where = f"line {mv.line} ({mv.name})"
        out.append(target_joints(mv.target, tool, wobj, model, where=where, q_near=near))  # type: ignore[arg-type]
    return out


def to_robot_program(
    read: ReadProgram,
    model: RobotModel,
    *,
    limits: MotionLimits | None = None,
    robot: str = "robot",
) -> RobotProgram:
    """Return the `RobotProgram` of a read program: targets re-solved (`solve_moves`), joint
    speeds as read (a move given only a time gets speed 1 and that duration), actions kept."""
    joints = iter(solve_moves(read, model))
    instructions: list[Instruction] = []
    for ins in read.instructions:
        if not isinstance(ins, ReadMove):
            instructions.append(ins)
            continue
        q = next(joints)
        tgt = ins.target
        via = None
        if ins.via is not None:
            tool = _find(read.tools, ins.tool, "tool", ins.line)
            wobj = _find(read.work_objects, ins.wobj, "work object", ins.line)
            qv = target_joints(ins.via, tool, wobj, model, where=f"line {ins.line} (via)")  # type: ignore[arg-type]
            via = Target(ins.via.name, qv, ins.via.T_wobj_tcp, arm_configuration(model, qv))
        speed = ins.speed if ins.speed is not None else 1.0
        instructions.append(
            MoveInstr(
                ins.kind,
                Target.planned(tgt.name, q, model, tgt.T_wobj_tcp),
                speed,
                ins.zone,
                ins.tool,
                ins.wobj,
                ins.duration or 0.0,
                via,
                ins.force,
            )
        )
    return RobotProgram(
        read.name,
        read.tools,
        read.work_objects,
        tuple(instructions),
        model.convention,
        model.dof,
        robot,
        limits or MotionLimits(),
    )


def in_robot_base(read: ReadProgram, T_world_base: FloatArray | None) -> ReadProgram:
    """Return `read` with its work objects moved from the controller's world into the robot's
    base (`inv(T_world_base) @ uframe`): a MultiMove task's work objects are in the shared
    world (RAPID's wobjdata uframe), the robot's model in its own base. None or the identity:
    `read` itself."""
    if T_world_base is None or np.allclose(T_world_base, np.eye(4), atol=1e-12, rtol=0.0):
        return read
    T_base_world = invert_transform(np.asarray(T_world_base, float))
    wobjs = tuple(WorkObject(w.name, T_base_world @ w.T_base_wobj) for w in read.work_objects)
    return ReadProgram(read.name, read.tools, wobjs, read.instructions, read.unknown, read.notes)
