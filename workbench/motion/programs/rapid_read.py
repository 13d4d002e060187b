"""ABB RAPID reader: a module written by `write_rapid`, or by hand, back into a `ReadProgram`.

`read_rapid(files)` reads the statements of ``PROC main`` (every procedure when there is no
main) in order, and the data declarations of the whole module (``CONST`` / ``VAR`` /
``PERS``, also ``LOCAL`` and ``TASK PERS``, also inside routines) of these types: tooldata,
wobjdata, robtarget, jointtarget, speeddata, zonedata, num, dnum, bool, string, syncident and
tasks; assignments ``p := <expression>;`` to such data update it.

Instructions understood (their RAPID meaning, RAPID Technical Reference Manual - Instructions,
Functions and Data types):

- ``MoveAbsJ`` (jointtarget), ``MoveJ`` / ``MoveL`` (robtarget), ``MoveC`` (via and end
  robtargets); speed: a speeddata name, a predefined ``v5`` .. ``v7000`` / ``vmax``
  (7000 mm/s) or a literal ``[v_tcp, v_ori, v_leax, v_reax]``, ``\\V:=`` overriding v_tcp,
  ``\\T:=`` the segment time [s]; zone: ``fine``, predefined ``z0`` (0.3 mm) .. ``z200``, a
  zonedata name or literal (``finep`` TRUE is an exact stop; pzone_tcp is the radius), ``\\Z:=``
  overriding it; the tool (``tool0`` predefined: the flange, 0.001 kg); ``\\WObj:=`` (default
  ``wobj0``: the base); ``\\Conc``, ``\\ID``, ``\\Inpos`` accepted. Targets are names, inline
  aggregates, ``Offs(p, dx, dy, dz)`` (displaced in the work object [mm]) or ``RelTool(p, dx,
  dy, dz \\Rx \\Ry \\Rz)`` (displaced in the tool frame [mm], turned about the tool's x, then
  the new y, then the new z [deg]).
- ABB's Force Control pressing (Application manual - Force control, RAPID references; the
  forms `rapid.py` writes): ``FCPress1LStart to, speed\\Fz:=F, threshold, zone, tool``,
  ``FCPressL to, speed, F, zone, tool`` (linear moves that press with F [N] along the tool's z:
  `ReadMove.force`) and ``FCPressEnd to, speed, tool`` (a linear move that ends the run: exact
  stop, no force); each with ``\\WObj:=``. ``FCCalib load;`` (the sensor calibrated before a
  run) is understood and gives no instruction; ``\\Fx``/``\\Fy`` and the other switches
  are listed in ``unknown``.
- ``SetDO``, ``Set``, ``Reset``, ``PulseDO`` (``\\PLength`` default 0.2 s), ``WaitDI`` (with
  ``\\MaxTime`` as the timeout; ``\\TimeFlag`` accepted), ``WaitTime``, ``WaitSyncTask`` (the
  SyncPoint's robots are the task names with the ``T_`` prefix dropped, lower-case).

Every other statement (other instructions, procedure calls, control flow and what is inside
it, routines other than main, error handlers) is listed in ``unknown`` with its line, never
dropped. Comments are skipped. Signal numbers are 0 (RAPID names signals; the I/O
configuration numbers them). Malformed input (unbalanced brackets, an unterminated statement,
a robtarget of the wrong shape, cfx outside 0..7) raises InputError naming the line.

A robtarget's confdata gives the target's `ArmConfiguration` (cfx, `rapid.CFX_TABLE`) and
its ``controller_ranges``: axes 1, 4 and 6 lie in their quadrants [cf * 90, (cf + 1) * 90)
deg, the other axes are free.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np

from workbench.errors import InputError
from workbench.geometry.transforms import (
    make_transform,
    matrix_to_wxyz,
    rot_x,
    rot_y,
    rot_z,
    wxyz_to_matrix,
)
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
from workbench.motion.programs.program_text import open_string, split_comment, split_statements
from workbench.motion.programs.rapid import (
    CFX_TABLE,
    PREDEFINED_SPEEDS_MM_S,
    PREDEFINED_ZONES_MM,
    configuration_of_cfx,
)

DOF = 6
_DATA_TYPES = {
    "tooldata",
    "wobjdata",
    "robtarget",
    "jointtarget",
    "speeddata",
    "zonedata",
    "num",
    "dnum",
    "bool",
    "string",
    "syncident",
    "tasks",
    "loaddata",
}
_BLOCK_OPEN = {"IF", "FOR", "WHILE", "TEST"}
_BLOCK_CLOSE = {"ENDIF", "ENDFOR", "ENDWHILE", "ENDTEST"}
_HEADERS = (
    _BLOCK_OPEN
    | _BLOCK_CLOSE
    | {
        "MODULE",
        "ENDMODULE",
        "PROC",
        "ENDPROC",
        "FUNC",
        "ENDFUNC",
        "TRAP",
        "ENDTRAP",
        "ELSE",
        "ELSEIF",
        "CASE",
        "DEFAULT",
        "ERROR",
        "UNDO",
        "BACKWARD",
        "RECORD",
        "ENDRECORD",
    }
)
_MOVE_SWITCHES = {"t", "v", "z", "wobj", "conc", "id", "inpos"}
_TOOL0 = ToolData("tool0", np.eye(4), mass=0.001, cog=np.array([0.0, 0.0, 1e-6]))
_WOBJ0 = WorkObject("wobj0", np.eye(4))


class _Unsupported(Exception):
    """A statement the reader does not understand: it goes to `unknown`."""


@dataclass(frozen=True)
class _Stmt:
    line: int
    text: str
    header: bool = False  # a line without ';' (MODULE, PROC, IF ... THEN, ENDIF, ...)


@dataclass
class _Datum:
    type: str
    name: str
    value: object
    line: int


@dataclass
class _Ref:
    """An identifier the module does not declare (a signal, a task list, ...)."""

    name: str


@dataclass
class _Args:
    positional: list = field(default_factory=list)
    switches: dict = field(default_factory=dict)  # lower-case name -> AST (None: a bare switch)
    switch_names: dict = field(default_factory=dict)  # lower-case name -> spelling


# ---------------------------------------------------------------- statements


def _strip_comment(line: str, where: str) -> str:
    code, comment = split_comment(line, "!")
    if comment is None and open_string(code):
        raise InputError("unterminated string; close it with '\"'", field=where)
    return code


def _first_word(text: str) -> str:
    m = re.match(r"\s*(?:LOCAL\s+)?([A-Za-z][A-Za-z0-9_]*)", text, re.IGNORECASE)
    return m.group(1).upper() if m else ""


def _statements(text: str, fname: str) -> list[_Stmt]:
    """Return the file's statements (split at ';', headers one per line) with their first line."""
    out: list[_Stmt] = []
    buf, start, in_header = "", 0, False
    for n, raw in enumerate(text.splitlines(), start=1):
        if raw.strip() == "%%%":
            in_header = not in_header
            continue
        if in_header:
            continue
        line = _strip_comment(raw, f"{fname} line {n}")
        if not line.strip():
            continue
        if not buf.strip():
            word = _first_word(line)
            is_compact_if = word == "IF" and not re.search(r"\bTHEN\b", line, re.IGNORECASE)
            if word in _HEADERS and not is_compact_if:
                out.append(_Stmt(n, line.strip(), header=True))
                continue
        for piece in split_statements(line, ";"):
            if not buf.strip():
                start = n
            if piece.endswith(";"):
                stmt = (buf + " " + piece[:-1]).strip()
                out.append(_Stmt(start, stmt))
                buf = ""
            else:
                buf += " " + piece
    if buf.strip():
        raise InputError(f"{fname} line {start}: the statement {buf.strip()[:60]!r} has no ';'")
    return out


# ---------------------------------------------------------------- expressions

_TOKEN = re.compile(
    r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<id>[A-Za-z][A-Za-z0-9_]*)"
    r'|(?P<str>"(?:[^"]|"")*")|(?P<op>:=|<>|<=|>=|[\[\](){},\\+\-*/:=<>.%]))'
)


def _tokens(text: str, where: str) -> list[tuple[str, str]]:
    out, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            raise _Unsupported(f"{where}: unexpected {text[pos:].strip()[:20]!r}")
        kind = str(m.lastgroup)
        out.append((kind, m.group(kind)))
        pos = m.end()
    depth = 0
    for kind, tok in out:
        if kind == "op" and tok in "([{":
            depth += 1
        elif kind == "op" and tok in ")]}":
            depth -= 1
            if depth < 0:
                break
    if depth != 0:
        raise InputError(f"unbalanced brackets in {text.strip()[:60]!r}", field=where)
    return out


class _Parser:
    def __init__(self, toks: list[tuple[str, str]]) -> None:
        self.t = toks
        self.i = 0

    def peek(self, k: int = 0) -> tuple[str, str]:
        j = self.i + k
        return self.t[j] if j < len(self.t) else ("end", "")

    def take(self) -> tuple[str, str]:
        tok = self.peek()
        self.i += 1
        return tok

    def at(self, op: str) -> bool:
        kind, tok = self.peek()
        return kind == "op" and tok == op

    def expect(self, op: str) -> None:
        if not self.at(op):
            raise _Unsupported(f"expected {op!r}, found {self.peek()[1]!r}")
        self.i += 1

    def ident(self) -> str:
        kind, tok = self.take()
        if kind != "id":
            raise _Unsupported(f"expected a name, found {tok!r}")
        return tok

    def done(self) -> bool:
        return self.peek()[0] == "end"

    # expr := term (('+'|'-') term)* ; term := unary (('*'|'/') unary)*
    def expr(self):  # noqa: ANN201
        node = self.term()
        while self.at("+") or self.at("-"):
            op = self.take()[1]
            node = ("bin", op, node, self.term())
        return node

    def term(self):  # noqa: ANN201
        node = self.unary()
        while self.at("*") or self.at("/"):
            op = self.take()[1]
            node = ("bin", op, node, self.unary())
        return node

    def unary(self):  # noqa: ANN201
        if self.at("-"):
            self.take()
            return ("neg", self.unary())
        if self.at("+"):
            self.take()
            return self.unary()
        return self.primary()

    def primary(self):  # noqa: ANN201
        kind, tok = self.take()
        if kind == "num":
            return ("num", float(tok))
        if kind == "str":
            return ("str", tok[1:-1].replace('""', '"'))
        if kind == "op" and tok == "[":
            items = []
            if not self.at("]"):
                items.append(self.expr())
                while self.at(","):
                    self.take()
                    items.append(self.expr())
            self.expect("]")
            return ("agg", items)
        if kind == "op" and tok == "(":
            node = self.expr()
            self.expect(")")
            return node
        if kind == "id":
            if self.at("("):
                self.take()
                args = self.args(close=")")
                self.expect(")")
                return ("call", tok, args)
            if self.at(".") or self.at("{"):
                raise _Unsupported("record components and array elements")
            return ("id", tok)
        raise _Unsupported(f"unexpected {tok!r}")

    def args(self, close: str = "") -> _Args:
        """Parse 'a, b\\S:=x, \\Flag, c' up to `close` (or the end)."""
        out = _Args()

        def stop() -> bool:
            return self.done() or (bool(close) and self.at(close))

        if stop():
            return out
        while True:
            if not self.at("\\"):
                out.positional.append(self.expr())
            while self.at("\\"):
                self.take()
                name = self.ident()
                val = None
                if self.at(":="):
                    self.take()
                    val = self.expr()
                out.switches[name.lower()] = val
                out.switch_names[name.lower()] = name
            if stop():
                return out
            self.expect(",")


# ---------------------------------------------------------------- values


def _quat_matrix(q, where: str) -> np.ndarray:  # noqa: ANN001
    qv = np.asarray(q, float)
    n = float(np.linalg.norm(qv))
    if not abs(n - 1.0) < 1e-3:
        raise InputError(
            f"the quaternion {qv.tolist()} has norm {n:.6f}; RAPID needs a unit"
            " quaternion [q1,q2,q3,q4] (q1^2+q2^2+q3^2+q4^2 = 1)",
            field=where,
        )
    return np.asarray(wxyz_to_matrix(qv / n), float)


def _numbers(v, n: int, what: str, where: str) -> list[float]:  # noqa: ANN001
    if (
        not isinstance(v, list)
        or len(v) != n
        or not all(_is_num(x) and math.isfinite(x) for x in v)
    ):
        raise InputError(f"{what} needs {n} finite numbers, got {_show(v)}", field=where)
    return [float(x) for x in v]


def _is_num(x) -> bool:  # noqa: ANN001
    return isinstance(x, float | int) and not isinstance(x, bool)


def _show(v) -> str:  # noqa: ANN001
    if isinstance(v, list):
        return "[" + ",".join(_show(x) for x in v) + "]"
    if isinstance(v, _Ref):
        return v.name
    return repr(v)


def _pose(v, what: str, where: str) -> np.ndarray:  # noqa: ANN001
    """Return the (4, 4) [m] of a RAPID pose [[x,y,z] mm,[q1..q4]]."""
    if not isinstance(v, list) or len(v) != 2:
        raise InputError(f"{what} needs [[x,y,z],[q1,q2,q3,q4]], got {_show(v)}", field=where)
    xyz = _numbers(v[0], 3, f"{what} position [x,y,z]", where)
    q = _numbers(v[1], 4, f"{what} quaternion [q1,q2,q3,q4]", where)
    return make_transform(_quat_matrix(q, where), np.array(xyz) / 1000.0)


def _robtarget(v, where: str) -> tuple[np.ndarray, list[float]]:  # noqa: ANN001
    """Return (T_wobj_tcp (4, 4) [m], confdata) of a robtarget value."""
    shape = "[[x,y,z],[q1,q2,q3,q4],[cf1,cf4,cf6,cfx],[eax_a,...,eax_f]]"
    if not isinstance(v, list) or len(v) != 4:
        raise InputError(f"a robtarget is {shape}, got {_show(v)}", field=where)
    T = _pose(v[:2], "the robtarget", where)
    conf = _numbers(v[2], 4, "confdata [cf1,cf4,cf6,cfx]", where)
    _numbers(v[3], 6, "the external axes", where)
    if any(c != int(c) for c in conf) or int(conf[3]) not in CFX_TABLE:
        raise InputError(f"confdata {conf} must be integers with cfx in 0..7", field=where)
    return T, conf


def _read_target(name: str, v, where: str) -> ReadTarget:  # noqa: ANN001
    T, conf = _robtarget(v, where)
    rng = np.full((DOF, 2), [-np.inf, np.inf])
    for axis, cf in zip((0, 3, 5), conf[:3], strict=True):
        rng[axis] = np.radians([cf * 90.0, (cf + 1) * 90.0])
    return ReadTarget(
        name, T_wobj_tcp=T, configuration=configuration_of_cfx(int(conf[3])), controller_ranges=rng
    )


def _joint_target(name: str, v, where: str) -> ReadTarget:  # noqa: ANN001
    if not isinstance(v, list) or len(v) != 2:
        raise InputError(
            f"a jointtarget is [[j1,...,j6],[eax_a,...,eax_f]], got {_show(v)}", field=where
        )
    j = _numbers(v[0], DOF, "robax [j1..j6] [deg]", where)
    _numbers(v[1], 6, "the external axes", where)
    return ReadTarget(name, joints=np.radians(j))


def _rel_tool(v, d: list[float], rxyz: list[float], where: str) -> list:  # noqa: ANN001
    T, _ = _robtarget(v, where)
    R = (
        T[:3, :3]
        @ rot_x(math.radians(rxyz[0]))
        @ rot_y(math.radians(rxyz[1]))
        @ rot_z(math.radians(rxyz[2]))
    )
    p = T[:3, 3] * 1000.0 + T[:3, :3] @ np.asarray(d, float)
    return [[float(x) for x in p], [float(x) for x in matrix_to_wxyz(R)], v[2], v[3]]


# ---------------------------------------------------------------- the reader


class _Reader:
    def __init__(self) -> None:
        self.env: dict[str, _Datum] = {}
        self.tools: dict[str, ToolData] = {}
        self.wobjs: dict[str, WorkObject] = {}
        self.instructions: list[ReadMove | Action] = []
        self.unknown: list[tuple[int, str]] = []
        self.notes: list[str] = []
        self.name = ""
        self.where = ""
        self.line = 0

    # -- evaluation
    def eval(self, node):  # noqa: ANN001, ANN201
        kind = node[0]
        if kind in ("num", "str"):
            return node[1]
        if kind == "agg":
            return [self.eval(x) for x in node[1]]
        if kind == "neg":
            v = self.eval(node[1])
            if not _is_num(v):
                raise _Unsupported("'-' of a non-number")
            return -v
        if kind == "bin":
            a, b = self.eval(node[2]), self.eval(node[3])
            if not (_is_num(a) and _is_num(b)):
                raise _Unsupported(f"{node[1]!r} of non-numbers")
            if node[1] == "/" and b == 0:
                raise InputError(f"{self.where}: division by zero")
            return {"+": a + b, "-": a - b, "*": a * b, "/": a / b if b else 0.0}[node[1]]
        if kind == "id":
            up = node[1].upper()
            if up in ("TRUE", "FALSE"):
                return up == "TRUE"
            if up in ("HIGH", "LOW"):
                return 1.0 if up == "HIGH" else 0.0
            d = self.env.get(node[1].lower())
            if d is None:
                return _Ref(node[1])
            if d.value is None:
                raise _Unsupported(f"{d.name} has no value")
            return d.value
        if kind == "call":
            return self.call(node[1], node[2])
        raise _Unsupported(kind)  # pragma: no cover

    def call(self, fname: str, args: _Args):  # noqa: ANN201
        f = fname.lower()
        pos = [self.eval(a) for a in args.positional]
        if f == "offs" and len(pos) == 4 and not args.switches:
            d = _numbers(pos[1:], 3, "Offs's displacement [dx,dy,dz]", self.where)
            T, _ = _robtarget(pos[0], self.where)
            p = T[:3, 3] * 1000.0 + np.asarray(d)
            return [[float(x) for x in p], pos[0][1], pos[0][2], pos[0][3]]
        if f == "reltool" and len(pos) == 4 and set(args.switches) <= {"rx", "ry", "rz"}:
            d = _numbers(pos[1:], 3, "RelTool's displacement [dx,dy,dz]", self.where)
            r = []
            for k in ("rx", "ry", "rz"):
                node = args.switches.get(k)
                v = 0.0 if node is None else self.eval(node)
                if not _is_num(v):
                    raise InputError(f"{self.where}: RelTool \\{k.title()} needs a number [deg]")
                r.append(float(v))
            return _rel_tool(pos[0], d, r, self.where)
        raise _Unsupported(f"function {fname}")

    # -- data
    def declare(self, p: _Parser, stmt: _Stmt) -> None:
        kind, tok = p.take()
        if tok.upper() in ("LOCAL", "TASK"):
            kind, tok = p.take()
        if tok.upper() not in ("CONST", "VAR", "PERS"):
            raise _Unsupported("declaration")
        dtype = p.ident().lower()
        name = p.ident()
        if p.at("{"):
            raise _Unsupported("arrays")  # only tasks lists are read, below
        value = None
        if p.at(":="):
            p.take()
            value = self.eval(p.expr())
        if not p.done() or dtype not in _DATA_TYPES:
            raise _Unsupported(f"data of type {dtype}")
        self.store(dtype, name, value, stmt)

    def declare_tasks(self, p: _Parser, stmt: _Stmt) -> None:
        """'[TASK] PERS tasks name{n} := [["T_A"],["T_B"]]'."""
        p.i = 0
        while p.peek()[1].upper() != "TASKS":
            p.take()
        p.take()
        name = p.ident()
        p.expect("{")
        p.take()
        p.expect("}")
        p.expect(":=")
        value = self.eval(p.expr())
        if not p.done():
            raise _Unsupported("tasks")
        self.store("tasks", name, value, stmt)

    def store(self, dtype: str, name: str, value, stmt: _Stmt) -> None:  # noqa: ANN001
        where = self.where
        if dtype == "tooldata" and value is not None:
            if not (isinstance(value, list) and len(value) == 3 and isinstance(value[2], list)):
                raise InputError(
                    "tooldata is [robhold,[[x,y,z],[q]],[mass,[cog],...]]", field=where
                )
            if value[0] is not True:
                self.notes.append(
                    f"line {stmt.line}: tooldata {name} is a stationary tool (robhold FALSE)"
                )
                raise _Unsupported("a stationary tool")
            T = _pose(value[1], f"tooldata {name} tframe", where)
            load = value[2]
            if len(load) != 6:
                raise InputError(
                    f"tooldata {name} tload is [mass,[cog],[aom],ix,iy,iz]", field=where
                )
            mass = _numbers([load[0]], 1, "tload mass [kg]", where)[0]
            cog = np.array(_numbers(load[1], 3, "tload cog [x,y,z] [mm]", where)) / 1000.0
            self.tools[name.lower()] = ToolData(name, T, mass=mass, cog=cog)
        elif dtype == "wobjdata" and value is not None:
            if not (isinstance(value, list) and len(value) == 5):
                raise InputError(
                    "wobjdata is [robhold,ufprog,ufmec,[uframe],[oframe]]", field=where
                )
            if value[0] is not False or value[2] not in ("",):
                self.notes.append(
                    f"line {stmt.line}: wobjdata {name} is held by the robot or moved by a"
                    " mechanical unit; not read"
                )
                raise _Unsupported("a moving work object")
            T = _pose(value[3], f"wobjdata {name} uframe", where) @ _pose(
                value[4], f"wobjdata {name} oframe", where
            )
            self.wobjs[name.lower()] = WorkObject(name, T)
        elif dtype == "robtarget" and value is not None:
            _robtarget(value, where)
        elif dtype == "jointtarget" and value is not None:
            _joint_target(name, value, where)
        self.env[name.lower()] = _Datum(dtype, name, value, stmt.line)

    def assign(self, p: _Parser, stmt: _Stmt) -> None:
        name = p.ident()
        p.expect(":=")
        value = self.eval(p.expr())
        d = self.env.get(name.lower())
        if not p.done() or d is None or d.type in ("tooldata", "wobjdata", "syncident", "tasks"):
            raise _Unsupported("assignment")
        self.store(d.type, d.name, value, stmt)

    # -- instructions
    def target(self, node, kind: str, fallback: str) -> ReadTarget:  # noqa: ANN001
        name = node[1] if node[0] == "id" else f"{fallback}_line{self.line}"
        if node[0] == "id":
            d = self.env.get(node[1].lower())
            if d is None or d.type != kind:
                raise _Unsupported(f"{node[1]} is not a declared {kind}")
            name = d.name
        v = self.eval(node)
        return (
            _joint_target(name, v, self.where)
            if kind == "jointtarget"
            else _read_target(name, v, self.where)
        )

    def speed(self, node, sw: _Args) -> float:  # noqa: ANN001
        """Return v_tcp [mm/s] of a speed argument (\\V overrides it)."""
        v_tcp = None
        if node[0] == "id" and node[1].lower() not in self.env:
            v_tcp = PREDEFINED_SPEEDS_MM_S.get(node[1].lower())
            if v_tcp is None:
                raise _Unsupported(f"speeddata {node[1]}")
        else:
            v = self.eval(node)
            v_tcp = _numbers(v, 4, "speeddata [v_tcp,v_ori,v_leax,v_reax]", self.where)[0]
        if "v" in sw.switches:
            v_tcp = self.number(sw.switches["v"], "\\V [mm/s]")
        if not (math.isfinite(v_tcp) and v_tcp > 0):
            raise InputError(f"{self.where}: the TCP speed {v_tcp} mm/s must be positive")
        return v_tcp

    def zone(self, node, sw: _Args) -> float:  # noqa: ANN001
        """Return the zone radius [mm] (0: fine); \\Z overrides it."""
        if node[0] == "id" and node[1].lower() not in self.env:
            z = node[1].lower()
            if z == "fine":
                r = 0.0
            elif z in PREDEFINED_ZONES_MM:
                r = PREDEFINED_ZONES_MM[z]
            else:
                raise _Unsupported(f"zonedata {node[1]}")
        else:
            v = self.eval(node)
            if not (isinstance(v, list) and len(v) == 7 and isinstance(v[0], bool)):
                raise InputError(
                    f"{self.where}: zonedata is [finep,pzone_tcp,...] (7 values), got {_show(v)}"
                )
            r = 0.0 if v[0] else _numbers([v[1]], 1, "pzone_tcp [mm]", self.where)[0]
        if "z" in sw.switches:
            r = self.number(sw.switches["z"], "\\Z [mm]")
        return r

    def number(self, node, what: str) -> float:  # noqa: ANN001
        v = None if node is None else self.eval(node)
        if not isinstance(v, float | int) or isinstance(v, bool) or not math.isfinite(v):
            raise InputError(f"{self.where}: {what} needs a number")
        return float(v)

    def frame_name(self, node, table: dict, predefined: str, what: str) -> str:  # noqa: ANN001
        if node is None or node[0] != "id":
            raise _Unsupported(f"an inline {what}")
        key = node[1].lower()
        if key in table:
            return table[key].name
        if key == predefined:
            return predefined
        self.notes.append(f"line {self.line}: {what} {node[1]} is not declared in the files read")
        return node[1]

    def move(self, instr: str, a: _Args) -> ReadMove:
        if set(a.switches) - _MOVE_SWITCHES:
            raise _Unsupported("switches " + ", ".join(sorted(set(a.switches) - _MOVE_SWITCHES)))
        n = 5 if instr == "movec" else 4
        if len(a.positional) != n:
            raise InputError(
                f"{self.where}: {instr} needs {n} arguments (target(s), speed, zone, tool)"
            )
        pos = a.positional
        via = self.target(pos[0], "robtarget", "via") if instr == "movec" else None
        to_kind = "jointtarget" if instr == "moveabsj" else "robtarget"
        to = self.target(pos[n - 4], to_kind, "target")
        v_tcp = self.speed(pos[n - 3], a)
        zone = self.zone(pos[n - 2], a)
        tool = self.frame_name(pos[n - 1], self.tools, "tool0", "tool")
        wobj = self.frame_name(
            a.switches.get("wobj", ("id", "wobj0")), self.wobjs, "wobj0", "work object"
        )
        duration = self.number(a.switches["t"], "\\T [s]") if "t" in a.switches else None
        kind = {"moveabsj": "joint", "movej": "joint", "movel": "linear", "movec": "circular"}[
            instr
        ]
        speed = None if kind == "joint" else v_tcp / 1000.0
        return ReadMove(kind, to, speed, zone / 1000.0, tool, wobj, duration, via, self.line)  # type: ignore[arg-type]

    def press(self, instr: str, a: _Args) -> ReadMove:
        """Return a Force Control pressing move (FCPress1LStart, FCPressL, FCPressEnd)."""
        allowed = {"fcpress1lstart": {"wobj", "fz"}}.get(instr, {"wobj"})
        n = {"fcpress1lstart": 5, "fcpressl": 5, "fcpressend": 3}[instr]
        if set(a.switches) - allowed or (instr == "fcpress1lstart" and "fz" not in a.switches):
            raise _Unsupported(f"{instr} with switches {sorted(a.switches)}")
        if len(a.positional) != n:
            raise InputError(f"{self.where}: {instr} needs {n} arguments")
        pos = a.positional
        force = 0.0
        if instr == "fcpress1lstart":
            force = self.number(a.switches["fz"], "\\Fz [N]")
        elif instr == "fcpressl":
            force = self.number(pos[2], "FCPressL's force [N]")
        if not force >= 0.0:
            raise InputError(f"{self.where}: the contact force {force} N must be >= 0")
        zone = 0.0 if instr == "fcpressend" else self.zone(pos[3], a) / 1000.0
        wobj = self.frame_name(
            a.switches.get("wobj", ("id", "wobj0")), self.wobjs, "wobj0", "work object"
        )
        return ReadMove(
            "linear",
            self.target(pos[0], "robtarget", "target"),
            self.speed(pos[1], a) / 1000.0,
            zone,
            self.frame_name(pos[n - 1], self.tools, "tool0", "tool"),
            wobj,
            line=self.line,
            force=force,
        )

    def signal(self, node) -> Signal:  # noqa: ANN001
        if node[0] != "id":
            raise _Unsupported("a signal expression")
        return Signal(node[1], 0)

    def bit(self, node) -> bool:  # noqa: ANN001
        v = self.eval(node)
        if isinstance(v, bool):
            return v
        if not _is_num(v) or v not in (0, 1):
            raise InputError(f"{self.where}: a digital value is 0 or 1, got {_show(v)}")
        return bool(v)

    def instruction(self, name: str, a: _Args) -> ReadMove | Action | None:
        n = name.lower()
        sw = set(a.switches)
        pos = a.positional
        if n in ("moveabsj", "movej", "movel", "movec"):
            return self.move(n, a)
        if n in ("fcpress1lstart", "fcpressl", "fcpressend"):
            return self.press(n, a)
        if n == "fccalib" and len(pos) == 1 and not sw:
            load = self.env.get(pos[0][1].lower()) if pos[0][0] == "id" else None
            if load is None or load.type != "loaddata":
                raise _Unsupported("FCCalib of an undeclared loaddata")
            return None  # the calibration before a pressed run: no instruction of its own
        if n == "setdo" and len(pos) == 2 and sw <= {"sync"}:
            return SetOutput(self.signal(pos[0]), self.bit(pos[1]))
        if n in ("set", "reset") and len(pos) == 1 and not sw:
            return SetOutput(self.signal(pos[0]), n == "set")
        if n == "pulsedo" and len(pos) == 1 and sw <= {"high", "plength"}:
            t = self.number(a.switches["plength"], "\\PLength [s]") if "plength" in sw else 0.2
            return PulseOutput(self.signal(pos[0]), t)
        if n == "waitdi" and len(pos) == 2 and sw <= {"maxtime", "timeflag"}:
            tmax = self.number(a.switches["maxtime"], "\\MaxTime [s]") if "maxtime" in sw else None
            return WaitInput(self.signal(pos[0]), self.bit(pos[1]), tmax)
        if n == "waittime" and len(pos) == 1 and sw <= {"inpos"}:
            return WaitTime(self.number(pos[0], "WaitTime [s]"))
        if n == "waitsynctask" and len(pos) == 2 and sw <= {"inpos"}:
            return self.sync(pos[0], pos[1])
        raise _Unsupported(name)

    def sync(self, ident, tasks) -> SyncPoint:  # noqa: ANN001
        if ident[0] != "id" or tasks[0] != "id":
            raise _Unsupported("WaitSyncTask arguments")
        d = self.env.get(tasks[1].lower())
        if d is None or d.type != "tasks" or not isinstance(d.value, list):
            raise _Unsupported(f"the task list {tasks[1]} is not declared")
        robots = []
        for item in d.value:
            if not (isinstance(item, list) and len(item) == 1 and isinstance(item[0], str)):
                raise InputError(f'line {d.line}: tasks {d.name} is [["T_ROB1"],["T_ROB2"],...]')
            task = item[0]
            robots.append((task[2:] if task.upper().startswith("T_") else task).lower())
        return SyncPoint(ident[1], tuple(robots))

    # -- statements
    def statement(self, stmt: _Stmt, reading: bool) -> None:
        p = _Parser(_tokens(stmt.text, self.where))
        first = p.peek()[1].upper()
        if first in ("LOCAL", "TASK", "CONST", "VAR", "PERS"):
            if any(t[1].lower() == "tasks" for t in p.t[:4]) and any(t[1] == "{" for t in p.t):
                self.declare_tasks(p, stmt)
            else:
                self.declare(p, stmt)
            return
        if not reading:
            raise _Unsupported("outside main")
        if p.peek(1) == ("op", ":="):
            self.assign(p, stmt)
            return
        name = p.ident()
        args = p.args()
        if not p.done():
            raise _Unsupported("trailing text")
        ins = self.instruction(name, args)
        if ins is not None:
            self.instructions.append(ins)

    def file(self, fname: str, text: str, multi: bool) -> None:
        stmts = _statements(text, fname)
        has_main = any(
            s.header and re.match(r"(LOCAL\s+)?PROC\s+main\s*\(", s.text, re.IGNORECASE)
            for s in stmts
        )
        routine, depth, handler = "", 0, False
        for s in stmts:
            self.line = s.line
            self.where = f"{fname} line {s.line}" if multi else f"line {s.line}"
            label = f"{fname}: {s.text}" if multi else s.text
            if s.header:
                word = _first_word(s.text)
                m = re.match(r"(?:LOCAL\s+)?(\w+)\s+(\w+)", s.text, re.IGNORECASE)
                if word == "MODULE" and m:
                    self.name = self.name or m.group(2)
                    continue
                if word == "ENDMODULE":
                    continue
                if word in ("PROC", "FUNC", "TRAP") and m:
                    routine, depth, handler = f"{word} {m.group(2)}", 0, False
                    if word != "PROC" or (has_main and m.group(2).lower() != "main"):
                        self.unknown.append((s.line, label))
                    continue
                if word in ("ENDPROC", "ENDFUNC", "ENDTRAP"):
                    if not (
                        routine.lower() == "proc main"
                        or (routine.startswith("PROC") and not has_main)
                    ):
                        self.unknown.append((s.line, label))
                    routine, depth, handler = "", 0, False
                    continue
                if word in ("ERROR", "UNDO", "BACKWARD"):
                    handler = True
                depth += word in _BLOCK_OPEN
                depth -= word in _BLOCK_CLOSE
                self.unknown.append((s.line, label))
                continue
            in_main = routine.lower() == "proc main" or (
                routine.startswith("PROC") and not has_main
            )
            reading = in_main and depth == 0 and not handler
            try:
                self.statement(s, reading)
            except _Unsupported:
                self.unknown.append((s.line, label))
        if not has_main and sum(s.header and _first_word(s.text) == "PROC" for s in stmts) > 1:
            self.notes.append(f"{fname}: no PROC main; every procedure was read in file order")


def read_rapid(files: dict[str, str]) -> ReadProgram:
    """Return the program of RAPID module files {name: text} (see the module docstring)."""
    if not files:
        raise InputError("read_rapid: no files given; pass {'<module>.mod': text}")
    r = _Reader()
    for fname, text in files.items():
        r.file(fname, text, len(files) > 1)
    tools = [*r.tools.values()]
    if "tool0" not in r.tools:
        tools.append(_TOOL0)
    wobjs = [*r.wobjs.values()]
    if "wobj0" not in r.wobjs:
        wobjs.append(_WOBJ0)
    name = r.name or next(iter(files)).rsplit(".", 1)[0]
    return ReadProgram(
        name, tuple(tools), tuple(wobjs), tuple(r.instructions), tuple(r.unknown), tuple(r.notes)
    )
