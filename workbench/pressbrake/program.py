"""The robot program of a bending plan: load, each bend at the die with the press handshake,
the transfer to the pallet as planned, unload, home (SI: m, rad, s).

What today's `BendingPlan` holds and how the program uses it:

- `placements`: per bend, the TCP pose and the joints holding the part on the die. Each bend
  is a joint move to its approach pose (the placement moved by the transfer's `retract` offset
  in the die frame, solved nearest the placement's joints and refused when that is another arm
  configuration), a linear move onto the die, the press's bend with the robot holding still
  (`press_signals.press_actions("press_bend", ...)`: set the press's start output, wait for
  clamping, reset start, wait for the ram at top dead centre, each wait with the press's
  timeout; without the project's `io.press` a comment says so), and a linear retreat to the
  approach pose.
- `trajectory`: the checked transfer (retract, via poses, pallet). Its waypoints are the
  targets with their planned joints and their durations between waypoints; the first one is
  the last bend's retreat.
- The plan times only the transfer (at the joints' full speed: its joint moves say 100 %). The
  other moves (approach joint moves at `MOVE_SPEED` of the joints' maximum speed, linear moves
  onto the die and back at `DIE_SPEED`, the joint move home) are timed here by the motion
  planner itself (`plan_program` + `time_program`, exact stop to exact stop) as the program
  states them, so the program planned again takes its stated time; the program's cycle time
  is the transfer's planned time plus those (and the waits).
- Load: the plan has no blank station, so the program closes the gripper at its start (a
  comment says the blank is put into the gripper there). Regrips: the plan has none (one grasp
  for the whole sequence).

A bend-following plan (issue 13) will add: the blank station (approach, pick, retreat), the
robot following the flange as the press closes (the bend as a timed move instead of a hold),
regrips at the flip rack, and the times of the die moves from the plan instead of from here.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from workbench.errors import UnreachableError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.arm_configuration import arm_configuration
from workbench.kinematics.model import RobotModel
from workbench.motion.program import Move, Program, nearest_ik
from workbench.motion.programs.controller_program import (
    Comment,
    Instruction,
    MoveInstr,
    ProgramSettings,
    RobotProgram,
    Target,
    ToolData,
    WorkObject,
)
from workbench.motion.programs.from_plan import planner_durations
from workbench.pressbrake.die import Die
from workbench.pressbrake.plan import BendingPlan
from workbench.pressbrake.press_signals import press_actions
from workbench.pressbrake.transfer import Transfer

F64 = NDArray[np.float64]

#: Speed of the joint moves the plan does not time (fraction of the joints' maximum speed).
MOVE_SPEED = 0.5
#: TCP speed [m/s] of the linear moves onto the die and back.
DIE_SPEED = 0.25
#: Blend radius [m] at the transfer's via poses (the plan passes through them without stopping).
TRANSFER_ZONE = 0.005


class RobotAt(Protocol):
    """The robot as the program needs it (`RobotSetup` is one): model and base pose [m]."""

    @property
    def model(self) -> RobotModel: ...
    @property
    def T_world_base(self) -> F64: ...


class BendingCell(Protocol):
    """The die and the transfer (the project's `BendingSI` is one)."""

    @property
    def die(self) -> Die: ...
    @property
    def transfer(self) -> Transfer: ...


def bending_program(
    plan: BendingPlan,
    robot_at: RobotAt,
    cell: BendingCell,
    settings: ProgramSettings,
    q_start: F64,
    *,
    name: str = "bending",
    robot: str | None = None,
) -> RobotProgram:
    """Return the bending `RobotProgram` of `plan` (see the module docstring).

    `cell`: the die (its frame) and the transfer (its `retract` offset in the die frame [m]:
    the approach and retreat of every bend), `settings` the tool, gripper and signals, `q_start` (dof,) [rad] the
    start (and home) joints the plan started from; `robot` names the robot (default: the model's name). UnreachableError names a bend whose
    approach pose needs another arm configuration than its placement.
    """
    model, tool = robot_at.model, settings.tool
    traj = plan.trajectory
    wq, wt = np.asarray(traj.waypoints, float), np.asarray(traj.waypoint_times, float)
    q_arr, labels = _die_joints(plan, robot_at, cell, tool, q_start, wq[0])
    dur = _die_durations(model, tool, q_arr, labels)
    home = Program("home", (Move.joint(np.asarray(q_start, float), speed=MOVE_SPEED),))
    home_dur = float(planner_durations(model, home, wq[-1], tool.T_flange_tcp)[0])
    ins = _load(plan, settings)
    ins += _bends(plan, model, settings, q_arr, labels, dur)
    ins.append(Comment("transfer to the pallet as planned (checked)"))
    ins += _transfer(model, tool, wq, wt)
    ins.append(Comment("unload"))
    ins.append(settings.open or Comment("gripper open: the project has no io.gripper; add one"))
    ins.append(
        MoveInstr(
            "joint",
            _target(model, tool, "home", np.asarray(q_start, float), False),
            MOVE_SPEED,
            0.0,
            tool.name,
            "base",
            home_dur,
        )
    )
    return base_program(name, model, settings, ins, robot)


def _die_joints(
    plan: BendingPlan,
    robot_at: RobotAt,
    cell: BendingCell,
    tool: ToolData,
    q_start: F64,
    q_transfer: F64,
) -> tuple[F64, list[str]]:
    """Return the joints (start, then per bend approach, placement, retreat; the last retreat
    is the transfer's start `q_transfer`) and their labels; UnreachableError names a bend whose
    approach needs another arm configuration than its placement."""
    model = robot_at.model
    T_base_world = invert_transform(np.asarray(robot_at.T_world_base, float))
    T_tcp_flange = invert_transform(tool.T_flange_tcp)
    off = cell.die.T_world_die[:3, :3] @ np.asarray(cell.transfer.retract, float)
    q_seq, labels = [np.asarray(q_start, float)], ["start"]
    for k, pl in enumerate(plan.placements):
        T = pl.T_world_tcp.copy()
        T[:3, 3] += off
        if k == len(plan.placements) - 1:
            qa = q_transfer
        else:
            qa = nearest_ik(
                model, T_base_world @ T @ T_tcp_flange, pl.q, f"bend {pl.bend!r} approach"
            )
        if arm_configuration(model, qa) != arm_configuration(model, pl.q):
            raise UnreachableError(
                f"bend {pl.bend!r}: its approach pose needs another arm configuration than its"
                " placement; shorten bending.retract or move the die"
            )
        q_seq += [qa, pl.q, qa]
        labels += [f"b{k + 1}_approach", f"b{k + 1}_bend", f"b{k + 1}_retreat"]
    return np.array(q_seq), labels


def _die_durations(model: RobotModel, tool: ToolData, q_arr: F64, labels: list[str]) -> F64:
    """Return the durations [s] of the moves the plan does not time (approach joint moves,
    linear moves onto the die and back), timed by the motion planner as the program states them."""
    T_base_tcp = model.fk(q_arr) @ tool.T_flange_tcp
    die = [
        Move.joint(q_arr[i], speed=MOVE_SPEED, name=labels[i])
        if labels[i].endswith("_approach")
        else Move.linear(T_base_tcp[i], speed=DIE_SPEED, name=labels[i])
        for i in range(1, len(q_arr))
    ]
    return planner_durations(model, Program("die", tuple(die)), q_arr[0], tool.T_flange_tcp)


def _target(
    model: RobotModel, tool: ToolData, label: str, q: F64, cartesian: bool = True
) -> Target:
    return Target.planned(label, q, model, model.fk(q) @ tool.T_flange_tcp if cartesian else None)


def _load(plan: BendingPlan, settings: ProgramSettings) -> list[Instruction]:
    """Return the program's head: what it does, a note on missing press signals, the load."""
    ins: list[Instruction] = [
        Comment(f"bending: {len(plan.placements)} bends ({plan.configuration})")
    ]
    if settings.press is None:
        ins.append(
            Comment("note: the project's io has no press section: the press handshake is comments")
        )
    ins.append(
        Comment("load: the plan has no blank station; the blank is put into the gripper here")
    )
    ins.append(settings.close or Comment("gripper close: the project has no io.gripper; add one"))
    return ins


def _bends(
    plan: BendingPlan,
    model: RobotModel,
    settings: ProgramSettings,
    q_arr: F64,
    labels: list[str],
    dur: F64,
) -> list[Instruction]:
    """Return every bend's moves: approach, onto the die, the press handshake, retreat."""
    tool = settings.tool
    ins: list[Instruction] = []
    for i in range(1, len(q_arr)):
        label = labels[i]
        if label.endswith("_approach"):
            b = plan.placements[(i - 1) // 3]
            ins.append(Comment(f"bend {b.bend!r} (step {b.step + 1})"))
            ins.append(
                MoveInstr(
                    "joint",
                    _target(model, tool, label, q_arr[i]),
                    MOVE_SPEED,
                    0.0,
                    tool.name,
                    "base",
                    float(dur[i - 1]),
                )
            )
            continue
        ins.append(
            MoveInstr(
                "linear",
                _target(model, tool, label, q_arr[i]),
                DIE_SPEED,
                0.0,
                tool.name,
                "base",
                float(dur[i - 1]),
            )
        )
        if label.endswith("_bend"):
            ins += press_actions("press_bend", settings.press)
    return ins


def _transfer(model: RobotModel, tool: ToolData, wq: F64, wt: F64) -> list[Instruction]:
    """Return the checked transfer's joint moves (blended at the via poses), as planned."""
    ins: list[Instruction] = []
    for j in range(1, len(wq)):
        last = j == len(wq) - 1
        label = "pallet" if last else f"transfer{j}"
        zone = 0.0 if last else TRANSFER_ZONE
        ins.append(
            MoveInstr(
                "joint",
                _target(model, tool, label, wq[j]),
                1.0,
                zone,
                tool.name,
                "base",
                float(wt[j] - wt[j - 1]),
            )
        )
    return ins


def base_program(
    name: str,
    model: RobotModel,
    settings: ProgramSettings,
    instructions: list[Instruction],
    robot: str | None = None,
) -> RobotProgram:
    """Return a bending program: the settings' tool, the robot's base as its one work object."""
    return RobotProgram(
        name,
        (settings.tool,),
        (WorkObject("base", np.eye(4)),),
        tuple(instructions),
        model.convention,
        model.dof,
        robot or model.name,
        settings.limits,
    )
