"""URScript reader: what `write_urscript` writes (and the common hand-written forms) back into
a `ReadProgram`.

Read: ``def name():`` .. ``end`` (and the call ``name()``); pose variables ``v = p[...]``
and joint variables ``v = [...]``; ``set_tcp(v | p[...])`` (the tool; a literal TCP is named
tcp_1, tcp_2, ...), ``set_payload(m[, cog])``; ``movej(q | [..] | get_inverse_kin(POSE,
qnear=[..]) | POSE, t=.. | a=.., v=.., r=..)`` (duration t, or speed v / pi: the fraction of
UR's 180 deg/s), ``movel(POSE, a, v, r)``, ``movec(POSE, POSE, a, v, r, mode)`` with POSE one
of ``pose_trans(wobj, p[..])``, ``p[..]`` (in the base: work object "base"), a pose
variable; the comment lines ``# name`` / ``# name, work object w`` / ``# name joints [..]`` /
``# via name joints [..]`` before a move (target names, a joint target's work object and the
joints a movel / movec ends in); digital outputs
``set_standard_digital_out(n, b)`` (configurable n -> signal 8 + n); waits ``while not
get_standard_digital_in(n): sync() end`` with the post's timeout pattern (``if wait_t >=
T:`` .. ``halt``); ``sleep(t)``; the ``# pulse`` and ``# sync name: robots`` blocks.

Returned: the tools set with set_tcp ("flange", the identity, for moves before the first
set_tcp, with a note: the installation's TCP applies there), the work objects used in
pose_trans plus "base" (identity); joint targets with their controller joints; Cartesian
targets with the pose and the joints the program states (qnear, or the ``joints`` comment;
none stated: pose only, with a note). Anything else is listed in `unknown` by line; a
malformed line raises InputError naming it.
"""

from __future__ import annotations

import re

import numpy as np

from workbench.errors import InputError
from workbench.geometry.transforms import make_transform
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
from workbench.motion.programs.program_text import Unbalanced, numbered_lines, split_top
from workbench.motion.programs.sync_handshake import match_handshake
from workbench.motion.programs.urscript import JOINT_SPEED, STANDARD_IO

_IDENT = r"[A-Za-z_][A-Za-z0-9_]*"
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")


def rotvec_matrix(r: np.ndarray) -> np.ndarray:
    """Return the (3, 3) rotation of a rotation vector r (3,) [rad] (Rodrigues)."""
    r = np.asarray(r, float)
    a = float(np.linalg.norm(r))
    if a < 1e-15:
        return np.eye(3)
    k = r / a
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(a) * K + (1.0 - np.cos(a)) * (K @ K)


def _split_args(s: str, where: str) -> list[str]:
    """Split an argument list at commas outside brackets (a trailing empty argument dropped)."""
    try:
        parts = split_top(s, ",", "()[]")
    except Unbalanced:
        raise InputError(f"unbalanced brackets in {s!r}", field=where) from None
    return parts if parts[-1] else parts[:-1]


def _call(text: str) -> tuple[str, str] | None:
    m = re.fullmatch(rf"({_IDENT})\s*\((.*)\)", text.strip())
    return (m.group(1), m.group(2)) if m else None


def _args(inner: str, where: str) -> tuple[list[str], dict[str, str]]:
    pos, kw = [], {}
    for a in _split_args(inner, where):
        m = re.fullmatch(rf"({_IDENT})\s*=\s*(.+)", a)
        if m and not a.startswith("p["):
            kw[m.group(1)] = m.group(2).strip()
        else:
            pos.append(a)
    return pos, kw


def _num(s: str, where: str) -> float:
    if not _NUMBER.match(s.strip()):
        raise InputError(f"{s!r} is not a number", field=where)
    return float(s)


def _vector(s: str, where: str, n: int | None = None) -> np.ndarray:
    m = re.fullmatch(r"\[(.*)\]", s.strip())
    if not m:
        raise InputError(f"expected a list [..], got {s!r}", field=where)
    v = np.array([_num(x, where) for x in _split_args(m.group(1), where)])
    if n is not None and v.shape != (n,):
        raise InputError(f"expected {n} numbers, got {len(v)}", field=where)
    return v


class _Reader:
    def __init__(self) -> None:
        self.poses: dict[str, np.ndarray] = {}
        self.qvars: dict[str, np.ndarray] = {}
        self.tools: dict[str, ToolData] = {}
        self.wobjs: dict[str, WorkObject] = {}
        self.tool: str | None = None
        self.literal_tcps = 0
        self.notes: list[str] = []
        self.unknown: list[tuple[int, str]] = []
        self.items: list[object] = []
        self.pending: list[str] = []  # comments before a move
        self.frame: str | None = None  # the work object a joint target's comment names

    # -- expressions ------------------------------------------------------------------
    def literal_pose(self, s: str, where: str) -> np.ndarray | None:
        m = re.fullmatch(r"p\s*(\[.*\])", s.strip())
        if not m:
            return None
        v = _vector(m.group(1), where, 6)
        return make_transform(rotvec_matrix(v[3:]), v[:3])

    def pose(self, s: str, where: str) -> tuple[str, np.ndarray]:
        """Return (work object name, T_wobj_tcp) of a pose expression."""
        s = s.strip()
        T = self.literal_pose(s, where)
        if T is not None:
            return self.base(), T
        if s in self.poses:
            return self.base(), self.poses[s]
        c = _call(s)
        if c and c[0] == "pose_trans":
            a, _ = _args(c[1], where)
            if len(a) != 2:
                raise InputError(f"pose_trans needs two poses, got {s!r}", field=where)
            frame = a[0].strip()
            if frame not in self.poses:
                raise InputError(
                    f"pose_trans of {frame!r}, which is not a pose variable", field=where
                )
            self.wobjs[frame] = WorkObject(frame, self.poses[frame])
            T = self.literal_pose(a[1], where)
            if T is None:
                if a[1].strip() not in self.poses:
                    raise InputError(
                        f"{a[1]!r} is not a pose p[..] or a pose variable", field=where
                    )
                T = self.poses[a[1].strip()]
            return frame, T
        raise InputError(f"{s!r} is not a pose (p[..], a pose variable or pose_trans)", field=where)

    def base(self) -> str:
        name = "base"
        if name in self.poses and not np.allclose(self.poses[name], np.eye(4)):
            name = "robot_base"  # a pose variable "base" that is not the robot base
        self.wobjs.setdefault(name, WorkObject(name, np.eye(4)))
        return name

    def current_tool(self, no: int) -> str:
        if self.tool is None:
            self.notes.append(
                f"line {no}: a move before any set_tcp: the installation's TCP applies; read as the flange"
            )
            self.tools.setdefault("flange", ToolData("flange", np.eye(4)))
            self.tool = "flange"
        return self.tool

    def name_comment(self) -> tuple[str | None, np.ndarray | None, str | None, np.ndarray | None]:
        """Return (name, joints, via name, via joints) from the comments before a move
        (and, in self.frame, the work object a joint target's comment names)."""
        name = via = None
        q = qv = None
        self.frame = None
        for c in self.pending:
            if m := re.fullmatch(rf"({_IDENT}),\s+work object\s+({_IDENT})", c):
                name, self.frame = m.group(1), m.group(2)
            elif m := re.fullmatch(rf"via\s+({_IDENT})\s+joints\s+(\[.*\])", c):
                via, qv = m.group(1), _vector(m.group(2), "comment")
            elif m := re.fullmatch(rf"({_IDENT})\s+joints\s+(\[.*\])", c):
                name, q = m.group(1), _vector(m.group(2), "comment")
            elif m := re.fullmatch(rf"({_IDENT})", c):
                name, q = m.group(1), None
        self.pending = []
        return name, q, via, qv

    # -- statements -------------------------------------------------------------------
    def move(self, fn: str, inner: str, no: int) -> None:
        where = f"line {no}"
        pos, kw = _args(inner, where)
        name, q_c, via_name, qv_c = self.name_comment()
        r = _num(kw.get("r", "0"), where)
        tool = self.current_tool(no)
        default = f"target_{no}"
        if fn == "movej":
            if len(pos) != 1:
                raise InputError(f"movej needs one target, got {inner!r}", field=where)
            tgt, wobj = self.joint_target(pos[0], name or default, where)
            if tgt.T_wobj_tcp is None and self.frame in self.poses:
                wobj = self.frame
                self.wobjs.setdefault(wobj, WorkObject(wobj, self.poses[wobj]))
            t = _num(kw["t"], where) if "t" in kw else 0.0
            speed = None if t > 0 else _num(kw.get("v", "1.05"), where) / JOINT_SPEED
            self.items.append(
                ReadMove("joint", tgt, speed, r, tool, wobj, t if t > 0 else None, None, no)
            )
            return
        if fn == "movel":
            if len(pos) != 1:
                raise InputError(f"movel needs one target, got {inner!r}", field=where)
            wobj, T = self.pose(pos[0], where)
            tgt = self.cart_target(name or default, T, q_c, where)
            self.items.append(
                ReadMove(
                    "linear", tgt, _num(kw.get("v", "0.25"), where), r, tool, wobj, None, None, no
                )
            )
            return
        if len(pos) != 2:
            raise InputError(f"movec needs a via and an end pose, got {inner!r}", field=where)
        wv, Tv = self.pose(pos[0], where)
        wobj, T = self.pose(pos[1], where)
        if wv != wobj:
            self.notes.append(
                f"{where}: movec via in {wv!r}, end in {wobj!r}: read both in {wobj!r}"
            )
        via = self.cart_target(via_name or f"via_{no}", Tv, qv_c, where)
        tgt = self.cart_target(name or default, T, q_c, where)
        if kw.get("mode", "0").strip() not in ("0",):
            self.notes.append(
                f"{where}: movec mode={kw['mode']} (fixed orientation) is read as a circular move"
            )
        self.items.append(
            ReadMove(
                "circular", tgt, _num(kw.get("v", "0.25"), where), r, tool, wobj, None, via, no
            )
        )

    def cart_target(self, name: str, T: np.ndarray, q: np.ndarray | None, where: str) -> ReadTarget:
        if q is None:
            self.notes.append(
                f"{where}: target {name!r} states no joints: the controller takes the nearest"
            )
        return ReadTarget(name, joints=q, T_wobj_tcp=T)

    def joint_target(self, s: str, name: str, where: str) -> tuple[ReadTarget, str]:
        s = s.strip()
        if s.startswith("["):
            return ReadTarget(name, joints=_vector(s, where)), self.base()
        if s in self.qvars:
            return ReadTarget(name, joints=self.qvars[s]), self.base()
        c = _call(s)
        if c and c[0] == "get_inverse_kin":
            a, kw = _args(c[1], where)
            qn = kw.get("qnear", a[1] if len(a) > 1 else None)
            if not a or qn is None:
                raise InputError("get_inverse_kin needs a pose and qnear=[..]", field=where)
            wobj, T = self.pose(a[0], where)
            q = self.qvars.get(qn.strip()) if qn.strip() in self.qvars else _vector(qn, where)
            return ReadTarget(name, joints=q, T_wobj_tcp=T), wobj
        wobj, T = self.pose(s, where)
        return self.cart_target(name, T, None, where), wobj

    def io(self, fn: str, inner: str, no: int) -> None:
        where = f"line {no}"
        m = re.fullmatch(r"set_(standard|configurable)_digital_out", fn)
        a, _ = _args(inner, where)
        if not m or len(a) != 2 or a[1] not in ("True", "False"):
            raise InputError(
                f"expected set_standard_digital_out(n, True|False), got {fn}({inner})", field=where
            )
        n = int(_num(a[0], where)) + (STANDARD_IO if m.group(1) == "configurable" else 0)
        self.items.append(SetOutput(Signal(f"DO{n}", n), a[1] == "True"))


def _in_condition(cond: str) -> tuple[Signal, bool] | None:
    m = re.fullmatch(
        r"(not\s+)?get_(standard|configurable)_digital_in\(\s*(\d+)\s*\)", cond.strip()
    )
    if not m:
        return None
    n = int(m.group(3)) + (STANDARD_IO if m.group(2) == "configurable" else 0)
    return Signal(f"DI{n}", n), bool(m.group(1))


def _block(lines: list[tuple[int, str]], k: int) -> int:
    """Return the index after the `end` that closes the block opened at lines[k]."""
    depth = 0
    for j in range(k, len(lines)):
        t = lines[j][1]
        if re.match(r"(while|if|def|thread|for)\b.*:$", t):
            depth += 1
        elif t == "end":
            depth -= 1
            if depth == 0:
                return j + 1
    raise InputError(f"line {lines[k][0]}: the block has no closing 'end'")


def _wait(lines: list[tuple[int, str]], k: int, timer: bool) -> tuple[WaitInput | None, int]:
    """Return (the WaitInput of the while loop at lines[k], index after it) or (None, ..)."""
    no, text = lines[k]
    end = _block(lines, k)
    m = re.fullmatch(r"while\s+(.*):", text)
    sig = _in_condition(m.group(1)) if m else None
    body = [t for _, t in lines[k + 1 : end - 1]]
    if sig is None:
        return None, end
    if body == ["sync()"]:
        return WaitInput(sig[0], sig[1], None), end
    if timer and len(body) == 6 and body[1].startswith("popup(") and body[2:] == [
        "halt", "end", "sync()", "wait_t = wait_t + get_steptime()"
    ]:  # fmt: skip
        t = re.fullmatch(r"if\s+wait_t\s*>=\s*(\S+)\s*:", body[0])
        if t:
            return WaitInput(sig[0], sig[1], _num(t.group(1), f"line {no}")), end
    return None, end


def read_urscript(files: dict[str, str]) -> ReadProgram:
    """Return the program of one URScript file ({"name.script": text}); see the module docstring."""
    scripts = {k: v for k, v in files.items() if k.lower().endswith((".script", ".urscript"))}
    if len(scripts) != 1:
        raise InputError(f"read_urscript needs exactly one .script file, got {sorted(files)}")
    lines = numbered_lines(next(iter(scripts.values())))
    rd = _Reader()
    name = ""
    k = 0
    # the header before def, and the def line
    while k < len(lines) and not lines[k][1].startswith("def "):
        if not lines[k][1].startswith("#"):
            rd.unknown.append(lines[k])
        k += 1
    if k == len(lines):
        raise InputError("the file has no 'def name():': not a URScript program")
    m = re.fullmatch(rf"def\s+({_IDENT})\s*\(\s*\)\s*:", lines[k][1])
    if not m:
        raise InputError(f"line {lines[k][0]}: expected 'def name():', got {lines[k][1]!r}")
    name = m.group(1)
    end = _block(lines, k)
    body = lines[k + 1 : end - 1]
    for no, t in lines[end:]:
        if t != f"{name}()" and not t.startswith("#"):
            rd.unknown.append((no, t))
    _statements(rd, body)
    instructions = _fold(rd.items, rd.unknown)
    wobjs = list(rd.wobjs.values())
    if not any(w.name == "base" for w in wobjs):
        wobjs.append(WorkObject("base", np.eye(4)))
    return ReadProgram(
        name,
        tuple(rd.tools.values()),
        tuple(wobjs),
        tuple(instructions),
        tuple(rd.unknown),
        tuple(rd.notes),
    )


def _statements(rd: _Reader, body: list[tuple[int, str]]) -> None:
    k = 0
    while k < len(body):
        no, t = body[k]
        where = f"line {no}"
        if t.startswith("#"):
            c = " ".join(t[1:].split())
            if m := re.fullmatch(r"pulse\s+DO\s+(\d+)\s+for\s+(\S+)\s+s", c):
                rd.items.append(("pulse", no, int(m.group(1)), _num(m.group(2), where)))
            elif m := re.fullmatch(r"sync\s+(\S+?)\s*:\s*(.*)", c):
                robots = tuple(r.strip() for r in m.group(2).split(",") if r.strip())
                rd.items.append(("sync", no, m.group(1), robots))
            else:
                rd.pending.append(c)
            k += 1
            continue
        if t == "wait_t = 0" and k + 1 < len(body) and body[k + 1][1].startswith("while "):
            w, nxt = _wait(body, k + 1, True)
            if w is None:
                rd.unknown.extend(body[k:nxt])
            else:
                rd.items.append(w)
            k = nxt
            continue
        if t.startswith("while "):
            w, nxt = _wait(body, k, False)
            if w is None:
                rd.unknown.extend(body[k:nxt])
            else:
                rd.items.append(w)
            k = nxt
            continue
        if re.match(r"(if|for|thread|def)\b", t):
            nxt = _block(body, k)
            rd.unknown.extend(body[k:nxt])
            k = nxt
            continue
        k += 1
        if not t.startswith(("movej(", "movel(", "movec(")):
            rd.pending = []  # name comments belong to the move right after them
        if m := re.fullmatch(rf"(?:global\s+|local\s+)?({_IDENT})\s*=\s*(.+)", t):
            var, val = m.group(1), m.group(2).strip()
            T = rd.literal_pose(val, where) if val.startswith("p") else None
            if T is not None:
                rd.poses[var] = T
            elif val.startswith("["):
                rd.qvars[var] = _vector(val, where)
            else:
                rd.unknown.append((no, t))
            continue
        call = _call(t)
        if call is None:
            rd.unknown.append((no, t))
            continue
        fn, inner = call
        if fn in ("movej", "movel", "movec"):
            rd.move(fn, inner, no)
        elif fn in ("set_standard_digital_out", "set_configurable_digital_out"):
            rd.io(fn, inner, no)
        elif fn == "sleep":
            rd.items.append(WaitTime(_num(inner, where)))
        elif fn == "set_tcp":
            _set_tcp(rd, inner.strip(), where)
        elif fn == "set_payload":
            _set_payload(rd, inner, where)
        else:
            rd.unknown.append((no, t))


def _set_tcp(rd: _Reader, arg: str, where: str) -> None:
    T: np.ndarray | None
    if arg in rd.poses:
        name, T = arg, rd.poses[arg]
    else:
        T = rd.literal_pose(arg, where)
        if T is None:
            raise InputError(
                f"set_tcp needs a pose p[..] or a pose variable, got {arg!r}", field=where
            )
        rd.literal_tcps += 1
        name = f"tcp_{rd.literal_tcps}"
    old = rd.tools.get(name)
    rd.tools[name] = ToolData(name, T, old.mass if old else None, old.cog if old else None)
    rd.tool = name


def _set_payload(rd: _Reader, inner: str, where: str) -> None:
    a, kw = _args(inner, where)
    if not a or rd.tool is None:
        raise InputError("set_payload(mass, cog) needs a mass and a set_tcp before it", field=where)
    mass = _num(a[0], where)
    cog = _vector(a[1] if len(a) > 1 else kw.get("cog", "[0, 0, 0]"), where, 3)
    t = rd.tools[rd.tool]
    rd.tools[rd.tool] = ToolData(t.name, t.T_flange_tcp, mass, cog)


def _fold(items: list[object], unknown: list[tuple[int, str]]) -> list[ReadMove | Action]:
    """Turn the pulse and sync markers and the actions after them into PulseOutput / SyncPoint."""
    out: list[ReadMove | Action] = []
    k = 0
    while k < len(items):
        it = items[k]
        if isinstance(it, tuple):
            seq = items[k + 1 : k + 4]
            if it[0] == "pulse":
                ok = (
                    len(seq) == 3
                    and isinstance(seq[0], SetOutput) and seq[0].value and seq[0].signal.number == it[2]
                    and isinstance(seq[1], WaitTime) and abs(seq[1].seconds - it[3]) < 1e-9
                    and isinstance(seq[2], SetOutput) and not seq[2].value and seq[2].signal.number == it[2]
                )  # fmt: skip
                if ok:
                    out.append(PulseOutput(seq[0].signal, it[3]))  # type: ignore[attr-defined]
                    k += 4
                    continue
            elif found := match_handshake(items[k + 1 : k + 5]):
                lead, sig_out, sig_in = found
                out.append(SyncPoint(it[2], it[3], sig_out, sig_in, lead))
                k += 5
                continue
            unknown.append(
                (it[1], f"# {it[0]} block not followed by its output and wait lines ({it[0]})")
            )
            k += 1
            continue
        out.append(it)  # type: ignore[arg-type]
        k += 1
    return out
