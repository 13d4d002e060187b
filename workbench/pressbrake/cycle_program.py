"""The robot program of a planned press-brake cycle (`BendingCycle`), SI units (m, rad, s).

Every waypoint of the cycle is one joint move to its planned joints (a Cartesian target:
the TCP pose in the base and the arm configuration, as planned) with the planned time from
the previous waypoint (`MoveJ ... \\T`, `PTP` with its time) and, for a bend-following move,
the joints' speed fraction at which it keeps the ram's pace; exact stops where the plan
stops, a small blend elsewhere. What the plan does while the robot stands still becomes
the program's actions, with the same times:

- grip / release: the gripper's close / open action (its output, confirming input and
  settle time, `io.gripper`);
- the ram closing before a followed bend: pulse `press_start`, then wait the ram's
  approach time (the robot follows the flange from there, move by move at the ram's pace);
- the ram opening after it: wait its return time, then wait for `press_done` (timeout);
- a bend the press makes alone (follow off): pulse `press_start`, wait the ram's time,
  wait for `press_done`.

Signals missing in the project's io leave a comment naming them. The waits are timed so
the program, planned again, takes the plan's cycle time.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.motion.programs.controller_program import (
    Comment,
    Instruction,
    MoveInstr,
    ProgramSettings,
    PulseOutput,
    RobotProgram,
    Target,
    WaitInput,
    WaitTime,
)
from workbench.pressbrake.cycle import BendingCycle, following_fraction
from workbench.pressbrake.program import (
    PRESS_DONE,
    PRESS_PULSE,
    PRESS_START,
    PRESS_TIMEOUT,
    TRANSFER_ZONE,
    RobotAt,
    base_program,
)

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
    start, done = settings.outputs.get(PRESS_START), settings.inputs.get(PRESS_DONE)
    ins: list[Instruction] = [
        Comment(
            f"bending cycle: {len(cycle.steps)} bends ({' '.join(s.bend for s in cycle.steps)}), "
            f"{cycle.regrips} regrip(s), {cycle.cycle_time:.2f} s planned ({cycle.configuration})"
        )
    ]
    for signal, what in ((start, f"output {PRESS_START!r}"), (done, f"input {PRESS_DONE!r}")):
        if signal is None:
            ins.append(
                Comment(
                    f"note: the project's io has no {what}: the press handshake is comments only"
                )
            )

    def target(i: int) -> Target:
        # Every target Cartesian (the home joints too, as the TCP pose there with its
        # configuration): the readers re-solve a Cartesian move from the one before it.
        label = _name(wps[i].label, i)
        return Target.planned(label, q[i], model, model.fk(q[i]) @ tool.T_flange_tcp)

    def pulse() -> Instruction:
        return (
            PulseOutput(start, PRESS_PULSE)
            if start
            else Comment(f"press: pulse output {PRESS_START!r}")
        )

    def wait_done() -> Instruction:
        return (
            WaitInput(done, True, PRESS_TIMEOUT)
            if done
            else Comment(f"press: wait for input {PRESS_DONE!r}")
        )

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
        elif w.action == "press_close":
            ins += [pulse(), Comment("the ram closes onto the sheet"), WaitTime(w.hold)]
        elif w.action == "press_open":
            ins += [Comment("the ram opens"), WaitTime(w.hold), wait_done()]
        elif w.action == "press_bend":
            ins += [
                pulse(),
                Comment("the press bends the part alone"),
                WaitTime(w.hold),
                wait_done(),
            ]
        elif w.hold > 0.0:
            ins.append(WaitTime(w.hold))
    return base_program(name, model, settings, ins, robot)


def _name(label: str, i: int) -> str:
    """Return a target name from a waypoint label: letters, digits and underscores."""
    word = "".join(c if c.isalnum() else "_" for c in label.lower()).strip("_")
    while "__" in word:
        word = word.replace("__", "_")
    return f"p{i}_{word[:24].rstrip('_')}"
