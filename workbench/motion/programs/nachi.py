"""NACHI FD post-processor: one program file `<unit>.<nnn>` of MOVEX lines and I/O instructions.

The preset robot (NACHI MZ07) runs on an FD11/FD controller. A program is a numbered file, e.g.
``MZ07-01-A.001`` as the controller lists it: ``<model>-<unit>-A.<nnn>``, the robot model
(`names.controller_model`), the unit number (01; `formats.write_programs` numbers a cell's
robots 01, 02, ...) and the program number (001 in every workflow), one instruction a line,
ending with ``END``. What is written, and where each form comes from:

Confirmed by a public source (forms seen in two or more independent writers):

- ``MOVEX A=<n>[P],AC=<n>,SM=<n>,M1J,<P|L|C1|C2>,(<J1..J6 deg>),<R=%|S=mm/s>,H=<tool>,MS``:
  the move instruction of mechanism 1 (``M1J`` joint target, ``M1X`` Cartesian target),
  interpolation ``P`` (joint), ``L`` (linear), ``C1``/``C2`` (circular: via point, then end point),
  ``S=`` a TCP speed [mm/s], ``R=`` a joint move's speed [% of maximum], ``H=`` the tool number,
  ``A=`` the accuracy level 1..8 with ``P`` = positioning, ``AC=`` acceleration level, ``SM=``
  smoothness level 0..3.
  Sources: RoboDK's open NACHI posts (ros-industrial-attic/robodk_postprocessors,
  ``Nachi_AX_FD.py``, ``Nachi_AX_FD_Smooth.py``, ``OTC.py``; "for Nachi robots (FD controllers
  and AX) as well as OTC robots with FD controllers") and Cenit's OTC-Daihen FD19 down/uploader
  (a FASTSUITE translator in the search corpus: ``R=`` % for P moves, ``S=`` mm/s for L/C,
  ``M1J,L`` joint targets moved linearly, ``A=1P``..``A=8``).
- ``SET O<n>`` / ``RESET O<n>`` (digital output on/off), ``WAITI I<n>`` / ``WAITJ I<n>`` (wait
  for input on/off), ``DELAY <s>`` (timer), ``'`` and ``REM "..."`` comments, ``END``: Cenit's
  downloader and RoboDK's posts.
- Orientation of a NACHI pose: (X, Y, Z, RZ, RY, RX) [mm, deg] with R = Rz(RZ) Ry(RY) Rx(RX),
  the order RoboDK's ``Pose_2_Nachi`` writes and Cenit writes, checked against real teach-pendant
  joint/pose pairs of an MZ07F and an MZ04D (gstorm-b/RobotKinematics,
  ``docs/preset_references/nachi-mz07f.md``, ``nachi-mz04d.md``); tests/motion/programs/test_nachi.py
  checks it again on the MZ07F pairs.

Our reading (no NACHI manual is public in the corpora; each is stated in docs/programs.md):

- Configuration word ``CONF=abcd``: the only public rule found is Cenit's for OTC's FD (J5 sign,
  a FASTSUITE configuration name, a J1 region, the J6 turn), not NACHI's; so this post writes
  NO Cartesian (``M1X``) target: every target is written as the planned CONTROLLER joints
  (``M1J``), linear and circular moves included (``M1J,L`` / ``M1J,C1``/``C2``: the controller
  moves the TCP of tool H on a line/arc to the pose of those joints). The joints pin the arm
  configuration and the turns exactly; the Cartesian pose, its work object and configuration
  are written in a ``' TARGET`` comment above the move for the programmer (and the reader).
- Accuracy: ``A=1P`` for an exact stop (RoboDK: "if we want movements to be accurate: A=1P";
  Cenit's downloader reads the P the other way round, so this is unconfirmed). A blend zone
  has no unit in the instruction: the level's distance is a controller constant (accuracy
  table). The post gives each distinct non-zero zone of the program its own level 2..8 in
  increasing order, and lists "level = distance" in the header for the operator to set; more
  than 7 distinct zones are refused, naming the move.
- Tools: ``H=<n>`` numbers the program's tools 1.. in declaration order; the TCPs are
  controller constants, listed in the header (``' TOOL H=n name X= .. RX=``) to be entered.
  User coordinates (work objects) are not selected: joint targets do not depend on them; they
  are listed in the header (``' USERCOORD``) for the pose comments.
- Wait with timeout: no NACHI form was found; ``WAITI`` waits without limit and a ``' TIMEOUT``
  comment above it states the plan's limit. Pulse: ``SET``, ``DELAY``, ``RESET`` under a
  ``' PULSE`` comment. Sync point: the four-phase I/O handshake of `sync_handshake` under a
  ``' SYNC`` comment (leading ``WAITJ``, ``SET``, ``WAITI``, ``RESET``; following ``WAITI``,
  ``SET``, ``WAITJ``, ``RESET``: own output, partner input). Gripper: its expanded actions under
  ``' gripper close/open``.
- ``AC=0`` (acceleration level 0) and ``SM=0`` (no extra smoothing) on every move.
"""

from __future__ import annotations

import re

import numpy as np

from workbench.errors import InputError
from workbench.motion.programs.angles import abc_deg
from workbench.motion.programs.controller_program import (
    Comment,
    Gripper,
    Instruction,
    MoveInstr,
    PulseOutput,
    RobotProgram,
    SetOutput,
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
from workbench.motion.programs.names import NameTable, controller_model, nachi_file_name
from workbench.motion.programs.sync_handshake import handshake, leads

RESERVED = (
    "MOVE",
    "MOVEJ",
    "MOVEX",
    "SET",
    "RESET",
    "SETM",
    "WAITI",
    "WAITJ",
    "DELAY",
    "PAUSE",
    "END",
    "REM",
    "CALLP",
    "GOTO",
    "GOSUB",
    "RETURN",
    "IF",
    "THEN",
    "ELSE",
    "FOR",
    "TO",
    "NEXT",
    "STOP",
    "TARGET",
    "TOOL",
    "USERCOORD",
    "ACCURACY",
    "PROGRAM",
    "TIMEOUT",
    "PULSE",
    "SYNC",
    "WOBJ",
)
"""NACHI instruction words (from the sources above) and the header words of our comments."""

MAX_LEVEL = 8
"""Accuracy levels A=1..8 (RoboDK: "1 to 8 or 1P to 8P")."""

DEFAULT_UNIT = "MZ07-01-A"
"""File name stem: robot unit and "-A" (RoboDK: ``MZ07L-01-A``, file ``<stem>.<nnn>``)."""


def nachi_pose(T: np.ndarray) -> np.ndarray:
    """Return NACHI's (X, Y, Z [mm], RZ, RY, RX [deg]) of a (4, 4) pose [m]: R = Rz Ry Rx."""
    return np.concatenate([np.asarray(T, float)[:3, 3] * 1000.0, abc_deg(np.asarray(T)[:3, :3])])


def pose_text(T: np.ndarray) -> str:
    """Return 'X=.. Y=.. Z=.. RZ=.. RY=.. RX=..' (mm 4 decimals, deg 6 decimals)."""
    x, y, z, rz, ry, rx = nachi_pose(T) + 0.0  # + 0.0: no "-0.000000"
    x, y, z = (v if abs(v) >= 5e-5 else 0.0 for v in (x, y, z))
    rz, ry, rx = (v if abs(v) >= 5e-7 else 0.0 for v in (rz, ry, rx))
    return f"X={x:.4f} Y={y:.4f} Z={z:.4f} RZ={rz:.6f} RY={ry:.6f} RX={rx:.6f}"


def config_text(target: Target) -> str:
    """Return 'front,elbow_up,no_flip' and the like for a Cartesian target's configuration."""
    c = target.configuration
    assert c is not None
    return ",".join(
        (
            "front" if c.front else "back",
            "elbow_up" if c.elbow_up else "elbow_down",
            "flip" if c.wrist_flip else "no_flip",
        )
    )


def accuracy_levels(program: RobotProgram) -> dict[float, int]:
    """Return {zone [m]: level} for the program's distinct non-zero zones (levels 2..8, by size).

    Level 1 with P is the exact stop. Raises InputError naming the first move whose zone needs
    a ninth level.
    """
    levels: dict[float, int] = {}
    zones = sorted({round(mv.zone, 7) for mv in program.moves if mv.zone > 0})
    if len(zones) > MAX_LEVEL - 1:
        extra = zones[MAX_LEVEL - 1]
        for k, mv in enumerate(program.moves):
            if round(mv.zone, 7) == extra:
                raise InputError(
                    f"{move_label(program, k, mv)}: NACHI has {MAX_LEVEL} accuracy levels and the"
                    f" program uses {len(zones)} distinct zones ({', '.join(f'{z * 1000:g}' for z in zones)}"
                    " mm) besides the exact stop; use at most 7 distinct zones"
                )
    for k, z in enumerate(zones):
        levels[z] = k + 2
    return levels


def _accuracy(zone: float, levels: dict[float, int]) -> str:
    return "A=1P" if zone <= 0 else f"A={levels[round(zone, 7)]}"


def _joints_text(program: RobotProgram, target: Target) -> str:
    deg = np.degrees(program.controller_joints(target.q))
    deg = np.where(np.abs(deg) < 5e-7, 0.0, deg)
    return "(" + ",".join(f"{v:.6f}" for v in deg) + ")"


def _number(program: RobotProgram, number: int | None) -> int:
    if number is None:
        number = 1  # the same for every workflow (not the program name's digits: MZ07 -> 007)
    if not 0 <= number <= 999:
        raise InputError(f"program {program.name}: NACHI program number {number} must be 0..999")
    return number


class _Writer:
    def __init__(self, program: RobotProgram) -> None:
        self.p = program
        self.names = NameTable("NACHI", RESERVED, max_len=32)
        self.tool_no = {t.name: k + 1 for k, t in enumerate(program.tools)}
        self.levels = accuracy_levels(program)
        self.body: list[str] = []

    def target_comment(self, tgt: Target, wobj: str) -> str:
        line = f"' TARGET {self.names(tgt.name, 'p')} WOBJ {self.names(wobj, 'wobj')}"
        if tgt.cartesian:
            assert tgt.T_wobj_tcp is not None
            line += f" {pose_text(tgt.T_wobj_tcp)} CONFIG {config_text(tgt)}"
        return line

    def movex(self, mv: MoveInstr, tgt: Target, interp: str) -> str:
        if mv.kind == "joint":
            speed = f"R={mv.speed * 100.0:.3f}"
        else:
            speed = f"S={mv.speed * 1000.0:.3f}"
        return (
            f"MOVEX {_accuracy(mv.zone, self.levels)},AC=0,SM=0,M1J,{interp},"
            f"{_joints_text(self.p, tgt)},{speed},H={self.tool_no[mv.tool]},MS"
        )

    def move(self, mv: MoveInstr) -> None:
        if mv.kind == "circular":
            assert mv.via is not None
            self.body += [self.target_comment(mv.via, mv.wobj), self.movex(mv, mv.via, "C1")]
            self.body += [self.target_comment(mv.target, mv.wobj), self.movex(mv, mv.target, "C2")]
            return
        interp = "P" if mv.kind == "joint" else "L"
        self.body += [self.target_comment(mv.target, mv.wobj), self.movex(mv, mv.target, interp)]

    def action(self, ins: Instruction) -> None:
        b = self.body
        if isinstance(ins, MoveInstr):
            self.move(ins)
        elif isinstance(ins, Comment):
            b += [f"' {line}" for line in ins.text.splitlines() or [""]]
        elif isinstance(ins, Gripper):
            b.append(f"' gripper {'close' if ins.close else 'open'}")
            for a in ins.expand():
                self.action(a)
        elif isinstance(ins, SetOutput):
            b.append(f"{'SET' if ins.value else 'RESET'} O{ins.signal.number}")
        elif isinstance(ins, PulseOutput):
            n = ins.signal.number
            b += [
                f"' PULSE O{n} {ins.duration:.3f} s",
                f"SET O{n}",
                f"DELAY {ins.duration:.3f}",
                f"RESET O{n}",
            ]
        elif isinstance(ins, WaitInput):
            if ins.timeout is not None:
                b.append(
                    f"' TIMEOUT {ins.timeout:.3f} s (planned limit; this WAIT has none on the controller)"
                )
            b.append(f"{'WAITI' if ins.value else 'WAITJ'} I{ins.signal.number}")
        elif isinstance(ins, WaitTime):
            b.append(f"DELAY {ins.seconds:.3f}")
        elif isinstance(ins, SyncPoint):
            # no task sync between FD controllers: the four-phase handshake of sync_handshake
            steps = handshake(ins, leads(ins, self.p.name))
            robots = ",".join(self.names(r, "robot") for r in ins.robots)
            b.append(f"' SYNC {self.names(ins.name, 'sync')} WITH {robots}")
            for a in steps:
                self.action(a)
        else:  # pragma: no cover - the model has no other instruction
            raise InputError(f"program {self.p.name}: NACHI cannot write {type(ins).__name__}")

    def header(self, file_name: str, notes: list[str]) -> list[str]:
        head = [
            f"' PROGRAM {self.names(self.p.name, 'program')}",
            f"' workbench NACHI FD program {file_name}, robot {self.p.robot}",
            "' joints J1..J6 in controller degrees; poses X,Y,Z mm, RZ,RY,RX deg (R = Rz Ry Rx)",
            "' set these tool constants (TCP in the flange) on the controller:",
        ]
        for t in self.p.tools:
            head.append(
                f"' TOOL H={self.tool_no[t.name]} {self.names(t.name, 'tool')} {pose_text(t.T_flange_tcp)}"
            )
        head.append("' user coordinates of the TARGET comments (in the robot base):")
        for w in self.p.work_objects:
            head.append(f"' USERCOORD {self.names(w.name, 'wobj')} {pose_text(w.T_base_wobj)}")
        head.append("' set these accuracy levels (positioning distance) on the controller:")
        head.append("' ACCURACY A=1 0.0000 mm")
        for z, lv in self.levels.items():
            head.append(f"' ACCURACY A={lv} {z * 1000.0:.4f} mm")
        head += [f"' note: {n}" for n in notes]
        return head


def unit_name(robot: str, unit: int = 1) -> str:
    """Return the file-name stem ``<model>-<unit>-A`` of a robot's program as an FD controller
    lists it: the robot's model (`names.controller_model`: 'NACHI MZ07' and 'MZ07' both give
    MZ07), the unit number in two digits (01: the first mechanism), "A"."""
    return nachi_file_name(controller_model(robot), unit, 0).rsplit(".", 1)[0]


def write_nachi(
    program: RobotProgram, *, unit: str | None = None, number: int | None = None
) -> ExportedProgram:
    """Return the NACHI FD program file ``<unit>.<nnn>`` of `program` (see the module docstring).

    `unit` is the file-name stem (default `unit_name(program.robot)`, e.g. ``MZ07-01-A``);
    `number` is the program number (default 1: every workflow's program is ``<unit>.001``).
    Raises InputError (naming the move) for what check_program refuses, for more than 7
    distinct blend zones, and for a sync point without its handshake signals.
    """
    program = safe_start(program)  # the first move: untimed, bounded speed
    check_program(program)
    if program.dof != 6:
        raise InputError(
            f"program {program.name}: the NACHI post writes 6-axis arms (M1J J1..J6); this robot"
            f" has {program.dof} joints"
        )
    unit = unit_name(program.robot) if unit is None else unit
    if not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_-]*", unit):
        raise InputError(
            f"NACHI unit {unit!r} must be letters, digits, '-' and '_' (e.g. {DEFAULT_UNIT})"
        )
    w = _Writer(program)
    for ins in program.instructions:
        w.action(ins)
    file_name = f"{unit}.{_number(program, number):03d}"
    notes = list(w.names.notes) + [
        "targets are written as controller joints (M1J): NACHI's CONF word is not publicly"
        " documented; the Cartesian poses are in the TARGET comments",
        "tool TCPs (H=n) and accuracy distances (A=n) are controller constants: set them as listed",
    ]
    notes[:0] = compliance_notes(program)  # first: what the targets assume
    if any(isinstance(i, WaitInput) and i.timeout is not None for i in program.actions()):
        notes.append(
            "wait-input timeouts are not enforced on the controller (see the TIMEOUT comments)"
        )
    lines = w.header(file_name, notes) + w.body + ["END", ""]
    return ExportedProgram({file_name: "\n".join(lines)}, tuple(notes))
