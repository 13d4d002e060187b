"""The press brake's signals in a bending program, and the order they come in (SI: s).

A press brake tells the robot where its ram is (`PressSignals`, the project's `io.press`):

- the robot sets `start` and holds it until the press reports `clamped` (the ram reached the
  clamping point: the sheet is held between punch and die), then resets it. Holding the level
  instead of pulsing it means no format waits for a pulse to end (URScript and NACHI have no
  non-blocking pulse: `SET`, `DELAY`, `RESET` holds the program), and the press cannot miss it;
- a followed bend starts its following moves when `clamped` is seen, not after a timer, and
  the robot leaves the bent part only when the press reports `top` (the ram back at top dead
  centre): the moves keep the ram's planned pace, the signals fix when they start and when the
  robot may go;
- every wait has the press's `timeout`: a press that does not answer stops the program with
  its fault (each post's timeout handler), never a silent continue.

`press_actions` gives the program's instructions for each press step of a cycle's waypoint,
`press_events` the plan's timeline of the same signals (what `BendingCycle.press_events`
returns), and `SimulatedPress` a press for `motion.programs.io_playback` whose ram takes given
times, to play the exported program against.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from workbench.motion.programs.controller_program import (
    Comment,
    Instruction,
    PressSignals,
    SetOutput,
    WaitInput,
)

if TYPE_CHECKING:
    from workbench.motion.programs.io_playback import Delivery
    from workbench.pressbrake.cycle import BendingCycle

#: The press steps of a cycle's waypoints (`Waypoint.action`).
PRESS_STEPS = ("press_close", "press_open", "press_bend")


def press_actions(step: str, press: PressSignals | None) -> list[Instruction]:
    """Return the instructions of a press step at a waypoint: "press_close" (start the bend and
    wait for the clamping point: the following moves come next), "press_open" (after the last
    following move: wait for the ram at top dead centre), "press_bend" (a bend the press makes
    alone: both). Without the project's press signals, comments name what is missing."""
    if step not in PRESS_STEPS:
        raise ValueError(f"press step {step!r} is not one of {PRESS_STEPS}")
    if press is None:
        what = {
            "press_close": "set press start, wait for clamping, reset start",
            "press_open": "wait for the ram at top dead centre",
            "press_bend": "set press start, wait for clamping, reset start, wait for top dead centre",
        }[step]
        return [Comment(f"press: {what} (the project's io has no press section: add io.press)")]
    close: list[Instruction] = [
        SetOutput(press.start, True),
        WaitInput(press.clamped, True, press.timeout),
        SetOutput(press.start, False),
    ]
    top: list[Instruction] = [WaitInput(press.top, True, press.timeout)]
    if step == "press_close":
        return [*close, Comment("clamped: follow the flange")]
    if step == "press_open":
        return [Comment("the ram opens"), *top]
    return [*close, *top]


@dataclass(frozen=True)
class PressEvent:
    """One signal of the plan's timeline: at `t` [s] the robot sets `start`, the press reports
    `clamped` or `top`, or the robot starts ("follow") or ends ("followed") following."""

    t: float
    what: str
    waypoint: int


def press_events(cycle: BendingCycle) -> list[PressEvent]:
    """Return the press signals of a planned cycle in time order: the plan holds the robot at
    the stop while the ram closes (`start` on arrival, `clamped` when the hold ends), follows
    the flange from there ("follow" .. "followed"), and holds at the last following waypoint
    while the ram opens (`top` when that hold ends). A bend the press makes alone: `start` on
    arrival at the waypoint clear of the part, `top` when its hold ends."""
    wps = cycle.path.waypoints
    arrive = cycle.waypoint_times()
    leave = [float(arrive[i]) + w.hold for i, w in enumerate(wps)]
    out: list[PressEvent] = []
    for i, w in enumerate(wps):
        if w.action == "press_close":
            out += [
                PressEvent(float(arrive[i]), "start", i),
                PressEvent(leave[i], "clamped", i),
                PressEvent(leave[i], "follow", i),
            ]
        elif w.action == "press_open":
            out += [PressEvent(float(arrive[i]), "followed", i), PressEvent(leave[i], "top", i)]
        elif w.action == "press_bend":
            out += [PressEvent(float(arrive[i]), "start", i), PressEvent(leave[i], "top", i)]
    return out


class SimulatedPress:
    """A press brake for `io_playback.play`: when the robot `robot` sets `press.start` on, the
    ram leaves top dead centre (`top` off), reaches the clamping point after `approach` [s]
    (`clamped` on), bends for `bend` [s] and opens in `opening` [s] (`clamped` off, then `top`
    on); each signal reaches the robot `io_delay` [s] after the press sets it. A start while
    the ram is moving is ignored (as a press ignores it until top dead centre)."""

    def __init__(  # noqa: PLR0913
        self,
        robot: str,
        press: PressSignals,
        approach: float,
        bend: float,
        opening: float,
        io_delay: float = 0.0,
    ) -> None:
        self.robot, self.press = robot, press
        self.approach, self.bend, self.opening, self.io_delay = approach, bend, opening, io_delay
        self.busy_until = -1.0
        self.strokes: list[float] = []  # when each stroke started [s]

    @property
    def stroke(self) -> float:
        """Return the ram's time for one bend, top dead centre to top dead centre [s]."""
        return self.approach + self.bend + self.opening

    def initial(self) -> dict[tuple[str, int], bool]:
        """Return the press's inputs at rest: the ram open at top dead centre."""
        return {
            (self.robot, self.press.top.number): True,
            (self.robot, self.press.clamped.number): False,
        }

    def on_output(self, t: float, robot: str, number: int, value: bool) -> Iterable[Delivery]:
        """Start a stroke on the start signal's rising level; return its input changes."""
        if (
            robot != self.robot
            or number != self.press.start.number
            or not value
            or t < self.busy_until
        ):
            return []
        self.strokes.append(t)
        self.busy_until = t + self.stroke
        d, top, clamped = self.io_delay, self.press.top.number, self.press.clamped.number
        t_clamp, t_bottom = t + self.approach, t + self.approach + self.bend
        return [
            (t + d, robot, top, False),
            (t_clamp + d, robot, clamped, True),
            (t_bottom + d, robot, clamped, False),
            (t + self.stroke + d, robot, top, True),
        ]
