"""Robot programs played against each other and against devices through their digital I/O, as
controllers run them: a discrete-event model of the interpreters and the wires between them.

What the model says about a controller (each an assumption that makes the check harder, not
easier):

- Every instruction (setting an output, one look at an input, starting a wait) takes one
  interpreter step of a random time (`Timing.step`). A wait for an input looks at it once per
  step, so a level that comes and goes between two looks is missed, as a controller that
  samples its inputs can miss it.
- An output reaches the input it is wired to after a random delay (`Timing.io_delay`) per
  change; one wire keeps the order of its changes (a later change never arrives before an
  earlier one).
- A move takes its stated duration times a random factor (`Timing.move_scale`), or a random
  time (`Timing.move`) where the program states none (KRL, LS and NACHI state speeds).
- A pulse sets the output and resets it `duration` later without waiting, as RAPID's PulseDO,
  KRL's PULSE and FANUC's DO=PULSE do (`pulse_blocks=True`: the program waits the pulse, as a
  SET, DELAY, RESET does).
- A wait with a timeout that runs out stops that robot's program with a named fault, as the
  posts' timeout handlers do (RAPID's ERR_WAIT_MAXTIME, KRL's HALT, LS's ABORT, UR's halt).
- Sync points are played as the I/O actions the formats without task sync write
  (`sync_handshake.handshake`, the role the program's `SyncPoint.lead` or its name gives; the
  readers set `lead` from the file). The time a robot begins a sync point's actions is when it
  *reaches* it, the time it ends them when it *passes* it.

Inputs nothing drives read `Playback.idle_inputs` (default: on, so a gripper's confirming input
is there). `devices` are further things wired to the robots (a press brake): they are told of
every output change and answer with input changes of their own.
"""

from __future__ import annotations

import heapq
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from workbench.motion.programs.controller_program import (
    Action,
    Comment,
    Gripper,
    Instruction,
    MoveInstr,
    PulseOutput,
    ReadMove,
    SetOutput,
    SyncPoint,
    WaitInput,
    WaitTime,
)
from workbench.motion.programs.sync_handshake import handshake, leads

#: An input change a device or a wire delivers: (time [s], robot, input number, value).
Delivery = tuple[float, str, int, bool]
#: The I/O actions of a sync point for the leading (True) or following robot.
SyncActions = Callable[[SyncPoint, bool], Sequence[Action]]


@dataclass(frozen=True)
class Wire:
    """Robot `src`'s output number `output` wired to robot `dst`'s input number `input`."""

    src: str
    output: int
    dst: str
    input: int


@dataclass(frozen=True)
class Timing:
    """Ranges [s] (low, high) the model draws from uniformly (see the module docstring)."""

    step: tuple[float, float] = (0.001, 0.012)
    io_delay: tuple[float, float] = (0.0, 0.1)
    move: tuple[float, float] = (0.0, 0.3)
    move_scale: tuple[float, float] = (0.9, 1.1)


class Device(Protocol):
    """Something wired to the robots' outputs and inputs (a press brake)."""

    def on_output(self, t: float, robot: str, number: int, value: bool) -> Iterable[Delivery]:
        """Return the input changes the device makes after robot `robot` set output `number`
        to `value` at time `t` [s]."""
        ...


@dataclass(frozen=True)
class Event:
    """What happened: at `t` [s] robot `robot` did `kind` ("move", "moved", "set", "seen",
    "reach", "pass", "fault", "end") with `detail` (the target, "O3 on", the sync point)."""

    t: float
    robot: str
    kind: str
    detail: str


@dataclass
class Playback:
    """The outcome: every event in time order, the time each robot ended its program (absent:
    it did not), the faults, and per sync point the robots whose programs hold it and when
    each reached and passed it."""

    robots: tuple[str, ...] = ()
    events: list[Event] = field(default_factory=list)
    ended: dict[str, float] = field(default_factory=dict)
    faults: list[str] = field(default_factory=list)
    holders: dict[str, set[str]] = field(default_factory=dict)
    reached: dict[tuple[str, str], float] = field(default_factory=dict)
    passed: dict[tuple[str, str], float] = field(default_factory=dict)

    def stuck(self) -> list[str]:
        """Return the robots that did not end their program (a deadlock or a fault)."""
        return [r for r in self.robots if r not in self.ended]

    def overtaking(self) -> list[str]:
        """Return every case of a robot passing a sync point before a partner reached it."""
        bad = []
        for (robot, name), t_pass in sorted(self.passed.items()):
            for other in sorted(self.holders.get(name, set()) - {robot}):
                t_reach = self.reached.get((other, name))
                if t_reach is None or t_reach >= t_pass:
                    when = "never" if t_reach is None else f"at {t_reach:.3f} s"
                    bad.append(
                        f"{robot} passed {name} at {t_pass:.3f} s; {other} reached it {when}"
                    )
        return bad

    def first(self, robot: str, kind: str, detail: str = "") -> float | None:
        """Return when `robot` first did `kind` (with `detail`, where given), None: never."""
        for e in self.events:
            if e.robot == robot and e.kind == kind and (not detail or e.detail == detail):
                return e.t
        return None


def _ops(robot: str, program: Sequence[Instruction | ReadMove], sync: SyncActions) -> list[tuple]:  # noqa: C901
    """Return the robot's program as flat operations (sync points and grippers expanded)."""
    ops: list[tuple] = []
    for ins in program:
        if isinstance(ins, (MoveInstr, ReadMove)):
            ops.append(("move", ins.target.name, ins.duration or 0.0))
        elif isinstance(ins, SyncPoint):
            ops.append(("reach", ins.name))
            ops += _ops(robot, sync(ins, leads(ins, robot)), sync)
            ops.append(("pass", ins.name))
        elif isinstance(ins, Gripper):
            ops += _ops(robot, ins.expand(), sync)
        elif isinstance(ins, SetOutput):
            ops.append(("set", ins.signal.number, ins.value))
        elif isinstance(ins, PulseOutput):
            ops.append(("pulse", ins.signal.number, ins.duration))
        elif isinstance(ins, WaitInput):
            ops.append(("wait", ins.signal.number, ins.value, ins.timeout))
        elif isinstance(ins, WaitTime):
            ops.append(("sleep", ins.seconds))
        elif not isinstance(ins, Comment):  # pragma: no cover - the model has no other
            raise TypeError(f"cannot play {ins!r}")
    return ops


class _Run:
    """The event loop of `play`."""

    def __init__(  # noqa: PLR0913
        self,
        programs: Mapping[str, Sequence[Instruction | ReadMove]],
        wires: Sequence[Wire],
        rng: np.random.Generator,
        timing: Timing,
        devices: Sequence[Device],
        initial: Mapping[tuple[str, int], bool],
        idle: bool,
        pulse_blocks: bool,
        sync: SyncActions,
    ) -> None:
        self.ops = {r: _ops(r, p, sync) for r, p in programs.items()}
        self.wires, self.rng, self.timing = list(wires), rng, timing
        self.devices, self.pulse_blocks = list(devices), pulse_blocks
        self.pb = Playback(tuple(self.ops))
        for r, ops in self.ops.items():
            for op in ops:
                if op[0] == "reach":
                    self.pb.holders.setdefault(op[1], set()).add(r)
        wired = {(w.dst, w.input) for w in self.wires}
        self.inputs: dict[tuple[str, int], bool] = dict.fromkeys(wired, False)
        self.inputs.update(initial)
        self.idle = idle
        self.pc = dict.fromkeys(self.ops, 0)
        self.wait_since: dict[str, float] = {}
        self.last_arrival: dict[Wire, float] = {}
        self.queue: list[tuple[float, int, str, tuple]] = []
        self.seq = 0
        self.pending = 0  # output changes and deliveries not yet processed

    def push(self, t: float, kind: str, data: tuple) -> None:
        self.seq += 1
        self.pending += kind != "step"
        heapq.heappush(self.queue, (t, self.seq, kind, data))

    def draw(self, span: tuple[float, float]) -> float:
        return float(self.rng.uniform(*span))

    def log(self, t: float, robot: str, kind: str, detail: str) -> None:
        self.pb.events.append(Event(t, robot, kind, detail))

    def emit(self, t: float, robot: str, number: int, value: bool) -> None:
        """Robot `robot`'s output `number` becomes `value` at `t`: deliver it."""
        self.log(t, robot, "set", f"O{number} {'on' if value else 'off'}")
        for w in self.wires:
            if (w.src, w.output) == (robot, number):
                at = max(self.last_arrival.get(w, 0.0), t + self.draw(self.timing.io_delay))
                self.last_arrival[w] = at
                self.push(at, "arrive", (w.dst, w.input, value))
        for d in self.devices:
            for at, r, n, v in d.on_output(t, robot, number, value):
                self.push(at, "arrive", (r, n, v))

    def level(self, robot: str, number: int) -> bool:
        return self.inputs.get((robot, number), self.idle)

    def stuck_waiting(self) -> bool:
        """Whether every robot still running waits, untimed, for a level nothing will bring."""
        if self.pending:
            return False
        for r, ops in self.ops.items():
            if r in self.pb.ended or self.pc[r] < 0:
                continue
            if self.pc[r] >= len(ops):
                return False
            op = ops[self.pc[r]]
            if op[0] != "wait" or op[3] is not None or self.level(r, op[1]) == op[2]:
                return False
        return True

    def step(self, t: float, r: str) -> None:  # noqa: C901
        """Run robot `r`'s operations from its program counter at time `t`."""
        ops, tm = self.ops[r], self.timing
        while True:
            k = self.pc[r]
            if k >= len(ops):
                self.pb.ended[r] = t
                self.log(t, r, "end", "")
                return
            op = ops[k]
            if op[0] in ("reach", "pass"):
                (self.pb.reached if op[0] == "reach" else self.pb.passed)[(r, op[1])] = t
                self.log(t, r, op[0], op[1])
                self.pc[r] += 1
                continue
            break
        if op[0] == "move":
            self.log(t, r, "move", op[1])
            dur = op[2] * self.draw(tm.move_scale) if op[2] > 0 else self.draw(tm.move)
            self.pc[r] += 1
            self.push(t + dur, "step", (r,))
        elif op[0] == "set":
            at = t + self.draw(tm.step)
            self.push(at, "emit", (r, op[1], op[2]))
            self.pc[r] += 1
            self.push(at, "step", (r,))
        elif op[0] == "pulse":
            at = t + self.draw(tm.step)
            self.push(at, "emit", (r, op[1], True))
            self.push(at + op[2], "emit", (r, op[1], False))
            self.pc[r] += 1
            self.push(at + op[2] if self.pulse_blocks else at, "step", (r,))
        elif op[0] == "sleep":
            self.pc[r] += 1
            self.push(t + op[1], "step", (r,))
        else:  # wait: one look per step
            since = self.wait_since.setdefault(r, t)
            if self.level(r, op[1]) == op[2]:
                self.log(t, r, "seen", f"I{op[1]} {'on' if op[2] else 'off'}")
                del self.wait_since[r]
                self.pc[r] += 1
            elif op[3] is not None and t - since >= op[3]:
                msg = f"{r}: input {op[1]} not {'on' if op[2] else 'off'} within {op[3]:g} s"
                self.pb.faults.append(msg)
                self.log(t, r, "fault", msg)
                self.pc[r] = -1
                return
            self.push(t + self.draw(tm.step), "step", (r,))

    def run(self, horizon: float) -> Playback:
        for r in self.ops:
            self.push(0.0, "step", (r,))
        while self.queue:
            t, _, kind, data = heapq.heappop(self.queue)
            if t > horizon:
                break
            if kind == "step":
                if self.pc[data[0]] >= 0:
                    self.step(t, data[0])
                if self.stuck_waiting():
                    break
                continue
            self.pending -= 1
            if kind == "emit":
                self.emit(t, *data)
            else:
                r, n, v = data
                self.inputs[(r, n)] = v
                self.log(t, r, "input", f"I{n} {'on' if v else 'off'}")
        self.pb.events.sort(key=lambda e: e.t)
        return self.pb


def play(
    programs: Mapping[str, Sequence[Instruction | ReadMove]],
    wires: Sequence[Wire] = (),
    *,
    rng: np.random.Generator,
    timing: Timing | None = None,
    devices: Sequence[Device] = (),
    initial: Mapping[tuple[str, int], bool] | None = None,
    idle_inputs: bool = True,
    pulse_blocks: bool = False,
    horizon: float = 3600.0,
    sync_actions: SyncActions = handshake,
) -> Playback:
    """Play `programs` (robot name -> instructions, e.g. a reader's `ReadProgram.instructions`)
    against each other through `wires` and `devices` (see the module docstring); `initial`
    input levels by (robot, number) (wired inputs start off, others at `idle_inputs`). Stops
    when every robot ended or faulted, when the running ones all wait for levels nothing
    will bring (a deadlock: `Playback.stuck`), or at `horizon` [s]. `sync_actions`: the I/O
    actions of a sync point for the leading or following robot (a twin plays other protocols)."""
    run = _Run(
        programs,
        wires,
        rng,
        timing or Timing(),
        devices,
        initial or {},
        idle_inputs,
        pulse_blocks,
        sync_actions,
    )
    return run.run(horizon)


def sync_wires(programs: Mapping[str, Sequence[Instruction | ReadMove]]) -> list[Wire]:
    """Return the wires of the programs' sync points: each robot's sync output to its
    partner's sync input (the partner: the other robot whose program holds the same sync
    point; robot names are the keys of `programs`)."""
    syncs = {
        r: {i.name: i for i in p if isinstance(i, SyncPoint) and i.output and i.input}
        for r, p in programs.items()
    }
    wires: list[Wire] = []
    for r, own in syncs.items():
        for name, s in own.items():
            for other, theirs in syncs.items():
                if other != r and name in theirs:
                    w = Wire(r, s.output.number, other, theirs[name].input.number)  # type: ignore[union-attr]
                    if w not in wires:
                        wires.append(w)
    return wires
