"""FANUC LS post-processor: a `RobotProgram` as a FANUC teach-pendant program in LS text.

`write_ls(program)` returns one file "<NAME>.ls" (/PROG, /ATTR, /MN, /POS, /END):

Frames. The program's tools get UTOOL numbers 1, 2, ... and its work objects UFRAME numbers
1, 2, ... in the order the program lists them. Their values live in the controller, so the
program's first lines are a comment block naming each number (and the tool's mass and centre
of gravity, for the controller's payload schedule), followed by the lines that set them:
``PR[90]=LPOS-LPOS`` (a Cartesian position register of zeros), ``PR[90,1..6]=X, Y, Z [mm],
W, P, R [deg]``, ``UTOOL[n]=PR[90]`` / ``UFRAME[m]=PR[90]`` (one spare register, `spare_pr`,
reused for every frame). A cell whose frames are managed on the controller deletes those
lines; the comments keep the values. UTOOL values are the TCP in the flange (faceplate)
frame; UFRAME values are the work object in the model's robot base frame, which must be the
controller's world frame (on most FANUC arms the world origin lies on the J1 axis at the
height of J2: shift the frames if the model's base is elsewhere). ``UTOOL_NUM=n`` /
``UFRAME_NUM=m`` select them before the first move that uses them.

Positions (/POS). Joint targets: J1..J6 [deg], controller joints (`RobotProgram.
controller_joints`). Cartesian targets: X, Y, Z [mm] and W, P, R [deg] (R = Rz(R) Ry(P)
Rx(W), fixed axes x, y, z) of the TCP in the move's user frame, with
``CONFIG : 'F/N U/D T/B, t1, t4, t6'``:

- F (flip) / N (no flip): the wrist is flipped (`ArmConfiguration.wrist_flip`): for a FANUC
  arm (`JointConvention.flip_sign` +1) the controller's J5 is positive, so the usual
  tool-down posture (J4 ~ 0, J5 ~ -90 deg) is N, as it is ABB's cfx 0 and KUKA's Status
  'B010' (geometrically the same wrist; RoboDK computes its flip bit on joints whose J5 turns
  the ABB way, FANUC's negated); for robots of other conventions the flip their convention
  says (NACHI's MZ07: J5 negative);
- U (up) / D (down): the elbow is up (`ArmConfiguration.elbow_up`);
- T (top, i.e. front) / B (bottom, i.e. back): the wrist centre lies in front of J1
  (`ArmConfiguration.front`);
- t1, t4, t6: the turn numbers of J1, J4 and J6 (`turn_number`): 0 for -180 < J < 180 deg,
  +1 for 180 <= J < 540, -1 for -540 < J <= -180 (and so on per 360 deg).

Source of the configuration rule: the FANUC HandlingTool/ArcTool operator's manuals
("configuration": wrist flip/no-flip, arm up/down, front/back, turn numbers of J1, J4, J6)
and, for the letters and the turn-number boundaries, RoboDK's open FANUC post
(ros-industrial-attic/robodk_postprocessors, scripts/postprocessors/Fanuc_R30iA.py,
``add_target_cartesian``: F from RoboDK's flip bit, D from its lower-elbow bit, B from its
rear bit, ``angle_2_turn``). Our own code follows that rule; tests check hand-computed cases.

Moves. ``J P[i] pct% FINE|CNT100`` (pct = the move's fraction of the joints' maximum speed, a
whole percent 1..100), ``L P[i] v mm/sec FINE|CRy`` (v a whole mm/sec, or whole cm/min where that is nearer),
``C P[via]`` + ``:  P[end] v mm/sec FINE|CRy`` (FANUC's circular move through P[via]). Zones
(FANUC operator's manual, "Motion options": CNT0..100 is the percentage of the speed kept
through the point, not a distance; "Corner Region Termination Type (CRy)": y the corner
region in mm, 0..1000, for LINEAR and CIRCULAR motion only, part of the Advanced Constant
Path option with Corner Distance switched off, ``$czcdcfg.$cd_enable = FALSE``): zone 0 ->
FINE; a linear or circular blend of z mm -> ``CR round(z)`` (at least CR1; over 1000 mm
refused), which states the planned corner in mm whatever the speed; a joint move's blend ->
``CNT100`` (CR has no joint form; the plan keeps the speed through a blended point). The
Advanced Constant Path option is assumed: a controller without it refuses the program when
it loads (loudly), where a CNT guessed from the zone would round every corner differently
from the plan (CNTn with n = the zone in mm, as this post wrote before, made the polishing
program nearly stop at each of its points). The reader reads CRy as y mm (whole-millimetre
zones round-trip exactly, others are rounded with a note) and CNT1..100 as a blend of no
stated radius (0, noted). Speeds and pulse/wait times are rounded to the controller's steps (1 %; 1 mm/sec, or
1 cm/min = 1/6 mm/s where mm/sec is off by more than 0.5 % and cm/min is nearer; 0.1 s pulses, 0.01 s waits) with a note when that
changes them (one note per kind with the largest change when there are more than three).

Actions. ``DO[n:name]=ON|OFF``, ``DO[n:name]=PULSE,t sec``, ``WAIT DI[n:name]=ON|OFF``,
``WAIT t(sec)``, comments ``!text`` (at most 32 characters a line; longer ones are split).
A wait with a timeout uses FANUC's $WAITTMOUT pattern: ``$WAITTMOUT=k`` (k in 1/100 s, the
unit of the FANUC operator's manual, "WAIT instructions") before ``WAIT DI[n]=ON TIMEOUT,
LBL[j]``; LBL[j] lies after the program's ``END`` and shows ``MESSAGE[...]`` then ``ABORT``:
a timed-out wait stops the program, as RAPID's WaitDI \\MaxTime does. A gripper action is a
comment "gripper close/open" and its expanded actions. A sync point is the four-phase I/O
handshake of `sync_handshake` after the comment ``!SYNC name: ROBOT_A,ROBOT_B``: leading
``WAIT DI[in]=OFF``, ``DO[out]=ON``, ``WAIT DI[in]=ON``, ``DO[out]=OFF``; following ``WAIT
DI[in]=ON``, ``DO[out]=ON``, ``WAIT DI[in]=OFF``, ``DO[out]=OFF``.

Names. The program name is upper case, letters, digits and _ (at most 36 characters, the
R-30iB limit); position comments (the target names) at most 16 characters; names that clash
with FANUC TP words (`RESERVED`) are renamed. Every rename and rounding is in
`ExportedProgram.notes` and in comment lines at the top of /MN.
"""

from __future__ import annotations

import math
import textwrap

import numpy as np

from workbench.errors import InputError
from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.motion.programs.angles import wpr_deg
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
    move_label,
)
from workbench.motion.programs.exported import ExportedProgram
from workbench.motion.programs.first_move import safe_start
from workbench.motion.programs.names import NameTable
from workbench.motion.programs.sync_handshake import handshake, leads

#: Words of FANUC's TP language (instructions, registers, operators) no name may take.
RESERVED = (
    "A", "ABORT", "ACC", "AI", "AND", "AO", "AR", "C", "CALL", "CNT", "CONFIG", "DI", "DIV",
    "DO", "ELSE", "END", "ENDFOR", "FINE", "FOR", "GI", "GO", "IF", "J", "JMP", "JPOS", "L",
    "LBL", "LPOS", "MESSAGE", "MOD", "NOT", "OFF", "OFFSET", "ON", "OR", "P", "PAUSE",
    "PAYLOAD", "PR", "PULSE", "R", "RI", "RO", "RUN", "SELECT", "SI", "SKIP", "SO", "SR",
    "TIMEOUT", "TIMER", "TO", "DOWNTO", "TOOL_OFFSET", "UALM", "UFRAME", "UFRAME_NUM", "UI",
    "UO", "UTOOL", "UTOOL_NUM", "VOFFSET", "WAIT", "WJNT", "INC", "MAIN",
)  # fmt: skip
PROGRAM_NAME_LEN = 36  # R-30iB program names
POSITION_COMMENT_LEN = 16  # P[i:"comment"]
COMMENT_LEN = 32  # a remark line (!...)
MAX_UTOOL = 10
MAX_UFRAME = 9
SPARE_PR = 90
TURN_JOINTS = (0, 3, 5)  # J1, J4, J6


def turn_number(angle_deg: float) -> int:
    """Return FANUC's turn number of a joint angle [deg]: 0 for (-180, 180), +1 for
    [180, 540), -1 for (-540, -180], and so on (see the module docstring for the source)."""
    a = float(angle_deg)
    if a >= 0.0:
        return int(math.floor((a + 180.0) / 360.0))
    return -int(math.floor((-a + 180.0) / 360.0))


def turn_range_deg(turn: int) -> tuple[float, float]:
    """Return the joint interval [deg] (lo, hi) of a turn number (ends as in `turn_number`)."""
    return 360.0 * turn - 180.0, 360.0 * turn + 180.0


def config_text(configuration: ArmConfiguration, q_controller: np.ndarray) -> str:
    """Return FANUC's configuration 'F U T, t1, t4, t6' of a configuration and controller
    joints (dof,) [rad]."""
    q = np.degrees(np.asarray(q_controller, float))
    letters = (
        "F" if configuration.wrist_flip else "N",
        "U" if configuration.elbow_up else "D",
        "T" if configuration.front else "B",
    )
    turns = ", ".join(str(turn_number(q[j])) for j in TURN_JOINTS)
    return f"{' '.join(letters)}, {turns}"


CR_MAX_MM = 1000
"""FANUC's corner region CRy takes y = 0..1000 mm (operator's manual, "Motion options",
Corner Region Termination Type)."""


def termination(kind: str, zone_m: float, where: str) -> tuple[str, float]:
    """Return (FANUC termination, the zone it means [m]) of a move of `kind` with a blend
    radius [m]: FINE for 0. A linear or circular move's blend is ``CRy``, the corner region in
    whole mm (at least CR1, so a blend stays a blend; over 1000 mm refused naming `where`).
    A joint move's blend is ``CNT100``: CR supports only Cartesian motion, and CNT is the
    percentage of the speed kept through the point, not a distance; the plan keeps its speed
    through a blended point, so 100 (the rounding is then the controller's; the zone it means
    is the plan's)."""
    if zone_m <= 0.0:
        return "FINE", 0.0
    if kind == "joint":
        return "CNT100", zone_m
    mm = zone_m * 1000.0
    if mm > CR_MAX_MM + 1e-9:
        raise InputError(
            f"zone {mm:g} mm is over FANUC's largest corner region CR{CR_MAX_MM}; lower the zone",
            field=where,
        )
    n = max(1, min(CR_MAX_MM, int(math.floor(mm + 0.5))))
    return f"CR{n}", n / 1000.0


def zone_of_termination(term: str) -> float | None:
    """Return the blend radius [m] of a FANUC termination: FINE 0, CRy y mm (the inverse of
    `termination`), CNT0 0; None for CNT1..CNT100 (a percentage of speed: no radius)."""
    t = term.strip().upper().replace(" ", "")
    if t == "FINE":
        return 0.0
    if t.startswith("CR") and t[2:].isdigit() and 0 <= int(t[2:]) <= CR_MAX_MM:
        return int(t[2:]) / 1000.0
    if t.startswith("CNT") and t[3:].isdigit() and 0 <= int(t[3:]) <= 100:
        return 0.0 if int(t[3:]) == 0 else None
    raise InputError(f"termination {term!r} is not FINE, CNT0..CNT100 or CR0..CR{CR_MAX_MM}")


def _n(x: float, nd: int) -> str:
    s = f"{x:.{nd}f}"
    return s[1:] if s.startswith("-") and float(s) == 0.0 else s


def _comment_lines(text: str) -> list[str]:
    clean = " ".join(text.replace(";", ",").replace('"', "'").split())
    return textwrap.wrap(clean, COMMENT_LEN, break_on_hyphens=False)


def _xyzwpr(T: np.ndarray) -> list[float]:
    return [*(np.asarray(T[:3, 3], float) * 1000.0), *wpr_deg(T[:3, :3])]


class _Writer:
    def __init__(self, program: RobotProgram, spare_pr: int) -> None:
        self.p = program
        self.spare_pr = spare_pr
        self.mn: list[str] = []
        self.pos: list[str] = []
        self.handlers: list[str] = []
        self.rounds: dict[str, list[tuple[str, float, float, str]]] = {}
        self.n_pos = 0
        self.n_lbl = 0
        self.names = NameTable("FANUC LS", RESERVED, max_len=POSITION_COMMENT_LEN)
        self.frame_names = NameTable("FANUC LS", RESERVED, max_len=POSITION_COMMENT_LEN)
        self.ut = {t.name: k for k, t in enumerate(program.tools, start=1)}
        self.uf = {w.name: k for k, w in enumerate(program.work_objects, start=1)}
        self.active = (-1, -1)

    def line(self, text: str, kind: str = " ") -> None:
        self.mn.append(f"{kind}{'' if kind != ' ' else ' '}{text} ;")

    def comment(self, text: str) -> None:
        for c in _comment_lines(text):
            self.line(f"!{c}")

    def io(self, kind: str, s: Signal) -> str:
        name = "".join(ch for ch in s.name if ch.isalnum() or ch in "_ -")[:16]
        return f"{kind}[{s.number}:{name}]" if name else f"{kind}[{s.number}]"

    def frames(self) -> None:
        self.comment(f"workbench program {self.p.name}")
        self.comment("frames (set below from PR):")
        for t in self.p.tools:
            k = self.ut[t.name]
            self.comment(f"UTOOL[{k}]: {self.frame_names(t.name, f'tool{k}')}")
            if t.mass is not None:
                self.comment(f"UT{k} mass {t.mass:.3f} kg")
            if t.cog is not None:
                c = np.asarray(t.cog, float) * 1000.0
                self.comment(f"UT{k} cog {c[0]:.1f},{c[1]:.1f},{c[2]:.1f} mm")
        for w in self.p.work_objects:
            k = self.uf[w.name]
            self.comment(f"UFRAME[{k}]: {self.frame_names(w.name, f'frame{k}')}")
        for what, items, T_of, num in (
            ("UTOOL", self.p.tools, lambda t: t.T_flange_tcp, self.ut),
            ("UFRAME", self.p.work_objects, lambda w: w.T_base_wobj, self.uf),
        ):
            for it in items:
                v = _xyzwpr(np.asarray(T_of(it), float))
                pr = self.spare_pr
                self.line(f"PR[{pr}]=LPOS-LPOS")
                for j, x in enumerate(v, start=1):
                    self.line(f"PR[{pr},{j}]={_n(x, 6)}")
                self.line(f"{what}[{num[it.name]}]=PR[{pr}]")

    def select(self, mv: MoveInstr) -> tuple[int, int]:
        ut, uf = self.ut[mv.tool], self.uf[mv.wobj]
        if self.active[0] != ut:
            self.line(f"UTOOL_NUM={ut}")
        if self.active[1] != uf:
            self.line(f"UFRAME_NUM={uf}")
        self.active = (ut, uf)
        return ut, uf

    def position(self, tgt: Target, ut: int, uf: int) -> int:
        self.n_pos += 1
        i = self.n_pos
        name = self.names(tgt.name, f"P{i}")
        self.pos += [f'P[{i}:"{name}"]{{', "   GP1:"]
        qc = self.p.controller_joints(tgt.q)
        if tgt.T_wobj_tcp is None:
            self.pos.append(f"\tUF : {uf}, UT : {ut},")
            j = np.degrees(qc)
            cells = [f"J{k + 1}={_n(x, 6):>14} deg" for k, x in enumerate(j)]
        else:
            assert tgt.configuration is not None  # check_program
            if self.p.dof != 6:
                raise InputError(
                    f"program {self.p.name}: FANUC's CONFIG needs a 6-axis arm for the"
                    f" Cartesian target {tgt.name!r}; this one has {self.p.dof} joints"
                )
            cfg = config_text(tgt.configuration, qc)
            self.pos.append(f"\tUF : {uf}, UT : {ut},\t\tCONFIG : '{cfg}',")
            v = _xyzwpr(np.asarray(tgt.T_wobj_tcp, float))
            labels = ("X", "Y", "Z", "W", "P", "R")
            cells = [
                f"{lab} ={_n(x, 6):>14} {'mm' if k < 3 else 'deg'}"
                for k, (lab, x) in enumerate(zip(labels, v, strict=True))
            ]
        rows = [cells[k : k + 3] for k in range(0, len(cells), 3)]
        for r, row in enumerate(rows):
            self.pos.append("\t" + ",\t".join(row) + ("," if r < len(rows) - 1 else ""))
        self.pos.append("};")
        return i

    def rounded(self, where: str, what: str, value: float, written: float, unit: str) -> None:
        if abs(value - written) > 1e-9 * max(1.0, abs(value)):
            self.rounds.setdefault(what, []).append((where, value, written, unit))

    def rounding_notes(self) -> list[str]:
        """Return one note per rounding (up to 3 of a kind), else a summary with the largest."""
        out = []
        for what, cases in self.rounds.items():
            text = [f"{w}: {what} {v:g} {u} written as {x:g} {u}" for w, v, x, u in cases]
            if len(cases) <= 3:
                out += text
                continue
            worst = max(
                range(len(cases)),
                key=lambda k: abs(cases[k][1] - cases[k][2]) / max(abs(cases[k][1]), 1e-12),
            )
            out.append(
                f"{what} rounded to the controller's steps on {len(cases)} lines; the largest: {text[worst]}"
            )
        return out

    def speed(self, where: str, v: float) -> str:
        """Return a TCP speed [m/s] as whole mm/sec (when within 0.5 %) or, where that is
        nearer, whole cm/min (1/6 mm/s steps: slow process speeds)."""
        mm = v * 1000.0
        mms = int(math.floor(mm + 0.5))
        cmm = int(math.floor(mm * 6.0 + 0.5))
        if mms < 1 and cmm < 1:
            raise InputError(
                f"{where}: TCP speed {mm:g} mm/s is under FANUC's 1 cm/min; raise the move's speed"
            )
        if mms >= 1 and abs(mms - mm) <= 5e-3 * mm or abs(mms - mm) <= abs(cmm / 6.0 - mm):
            self.rounded(where, "TCP speed", mm, mms, "mm/s")
            return f"{mms}mm/sec"
        self.rounded(where, "TCP speed", mm, cmm / 6.0, "mm/s")
        return f"{cmm}cm/min"

    def move(self, k: int, mv: MoveInstr) -> None:
        where = move_label(self.p, k, mv)
        ut, uf = self.select(mv)
        term, z = termination(mv.kind, mv.zone, where)
        self.rounded(where, "zone", mv.zone * 1000.0, z * 1000.0, "mm")
        if mv.kind == "joint":
            pct = max(1, min(100, int(math.floor(mv.speed * 100.0 + 0.5))))
            self.rounded(where, "joint speed", mv.speed * 100.0, pct, "%")
            i = self.position(mv.target, ut, uf)
            self.mn.append(f"J P[{i}] {pct}% {term} ;")
            return
        speed = self.speed(where, mv.speed)
        if mv.kind == "linear":
            i = self.position(mv.target, ut, uf)
            self.mn.append(f"L P[{i}] {speed} {term} ;")
            return
        assert mv.via is not None  # check_program
        iv = self.position(mv.via, ut, uf)
        i = self.position(mv.target, ut, uf)
        self.mn.append(f"C P[{iv}]\n    :  P[{i}] {speed} {term} ;")

    def action(self, a: object) -> None:
        if isinstance(a, SetOutput):
            self.line(f"{self.io('DO', a.signal)}={'ON' if a.value else 'OFF'}")
        elif isinstance(a, PulseOutput):
            t = round(a.duration, 1)
            if not 0.1 <= t <= 25.5:
                raise InputError(
                    f"program {self.p.name}: pulse of DO[{a.signal.number}] lasts"
                    f" {a.duration:g} s; FANUC pulses last 0.1 .. 25.5 s"
                )
            self.rounded(f"pulse DO[{a.signal.number}]", "duration", a.duration, t, "s")
            self.line(f"{self.io('DO', a.signal)}=PULSE,{t:.1f}sec")
        elif isinstance(a, WaitInput):
            cond = f"WAIT {self.io('DI', a.signal)}={'ON' if a.value else 'OFF'}"
            if a.timeout is None:
                self.line(cond)
                return
            ticks = int(math.floor(a.timeout * 100.0 + 0.5))
            if ticks < 1:
                raise InputError(
                    f"program {self.p.name}: the wait for DI[{a.signal.number}] has a timeout"
                    f" of {a.timeout:g} s; FANUC's $WAITTMOUT counts 0.01 s steps (>= 0.01 s)"
                )
            self.rounded(f"wait DI[{a.signal.number}]", "timeout", a.timeout, ticks / 100.0, "s")
            self.n_lbl += 1
            lbl = self.n_lbl
            self.line(f"$WAITTMOUT={ticks}")
            self.line(f"{cond} TIMEOUT,LBL[{lbl}]")
            self.handlers += [
                f"LBL[{lbl}]",
                f"!timeout DI[{a.signal.number}] {ticks / 100:g} s",
                f"MESSAGE[TIMEOUT DI {a.signal.number}]",
                "ABORT",
            ]
        elif isinstance(a, WaitTime):
            t = round(a.seconds, 2)
            self.rounded("wait", "time", a.seconds, t, "s")
            self.line(f"WAIT {t:.2f}(sec)")
        elif isinstance(a, Comment):
            self.comment(a.text)
        elif isinstance(a, Gripper):
            self.comment(f"gripper {'close' if a.close else 'open'}")
            for b in a.expand():
                self.action(b)
        elif isinstance(a, SyncPoint):
            # FANUC has no task sync (without Multi-Arm): the four-phase handshake of sync_handshake
            steps = handshake(a, leads(a, self.p.name))
            self.comment(f"SYNC {a.name}: {','.join(a.robots)}")
            for b in steps:
                self.action(b)
        else:  # pragma: no cover - the model has no other action
            raise InputError(f"program {self.p.name}: FANUC LS cannot write {a!r}")


def _attr(name: str, lines: int, date: str) -> list[str]:
    return [
        f"/PROG  {name}",
        "/ATTR",
        "OWNER\t\t= MNEDITOR;",
        'COMMENT\t\t= "workbench";',
        "PROG_SIZE\t= 0;",
        f"CREATE\t\t= DATE {date}  TIME 00:00:00;",
        f"MODIFIED\t= DATE {date}  TIME 00:00:00;",
        "FILE_NAME\t= ;",
        "VERSION\t\t= 0;",
        f"LINE_COUNT\t= {lines};",
        "MEMORY_SIZE\t= 0;",
        "PROTECT\t\t= READ_WRITE;",
        "TCD:  STACK_SIZE\t= 0,",
        "      TASK_PRIORITY\t= 50,",
        "      TIME_SLICE\t= 0,",
        "      BUSY_LAMP_OFF\t= 0,",
        "      ABORT_REQUEST\t= 0,",
        "      PAUSE_REQUEST\t= 0;",
        "DEFAULT_GROUP\t= 1,*,*,*,*;",
        "CONTROL_CODE\t= 00000000 00000000;",
    ]


def write_ls(
    program: RobotProgram, *, date: str = "26-01-01", spare_pr: int = SPARE_PR
) -> ExportedProgram:
    """Return `program` as a FANUC LS file "<NAME>.ls" (conventions: the module docstring).

    Raises InputError naming the move for what FANUC cannot be told (check_program's limits,
    a zone over CNT100, a speed under 1 mm/sec), and for more tools or work objects than
    UTOOL 1..10 / UFRAME 1..9.
    """
    program = safe_start(program)  # the first move: untimed, bounded speed
    check_program(program)
    if len(program.tools) > MAX_UTOOL or len(program.work_objects) > MAX_UFRAME:
        raise InputError(
            f"program {program.name}: FANUC has UTOOL 1..{MAX_UTOOL} and UFRAME 1..{MAX_UFRAME};"
            f" the program has {len(program.tools)} tools and {len(program.work_objects)}"
            " work objects"
        )
    prog_names = NameTable("FANUC LS", RESERVED, max_len=PROGRAM_NAME_LEN)
    name = prog_names(program.name.upper(), "PROG")
    w = _Writer(program, spare_pr)
    w.frames()
    k = 0
    for ins in program.instructions:
        if isinstance(ins, MoveInstr):
            w.move(k, ins)
            k += 1
        else:
            w.action(ins)
    notes = [*compliance_notes(program), *prog_names.notes, *w.frame_names.notes, *w.names.notes]
    notes += w.rounding_notes()
    head = [f"!{c}" for n in notes for c in _comment_lines("note: " + n)]
    body = [f"  {h} ;" for h in head] + w.mn
    if w.handlers:
        body.append("  END ;")
        body += [f"  {h} ;" for h in w.handlers]
    mn = []
    for n, text in enumerate(body, start=1):
        first, *rest = text.split("\n")
        mn.append(f"{n:4d}:{first}")
        mn += rest
    text = "\n".join([*_attr(name, len(body), date), "/MN", *mn, "/POS", *w.pos, "/END", ""])
    return ExportedProgram({f"{name}.ls": text}, tuple(notes))
