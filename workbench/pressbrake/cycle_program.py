"""The robot program of a planned press-brake cycle (`BendingCycle`), SI units (m, rad, s).

Every waypoint of the cycle is one joint move to its planned joints (a Cartesian target:
the TCP pose in the base and the arm configuration, as planned) with the planned time from
the previous waypoint (`MoveJ ... \\T`, `PTP` with its time) and, for a bend-following move,
the joints' speed fraction at which it keeps the ram's pace; exact stops where the plan
stops, a small blend elsewhere. What the plan does while the robot stands still becomes
the program's actions, with the same times:

- grip / release: the gripper's close / open action (its output, confirming input and
  settle time, `io.gripper`);
- the ram closing before a followed bend: set the press's start output, wait for its
  clamping signal, reset start (`press_signals.press_actions`); the robot follows the flange
  from there, move by move at the ram's planned pace;
- the ram opening after it: wait for the ram at top dead centre;
- a bend the press makes alone (follow off): start, clamping, top dead centre.

Every press wait has the press's timeout (a fault stops the program), none is a timer: the
press's own times (the plan's holds at those waypoints) are not in the program, so the
program's `cycle_time` is the plan's without them. A project without `io.press` gets
comments naming what is missing. The other holds (the gripper's) are waits of their time.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.motion.programs.controller_program import (
    Comment,
    Instruction,
    MoveInstr,
    ProgramSettings,
    RobotProgram,
    Target,
    WaitTime,
)
from workbench.pressbrake.cycle import BendingCycle, following_fraction
from workbench.pressbrake.press_signals import PRESS_STEPS, press_actions
from workbench.pressbrake.program import TRANSFER_ZONE, RobotAt, base_program

F64 = NDArray[np.float64]


def cycle_program(
    cycle: BendingCycle,
    robot_at: RobotAt,
    settings: ProgramSettings,
    q_start: F64,
    *,
    name: str = "bending",
    robot: str | None = None,
) -> RobotProgram:
    """Return the `RobotProgram` of `cycle` (see the module docstring); `q_start` (dof,)
    [rad] the home joints the cycle starts and ends at."""
    model, tool = robot_at.model, settings.tool
    vmax = np.asarray(model.max_velocity, float)
    wps = cycle.path.waypoints
    q = np.asarray(cycle.q, float)
    arrive = np.asarray(cycle.trajectory.waypoint_times, float)
    leave = arrive + np.array([w.hold for w in wps])
    ins: list[Instruction] = [
        Comment(
            f"bending cycle: {len(cycle.steps)} bends ({' '.join(s.bend for s in cycle.steps)}), "
            f"{cycle.regrips} regrip(s), {cycle.cycle_time:.2f} s planned ({cycle.configuration})"
        )
    ]
    if settings.press is None:
        ins.append(
            Comment("note: the project's io has no press section: the press handshake is comments")
        )

    def target(i: int) -> Target:
        # Every target Cartesian (the home joints too, as the TCP pose there with its
        # configuration): the readers re-solve a Cartesian move from the one before it.
        label = _name(wps[i].label, i)
        return Target.planned(label, q[i], model, model.fk(q[i]) @ tool.T_flange_tcp)

    for i in range(1, len(wps)):
        w = wps[i]
        if w.action in ("press_close", "press_bend") or w.label.startswith("in front of the die"):
            ins.append(Comment(w.label))
        ins.append(
            MoveInstr(
                "joint",
                target(i),
                1.0 if w.bend_time <= 0 else following_fraction(q[i - 1], q[i], w.bend_time, vmax),
                0.0 if w.stop else TRANSFER_ZONE,
                tool.name,
                "base",
                float(arrive[i] - leave[i - 1]),
            )
        )
        if w.action == "grip":
            ins.append(
                settings.close or Comment("gripper close: the project has no io.gripper; add one")
            )
        elif w.action == "release":
            ins.append(
                settings.open or Comment("gripper open: the project has no io.gripper; add one")
            )
        elif w.action in PRESS_STEPS:
            if w.action == "press_bend":
                ins.append(Comment("the press bends the part alone"))
            ins += press_actions(w.action, settings.press)
        elif w.hold > 0.0:
            ins.append(WaitTime(w.hold))
    return base_program(name, model, settings, ins, robot)


def _name(label: str, i: int) -> str:
    """Return a target name from a waypoint label: letters, digits and underscores."""
    word = "".join(c if c.isalnum() else "_" for c in label.lower()).strip("_")
    while "__" in word:
        word = word.replace("__", "_")
    return f"p{i}_{word[:24].rstrip('_')}"
