"""ABB RAPID post-processor: one module (``<name>.mod``) an IRC5 / OmniCore controller runs.

`write_rapid(program)` writes, for a `RobotProgram`:

- ``PERS tooldata`` per tool: robhold TRUE, tframe [[x,y,z] mm, [q1,q2,q3,q4]], tload [mass kg,
  [cog mm], [1,0,0,0], 0, 0, 0] (axes of moment = tool frame, inertia 0: the controller treats
  the load as a point mass). A tool without mass or centre of gravity is refused
  (`check_program(needs_mass=True)`); a tool with an identity TCP and no load data is the
  flange, written as the predefined ``tool0``.
- ``PERS wobjdata`` per work object: robhold FALSE, ufprog TRUE, ufmec "", uframe = the frame
  in the robot base [[x,y,z] mm, [q]], oframe identity; an identity work object is ``wobj0``.
  The robot base is taken as the controller's world frame (a single robot's default).
- ``CONST jointtarget`` (controller joint values [deg], 9E9 for the external axes) and
  ``CONST robtarget`` (TCP pose in the move's work object [mm, quaternion], confdata, 9E9).
- ``MoveAbsJ`` (joint target) / ``MoveJ`` (Cartesian target) with ``\\T:=<planned duration
  s>`` so the controller runs the planned segment time (the speeddata ``v1000`` beside it is
  nominal: \\T replaces it); ``MoveL`` / ``MoveC`` with a speeddata literal [v_tcp mm/s,
  v_ori 500 deg/s, v_leax 5000 mm/s, v_reax 1000 deg/s] (the orientation and external-axis
  speeds of ABB's predefined v-data); zonedata ``fine``, the predefined ``zN`` when the radius
  is one of them, else a literal [FALSE, r, 1.5 r, 1.5 r, 0.15 r, 1.5 r, 0.15 r] (the same
  proportions as ABB's z10..z200); every move with its tool and ``\\WObj:=``.
- ``SetDO``, ``PulseDO \\High\\PLength:=``, ``WaitDI ...\\MaxTime:=`` (no \\TimeFlag: a timeout
  stops the program with ERR_WAIT_MAXTIME instead of running on), ``WaitTime``, ``!``
  comments; a gripper action as ``! gripper close`` / ``! gripper open`` and its expanded
  SetDO / WaitDI / WaitTime; a `SyncPoint` as ``WaitSyncTask`` with a ``VAR syncident`` and a
  ``PERS tasks`` list of the MultiMove task names ``"T_" + robot program name upper-case``
  (the controller's motion tasks must carry those names; MultiMove's defaults are T_ROB1..).

Force control (a program whose moves carry a contact `force`, e.g. polishing): ABB's FC
Pressure instructions (Application manual - Force Control, RAPID references, instructions
FCCalib, FCPress1LStart, FCPressL, FCPressEnd; the RobotWare Force Control option with a force
sensor), `_Press`: a run of pressed linear moves starts after an exact stop with ``FCCalib
<tool>_load;`` (the sensor calibrated with the tool's ``PERS loaddata``, the tooldata's tload)
and ``FCPress1LStart to, speed\\Fz:=F, 50, zone, tool\\WObj:=w;`` (press along the tool's z
from where the robot stands until 50 % of F, then move to the target with F), goes on with
``FCPressL to, speed, F, zone, tool\\WObj:=w;`` and ends with ``FCPressEnd to, speed,
tool\\WObj:=w;`` on the next (linear) move, which lifts off. Along the force direction the robot
follows F, not the targets (they lie D = F/k inside the surface, `ContactForce`).

confdata [cf1, cf4, cf6, cfx] (RAPID Technical Reference Manual - Instructions, Functions and
Data types, data type *confdata*, serial robots): cf1, cf4, cf6 are the quadrant numbers of the
controller's axes 1, 4 and 6, floor(angle / 90 deg) (0..90 deg -> 0, -90..0 deg -> -1,
180..270 deg -> 2); cfx selects one of eight branches (`CFX_TABLE`, the manual's table as
reproduced in CEAD-group/py-opw-kinematics AXIS_CONFIGURATION.md):

    cfx  wrist centre / axis 1   wrist centre / lower arm   axis 5
     0   in front of             in front of                positive
     1   in front of             in front of                negative
     2   in front of             behind                     positive
     3   in front of             behind                     negative
     4   behind                  in front of                positive
     5   behind                  in front of                negative
     6   behind                  behind                     positive
     7   behind                  behind                     negative

From `ArmConfiguration`: "wrist centre in front of axis 1" is `front`; "axis 5 negative" is
`wrist_flip` (the controller's J5 < 0); "wrist centre in front of the lower arm" is
`elbow_up`. ABB's lower arm is the link axis 2 -> axis 3; the wrist centre is in front of it
when it lies on the forward side of that link's line in the arm plane, i.e. the forearm is
bent forward/down from the stretched arm: the usual pose (lower arm up, forearm reaching
forward) is cfx 0 and `elbow_up` (u x w . y_arm > 0 with u = axis 2 -> 3, w = axis 3 ->
wrist centre). Both flip at the same singularity, the stretched arm (on ABB's arms near
axis 3 = -90 deg).

Names (targets, tools, work objects, signals, the module) pass a `NameTable` of RAPID's
reserved words (`RAPID_RESERVED`: the kernel's reserved words plus the instructions, data
types and predefined data this post and its reader use), at most 32 characters; renames are
in `ExportedProgram.notes` and as comments at the top of the module. Numbers: mm with 6
decimals, degrees with 6, quaternions with 9, trailing zeros dropped: enough that re-solving
a target gives the planned joints within 1e-6 rad even near the shoulder singularity (with 4
decimals a target 0.2 m from axis 1 moved the joints by 1e-6 rad). The controller's num is
single precision (about 7 significant digits, ~0.0001 mm at 1 m): it rounds further, so a
controller's joints near a singularity can differ from the plan by more than the file's.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from workbench.errors import InputError
from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.motion.programs.angles import quaternion_wxyz
from workbench.motion.programs.controller_program import (
    Comment,
    Gripper,
    MoveInstr,
    PulseOutput,
    RobotProgram,
    SetOutput,
    SyncPoint,
    Target,
    ToolData,
    WaitInput,
    WaitTime,
    check_program,
)
from workbench.motion.programs.exported import ExportedProgram
from workbench.motion.programs.first_move import (
    FIRST_MOVE_ORI_SPEED,
    FIRST_MOVE_TCP_SPEED,
    safe_start,
)
from workbench.motion.programs.names import NameTable

# ABB's predefined zones (TCP path radius in mm); other radii become zonedata literals.
_ZONES = (0, 1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200)
_VMAX_TCP = 7000.0  # ABB's vmax speeddata [mm/s], the reference for joint-move fractions

#: Predefined zonedata radii [mm] (pzone_tcp) for writing: z0 is 0.3 mm, not an exact stop.
PREDEFINED_ZONES_MM = {f"z{z}": (0.3 if z == 0 else float(z)) for z in _ZONES}
#: Predefined speeddata v_tcp [mm/s]; vmax is taken as 7000 mm/s.
PREDEFINED_SPEEDS_MM_S = {
    f"v{v}": float(v)
    for v in "5 10 20 30 40 50 60 80 100 150 200 300 400 500 600 800 1000 1500 2000 2500 3000"
    " 4000 5000 6000 7000".split()
} | {"vmax": 7000.0}

#: RAPID's reserved words (Technical Reference Manual - RAPID kernel, "Reserved words") plus
#: the instructions, functions, data types and predefined data a program must not redefine.
RAPID_RESERVED = (
    "ALIAS AND BACKWARD CASE CONNECT CONST DEFAULT DIV DO ELSE ELSEIF ENDFOR ENDFUNC ENDIF"
    " ENDMODULE ENDPROC ENDRECORD ENDTEST ENDTRAP ENDWHILE ERROR EXIT FALSE FOR FROM FUNC GOTO"
    " IF INOUT LOCAL MOD MODULE NOSTEPIN NOT NOVIEW OR PERS PROC RAISE READONLY RECORD RETRY"
    " RETURN STEP SYSMODULE TASK TEST THEN TO TRAP TRUE TRYNEXT UNDO VAR VIEWONLY WHILE WITH XOR"
    " MoveAbsJ MoveJ MoveL MoveC MoveExtJ SearchL TriggL SetDO PulseDO Set Reset WaitDI WaitDO"
    " WaitTime WaitUntil WaitSyncTask SyncMoveOn SyncMoveOff ConfJ ConfL SingArea VelSet AccSet"
    " Stop Offs RelTool CRobT CJointT TPWrite"
    " FCCalib FCPress1LStart FCPressL FCPressEnd FCAct FCDeact"
    " robtarget jointtarget tooldata wobjdata loaddata speeddata zonedata confdata syncident"
    " tasks num dnum bool string pos orient pose signaldi signaldo"
    " main tool0 wobj0 load0 fine "
    + " ".join(PREDEFINED_ZONES_MM)
    + " "
    + " ".join(PREDEFINED_SPEEDS_MM_S)
).split()
MAX_NAME_LEN = 32

#: cfx -> (wrist centre in front of axis 1, in front of the lower arm, axis 5 negative).
CFX_TABLE = {
    0: (True, True, False),
    1: (True, True, True),
    2: (True, False, False),
    3: (True, False, True),
    4: (False, True, False),
    5: (False, True, True),
    6: (False, False, False),
    7: (False, False, True),
}
_V_ORI, _V_LEAX, _V_REAX = 500, 5000, 1000
_JOINT_SPEED = "v1000"  # nominal: \T sets the time
#: FCPress1LStart's ForceThreshold [% of the force]: the contact is taken as made, and the move
#: to the target starts, at this share of F (ours; public RAPID programs use 15 .. 60).
FC_START_THRESHOLD = 50


def _num(x: float, nd: int) -> str:
    """Return x with at most nd decimals, trailing zeros dropped ('250', '0.3', '-12.5')."""
    s = f"{x:.{nd}f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "", "-") else s


def _vec(xs, nd: int) -> str:  # noqa: ANN001
    return "[" + ",".join(_num(float(x), nd) for x in xs) + "]"


def _pose(T: np.ndarray) -> str:
    """Return [[x,y,z] mm,[q1,q2,q3,q4]] of a (4, 4) transform [m]."""
    return f"[{_vec(T[:3, 3] * 1000.0, 6)},{_vec(quaternion_wxyz(T[:3, :3]), 9)}]"


def quadrant(angle_rad: float) -> int:
    """Return ABB's quadrant number of a controller joint angle: floor(angle / 90 deg)."""
    return int(math.floor(math.degrees(angle_rad) / 90.0 + 1e-12))


def cfx_of(configuration: ArmConfiguration) -> int:
    """Return ABB's cfx (0..7) of an arm configuration (see the module docstring)."""
    key = (configuration.front, configuration.elbow_up, configuration.wrist_flip)
    return next(k for k, v in CFX_TABLE.items() if v == key)


def configuration_of_cfx(cfx: int) -> ArmConfiguration:
    """Return the `ArmConfiguration` ABB's cfx (0..7) stands for."""
    front, in_front_of_lower_arm, axis5_negative = CFX_TABLE[cfx]
    return ArmConfiguration(front, in_front_of_lower_arm, axis5_negative)


def confdata(
    q_controller: np.ndarray, configuration: ArmConfiguration
) -> tuple[int, int, int, int]:
    """Return [cf1, cf4, cf6, cfx] of controller joints (6,) [rad] and their arm configuration."""
    q = np.asarray(q_controller, float)
    return quadrant(q[0]), quadrant(q[3]), quadrant(q[5]), cfx_of(configuration)


def zonedata(zone_m: float) -> str:
    """Return the RAPID zonedata of a blend radius [m]: fine, a predefined zN or a literal."""
    mm = zone_m * 1000.0
    if mm <= 0.0:
        return "fine"
    for name, r in PREDEFINED_ZONES_MM.items():
        if name != "z0" and abs(mm - r) < 1e-6:
            return name
    parts = [mm, 1.5 * mm, 1.5 * mm, 0.15 * mm, 1.5 * mm, 0.15 * mm]
    return "[FALSE," + ",".join(_num(x, 4) for x in parts) + "]"


def speeddata(v_m_s: float) -> str:
    """Return the speeddata literal [v_tcp mm/s, v_ori, v_leax, v_reax] of a TCP speed [m/s]."""
    return f"[{_num(v_m_s * 1000.0, 4)},{_V_ORI},{_V_LEAX},{_V_REAX}]"


def task_name(program_name: str) -> str:
    """Return the MultiMove task name of a robot program: 'T_' + the name upper-case."""
    return "T_" + "".join(c if c.isalnum() else "_" for c in program_name).upper()


def _is_identity(T: np.ndarray) -> bool:
    return bool(np.allclose(np.asarray(T, float), np.eye(4), atol=1e-12, rtol=0.0))


def _is_flange(tool: ToolData) -> bool:
    return _is_identity(tool.T_flange_tcp) and tool.mass is None and tool.cog is None


_TOOL0_LOAD = (0.001, np.array([0.0, 0.0, 1e-6]))  # tool0's tload: 0.001 kg at [0,0,0.001] mm


class _Writer:
    def __init__(self, program: RobotProgram) -> None:
        self.p = program
        self.names = NameTable("RAPID", RAPID_RESERVED, max_len=MAX_NAME_LEN, prefix="p")
        self.module = self.names(program.name, "program")
        # declarations by kind, each in the order first used: tools, work objects, sync data, targets
        self.decl: dict[str, list[str]] = {
            "tool": [],
            "load": [],
            "wobj": [],
            "sync": [],
            "target": [],
        }
        self.multimove = any(isinstance(i, SyncPoint) for i in program.instructions)
        # MultiMove: PERS data of one name is shared by all tasks; TASK PERS keeps each robot's own
        self.pers = "TASK PERS" if self.multimove else "PERS"
        self.data: dict[str, str] = {}  # identifier -> declaration (one per identifier)
        self.data[self.module] = "MODULE"
        self.body: list[str] = []
        self.tools: dict[str, str] = {}
        self.wobjs: dict[str, str] = {}
        self.task_lists: dict[tuple[str, ...], str] = {}
        self.syncs: dict[str, str] = {}
        self.notes: list[str] = []
        self.moved = self.first_move = False
        self.press = _Press(self)

    def _declare(self, name: str, fallback: str, text_of, group: str = "") -> str:  # noqa: ANN001
        """Return the identifier of a datum (`text_of(ident)` its declaration); a different
        datum of the same name (a target and a tool both called 'a') gets a new identifier."""
        ident = self.names(name, fallback)
        first, k = ident, 1
        while ident in self.data and self.data[ident] != text_of(ident):
            k += 1
            ident = self.names(f"{name or fallback}_{k}", fallback)
        if ident != first:
            self.notes.append(f"renamed {name!r} to {ident!r}: {first!r} names another datum")
        if ident not in self.data:
            self.data[ident] = text_of(ident)
            if group:
                self.decl[group].append(self.data[ident])
        return ident

    def tool(self, name: str) -> str:
        if name not in self.tools:
            t = self.p.tool(name)
            if _is_flange(t):
                self.tools[name] = "tool0"
            else:
                mass = float(t.mass)  # type: ignore[arg-type]
                cog = np.asarray(t.cog, float) * 1000.0
                load = f"[{_num(mass, 4)},{_vec(cog, 4)},[1,0,0,0],0,0,0]"
                self.tools[name] = self._declare(
                    t.name,
                    "tool",
                    lambda i: (
                        f"    {self.pers} tooldata {i}:=[TRUE,{_pose(t.T_flange_tcp)},{load}];"
                    ),
                    "tool",
                )
        return self.tools[name]

    def wobj(self, name: str) -> str:
        if name not in self.wobjs:
            w = self.p.work_object(name)
            T, label = w.T_base_wobj, w.name
            world = self.p.T_world_base
            if world is not None and not _is_identity(world):
                # MultiMove: one world for every task (wobj0); this robot's base lies elsewhere
                # in it, so its work objects are written in the world: uframe = the base in the
                # world times the frame in the base (RAPID reference, wobjdata: uframe "in the
                # world coordinate system"); its base itself is a declared work object
                T = np.asarray(world, float) @ np.asarray(T, float)
                if _is_identity(w.T_base_wobj):
                    label = f"{self.p.robot}_base"
            if _is_identity(T):
                self.wobjs[name] = "wobj0"
            else:
                frame = _pose(T)
                self.wobjs[name] = self._declare(
                    label,
                    "wobj",
                    lambda i: (
                        f'    {self.pers} wobjdata {i}:=[FALSE,TRUE,"",{frame},[[0,0,0],[1,0,0,0]]];'
                    ),
                    "wobj",
                )
        return self.wobjs[name]

    def target(self, tgt: Target) -> str:
        qc = self.p.controller_joints(tgt.q)
        ext = "[9E9,9E9,9E9,9E9,9E9,9E9]"
        if not tgt.cartesian:
            deg = _vec(np.degrees(qc), 6)
            return self._declare(
                tgt.name, "jt", lambda i: f"    CONST jointtarget {i}:=[{deg},{ext}];", "target"
            )
        conf = "[" + ",".join(str(c) for c in confdata(qc, tgt.configuration)) + "]"  # type: ignore[arg-type]
        pose = _pose(np.asarray(tgt.T_wobj_tcp, float))
        return self._declare(
            tgt.name,
            "p",
            lambda i: f"    CONST robtarget {i}:=[{pose[1:-1]},{conf},{ext}];",
            "target",
        )

    def signal(self, name: str) -> str:
        # signals are declared in the controller's I/O configuration, not in the module
        return self._declare(name, "sig", lambda i: f"signal {name}")

    def move(self, mv: MoveInstr) -> None:
        self.first_move = not self.moved
        self.moved = True
        tool, wobj = self.tool(mv.tool), self.wobj(mv.wobj)
        zone = zonedata(mv.zone)
        tail = f"{zone}, {tool}\\WObj:={wobj};"
        via = self.target(mv.via) if mv.via is not None else ""
        to = self.target(mv.target)
        if self.press.move(mv, to, tool, wobj):
            return
        if mv.kind == "joint":
            instr = "MoveJ" if mv.target.cartesian else "MoveAbsJ"
            speed = _JOINT_SPEED
            if self.first_move:
                # reached from wherever the robot stands: no \T (the RAPID reference, MoveJ
                # and MoveAbsJ: \T "the total time ... the robot moves", whatever the
                # distance), the TCP and reorientation speeds bounded instead
                speed = (
                    f"[{_num(FIRST_MOVE_TCP_SPEED * 1000.0, 1)},{_num(FIRST_MOVE_ORI_SPEED, 1)},"
                    "5000,1000]"
                )
            elif mv.duration > 0.0:
                speed += f"\\T:={_num(mv.duration, 4)}"
            else:
                self.notes.append(
                    f"{instr} {to}: no planned time; {_JOINT_SPEED} is a TCP speed"
                    " (RAPID has no joint-speed percentage)"
                )
            self.body.append(f"        {instr} {to}, {speed}, {tail}")
        elif mv.kind == "linear":
            self.body.append(f"        MoveL {to}, {speeddata(mv.speed)}, {tail}")
        else:
            self.body.append(f"        MoveC {via}, {to}, {speeddata(mv.speed)}, {tail}")

    def action(self, a) -> None:  # noqa: ANN001
        out = self.body
        if isinstance(a, Comment):
            out.extend(f"        ! {line}".rstrip() for line in a.text.splitlines() or [""])
        elif isinstance(a, Gripper):
            out.append(f"        ! gripper {'close' if a.close else 'open'}")
            for b in a.expand():
                self.action(b)
        elif isinstance(a, SetOutput):
            out.append(f"        SetDO {self.signal(a.signal.name)}, {int(a.value)};")
        elif isinstance(a, PulseOutput):
            out.append(
                f"        PulseDO \\High\\PLength:={_num(a.duration, 4)}, {self.signal(a.signal.name)};"
            )
        elif isinstance(a, WaitInput):
            t = "" if a.timeout is None else f"\\MaxTime:={_num(a.timeout, 4)}"
            out.append(f"        WaitDI {self.signal(a.signal.name)}, {int(a.value)}{t};")
        elif isinstance(a, WaitTime):
            out.append(f"        WaitTime {_num(a.seconds, 4)};")
        elif isinstance(a, SyncPoint):
            out.append(f"        WaitSyncTask {self.sync(a)}, {self.task_list(a.robots)};")
        else:  # pragma: no cover - the model has no other actions
            raise TypeError(f"unknown action {a!r}")

    def sync(self, s: SyncPoint) -> str:
        if s.name not in self.syncs:
            self.syncs[s.name] = self._declare(
                s.name, "sync", lambda i: f"    VAR syncident {i};", "sync"
            )
        return self.syncs[s.name]

    def task_list(self, robots: tuple[str, ...]) -> str:
        if robots not in self.task_lists:
            names = [task_name(r) for r in robots]
            items = ",".join(f'["{n}"]' for n in names)
            ident = self._declare(
                f"task_list{len(self.task_lists) + 1}",
                "task_list",
                lambda i: f"    PERS tasks {i}{{{len(names)}}}:=[{items}];",
                "sync",
            )
            self.notes.append(
                f"MultiMove: {ident} names the tasks {', '.join(names)}; the controller's"
                " motion tasks must carry these names"
            )
            self.task_lists[robots] = ident
        return self.task_lists[robots]

    def text(self) -> tuple[str, tuple[str, ...]]:
        for ins in self.p.instructions:
            if isinstance(ins, MoveInstr):
                self.move(ins)
            else:
                self.action(ins)
        self.press.end()
        notes = tuple(self.names.notes + self.notes)
        head = [
            f"MODULE {self.module}",
            f"    ! {self.p.name}: robot {self.p.robot}, written by workbench (ABB RAPID post)",
            "    ! units: mm, deg, kg, s; orientations as quaternions [q1,q2,q3,q4] = [w,x,y,z]",
            "    ! robtargets: TCP in the move's work object; confdata [cf1,cf4,cf6,cfx] by ABB's rules",
            "    ! joint moves run in the planned time (\\T); their v1000 is nominal",
            *(f"    ! note: {n}" for n in notes),
        ]
        if self.multimove:
            notes += ("MultiMove: tooldata and wobjdata are TASK PERS (each task keeps its own)",)
            head.append(f"    ! note: {notes[-1]}")
        decl = [d for group in self.decl.values() for d in group]
        lines = [
            *head,
            "",
            *decl,
            "",
            "    PROC main()",
            *self.body,
            "    ENDPROC",
            "ENDMODULE",
            "",
        ]
        return "\n".join(lines), notes


class _Press:
    """The force-controlled runs of a RAPID program (module docstring, "Force control").

    ABB, "Application manual - Force control" (e.g. 3HAC083267-001, RobotWare 7.7), chapter
    RAPID references, instructions FCCalib (calibrate the sensor with the load data, robot
    still and out of contact), FCPress1LStart (ToPoint, Speed \\Fx|\\Fy|\\Fz force [N],
    ForceThreshold [%], Zone, Tool \\WObj), FCPressL (ToPoint, Speed, Force [N], Zone, Tool
    \\WObj) and FCPressEnd (ToPoint, Speed, Tool \\WObj); the argument order as public RAPID
    polishing programs write them (found with the code search, not copied). The manual's own
    pages were not readable here: check ForceThreshold's unit and the force frame (the tool's,
    \\Fz along its z) against the manual before a program runs on a cell."""

    def __init__(self, w: _Writer) -> None:
        self.w = w
        self.pressing = False
        self.stopped = True  # the last move ended in an exact stop (none yet: standing)
        self.last = ""  # the last move's target, for errors

    def load(self, name: str) -> str:
        """Return the loaddata of a tool (its tooldata's tload), declared on first use."""
        t = self.w.p.tool(name)
        mass, cog = _TOOL0_LOAD if _is_flange(t) else (t.mass, t.cog)  # type: ignore[assignment]
        load = (
            f"[{_num(float(mass), 4)},{_vec(np.asarray(cog, float) * 1000.0, 4)},[1,0,0,0],0,0,0]"  # type: ignore[arg-type]
        )
        return self.w._declare(
            f"{t.name}_load", "load", lambda i: f"    PERS loaddata {i}:={load};", "load"
        )

    def move(self, mv: MoveInstr, to: str, tool: str, wobj: str) -> bool:
        """Write `mv` if it starts, continues or ends a pressed run; False: a plain move."""
        body, speed, force = self.w.body, speeddata(mv.speed), _num(mv.force, 4)
        tail = f"{zonedata(mv.zone)}, {tool}\\WObj:={wobj};"
        was, self.last = self.last, f"move to {mv.name!r}"
        if mv.force > 0.0 and not self.pressing:
            if not self.stopped:  # FCCalib measures the sensor's offset: robot still, no contact
                raise InputError(
                    f"{was}: a force-controlled run starts after an exact stop (FCCalib needs"
                    " the robot standing still); give that move zone 0",
                    field=f"program {self.w.p.name}",
                )
            body.append(f"        FCCalib {self.load(mv.tool)};")
            body.append(
                f"        FCPress1LStart {to}, {speed}\\Fz:={force}, {FC_START_THRESHOLD}, {tail}"
            )
            self.w.notes.append(
                f"force control: ABB's Force Control option presses with {mv.force:g} N along"
                " the tool's z (FCPress1LStart .. FCPressEnd) instead of the targets' offset"
            )
        elif mv.force > 0.0:
            body.append(f"        FCPressL {to}, {speed}, {force}, {tail}")
        elif self.pressing:
            if mv.kind != "linear":
                raise InputError(
                    f"{self.last}: a force-controlled run ends with a linear move off the"
                    " surface (FCPressEnd)",
                    field=f"program {self.w.p.name}",
                )
            body.append(f"        FCPressEnd {to}, {speed}, {tool}\\WObj:={wobj};")
        else:
            self.stopped = mv.zone <= 0.0
            return False
        self.pressing, self.stopped = mv.force > 0.0, mv.zone <= 0.0 or mv.force <= 0.0
        return True

    def end(self) -> None:
        """Refuse a program that ends while pressing (no FCPressEnd would lift the tool)."""
        if self.pressing:
            raise InputError(
                f"{self.last}: the program ends while pressing; end the force-controlled run"
                " with a linear move off the surface (FCPressEnd)",
                field=f"program {self.w.p.name}",
            )


def write_rapid(program: RobotProgram) -> ExportedProgram:
    """Return `program` as one RAPID module, ``{"<module>.mod": text}`` (see the module docstring).

    Raises InputError (naming the move or tool) for what `check_program` refuses, including a
    tool without mass and centre of gravity (tooldata's tload needs them).
    """
    # the flange (identity TCP, no load data) is tool0, which carries ABB's own load
    loaded = tuple(
        replace(t, mass=_TOOL0_LOAD[0], cog=_TOOL0_LOAD[1]) if _is_flange(t) else t
        for t in program.tools
    )
    program = safe_start(program)  # the first move: no \T, a bounded speed
    check_program(replace(program, tools=loaded), needs_mass=True)
    w = _Writer(program)
    text, notes = w.text()
    return ExportedProgram({f"{w.module}.mod": text}, notes)
