"""NACHI FD reader: a program file (``MZ07-01-A.001``) back into moves, targets, tools and actions.

Parses what `write_nachi` writes (see nachi.py for the forms and their sources) and the common
hand-written forms: ``MOVEX`` with ``M1J`` (joints) or ``M1X`` (X, Y, Z, RZ, RY, RX) targets, any
of ``A=``, ``AC=``, ``SM=``, ``HM``, ``CONF=``, ``S=``/``R=``/``T=``, ``H=``, ``MS`` in any order,
spaces after commas; ``SET``/``RESET O<n>``, ``WAITI``/``WAITJ I<n>``, ``DELAY``/``PAUSE <s>``,
``'`` and ``REM`` comments, ``END``. Units back to SI: joints rad (controller convention), mm to
m, ``R=`` % to a fraction, ``S=`` mm/s to m/s, ``T=`` s as the move's duration.

What a file alone does not say, and how it is read:

- tool TCPs (``H=n``) and accuracy distances (``A=n``) are controller constants: read from our
  header comments (``' TOOL``, ``' ACCURACY``); a tool number without one becomes ``H<n>`` at the
  flange, an accuracy level without one a zone of 0, each with a note.
- ``M1X`` (Cartesian) targets: the pose is read in the robot base (work object ``base``); the
  ``CONF=`` word is kept in a note, not decoded (its NACHI meaning is not public), so such a
  target has no configuration and re-solving it asks for one.
- comments are not instructions: ``ReadProgram.instructions`` holds moves and low-level actions.

Lines the reader does not understand are listed in ``ReadProgram.unknown`` by line number;
malformed ``MOVEX`` lines raise InputError naming the line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from workbench.errors import InputError
from workbench.geometry.transforms import make_transform, rpy_to_matrix
from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.motion.programs.controller_program import (
    Action,
    PulseOutput,
    ReadMove,
    ReadProgram,
    ReadTarget,
    SetOutput,
    Signal,
    SyncPoint,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
)
from workbench.motion.programs.program_text import Unbalanced, split_top

_FILE = re.compile(r"^.+\.\d{3}$")
_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_POSE = re.compile(
    rf"X=({_NUM})\s+Y=({_NUM})\s+Z=({_NUM})\s+RZ=({_NUM})\s+RY=({_NUM})\s+RX=({_NUM})"
)
_TOOL = re.compile(r"^'\s*TOOL\s+H=(\d+)\s+(\S+)\s+(.*)$")
_UCOORD = re.compile(r"^'\s*USERCOORD\s+(\S+)\s+(.*)$")
_ACCURACY = re.compile(rf"^'\s*ACCURACY\s+A=(\d+)\s+({_NUM})\s*mm")
_PROGRAM = re.compile(r"^'\s*PROGRAM\s+(\S+)")
_TARGET = re.compile(r"^'\s*TARGET\s+(\S+)\s+WOBJ\s+(\S+)(.*)$")
_CONFIG = re.compile(r"CONFIG\s+(front|back),(elbow_up|elbow_down),(flip|no_flip)")
_TIMEOUT = re.compile(rf"^'\s*TIMEOUT\s+({_NUM})\s*s")
_PULSE = re.compile(rf"^'\s*PULSE\s+O(\d+)\s+({_NUM})\s*s")
_SYNC = re.compile(r"^'\s*SYNC\s+(\S+)\s+WITH\s+(\S*)")
_IO = re.compile(r"^(SET|RESET|WAITI|WAITJ)\s+\[?([OI])?\[?(\d+)\]?\s*$", re.IGNORECASE)
_DELAY = re.compile(rf"^(DELAY|PAUSE)\s+({_NUM})\s*$", re.IGNORECASE)


def nachi_transform(values: np.ndarray) -> np.ndarray:
    """Return the (4, 4) pose [m] of NACHI's (X, Y, Z [mm], RZ, RY, RX [deg]): R = Rz Ry Rx."""
    x, y, z, rz, ry, rx = np.asarray(values, float)
    return make_transform(rpy_to_matrix(np.radians([rx, ry, rz])), np.array([x, y, z]) / 1000.0)


def _pose(text: str, line: int) -> np.ndarray:
    m = _POSE.search(text)
    if m is None:
        raise InputError(
            f"line {line}: expected X=.. Y=.. Z=.. RZ=.. RY=.. RX=.. [mm, deg] in {text!r}"
        )
    return nachi_transform(np.array([float(v) for v in m.groups()]))


@dataclass
class _Note:
    name: str
    wobj: str
    T: np.ndarray | None
    config: ArmConfiguration | None


def _split_options(text: str, line: int) -> list[str]:
    """Split a MOVEX argument list at commas outside parentheses."""
    try:
        parts = split_top(text, ",", "()")
    except Unbalanced as exc:
        which = "')'" if exc.closing else "'('"
        raise InputError(f"line {line}: unbalanced {which} in the MOVEX line") from None
    return [t for t in parts if t]


@dataclass
class _Movex:
    interp: str  # P, L, C1, C2
    target: str  # J or X
    values: np.ndarray
    accuracy: int | None
    positioning: bool
    speed_kind: str | None  # R, S, T
    speed: float | None
    tool: int
    conf: str | None
    extra: list[str]


def _parse_movex(text: str, line: int) -> _Movex:
    body = text.strip()[5:].strip()
    toks = _split_options(body, line)
    acc, pos, kind, speed, tool, conf = None, False, None, None, None, None
    interp = target = None
    values = None
    extra: list[str] = []
    group_seen = False
    for t in toks:
        u = t.upper().replace(" ", "")
        if group_seen and re.fullmatch(r"M[2-9]\d*(J|X|XW)", u):
            extra.append(t)  # an external mechanism group follows: not ours
            break
        if m := re.fullmatch(r"A=(\d+)(P?)", u):
            acc, pos = int(m.group(1)), bool(m.group(2))
        elif re.fullmatch(r"(AC|SM)=\d+", u) or u in ("MS", "HM"):
            pass
        elif m := re.fullmatch(r"M1(J|X|XW)", u):
            target, group_seen = m.group(1)[0], True
        elif u in ("P", "L", "C1", "C2"):
            interp = u
        elif t.startswith("("):
            try:
                values = np.array([float(v) for v in t.strip("()").split(",")])
            except ValueError as exc:
                raise InputError(f"line {line}: the MOVEX position {t} must be numbers") from exc
        elif m := re.fullmatch(rf"([RST])=({_NUM})", u):
            kind, speed = m.group(1), float(m.group(2))
        elif m := re.fullmatch(r"H=(-?\d+)", u):
            tool = int(m.group(1))
        elif m := re.fullmatch(r"CONF=(\d+)", u):
            conf = m.group(1)
        else:
            extra.append(t)
    if target is None or interp is None or values is None:
        raise InputError(
            f"line {line}: a MOVEX line needs the mechanism (M1J or M1X), the interpolation"
            " (P, L, C1, C2) and a position (...)"
        )
    if values.size != 6 or not np.all(np.isfinite(values)):
        raise InputError(
            f"line {line}: the MOVEX position needs 6 finite values, got {values.size}"
        )
    if tool is None:
        raise InputError(f"line {line}: the MOVEX line has no tool number H=")
    if speed is not None and not (np.isfinite(speed) and speed > 0):
        raise InputError(f"line {line}: the MOVEX speed {kind}={speed} must be positive")
    return _Movex(interp, target, values, acc, pos, kind, speed, tool, conf, extra)


class _Reader:
    def __init__(self, name: str, lines: list[str]) -> None:
        self.name = name
        self.lines = lines
        self.tools: dict[int, ToolData] = {}
        self.wobjs: dict[str, WorkObject] = {}
        self.levels: dict[int, float] = {1: 0.0}
        self.instructions: list[ReadMove | Action] = []
        self.unknown: list[tuple[int, str]] = []
        self.notes: list[str] = []
        self.pending: _Note | None = None
        self.timeout: float | None = None
        self.via: tuple[ReadTarget, int] | None = None

    def tool_name(self, h: int) -> str:
        if h not in self.tools:
            self.tools[h] = ToolData(f"H{h}", np.eye(4))
            self.notes.append(
                f"tool H={h} is a controller constant the file does not state; read as the flange"
            )
        return self.tools[h].name

    def wobj(self, name: str) -> str:
        if name not in self.wobjs:
            if name != "base":
                self.notes.append(
                    f"user coordinate {name!r} is not declared; read as the robot base"
                )
            self.wobjs[name] = WorkObject(name, np.eye(4))
        return name

    def io(self, k: int, want: str) -> tuple[str, int] | None:
        """Return (verb, number) of line index k if it is the I/O instruction `want`."""
        if k >= len(self.lines):
            return None
        m = _IO.match(self.lines[k].strip())
        if m and m.group(1).upper() == want:
            return m.group(1).upper(), int(m.group(3))
        return None

    def target(self, mx: _Movex, line: int) -> tuple[ReadTarget, str]:
        note, self.pending = self.pending, None
        rad = np.radians(mx.values)
        if mx.target == "J":
            if note is None:
                return ReadTarget(f"line{line}", joints=rad), self.wobj("base")
            return (
                ReadTarget(note.name, joints=rad, T_wobj_tcp=note.T, configuration=note.config),
                self.wobj(note.wobj),
            )
        T = np.asarray(nachi_transform(mx.values), float)
        if mx.conf is not None:
            self.notes.append(
                f"line {line}: CONF={mx.conf} kept undecoded (NACHI's configuration word is not publicly documented)"
            )
        name = note.name if note is not None else f"line{line}"
        return ReadTarget(name, T_wobj_tcp=T), self.wobj("base")

    def move(self, mx: _Movex, line: int, text: str) -> None:
        if mx.extra:
            self.unknown.append((line, text))
            self.notes.append(
                f"line {line}: options {mx.extra} not understood; the move is read without them"
            )
        tgt, wobj = self.target(mx, line)
        if mx.interp == "C1":
            if self.via is not None:
                raise InputError(
                    f"line {self.via[1]}: the C1 (via) MOVEX is not followed by its C2 line"
                )
            self.via = (tgt, line)
            return
        if mx.interp == "C2" and self.via is None:
            raise InputError(
                f"line {line}: a C2 (circle end) MOVEX needs a C1 (via) line before it"
            )
        if mx.interp != "C2" and self.via is not None:
            raise InputError(
                f"line {self.via[1]}: the C1 (via) MOVEX is not followed by its C2 line"
            )
        kind = {"P": "joint", "L": "linear", "C2": "circular"}[mx.interp]
        speed = duration = None
        if mx.speed_kind == "R" and mx.speed is not None:
            speed = mx.speed / 100.0 if kind == "joint" else None
            if kind != "joint":
                self.notes.append(
                    f"line {line}: R= (percent) on a {kind} move; its speed is not read"
                )
        elif mx.speed_kind == "S" and mx.speed is not None:
            if kind == "joint":
                self.notes.append(
                    f"line {line}: a joint move with TCP speed S={mx.speed:g} mm/s; read as 100 %"
                )
                speed = 1.0
            else:
                speed = mx.speed / 1000.0
        elif mx.speed_kind == "T":
            duration = mx.speed
        if mx.positioning or mx.accuracy is None:
            zone = 0.0
        elif mx.accuracy in self.levels:
            zone = self.levels[mx.accuracy]
        else:
            zone = 0.0
            self.notes.append(
                f"line {line}: accuracy level A={mx.accuracy} is a controller constant the file does not state; read as 0"
            )
        via = None
        if self.via is not None:
            via, self.via = self.via[0], None
        self.instructions.append(
            ReadMove(kind, tgt, speed, zone, self.tool_name(mx.tool), wobj, duration, via, line)  # type: ignore[arg-type]
        )

    def comment(self, s: str, k: int) -> int:
        """Read a comment line at index k; return how many extra lines it consumed."""
        line = k + 1
        if m := _PROGRAM.match(s):
            self.name = m.group(1)
        elif m := _TOOL.match(s):
            h = int(m.group(1))
            self.tools[h] = ToolData(m.group(2), _pose(m.group(3), line))
        elif m := _UCOORD.match(s):
            self.wobjs[m.group(1)] = WorkObject(m.group(1), _pose(m.group(2), line))
        elif m := _ACCURACY.match(s):
            self.levels[int(m.group(1))] = float(m.group(2)) / 1000.0
        elif m := _TARGET.match(s):
            rest = m.group(3)
            T = _pose(rest, line) if "X=" in rest else None
            c = _CONFIG.search(rest)
            cfg = (
                ArmConfiguration(
                    c.group(1) == "front", c.group(2) == "elbow_up", c.group(3) == "flip"
                )
                if c
                else None
            )
            self.pending = _Note(m.group(1), m.group(2), T, cfg)
        elif m := _TIMEOUT.match(s):
            self.timeout = float(m.group(1))
        elif m := _PULSE.match(s):
            n, t = int(m.group(1)), float(m.group(2))
            d = _DELAY.match(self.lines[k + 2].strip()) if k + 2 < len(self.lines) else None
            on, off = self.io(k + 1, "SET"), self.io(k + 3, "RESET")
            if on and off and d and on[1] == n == off[1] and abs(float(d.group(2)) - t) < 1e-9:
                self.instructions.append(PulseOutput(Signal(f"O{n}", n), t))
                return 3
        elif m := _SYNC.match(s):
            # the four-phase handshake (sync_handshake): WAITJ/WAITI, SET, WAITI/WAITJ, RESET
            w0 = self.io(k + 1, "WAITJ") or self.io(k + 1, "WAITI")
            on, off = self.io(k + 2, "SET"), self.io(k + 4, "RESET")
            w2 = self.io(k + 3, "WAITI" if w0 and w0[0] == "WAITJ" else "WAITJ")
            if w0 and on and w2 and off and on[1] == off[1] and w0[1] == w2[1]:
                robots = tuple(r for r in m.group(2).split(",") if r)
                sig_out, sig_in = Signal(f"O{on[1]}", on[1]), Signal(f"I{w0[1]}", w0[1])
                lead = w0[0] == "WAITJ"
                self.instructions.append(SyncPoint(m.group(1), robots, sig_out, sig_in, lead))
                return 4
        return 0

    def read(self) -> ReadProgram:
        k, ended = 0, False
        while k < len(self.lines):
            s = self.lines[k].strip()
            line = k + 1
            if not s:
                k += 1
                continue
            if ended:
                self.unknown.append((line, s))
            elif s.startswith("'"):
                k += self.comment(s, k)
            elif re.match(r"^REM\b", s, re.IGNORECASE):
                pass
            elif re.match(r"^MOVEX\b", s, re.IGNORECASE):
                self.move(_parse_movex(s, line), line, s)
            elif m := _IO.match(s):
                verb, n = m.group(1).upper(), int(m.group(3))
                if verb in ("SET", "RESET"):
                    self.instructions.append(SetOutput(Signal(f"O{n}", n), verb == "SET"))
                else:
                    self.instructions.append(
                        WaitInput(Signal(f"I{n}", n), verb == "WAITI", self.timeout)
                    )
                    self.timeout = None
            elif m := _DELAY.match(s):
                self.instructions.append(WaitTime(float(m.group(2))))
            elif s.upper() == "END":
                ended = True
            else:
                self.unknown.append((line, s))
            k += 1
        if self.via is not None:
            raise InputError(
                f"line {self.via[1]}: the C1 (via) MOVEX is not followed by its C2 line"
            )
        return ReadProgram(
            self.name,
            tuple(self.tools[h] for h in sorted(self.tools)),
            tuple(self.wobjs.values()),
            tuple(self.instructions),
            tuple(self.unknown),
            tuple(self.notes),
        )


def read_nachi(files: dict[str, str]) -> ReadProgram:
    """Return the program of one NACHI FD program file (name ``<unit>.<nnn>`` -> text).

    Raises InputError when `files` holds no such file or several (read one program at a time),
    and for malformed MOVEX lines (naming the line).
    """
    progs = [n for n in files if _FILE.match(n)] or (list(files) if len(files) == 1 else [])
    if len(progs) != 1:
        raise InputError(
            f"read_nachi: expected one NACHI program file named like MZ07-01-A.001, got {list(files)}"
        )
    name = progs[0]
    stem = name.rsplit(".", 1)[0]
    return _Reader(stem, files[name].splitlines()).read()
