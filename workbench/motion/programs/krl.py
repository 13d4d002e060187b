"""KUKA KRL post-processor: a `RobotProgram` as a KRL module, `<name>.src` + `<name>.dat`.

`write_krl(program)` writes what a KUKA programmer reads on the pendant (KSS 8.x expert view),
with no INI fold and no BAS/ILF calls, every setting explicit:

- `.dat`: `DEFDAT name` ... `ENDDAT` with one declaration per target, named as KUKA's inline
  forms name them (point P1 is `XP1`): `DECL E6POS Xname={X .., Y .., Z .., A .., B .., C ..,
  S .., T .., E1 0.0, ..., E6 0.0}` for Cartesian targets (TCP in the move's base, mm; A, B, C
  [deg] = Z-Y-X Euler: R = Rz(A) Ry(B) Rx(C)) and `DECL E6AXIS Xname={A1 .., ..., A6 .., E1 0.0,
  ...}` for joint targets (controller joints, deg).
- `.src`: `DEF name()` ... `END`. Tools and bases are numbered as the controller numbers them
  (1, 2, ... in the program's order) and their frames are written at the start of the program:
  `TOOL_DATA[n] = {X .., ...}` (TCP in the flange), `LOAD_DATA[n] = {M .., CM {..}, J {..}}`
  (mass [kg] and centre of gravity [mm] where the tool gives them), `BASE_DATA[n] = {..}`
  (work object in the robot base; KUKA's BASE_DATA is relative to $WORLD, so this assumes
  the factory setting $ROBROOT = $WORLD). Each move selects them with `$TOOL = TOOL_DATA[n]`,
  `$LOAD = LOAD_DATA[n]`, `$BASE = BASE_DATA[n]`, as KUKA's own `BAS(#TOOL)`/`BAS(#BASE)` do,
  so the pendant shows the tool and base numbers. A cell whose TOOL_DATA/BASE_DATA are
  measured on the controller deletes the fold with the `*_DATA[n] = ...` lines.
- Speeds: a joint move's fraction of the maximum joint speed becomes `$VEL_AXIS[1..6]` [%];
  KRL's $VEL_AXIS is an integer percentage, so the fraction is rounded to the nearest whole
  percent (at least 1); where that changes it by more than 1 % (fractions under 50 % that
  are not whole percents) the export says so in its notes. Linear and circular moves set
  `$VEL.CP` [m/s] (6 decimals).
- Zones: `$APO.CDIS` [mm] with `C_DIS`, on LIN, CIRC and PTP alike (the zone is a distance;
  `$APO.CPTP` is a percentage of the machine datum $APO_DIS_PTP, an axis angle the program
  does not know, so it is never written). 0 = exact stop (no flag).
- I/O: `$OUT[n] = TRUE/FALSE` (an advance-run stop: it switches when the robot is at the
  point), `PULSE($OUT[n], TRUE, t)`, `WAIT FOR $IN[n]` / `WAIT FOR NOT $IN[n]`, `WAIT SEC t`.
  A wait with a timeout uses KUKA's timer pattern: `$TIMER[1] = -ms`, `$TIMER_STOP[1] =
  FALSE`, `WAIT FOR $IN[n] OR $TIMER_FLAG[1]` ($TIMER_FLAG[1] turns TRUE when the timer
  reaches 0), `$TIMER_STOP[1] = TRUE`, `IF $TIMER_FLAG[1] THEN HALT, WAIT FOR $IN[n] ENDIF`
  (timer 1 is used; its resolution is 1 ms): a timed-out wait stops the robot with a message,
  and Start resumes at the re-wait, so the program never runs on with the signal unconfirmed. A
  gripper action is its expanded actions under a `; gripper close`/`; gripper open` comment; a
  sync point is the four-phase I/O handshake of `sync_handshake` under `; sync point NAME:
  robots A, B`: leading `WAIT FOR NOT $IN[in]`, `$OUT[out] = TRUE`, `WAIT FOR $IN[in]`,
  `$OUT[out] = FALSE`; following `WAIT FOR $IN[in]`, `$OUT[out] = TRUE`, `WAIT FOR NOT
  $IN[in]`, `$OUT[out] = FALSE`.

Status and Turn (the E6POS `S` and `T`), KUKA's definitions (KUKA Expert Programming manual
"Status"/"Turn", quoted at robot-forum.com/robotforum/thread/7173; the same bits in Siemens
SINUMERIK's KUKA-compatible STAT/TU addresses, Programming Manual NC programming 12/2019,
section 3.9, p. 710; Turn in ISG kernel "Status & Turn (IS, IT)",
isg-stuttgart.de/fileadmin/kernel/kernel-html/en-GB/814171275.html):

- S bit 0 = 1: overhead area, the wrist root point (intersection of A4, A5, A6) has a negative
  x in the A1 coordinate system; 0: basic area (x >= 0). This is `not configuration.front`
  (`ArmConfiguration.front` is exactly that test on the model's frames).
- S bit 1 = 1: A3 >= phi, elbow up; 0: A3 < phi, elbow down, where phi is the A3 angle of the
  stretched arm (0 deg for robots whose axes 3 and 4 intersect, shifted by the A3-A4 offset
  otherwise). The stretched arm is also `ArmConfiguration.elbow_up`'s boundary (the sign of
  u x w about the arm plane's normal), so bit 1 = `configuration.elbow_up`, computed from the
  geometry and not from a controller's A3 zero, which differs between vendors. One
  difference: `elbow_up` (a sign of u x w) also changes where the forearm folds back across
  the upper arm's line, KUKA's A3 rule does not; on the MZ07 that is controller J3 below
  -97 deg (its estimated limit is -120 deg). There bit 1 is the opposite of KUKA's, which the
  reader undoes consistently, but a KUKA controller would take the other elbow.
- S bit 2 = 1: A5 < 0 (wrist flipped); 0: A5 >= 0. This is `configuration.wrist_flip`, the
  sign of the controller's J5 (A5 within +-180 deg).
- T bit i (i = 0..5) = 1 when the controller's axis i+1 is < 0 deg, 0 when >= 0.
- "< 0" for S bit 2 and T: below -1e-6 deg (`ZERO_TOL`); an axis within 1e-6 deg of 0 is 0,
  as the 6-decimal file and the pendant show it (a planned -1e-12 deg is "0.000000").

Numbers: mm and deg with 6 decimals (KUKA's own .dat files carry about 9 significant
digits): re-solving a target gives the planned joints within 1e-6 rad even near a singularity
(the sample's p_back lies 0.5 deg from the stretched elbow, where 4 decimals in mm moved A3 by
0.002 deg). The controller holds REAL as 32-bit floats (about 7 significant digits, 0.0001 mm
at 1 m), so on the robot such a target moves by about that much; elsewhere by less than the
file's rounding.
"""

from __future__ import annotations

import numpy as np

from workbench.errors import InputError
from workbench.motion.programs.angles import abc_deg
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
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
    check_program,
    compliance_notes,
    move_label,
)
from workbench.motion.programs.exported import ExportedProgram
from workbench.motion.programs.first_move import safe_start
from workbench.motion.programs.names import NameTable
from workbench.motion.programs.sync_handshake import handshake, leads

#: KRL keywords, data types and names of the controller's global data (compared
#: case-insensitively): identifiers the post never writes.
KRL_RESERVED = frozenset(
    """
    AND ANIN ANOUT B_AND B_EXOR B_NOT B_OR BOOL BRAKE C_DIS C_ORI C_PTP C_SPL C_VEL CA CASE
    CAST_FROM CAST_TO CHAR CIRC CIRC_REL CONFIRM CONST CONTINUE DECL DEF DEFAULT DEFDAT DEFFCT
    DELAY DIGIN DIV DO ELSE END ENDDAT ENDFCT ENDFOR ENDIF ENDLOOP ENDSPLINE ENDSWITCH ENDWHILE
    ENUM EXIT EXOR EXT EXTFCT FALSE FOR GLOBAL GOTO HALT IF IMPORT INT INTERRUPT IS LIN
    LIN_REL LOOP MAXIMUM MINIMUM MOD NOT OR PRIO PTP PTP_REL PUBLIC PULSE REAL REPEAT RESUME
    RETURN SCIRC SEC SIGNAL SLIN SPL SPLINE SPTP STEP STRUC SWITCH THEN TO TRIGGER TRUE UNTIL
    WAIT WHEN WHILE ON OFF DISTANCE PATH DELAY ONSTART
    AXIS E6AXIS POS E6POS FRAME LOAD INERTIA
    HOME XHOME BAS TOOL_DATA BASE_DATA LOAD_DATA
    """.split()
)

KRL_NAME_LEN = 24
"""KRL names have at most 24 characters (a target's declared name is "X" + its name)."""

TIMEOUT_TIMER = 1
"""The $TIMER a wait with a timeout uses."""

_MAX_TOOLS, _MAX_BASES = 16, 32  # TOOL_DATA[1..16], BASE_DATA[1..32] (KSS 8)


ZERO_TOL = np.radians(1e-6)
"""An axis within 1e-6 deg of 0 counts as 0 (>= 0) for the Status and Turn bits: the file
writes 6 decimals of a degree, so a planned -1e-12 deg is 0.000000 on the pendant, and a
"< 0" bit from floating-point noise would send the controller to another turn or wrist."""


def is_negative(angle_rad: float) -> bool:
    """Return True when a controller axis counts as < 0 for KUKA's Status/Turn bits: below
    -`ZERO_TOL` (1e-6 deg); values within 1e-6 deg of 0 count as 0, which is >= 0."""
    return bool(float(angle_rad) < -ZERO_TOL)


def status_turn(configuration, q_ctrl) -> tuple[int, int]:  # noqa: ANN001
    """Return KUKA's (Status, Turn) of a Cartesian target: S bits 0 and 1 from its
    `ArmConfiguration` (bit 0 overhead = not front, bit 1 = elbow up), bit 2 (A5 < 0) and T
    from the controller joints `q_ctrl` (6,) [rad] (T bit i set when axis i+1 < 0), an axis
    within 1e-6 deg of 0 counted as 0 (`is_negative`). KUKA's definitions: KSS 8 expert
    programming manual, "Status" and "Turn" (the module docstring quotes them)."""
    q = np.asarray(q_ctrl, float)
    s = (0 if configuration.front else 1) | (2 if configuration.elbow_up else 0)
    s |= 4 if is_negative(q[4]) else 0
    t = sum(1 << i for i, x in enumerate(q) if is_negative(x))
    return s, t


def _num(x: float, nd: int) -> str:
    s = f"{x:.{nd}f}"
    return s[1:] if s.startswith("-") and float(s) == 0.0 else s


def _compact(x: float, nd: int = 6) -> str:
    s = f"{x:.{nd}f}".rstrip("0")
    s = s + "0" if s.endswith(".") else s
    if float(s) == 0.0:
        return "0.0" if x == 0.0 else f"{x:.6E}"
    return s


def frame_text(T: np.ndarray) -> str:
    """Return a KRL FRAME aggregate body 'X .., Y .., Z .., A .., B .., C ..' (mm, deg) of T [m]."""
    x, y, z = np.asarray(T, float)[:3, 3] * 1000.0
    a, b, c = abc_deg(np.asarray(T, float)[:3, :3])
    return (
        f"X {_num(x, _MM)}, Y {_num(y, _MM)}, Z {_num(z, _MM)},"
        f" A {_num(a, _DEG)}, B {_num(b, _DEG)}, C {_num(c, _DEG)}"
    )


_MM, _DEG = 6, 6  # decimals of mm and deg in poses (see the module docstring)
_EXTERNAL = ", ".join(f"E{k} 0.0" for k in range(1, 7))


class _Writer:
    def __init__(self, program: RobotProgram) -> None:
        self.p = program
        self.names = NameTable("KRL", KRL_RESERVED, max_len=KRL_NAME_LEN - 1)
        self.decls: dict[str, str] = {}  # declared name -> aggregate text
        self.by_target: dict[int, str] = {}
        self.notes: list[str] = []
        self.src: list[str] = []

    # -- targets -----------------------------------------------------------------------
    def target(self, tgt: Target, fallback: str) -> str:
        key = id(tgt)
        if key in self.by_target:
            return self.by_target[key]
        q_ctrl = self.p.controller_joints(tgt.q)
        if tgt.cartesian:
            assert tgt.T_wobj_tcp is not None and tgt.configuration is not None
            s, t = status_turn(tgt.configuration, q_ctrl)
            body = f"E6POS|{{{frame_text(tgt.T_wobj_tcp)}, S {s}, T {t}, {_EXTERNAL}}}"
        else:
            axes = ", ".join(f"A{k} {_num(v, _DEG)}" for k, v in enumerate(np.degrees(q_ctrl), 1))
            body = f"E6AXIS|{{{axes}, {_EXTERNAL}}}"
        src, k = tgt.name, 1
        while True:
            ident = self.names(src, fallback)
            if ident not in self.decls or self.decls[ident] == body:
                break
            k += 1
            src = f"{tgt.name or fallback}_{k}"
        if k > 1:
            self.notes.append(
                f"two targets are named {tgt.name or fallback!r} with different values;"
                f" the later one is declared as X{ident}"
            )
        self.decls[ident] = body
        self.by_target[key] = "X" + ident
        return "X" + ident

    # -- program -----------------------------------------------------------------------
    def write(self) -> ExportedProgram:
        p = self.p
        check_program(p)
        if p.dof != 6:
            raise InputError(
                f"program {p.name}: KRL's E6AXIS/E6POS hold 6 robot axes; this robot has {p.dof}"
            )
        prog_names = NameTable("KRL", KRL_RESERVED, max_len=KRL_NAME_LEN)
        name = prog_names(p.name, "main")
        tools = [t for t in p.tools if any(m.tool == t.name for m in p.moves)]
        bases = [w for w in p.work_objects if any(m.wobj == w.name for m in p.moves)]
        if len(tools) > _MAX_TOOLS or len(bases) > _MAX_BASES:
            raise InputError(
                f"program {p.name}: KRL has TOOL_DATA[1..{_MAX_TOOLS}] and"
                f" BASE_DATA[1..{_MAX_BASES}]; the program uses {len(tools)} tools and"
                f" {len(bases)} work objects"
            )
        tool_no = {t.name: k for k, t in enumerate(tools, 1)}
        base_no = {w.name: k for k, w in enumerate(bases, 1)}
        body: list[str] = []
        state: dict[str, object] = {}
        for k, ins in enumerate(p.instructions):
            if isinstance(ins, MoveInstr):
                body += self._move(ins, k, tool_no, base_no, state)
            else:
                body += self._action(ins)
        self.notes = [*compliance_notes(p), *prog_names.notes, *self.names.notes, *self.notes]
        head = [f"DEF {name}()", f"  ; generated by workbench: robot {p.robot}; mm, deg, s"]
        head += [f"  ; note: {n}" for n in self.notes]
        head += self._frames(tools, bases, tool_no, base_no)
        head += [
            "  ;FOLD motion settings (explicit, no INI/BAS)",
            "  $ADVANCE = 3",
            "  $IPO_MODE = #BASE",
            "  $ORI_TYPE = #VAR",
            "  $CIRC_TYPE = #BASE",
            *[f"  $ACC_AXIS[{i}] = 100" for i in range(1, 7)],
            "  $VEL.ORI1 = $VEL_MA.ORI1",
            "  $VEL.ORI2 = $VEL_MA.ORI2",
            "  $ACC.CP = $ACC_MA.CP",
            "  $ACC.ORI1 = $ACC_MA.ORI1",
            "  $ACC.ORI2 = $ACC_MA.ORI2",
            "  ;ENDFOLD",
        ]
        src = "\n".join(head + body + ["END", ""])
        dat = [f"DEFDAT {name}", f"  ; targets of {name}.src: mm, deg (A, B, C = Z-Y-X Euler)"]
        for ident, text in self.decls.items():
            kind, agg = text.split("|", 1)
            dat.append(f"  DECL {kind} X{ident}={agg}")
        dat += ["ENDDAT", ""]
        return ExportedProgram(
            {f"{name}.src": src, f"{name}.dat": "\n".join(dat)}, tuple(self.notes)
        )

    def _frames(
        self, tools: list[ToolData], bases: list[WorkObject], tool_no, base_no
    ) -> list[str]:  # noqa: ANN001
        out = [
            "  ;FOLD tool, load and base data (delete where the cell's TOOL_DATA/BASE_DATA are measured)"
        ]
        for t in tools:
            n = tool_no[t.name]
            out.append(f"  TOOL_DATA[{n}] = {{{frame_text(t.T_flange_tcp)}}} ; tool {t.name}")
            if t.mass is not None and t.mass > 0:
                cog = np.zeros(3) if t.cog is None else np.asarray(t.cog, float) * 1000.0
                cm = f"X {_num(cog[0], 4)}, Y {_num(cog[1], 4)}, Z {_num(cog[2], 4)}, A 0.0, B 0.0, C 0.0"
                out.append(
                    f"  LOAD_DATA[{n}] = {{M {_compact(t.mass, 4)}, CM {{{cm}}},"
                    f" J {{X 0.0, Y 0.0, Z 0.0}}}} ; tool {t.name}"
                )
            else:
                self.notes.append(
                    f"tool {t.name!r} has no mass: $LOAD is left as the controller has it;"
                    " set tool.mass and tool.cog for the load data"
                )
        for w in bases:
            out.append(
                f"  BASE_DATA[{base_no[w.name]}] = {{{frame_text(w.T_base_wobj)}}} ; base {w.name}"
            )
        out.append("  ;ENDFOLD")
        return out

    def _move(self, mv: MoveInstr, k: int, tool_no, base_no, state) -> list[str]:  # noqa: ANN001
        out: list[str] = []
        if not state.get("moved"):  # `safe_start` made the first move a slow, untimed PTP
            out.append(
                "  ; BCO run: the first move, PTP at reduced velocity from where the robot stands"
            )
            state["moved"] = True
        tool = self.p.tool(mv.tool)
        if state.get("tool") != mv.tool:
            out.append(f"  $TOOL = TOOL_DATA[{tool_no[mv.tool]}]")
            if tool.mass is not None and tool.mass > 0:
                out.append(f"  $LOAD = LOAD_DATA[{tool_no[mv.tool]}]")
            state["tool"] = mv.tool
        if state.get("base") != mv.wobj:
            out.append(f"  $BASE = BASE_DATA[{base_no[mv.wobj]}]")
            state["base"] = mv.wobj
        mm = mv.zone * 1000.0
        if mv.kind == "joint":
            pct = max(1, min(100, int(round(mv.speed * 100.0))))
            if abs(pct / 100.0 - mv.speed) > 0.01 * mv.speed:
                self.notes.append(
                    f"{move_label(self.p, k, mv)}: joint speed {mv.speed * 100:g} % written as"
                    f" $VEL_AXIS {pct} % (KRL takes whole percents)"
                )
            if state.get("vel_axis") != pct:
                out += [f"  $VEL_AXIS[{i}] = {pct}" for i in range(1, 7)]
                state["vel_axis"] = pct
        else:
            vel = _compact(mv.speed, 6)
            if state.get("vel_cp") != vel:
                out.append(f"  $VEL.CP = {vel}")
                state["vel_cp"] = vel
        flag = ""
        if mm > 0.0:
            cdis = _compact(mm, 4)
            if state.get("cdis") != cdis:
                out.append(f"  $APO.CDIS = {cdis}")
                state["cdis"] = cdis
            # every blend is a distance [mm]: $APO.CDIS with C_DIS, on PTP too. $APO.CPTP is a
            # percentage of the machine datum $APO_DIS_PTP (an axis angle), not a distance, so
            # the post never writes it (KSS 8 expert programming manual, "Approximate
            # positioning": C_PTP uses $APO.CPTP [%], C_DIS $APO.CDIS [mm]; KSS 8's inline
            # forms write PTP ... C_DIS, robot-forum.com thread 14422)
            flag = " C_DIS"
        if mv.kind == "circular":
            assert mv.via is not None
            via = self.target(mv.via, f"p{k}_via")
            out.append(f"  CIRC {via}, {self.target(mv.target, f'p{k}')}{flag}")
        else:
            target = self.target(mv.target, f"p{k}")
            out.append(f"  {'PTP' if mv.kind == 'joint' else 'LIN'} {target}{flag}")
        return out

    def _action(self, a) -> list[str]:  # noqa: ANN001
        if isinstance(a, Comment):
            return [f"  ; {line}" for line in (a.text.splitlines() or [""])]
        if isinstance(a, Gripper):
            out = [f"  ; gripper {'close' if a.close else 'open'}"]
            for b in a.expand():
                out += self._action(b)
            return out
        if isinstance(a, SetOutput):
            return [f"  $OUT[{_number(a.signal)}] = {_bool(a.value)} ; {a.signal.name}"]
        if isinstance(a, PulseOutput):
            if not np.isfinite(a.duration) or a.duration <= 0:
                raise InputError(f"pulse of {a.signal.name}: duration {a.duration!r} s must be > 0")
            return [
                f"  PULSE($OUT[{_number(a.signal)}], TRUE, {_compact(a.duration)}) ; {a.signal.name}"
            ]
        if isinstance(a, WaitTime):
            if not np.isfinite(a.seconds) or a.seconds < 0:
                raise InputError(f"wait time {a.seconds!r} s must be >= 0")
            return [f"  WAIT SEC {_compact(a.seconds)}"]
        if isinstance(a, WaitInput):
            return self._wait(a)
        if isinstance(a, SyncPoint):
            # KRL has no task sync: the four-phase handshake of sync_handshake
            steps = handshake(a, leads(a, self.p.name))
            out = [f"  ; sync point {a.name}: robots {', '.join(a.robots)}"]
            for b in steps:
                out += self._action(b)
            return out
        raise InputError(f"KRL: cannot write the instruction {a!r}")

    def _wait(self, a: WaitInput) -> list[str]:
        n = _number(a.signal)
        cond = f"$IN[{n}]" if a.value else f"NOT $IN[{n}]"
        if a.timeout is None:
            return [f"  WAIT FOR {cond} ; {a.signal.name}"]
        if not np.isfinite(a.timeout) or a.timeout <= 0:
            raise InputError(f"wait for {a.signal.name}: timeout {a.timeout!r} s must be > 0")
        ms = int(round(a.timeout * 1000.0))
        if abs(ms / 1000.0 - a.timeout) > 1e-9:
            self.notes.append(
                f"wait for {a.signal.name}: timeout {a.timeout:g} s written as {ms} ms ($TIMER counts ms)"
            )
        k = TIMEOUT_TIMER
        return [
            f"  $TIMER[{k}] = -{ms} ; timeout {_compact(ms / 1000.0, 3)} s",
            f"  $TIMER_STOP[{k}] = FALSE",
            f"  WAIT FOR {cond} OR $TIMER_FLAG[{k}] ; {a.signal.name}",
            f"  $TIMER_STOP[{k}] = TRUE",
            f"  IF $TIMER_FLAG[{k}] THEN",
            f"    HALT ; $IN[{n}] ({a.signal.name}) not {_bool(a.value)} within {_compact(ms / 1000.0, 3)} s",
            # HALT stops the program and Start resumes it at the next statement (KSS 8 expert
            # programming manual, "HALT"): wait again there, never continue unconfirmed
            f"    WAIT FOR {cond} ; {a.signal.name}: Start waits for it again",
            "  ENDIF",
        ]


def _number(sig: Signal) -> int:
    if not isinstance(sig.number, (int, np.integer)) or not 1 <= int(sig.number) <= 4096:
        raise InputError(
            f"signal {sig.name!r}: KRL's $IN/$OUT are numbered 1..4096, got {sig.number!r}"
        )
    return int(sig.number)


def _bool(v: bool) -> str:
    return "TRUE" if v else "FALSE"


def write_krl(program: RobotProgram) -> ExportedProgram:
    """Return `program` as a KRL module: files "<name>.src" and "<name>.dat" (see the module
    docstring for the frames, Status/Turn, speeds, zones and I/O). Refuses (InputError naming
    the move) what `check_program` refuses; renamed identifiers are in `notes` and commented
    at the top of the .src."""
    return _Writer(safe_start(program)).write()
