"""FANUC LS reader: what `write_ls` writes (and the same instructions written by hand) back
into a `ReadProgram`.

Read: /PROG name; in /MN the frame lines (``PR[k]=LPOS-LPOS``, ``PR[k,j]=v``,
``UTOOL[n]=PR[k]``, ``UFRAME[m]=PR[k]``, named by the comments ``!UTOOL[n]: name`` /
``!UFRAME[m]: name``, mass and cog from ``!UTn mass ... kg`` / ``!UTn cog x,y,z mm``),
``UTOOL_NUM`` / ``UFRAME_NUM``, ``J P[i] pct% FINE|CNTn``, ``L P[i] v mm/sec|cm/min FINE|CRy|CNTn``,
``C P[via]`` + ``: P[end] v mm/sec ...``, ``DO[n]=ON|OFF``, ``DO[n]=PULSE,t sec``,
``$WAITTMOUT=k`` + ``WAIT DI[n]=ON|OFF TIMEOUT,LBL[j]`` (timeout k/100 s; FANUC's default
3000 = 30 s when the program does not set it), ``WAIT DI[n]=ON|OFF``, ``WAIT t(sec)``,
comments, the ``!SYNC name: robots`` four-phase handshake (`sync_handshake`) as a SyncPoint,
and after ``END`` the timeout handlers (LBL, MESSAGE, ABORT); in /POS joint positions
(J1..Jn deg) and Cartesian ones (X, Y, Z mm, W, P, R deg, UF, UT, CONFIG).

Returned: tools UTOOL0 (the faceplate) and UFRAME0 (the world), both identity, plus every
frame the program sets or uses (a number the program uses but does not set is read as
identity, with a note: its value lives in the controller); Cartesian targets with their
`ArmConfiguration` (F/N, U/D, T/B) and controller joint ranges from the turn numbers of J1,
J4, J6 (`fanuc.turn_range_deg`; `select_solution` takes them half-open, so a joint on a
boundary is found in one turn only); zones CRy -> y mm, CNT1..100 -> a blend of no stated radius, read as 0 with a note
(`fanuc.zone_of_termination`). Lines it does not understand are in
`unknown`; a malformed line raises InputError naming it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

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
from workbench.motion.programs.fanuc import TURN_JOINTS, turn_range_deg, zone_of_termination
from workbench.motion.programs.sync_handshake import match_handshake

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
DEFAULT_WAITTMOUT = 3000  # 1/100 s, FANUC's default $WAITTMOUT

_IO = r"\[\s*(\d+)\s*(?::([^\]]*))?\]"
_TERM = r"(FINE|CNT\s*\d+|CR\s*\d+)"
_PATTERNS = {
    "utool_num": re.compile(r"UTOOL_NUM\s*=\s*(\d+)$", re.I),
    "uframe_num": re.compile(r"UFRAME_NUM\s*=\s*(\d+)$", re.I),
    "pr_zero": re.compile(r"PR\[\s*(\d+)\s*(?::[^\]]*)?\]\s*=\s*LPOS\s*-\s*LPOS$", re.I),
    "pr_elem": re.compile(rf"PR\[\s*(\d+)\s*,\s*(\d+)\s*\]\s*=\s*({NUM})$", re.I),
    "frame": re.compile(
        r"(UTOOL|UFRAME)\[\s*(\d+)\s*\]\s*=\s*PR\[\s*(\d+)\s*(?::[^\]]*)?\]$", re.I
    ),
    "do": re.compile(rf"DO{_IO}\s*=\s*(ON|OFF)$", re.I),
    "pulse": re.compile(rf"DO{_IO}\s*=\s*PULSE\s*,\s*({NUM})\s*sec$", re.I),
    "waittmout": re.compile(r"\$WAITTMOUT\s*=\s*\(?\s*(\d+)\s*\)?$", re.I),
    "wait_di": re.compile(
        rf"WAIT\s+DI{_IO}\s*=\s*(ON|OFF)(?:\s+TIMEOUT\s*,\s*LBL\[\s*(\d+)\s*(?::[^\]]*)?\])?$", re.I
    ),
    "wait_t": re.compile(rf"WAIT\s+({NUM})\s*\(\s*sec\s*\)$", re.I),
    "end": re.compile(r"END$", re.I),
    "j": re.compile(rf"J\s+P\[\s*(\d+)\s*(?::[^\]]*)?\]\s+({NUM})\s*%\s+{_TERM}\s*(.*)$", re.I),
    "l": re.compile(
        rf"L\s+P\[\s*(\d+)\s*(?::[^\]]*)?\]\s+({NUM})\s*(mm/sec|cm/min)\s+{_TERM}\s*(.*)$", re.I
    ),
    "c": re.compile(
        rf"C\s+P\[\s*(\d+)\s*(?::[^\]]*)?\]\s+P\[\s*(\d+)\s*(?::[^\]]*)?\]\s+({NUM})\s*(mm/sec|cm/min)"
        rf"\s+{_TERM}\s*(.*)$",
        re.I,
    ),
}
_HANDLER = re.compile(r"(LBL\[[^\]]*\]|MESSAGE\[.*\]|ABORT|!.*)$", re.I)
_C_TOOL = re.compile(r"(UTOOL|UFRAME)\[(\d+)\]\s*:\s*(\S+)\s*$", re.I)
_C_MASS = re.compile(rf"UT(\d+)\s+mass\s+({NUM})\s*kg\s*$", re.I)
_C_COG = re.compile(rf"UT(\d+)\s+cog\s+({NUM})\s*,\s*({NUM})\s*,\s*({NUM})\s*mm\s*$", re.I)
_C_SYNC = re.compile(r"SYNC\s+(\S+)\s*:\s*(.*)$", re.I)


@dataclass
class _Position:
    line: int
    name: str
    uf: int
    ut: int
    joints: np.ndarray | None = None  # deg
    xyzwpr: np.ndarray | None = None
    config: str | None = None


@dataclass
class _State:
    tool_names: dict[int, str] = field(default_factory=dict)
    frame_names: dict[int, str] = field(default_factory=dict)
    tool_values: dict[int, np.ndarray] = field(default_factory=dict)
    frame_values: dict[int, np.ndarray] = field(default_factory=dict)
    mass: dict[int, float] = field(default_factory=dict)
    cog: dict[int, np.ndarray] = field(default_factory=dict)
    pr: dict[int, np.ndarray] = field(default_factory=dict)
    ut: int = 0
    uf: int = 0
    used_ut: set[int] = field(default_factory=set)
    used_uf: set[int] = field(default_factory=set)


def _T(xyzwpr: np.ndarray) -> np.ndarray:
    v = np.asarray(xyzwpr, float)
    return make_transform(rpy_to_matrix(np.radians(v[3:6])), v[:3] / 1000.0)


def parse_config(text: str, where: str) -> tuple[ArmConfiguration, tuple[int, int, int]]:
    """Return (ArmConfiguration, turn numbers of J1, J4, J6) of FANUC's 'F U T, t1, t4, t6'."""
    m = re.fullmatch(
        r"\s*([NF])\s*([UD])\s*([TB])\s*(?:,\s*(-?\d+)\s*,\s*(-?\d+)\s*,\s*(-?\d+))?\s*", text, re.I
    )
    if not m:
        raise InputError(f"CONFIG {text!r} is not 'N|F U|D T|B, t1, t4, t6'", field=where)
    f, u, t = (g.upper() for g in m.groups()[:3])
    turns = tuple(int(g) if g is not None else 0 for g in m.groups()[3:])
    return ArmConfiguration(front=t == "T", elbow_up=u == "U", wrist_flip=f == "F"), turns  # type: ignore[return-value]


def controller_ranges(turns: tuple[int, ...], dof: int = 6) -> np.ndarray:
    """Return the controller joint ranges (dof, 2) [rad] of the turn numbers of J1, J4, J6."""
    rng = np.tile([-np.inf, np.inf], (dof, 1))
    for j, t in zip(TURN_JOINTS, turns, strict=True):
        # half-open, as select_solution reads ranges: a joint on a boundary (J6 at 180 deg) is
        # found in one turn, not also one turn over
        rng[j] = np.radians(turn_range_deg(t))
    return rng


def _tcp_speed(value: str, unit: str, where: str) -> float:
    """Return a TCP speed [m/s] of FANUC's `value` in mm/sec or cm/min."""
    v = _num(value, where)
    return v / 1000.0 if unit.lower() == "mm/sec" else v / 6000.0


def _num(s: str, where: str) -> float:
    try:
        return float(s)
    except ValueError as exc:
        raise InputError(f"{s!r} is not a number", field=where) from exc


def _positions(lines: list[tuple[int, str]]) -> dict[int, _Position]:
    out: dict[int, _Position] = {}
    k = 0
    while k < len(lines):
        no, text = lines[k]
        if not text.strip():
            k += 1
            continue
        m = re.match(r'\s*P\[\s*(\d+)\s*(?::\s*"?([^"\]]*)"?\s*)?\]\s*\{', text)
        if not m:
            raise InputError(
                f"line {no}: expected a position 'P[i]{{' in /POS, got {text.strip()!r}"
            )
        block = [text[m.end() :]]
        while "};" not in block[-1]:
            k += 1
            if k >= len(lines):
                raise InputError(f"line {no}: position P[{m.group(1)}] has no closing '}};'")
            block.append(lines[k][1])
        k += 1
        body = " ".join(block)
        where = f"line {no} (P[{m.group(1)}])"
        if re.search(r"\bGP[2-9]\s*:", body) or re.search(r"\bE\d\s*=", body):
            raise InputError("extra motion groups and axes are not supported", field=where)
        uf = re.search(r"UF\s*:\s*(\d+)", body)
        ut = re.search(r"UT\s*:\s*(\d+)", body)
        if not uf or not ut:
            raise InputError("the position needs 'UF : m, UT : n'", field=where)
        pos = _Position(
            no, (m.group(2) or "").strip() or f"P{m.group(1)}", int(uf.group(1)), int(ut.group(1))
        )
        joints = dict(re.findall(rf"\bJ(\d)\s*=\s*({NUM})\s*deg", body))
        cart = dict(re.findall(rf"\b([XYZWPR])\s*=\s*({NUM})\s*(?:mm|deg)", body))
        cfg = re.search(r"CONFIG\s*:\s*'([^']*)'", body)
        if joints:
            n = len(joints)
            if sorted(joints) != [str(i) for i in range(1, n + 1)]:
                raise InputError(
                    f"joint position needs J1..J{n}, got {sorted(joints)}", field=where
                )
            pos.joints = np.array([_num(joints[str(i)], where) for i in range(1, n + 1)])
        elif len(cart) == 6:
            pos.xyzwpr = np.array([_num(cart[c], where) for c in "XYZWPR"])
            if not cfg:
                raise InputError(
                    "a Cartesian position needs CONFIG : 'F U T, t1, t4, t6'", field=where
                )
            pos.config = cfg.group(1)
        else:
            raise InputError("expected J1..J6 [deg] or X, Y, Z [mm], W, P, R [deg]", field=where)
        out[int(m.group(1))] = pos
    return out


def _sections(text: str) -> tuple[str, list[tuple[int, str]], list[tuple[int, str]]]:
    name, section = "", ""
    mn: list[tuple[int, str]] = []
    pos: list[tuple[int, str]] = []
    for no, raw in enumerate(text.splitlines(), start=1):
        head = raw.strip()
        if head.startswith("/"):
            word = head.split()[0].upper()
            section = word
            if word == "/PROG":
                parts = head.split()
                if len(parts) < 2:
                    raise InputError(f"line {no}: /PROG needs the program name")
                name = parts[1]
            continue
        if section == "/MN":
            mn.append((no, raw))
        elif section == "/POS":
            pos.append((no, raw))
    if not name:
        raise InputError("the file has no '/PROG  NAME' line: not a FANUC LS program")
    return name, mn, pos


def _instructions(mn: list[tuple[int, str]]) -> list[tuple[int, str]]:
    out: list[tuple[int, str]] = []
    for no, raw in mn:
        if not raw.strip():
            continue
        m = re.match(r"\s*(\d+)\s*:(.*)$", raw)
        cont = re.match(r"\s*:(.*)$", raw)
        if m:
            out.append((no, m.group(2)))
        elif cont and out:
            out[-1] = (out[-1][0], out[-1][1].rstrip() + " " + cont.group(1).strip())
        else:
            raise InputError(
                f"line {no}: a /MN line starts with its number 'n:', got {raw.strip()!r}"
            )
    clean = []
    for no, text in out:
        t = text.strip()
        if t.endswith(";"):
            t = t[:-1].rstrip()
        clean.append((no, t))
    return clean


def _signal(kind: str, number: str, comment: str | None) -> Signal:
    name = (comment or "").strip() or f"{kind}{int(number)}"
    return Signal(name, int(number))


class _LsReader:
    """The /MN instructions read one at a time into items, the frames they set and use, notes."""

    def __init__(self, positions: dict[int, _Position]) -> None:
        self.positions = positions
        self.st = _State()
        self.unknown: list[tuple[int, str]] = []
        self.notes: list[str] = []
        self.items: list[tuple[int, object]] = []  # (line, ReadMove | Action | ("sync", ..))
        self.waittmout: int | None = None
        self.after_end = False

    def target(self, i: str, no: int) -> ReadTarget:
        """Return the target P[i] of /POS, noting where it is recorded in other frames."""
        st = self.st
        p = self.positions.get(int(i))
        if p is None:
            raise InputError(f"line {no}: P[{i}] is not in /POS")
        st.used_ut.add(p.ut)
        st.used_uf.add(p.uf)
        if (p.ut, p.uf) != (st.ut, st.uf):
            self.notes.append(
                f"line {no}: P[{i}] is recorded with UT {p.ut}, UF {p.uf} while UTOOL_NUM={st.ut},"
                f" UFRAME_NUM={st.uf}; read in the position's frames"
            )
        if p.joints is not None:
            return ReadTarget(p.name, joints=np.radians(p.joints))
        assert p.xyzwpr is not None and p.config is not None
        cfg, turns = parse_config(p.config, f"line {p.line} (P[{i}])")
        return ReadTarget(
            p.name,
            T_wobj_tcp=_T(p.xyzwpr),
            configuration=cfg,
            controller_ranges=controller_ranges(turns),
        )

    def move(
        self,
        kind: str,
        i: str,
        speed: float,
        term: str,
        rest: str,
        no: int,
        text: str,
        via: ReadTarget | None = None,
    ) -> None:
        """Read a move to P[i]; text after its termination goes to `unknown`."""
        tgt = self.target(i, no)
        p = self.positions[int(i)]
        zone = zone_of_termination(term)
        if zone is None:
            self.notes.append(
                f"line {no}: {term.replace(' ', '')} is a percentage of the speed kept through"
                " P[" + i + "], not a radius: read as a blend of no stated size (zone 0)"
            )
            zone = 0.0
        mv = ReadMove(kind, tgt, speed, zone, f"UTOOL{p.ut}", f"UFRAME{p.uf}", None, via, no)  # type: ignore[arg-type]
        self.items.append((no, mv))
        if rest:
            self.unknown.append((no, text))

    def comment(self, no: int, c: str) -> None:
        """Read a comment: tool and frame names, tool mass and cog, a sync point."""
        st = self.st
        if m := _C_TOOL.match(c):
            (st.tool_names if m.group(1).upper() == "UTOOL" else st.frame_names)[
                int(m.group(2))
            ] = m.group(3)
        elif m := _C_MASS.match(c):
            st.mass[int(m.group(1))] = float(m.group(2))
        elif m := _C_COG.match(c):
            st.cog[int(m.group(1))] = np.array([float(g) for g in m.groups()[1:]]) / 1000.0
        elif m := _C_SYNC.match(c):
            robots = tuple(r.strip() for r in m.group(2).split(",") if r.strip())
            self.items.append((no, ("sync", m.group(1), robots)))

    def line(self, no: int, text: str) -> None:
        """Read one /MN instruction."""
        if self.after_end:
            if not _HANDLER.match(text):
                self.unknown.append((no, text))
            return
        if text.startswith("!"):
            self.comment(no, text[1:].strip())
            return
        for key, pat in _PATTERNS.items():
            if m := pat.match(text):
                self.instruction(key, m.groups(), no, text)
                return
        self.unknown.append((no, text))

    def instruction(self, hit: str, g: tuple, no: int, text: str) -> None:
        """Read an instruction that matched the pattern `hit` with groups `g`."""
        st, items, where = self.st, self.items, f"line {no}"
        if hit == "utool_num":
            st.ut = int(g[0])
        elif hit == "uframe_num":
            st.uf = int(g[0])
        elif hit == "pr_zero":
            st.pr[int(g[0])] = np.zeros(6)
        elif hit == "pr_elem":
            k, j = int(g[0]), int(g[1])
            if not 1 <= j <= 6:
                raise InputError(
                    f"PR[{k},{j}]: a Cartesian element is 1..6 (X Y Z W P R)", field=where
                )
            st.pr.setdefault(k, np.zeros(6))[j - 1] = _num(g[2], where)
        elif hit == "frame":
            k = int(g[2])
            if k not in st.pr:
                raise InputError(f"PR[{k}] is used before the program sets it", field=where)
            (st.tool_values if g[0].upper() == "UTOOL" else st.frame_values)[int(g[1])] = st.pr[
                k
            ].copy()
        elif hit == "do":
            items.append((no, SetOutput(_signal("DO", g[0], g[1]), g[2].upper() == "ON")))
        elif hit == "pulse":
            items.append((no, PulseOutput(_signal("DO", g[0], g[1]), _num(g[2], where))))
        elif hit == "waittmout":
            self.waittmout = int(g[0])
        elif hit == "wait_di":
            items.append((no, self.wait_input(g, where)))
        elif hit == "wait_t":
            items.append((no, WaitTime(_num(g[0], where))))
        elif hit == "end":
            self.after_end = True
        elif hit == "j":
            self.move("joint", g[0], _num(g[1], where) / 100.0, g[2], g[3], no, text)
        elif hit == "l":
            self.move("linear", g[0], _tcp_speed(g[1], g[2], where), g[3], g[4], no, text)
        elif hit == "c":
            via = self.target(g[0], no)
            self.move("circular", g[1], _tcp_speed(g[2], g[3], where), g[4], g[5], no, text, via)

    def wait_input(self, g: tuple, where: str) -> WaitInput:
        """Return WAIT DI[n]=ON|OFF, its TIMEOUT from $WAITTMOUT (or FANUC's default)."""
        timeout = None
        if g[3] is not None:
            if self.waittmout is None:
                self.notes.append(
                    f"{where}: TIMEOUT without $WAITTMOUT: FANUC's default 30 s applies"
                )
            timeout = (self.waittmout if self.waittmout is not None else DEFAULT_WAITTMOUT) / 100.0
        return WaitInput(_signal("DI", g[0], g[1]), g[2].upper() == "ON", timeout)

    def frames(self) -> tuple[list[ToolData], list[WorkObject]]:
        """Return the tools and work objects: number 0 (identity) and every one set or used."""
        st = self.st
        tools = [ToolData("UTOOL0", np.eye(4))]
        for n in sorted(set(st.tool_values) | st.used_ut - {0}):
            if n not in st.tool_values:
                self.notes.append(
                    f"UTOOL[{n}] is used but not set in the program: read as identity (the controller's value applies)"
                )
            T = _T(st.tool_values[n]) if n in st.tool_values else np.eye(4)
            tools.append(ToolData(f"UTOOL{n}", T, st.mass.get(n), st.cog.get(n)))
        wobjs = [WorkObject("UFRAME0", np.eye(4))]
        for n in sorted(set(st.frame_values) | st.used_uf - {0}):
            if n not in st.frame_values:
                self.notes.append(
                    f"UFRAME[{n}] is used but not set in the program: read as identity (the controller's value applies)"
                )
            wobjs.append(
                WorkObject(
                    f"UFRAME{n}", _T(st.frame_values[n]) if n in st.frame_values else np.eye(4)
                )
            )
        return tools, wobjs


def read_ls(files: dict[str, str]) -> ReadProgram:
    """Return the program of one FANUC LS file ({"NAME.ls": text}); see the module docstring."""
    ls = {k: v for k, v in files.items() if k.lower().endswith(".ls")}
    if len(ls) != 1:
        raise InputError(f"read_ls needs exactly one .ls file, got {sorted(files)}")
    text = next(iter(ls.values()))
    name, mn, pos_lines = _sections(text)
    rd = _LsReader(_positions(pos_lines))
    for no, line in _instructions(mn):
        rd.line(no, line)
    instructions = _fold_syncs(rd.items, rd.unknown)
    tools, wobjs = rd.frames()
    tools, wobjs, instructions = _named(tools, wobjs, instructions, rd.st)
    return ReadProgram(
        name, tuple(tools), tuple(wobjs), tuple(instructions), tuple(rd.unknown), tuple(rd.notes)
    )


def _fold_syncs(
    items: list[tuple[int, object]], unknown: list[tuple[int, str]]
) -> list[ReadMove | Action]:
    out: list[ReadMove | Action] = []
    k = 0
    while k < len(items):
        no, it = items[k]
        if isinstance(it, tuple):
            _, name, robots = it
            found = match_handshake([x for _, x in items[k + 1 : k + 5]])
            if found:
                lead, sig_out, sig_in = found
                out.append(SyncPoint(name, robots, sig_out, sig_in, lead))
                k += 5
                continue
            unknown.append(
                (
                    no,
                    f"!SYNC {name}: not followed by the four-phase handshake (WAIT DI[m]=OFF/ON,"
                    " DO[n]=ON, WAIT DI[m]=ON/OFF, DO[n]=OFF)",
                )
            )
            k += 1
            continue
        out.append(it)  # type: ignore[arg-type]
        k += 1
    return out


def _named(
    tools: list[ToolData], wobjs: list[WorkObject], ins: list, st: _State
) -> tuple[list, list, list]:
    """Give tools and frames the names of the program's comments (!UTOOL[n]: name)."""
    tmap = {f"UTOOL{n}": nm for n, nm in st.tool_names.items()}
    fmap = {f"UFRAME{n}": nm for n, nm in st.frame_names.items()}
    if len(set(tmap.values())) != len(tmap) or set(tmap.values()) & {t.name for t in tools}:
        tmap = {}
    if len(set(fmap.values())) != len(fmap) or set(fmap.values()) & {w.name for w in wobjs}:
        fmap = {}
    tools = [ToolData(tmap.get(t.name, t.name), t.T_flange_tcp, t.mass, t.cog) for t in tools]
    wobjs = [WorkObject(fmap.get(w.name, w.name), w.T_base_wobj) for w in wobjs]
    out = []
    for i in ins:
        if isinstance(i, ReadMove):
            i = ReadMove(
                i.kind,
                i.target,
                i.speed,
                i.zone,
                tmap.get(i.tool, i.tool),
                fmap.get(i.wobj, i.wobj),
                i.duration,
                i.via,
                i.line,
            )
        out.append(i)
    return tools, wobjs, out
