"""Universal Robots URScript post-processor: a `RobotProgram` as one URScript program.

`write_urscript(program)` returns one file "<name>.script": ``def name(): ... end`` and the
call ``name()``. Units are URScript's: m, rad, s.

Frames. Every tool and work object is a pose variable ``name = p[x, y, z, rx, ry, rz]``
(m, rotation vector rad): tools in the flange frame, work objects in the robot base frame.
Before the first move with a tool: ``set_tcp(tool)`` and ``set_payload(mass, [cx, cy, cz])``
(kg, m in the flange frame; a comment instead when the tool has no mass: the installation's
payload applies). A Cartesian target is ``pose_trans(wobj, p[...])``: the TCP pose in its
work object, mapped into the base frame on the controller.

Moves.
- Joint move to a joint target: ``movej([q1, ..., q6], t=T, r=R)``, controller joints
  (`RobotProgram.controller_joints`) in rad. URScript has no speed percentage, so the post
  writes the planned duration ``t=`` (mv.duration [s]), which reproduces the plan's segment
  time; a move without a planned duration gets ``a=1.4, v=speed * pi`` (UR's 180 deg/s
  joint speed times the move's fraction) instead.
- Joint move to a Cartesian target: ``movej(get_inverse_kin(pose_trans(wobj, p[...]),
  qnear=[planned joints]), t=T, r=R)``: the controller's IK returns the solution nearest
  qnear, which is the planned one (the reader returns those joints).
- ``movel(pose_trans(wobj, p[...]), a=1.2, v=V, r=R)`` and ``movec(pose_trans(wobj,
  p_via), pose_trans(wobj, p_end), a=1.2, v=V, r=R, mode=0)``: V the TCP speed [m/s], R the
  blend radius [m]; the controller keeps the joints continuous along the line, so each such
  target has a comment line ``# name joints [..]`` (via: ``# via name joints [..]``) with the
  planned joints the move ends in, for people and for the reader.
- Blend radii ``r`` never overlap (`blend_radii`, UR's rule for blends: each r at most half
  of either segment it touches, so r_i + r_(i+1) <= the segment between the two waypoints);
  cut radii are noted (the bending programs' 5 mm blends on ~9.4 mm steps become ~4.7 mm).
- Each move is preceded by ``# name`` (its target's name; a joint target adds ``, work
  object w``: the frame the plan moved in, which a joint target does not need).

Actions. Signal numbers 0..7 are the controller's standard digital I/O
(``set_standard_digital_out(n, True)``, ``get_standard_digital_in(n)``), 8..15 its
configurable I/O 0..7 (``set_configurable_digital_out(n - 8, ...)``); other numbers are
refused. A wait is ``while not get_standard_digital_in(n): sync() end``; with a timeout it
counts the controller steps: ``wait_t = 0`` before the loop, ``if wait_t >= T: popup(...,
error=True) halt end`` and ``wait_t = wait_t + get_steptime()`` in it (a timed-out wait
stops the program). ``sleep(t)`` waits. A pulse is ``# pulse DO n for t s``, the output
high, ``sleep(t)``, low (it holds the program for t: URScript has no pulse instruction).
Comments ``# text``; a gripper action is ``# gripper close/open`` and its expanded actions;
a sync point is ``# sync name: robot_a, robot_b`` and the four-phase I/O handshake of
`sync_handshake` (leading: wait for the input low, output high, wait for the input high,
output low; following: wait high, output high, wait low, output low).

Names are legal URScript identifiers (NameTable, case-sensitive, `RESERVED`: keywords and
the built-ins this post uses); every rename is a note in `ExportedProgram.notes` and a
comment at the top. Numbers: joints and rotation vectors 9 decimals [rad], positions 9
decimals [m].
"""

from __future__ import annotations

import math

import numpy as np

from workbench.errors import InputError
from workbench.motion.programs.angles import rotation_vector
from workbench.motion.programs.controller_program import (
    Comment,
    Gripper,
    MoveInstr,
    PulseOutput,
    RobotProgram,
    SetOutput,
    Signal,
    SyncPoint,
    Target,
    WaitInput,
    WaitTime,
    check_program,
    compliance_notes,
)
from workbench.motion.programs.exported import ExportedProgram
from workbench.motion.programs.first_move import safe_start
from workbench.motion.programs.names import NameTable
from workbench.motion.programs.sync_handshake import handshake, leads

#: URScript keywords and the built-in functions and names a program must not shadow.
RESERVED = (
    "def", "end", "if", "elif", "else", "while", "for", "in", "thread", "run", "join", "kill",
    "return", "True", "False", "and", "or", "not", "xor", "halt", "break", "continue",
    "global", "local", "sec", "enter_critical", "exit_critical", "p", "movej", "movel",
    "movep", "movec", "servoj", "speedj", "speedl", "stopj", "stopl", "sleep", "sync",
    "set_tcp", "set_payload", "pose_trans", "pose_inv", "pose_add", "get_inverse_kin",
    "get_forward_kin", "get_steptime", "popup", "textmsg", "set_standard_digital_out",
    "get_standard_digital_in", "set_configurable_digital_out", "get_configurable_digital_in",
    "set_digital_out", "get_digital_in", "wait_t", "pi",
)  # fmt: skip
JOINT_SPEED = np.pi  # rad/s: UR's 180 deg/s joint speed, the scale of a fraction without time
JOINT_ACCEL = 1.4  # rad/s^2, URScript's default
TCP_ACCEL = 1.2  # m/s^2, URScript's default
STANDARD_IO = 8  # standard digital I/O 0..7, then configurable 0..7 as 8..15


def _f(x: float, nd: int = 9) -> str:
    s = f"{x:.{nd}f}".rstrip("0")
    s = s + "0" if s.endswith(".") else s
    return "0.0" if float(s) == 0.0 else s


def _list(v: np.ndarray) -> str:
    return "[" + ", ".join(_f(x) for x in v) + "]"


def pose_text(T: np.ndarray) -> str:
    """Return URScript's p[x, y, z, rx, ry, rz] (m, rotation vector rad) of a (4, 4) pose."""
    T = np.asarray(T, float)
    return "p" + _list(np.concatenate([T[:3, 3], rotation_vector(T[:3, :3])]))


def _io(s: Signal, what: str) -> tuple[str, int]:
    if 0 <= s.number < STANDARD_IO:
        return "standard", s.number
    if STANDARD_IO <= s.number < 2 * STANDARD_IO:
        return "configurable", s.number - STANDARD_IO
    raise InputError(
        f"signal {s.name!r}: {what} {s.number} is not a UR digital {what}: use 0..7 (standard)"
        " or 8..15 (configurable 0..7)"
    )


def _tcp_position(program: RobotProgram, mv: MoveInstr, tgt: Target | None) -> np.ndarray | None:
    """Return the TCP position [m] of a Cartesian target in the robot base, None for a joint
    target (the post has no kinematic model to place it)."""
    if tgt is None or tgt.T_wobj_tcp is None:
        return None
    T = program.work_object(mv.wobj).T_base_wobj @ np.asarray(tgt.T_wobj_tcp, float)
    return np.asarray(T[:3, 3], float)


def blend_radii(program: RobotProgram) -> list[float]:
    """Return the blend radius [m] written for each move: its zone, cut so that no two blends
    overlap: "Blends cannot overlap, so it is not possible to set a blend radius that
    overlaps with the blend radius of a previous or following waypoint" (Universal Robots
    user manual, CB3 / PolyScope 3.x, "Command: Fixed Waypoint", blend parameters). The post
    keeps r_i <= half of each segment it touches, so r_i + r_(i+1) <= the segment between waypoints i and i+1. A segment's length
    is the TCP distance between its ends (through the via point for a circular move); a
    segment that starts or ends at a joint target, whose pose the post does not know, does not
    cut (the examples' joint targets lie far from their neighbours); the first move's
    incoming segment starts wherever the robot stands and is not known either. The last move
    has no blend (nothing follows it)."""
    moves = program.moves
    pts = [_tcp_position(program, m, m.target) for m in moves]
    radii = []
    for k, mv in enumerate(moves):
        r = float(mv.zone)
        if r <= 0.0:
            radii.append(0.0)
            continue
        if k == len(moves) - 1:
            radii.append(0.0)
            continue
        for a, b in ((k - 1, k), (k, k + 1)):
            if a < 0:
                continue
            length = _segment_length(program, moves[b], pts[a], pts[b])
            if length is not None and r > 0.5 * length:
                # down to the 9 decimals written, so the written radii keep the rule too
                r = math.floor(0.5 * length * 1e9 + 1e-6) / 1e9
        radii.append(r)
    return radii


def _segment_length(
    program: RobotProgram, mv: MoveInstr, start: np.ndarray | None, end: np.ndarray | None
) -> float | None:
    """Return the TCP path length [m] of move `mv` from `start` to `end` (a circular move via
    its via point: the two chords, no longer than the arc), None where an end is unknown."""
    if start is None or end is None:
        return None
    via = _tcp_position(program, mv, mv.via) if mv.kind == "circular" else None
    if via is not None:
        return float(np.linalg.norm(via - start) + np.linalg.norm(end - via))
    return float(np.linalg.norm(end - start))


def _comment(text: str) -> str:
    return "# " + " ".join(str(text).split())


class _Writer:
    def __init__(self, program: RobotProgram) -> None:
        self.p = program
        self.out: list[str] = []
        self.vars = NameTable("URScript", RESERVED, max_len=63, case_sensitive=True, prefix="v")
        self.targets = NameTable("URScript", RESERVED, max_len=63, case_sensitive=True)
        self.name = self.vars(program.name, "program")
        self.tool_var = {t.name: self.vars(t.name, "tool") for t in program.tools}
        self.wobj_var = {w.name: self.vars(w.name, "wobj") for w in program.work_objects}
        self.tool: str | None = None
        self.radii = blend_radii(program)
        self.cut = [
            (k, m.zone, r)
            for k, (m, r) in enumerate(zip(program.moves, self.radii, strict=True))
            if r < m.zone
        ]

    def add(self, line: str, depth: int = 1) -> None:
        self.out.append("  " * depth + line)

    def frames(self) -> None:
        self.add("# tools: TCP in the flange frame [m, rotation vector rad]")
        for t in self.p.tools:
            self.add(f"{self.tool_var[t.name]} = {pose_text(t.T_flange_tcp)}")
        self.add("# work objects: frames in the robot base frame [m, rotation vector rad]")
        for w in self.p.work_objects:
            self.add(f"{self.wobj_var[w.name]} = {pose_text(w.T_base_wobj)}")

    def select_tool(self, name: str) -> None:
        if self.tool == name:
            return
        self.tool = name
        t = self.p.tool(name)
        self.add(f"set_tcp({self.tool_var[name]})")
        if t.mass is not None and t.mass > 0:
            cog = np.zeros(3) if t.cog is None else np.asarray(t.cog, float)
            self.add(f"set_payload({_f(t.mass)}, {_list(cog)})")
        else:
            self.add(_comment(f"tool {name} has no mass: the installation's payload applies"))

    def pose(self, mv: MoveInstr, tgt: Target) -> str:
        assert tgt.T_wobj_tcp is not None
        return f"pose_trans({self.wobj_var[mv.wobj]}, {pose_text(tgt.T_wobj_tcp)})"

    def joints(self, tgt: Target) -> str:
        return _list(self.p.controller_joints(tgt.q))

    def move(self, k: int, mv: MoveInstr) -> None:
        self.select_tool(mv.tool)
        name = self.targets(mv.target.name, f"target_{k}")
        r = _f(self.radii[k])
        if mv.kind == "joint":
            here = "" if mv.target.cartesian else f", work object {self.wobj_var[mv.wobj]}"
            self.add(_comment(name + here))
            if mv.duration > 0:
                timing = f"t={_f(mv.duration)}"
            else:
                timing = f"a={_f(JOINT_ACCEL)}, v={_f(mv.speed * JOINT_SPEED)}"
            if mv.target.cartesian:
                q = f"get_inverse_kin({self.pose(mv, mv.target)}, qnear={self.joints(mv.target)})"
            else:
                q = self.joints(mv.target)
            self.add(f"movej({q}, {timing}, r={r})")
            return
        v = _f(mv.speed)
        if mv.kind == "linear":
            self.add(_comment(f"{name} joints {self.joints(mv.target)}"))
            self.add(f"movel({self.pose(mv, mv.target)}, a={_f(TCP_ACCEL)}, v={v}, r={r})")
            return
        assert mv.via is not None  # check_program
        via = self.targets(mv.via.name, f"via_{k}")
        self.add(_comment(f"via {via} joints {self.joints(mv.via)}"))
        self.add(_comment(f"{name} joints {self.joints(mv.target)}"))
        self.add(
            f"movec({self.pose(mv, mv.via)}, {self.pose(mv, mv.target)},"
            f" a={_f(TCP_ACCEL)}, v={v}, r={r}, mode=0)"
        )

    def set_out(self, s: Signal, value: bool) -> None:
        kind, n = _io(s, "output")
        self.add(f"set_{kind}_digital_out({n}, {value})")

    def wait_in(self, s: Signal, value: bool, timeout: float | None) -> None:
        kind, n = _io(s, "input")
        cond = f"{'not ' if value else ''}get_{kind}_digital_in({n})"
        if timeout is None:
            self.add(f"while {cond}:")
            self.add("sync()", 2)
            self.add("end")
            return
        if not np.isfinite(timeout) or timeout <= 0:
            raise InputError(f"signal {s.name!r}: the wait's timeout {timeout!r} s must be > 0")
        msg = f"timeout: digital input {s.number} ({s.name}) not {value} after {timeout:g} s"
        msg = msg.replace('"', "'")
        self.add("wait_t = 0")
        self.add(f"while {cond}:")
        self.add(f"if wait_t >= {_f(timeout)}:", 2)
        self.add(f'popup("{msg}", "{self.name}", error=True)', 3)
        self.add("halt", 3)
        self.add("end", 2)
        self.add("sync()", 2)
        self.add("wait_t = wait_t + get_steptime()", 2)
        self.add("end")

    def action(self, a: object) -> None:
        if isinstance(a, SetOutput):
            self.set_out(a.signal, a.value)
        elif isinstance(a, PulseOutput):
            if not np.isfinite(a.duration) or a.duration <= 0:
                raise InputError(
                    f"signal {a.signal.name!r}: pulse duration {a.duration!r} s must be > 0"
                )
            self.add(_comment(f"pulse DO {a.signal.number} for {_f(a.duration)} s"))
            self.set_out(a.signal, True)
            self.add(f"sleep({_f(a.duration)})")
            self.set_out(a.signal, False)
        elif isinstance(a, WaitInput):
            self.wait_in(a.signal, a.value, a.timeout)
        elif isinstance(a, WaitTime):
            self.add(f"sleep({_f(a.seconds)})")
        elif isinstance(a, Comment):
            self.add(_comment(a.text))
        elif isinstance(a, Gripper):
            self.add(_comment(f"gripper {'close' if a.close else 'open'}"))
            for b in a.expand():
                self.action(b)
        elif isinstance(a, SyncPoint):
            # URScript has no task sync: the four-phase handshake of sync_handshake
            steps = handshake(a, leads(a, self.p.name))
            self.add(_comment(f"sync {a.name}: {', '.join(a.robots)}"))
            for b in steps:
                self.action(b)
        else:  # pragma: no cover - the model has no other action
            raise InputError(f"program {self.p.name}: URScript cannot write {a!r}")


def write_urscript(program: RobotProgram) -> ExportedProgram:
    """Return `program` as a URScript file "<name>.script" (conventions: the module docstring).

    Raises InputError naming the move for what the controller should not be told
    (check_program), and naming the signal for an I/O number UR does not have.
    """
    program = safe_start(program)  # the first move: untimed, bounded speed
    check_program(program)
    w = _Writer(program)
    w.frames()
    k = 0
    for ins in program.instructions:
        if isinstance(ins, MoveInstr):
            w.move(k, ins)
            k += 1
        else:
            w.action(ins)
    notes = tuple(compliance_notes(program) + w.vars.notes + w.targets.notes)
    if w.cut:
        k, z, r = max(w.cut, key=lambda c: c[1] - c[2])
        notes += (
            f"{len(w.cut)} blend radii cut so that no two blends overlap (UR: r <= half of"
            f" each adjacent segment); the largest cut: move {k}, {z * 1000:g} -> {r * 1000:.3g} mm",
        )
    head = [_comment(f"workbench program {program.name} (robot {program.robot})")]
    head += [_comment(f"note: {n}") for n in notes]
    text = "\n".join([*head, f"def {w.name}():", *w.out, "end", f"{w.name}()", ""])
    return ExportedProgram({f"{w.name}.script": text}, notes)
