"""THE CONTROLLER PROGRAM: what every workflow's builder makes from its plan, every post writes
and every reader reads back (as its `ReadProgram` view, below).

A `RobotProgram` is one robot's program as a controller runs it: named tools (TCP, mass,
centre of gravity), named work objects (frames in the robot base), and a list of
instructions: moves (joint, linear, circular) to targets, and actions (digital outputs, waits
for inputs, waits, gripper open/close, comments, sync points with other robots).

A `Target` holds the joints the planner chose (model convention, rad) and, for a Cartesian
target, the TCP pose in its work object and the arm configuration of those joints; posts
write controller joints (`RobotProgram.convention`), readers return them. A move carries its
planned duration [s] so posts can write speed data that reproduce the planned times, and
`check_program` refuses speeds, zones and accelerations outside the robot's limits, naming
the move, before anything is written.

A reader returns a `ReadProgram`: the same tools, work objects and actions, but targets as the
text states them (controller joints, or a pose with configuration data and turn ranges, no
model joints) and the lines it did not understand; `readback.to_robot_program` re-solves it
into a `RobotProgram` with the robot's model.

SI inside: m, rad, s, kg. Posts convert to each controller's units.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.kinematics.arm_configuration import ArmConfiguration, arm_configuration
from workbench.kinematics.joint_convention import JointConvention
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]

MoveKind = Literal["joint", "linear", "circular"]


@dataclass(frozen=True, eq=False)
class ToolData:
    """A tool: TCP pose in the flange frame (4, 4) [m], mass [kg] and centre of gravity (3,) [m]
    in the flange frame (None where the project does not give them; RAPID needs both)."""

    name: str
    T_flange_tcp: FloatArray
    mass: float | None = None
    cog: FloatArray | None = None


@dataclass(frozen=True, eq=False)
class WorkObject:
    """A work object: a named frame (4, 4) [m] in the robot base frame."""

    name: str
    T_base_wobj: FloatArray


@dataclass(frozen=True, eq=False)
class Signal:
    """A digital signal: its name (RAPID, URScript comments) and its number (KRL, FANUC, NACHI, UR)."""

    name: str
    number: int


@dataclass(frozen=True, eq=False)
class Target:
    """A move's target: the planned joints `q` (dof,) [rad, model convention]; for a Cartesian
    target also the TCP pose `T_wobj_tcp` (4, 4) [m] in the move's work object and the arm
    `configuration` of `q` (None for joint targets)."""

    name: str
    q: FloatArray
    T_wobj_tcp: FloatArray | None = None
    configuration: ArmConfiguration | None = None

    @property
    def cartesian(self) -> bool:
        """Return True for a Cartesian (pose) target, False for a joint target."""
        return self.T_wobj_tcp is not None

    @classmethod
    def planned(
        cls, name: str, q: FloatArray, model: RobotModel, T_wobj_tcp: FloatArray | None = None
    ) -> Target:
        """Return the target of planned joints `q`: a joint target, or with `T_wobj_tcp` a
        Cartesian one carrying the arm configuration of `q` (what every builder writes)."""
        if T_wobj_tcp is None:
            return cls(name, q)
        return cls(name, q, T_wobj_tcp, arm_configuration(model, q))


@dataclass(frozen=True, eq=False)
class MoveInstr:
    """A move: `kind` joint (PTP/MoveJ/MoveAbsJ), linear (LIN/MoveL) or circular (CIRC/MoveC,
    through `via`) to `target` with `tool` and `wobj` (names in the program).

    `speed`: a joint move's fraction (0, 1] of the joints' maximum speed; a linear or circular
    move's TCP speed [m/s]. `zone`: blend radius [m], 0 = exact stop. `duration`: the planned
    time [s] from the previous target to this one (0 where unknown). `force`: the contact force
    [N] a linear move presses with along the tool's z axis where the controller has force
    control (RAPID: FCPress1LStart / FCPressL, `rapid.py`); 0: none. Posts without force
    control move to the target (see `ContactForce`).
    """

    kind: MoveKind
    target: Target
    speed: float
    zone: float = 0.0
    tool: str = "tool"
    wobj: str = "base"
    duration: float = 0.0
    via: Target | None = None
    force: float = 0.0

    @property
    def name(self) -> str:
        """Return the target's name."""
        return self.target.name


@dataclass(frozen=True)
class ContactForce:
    """A process that presses on a surface (polishing): the contact `force` F [N] along the tool's
    z axis and the contact `stiffness` k [N/m] its targets were planned with: they lie
    D = F/k inside the surface along the tool axis (`offset` [m]). A controller with force
    control presses with F itself (RAPID's FC Pressure: the moves' `force`); a position-only
    program presses with F only through a compliant tool of spring rate k, which every other
    post states in its header (`compliance_note`)."""

    force: float
    stiffness: float

    @property
    def offset(self) -> float:
        """Return D = F/k [m]."""
        return self.force / self.stiffness

    def compliance_note(self) -> str:
        """Return the plain statement a position-only program carries in its header."""
        d_mm = self.offset * 1000.0
        return (
            f"NO FORCE CONTROL: position-only targets D = F/k = {d_mm:.3f} mm inside the surface"
            f" (along the tool axis); they assume a compliant tool of spring rate k ="
            f" {self.stiffness:g} N/m that presses with F = {self.force:g} N there; a stiffer"
            f" tool presses harder, a rigid one is driven {d_mm:.3f} mm into the part"
        )


def compliance_notes(program: RobotProgram) -> list[str]:
    """Return the header notes of a program written without force control: the compliant tool
    its targets assume (`ContactForce.compliance_note`), or none."""
    return [] if program.contact is None else [program.contact.compliance_note()]


@dataclass(frozen=True, eq=False)
class SetOutput:
    """Set a digital output to `value`."""

    signal: Signal
    value: bool


@dataclass(frozen=True, eq=False)
class PulseOutput:
    """Pulse a digital output high for `duration` [s]."""

    signal: Signal
    duration: float


@dataclass(frozen=True, eq=False)
class WaitInput:
    """Wait until a digital input equals `value`; `timeout` [s] (None: wait forever)."""

    signal: Signal
    value: bool
    timeout: float | None = None


@dataclass(frozen=True, eq=False)
class WaitTime:
    """Wait `seconds` [s]."""

    seconds: float


@dataclass(frozen=True, eq=False)
class Gripper:
    """Open or close the gripper: set `output` to `value`, then wait for `confirm` (if any,
    with `timeout` [s]) and `settle` [s]. Posts write its `expand()`ed actions with a comment."""

    close: bool
    output: Signal
    value: bool
    confirm: Signal | None = None
    timeout: float | None = None
    settle: float = 0.0

    def expand(self) -> tuple[Action, ...]:
        """Return the low-level actions a controller runs for this gripper action."""
        out: list[Action] = [SetOutput(self.output, self.value)]
        if self.confirm is not None:
            out.append(WaitInput(self.confirm, True, self.timeout))
        if self.settle > 0.0:
            out.append(WaitTime(self.settle))
        return tuple(out)


@dataclass(frozen=True, eq=False)
class Comment:
    """A comment line."""

    text: str


@dataclass(frozen=True, eq=False)
class SyncPoint:
    """Wait here until every robot in `robots` (program names) reaches the sync point `name`.

    RAPID writes WaitSyncTask; languages without task sync use the four-phase I/O handshake
    of `sync_handshake` on `output` and `input` (the partner's output), which the robot whose
    name sorts first leads; `lead` (set by the readers from the file) says whether this
    program leads.
    """

    name: str
    robots: tuple[str, ...]
    output: Signal | None = None
    input: Signal | None = None
    lead: bool | None = None


Action = SetOutput | PulseOutput | WaitInput | WaitTime | Gripper | Comment | SyncPoint
Instruction = MoveInstr | Action


@dataclass(frozen=True)
class MotionLimits:
    """What a controller can be told to do: largest TCP speed [m/s] and blend radius [m]
    (named settings of the robot; the posts refuse moves beyond them)."""

    max_tcp_speed: float = 2.0
    max_zone: float = 0.5


@dataclass(frozen=True, eq=False)
class RobotProgram:
    """One robot's program (see the module docstring). `dof` joints; `convention` maps the
    targets' model joints to the controller's; `robot` names the robot (a MultiMove task);
    `contact` the contact force a pressing process plans with (None: no contact)."""

    name: str
    tools: tuple[ToolData, ...]
    work_objects: tuple[WorkObject, ...]
    instructions: tuple[Instruction, ...]
    convention: JointConvention
    dof: int = 6
    robot: str = "robot"
    limits: MotionLimits = field(default_factory=MotionLimits)
    contact: ContactForce | None = None
    T_world_base: FloatArray | None = None
    """The robot's base (4, 4) [m] in the world its controller shares with other robots (an
    assembly cell: the main robot's base, RAPID MultiMove's wobj0; each robot's work objects
    are written in it); None: the program stands alone and its base is its controller's world."""

    @property
    def moves(self) -> tuple[MoveInstr, ...]:
        """Return the moves, in order."""
        return tuple(i for i in self.instructions if isinstance(i, MoveInstr))

    def tool(self, name: str) -> ToolData:
        """Return the tool called `name` (InputError when there is none)."""
        for t in self.tools:
            if t.name == name:
                return t
        raise InputError(
            f"program {self.name}: no tool {name!r}; tools: {[t.name for t in self.tools]}"
        )

    def work_object(self, name: str) -> WorkObject:
        """Return the work object called `name` (InputError when there is none)."""
        for w in self.work_objects:
            if w.name == name:
                return w
        raise InputError(
            f"program {self.name}: no work object {name!r};"
            f" work objects: {[w.name for w in self.work_objects]}"
        )

    def controller_joints(self, q_model: FloatArray) -> FloatArray:
        """Return joints (dof,) [rad] in the controller's convention."""
        return np.asarray(self.convention.to_controller(q_model), float)

    def actions(self) -> tuple[Action, ...]:
        """Return the low-level actions in order (gripper actions expanded; comments left out):
        what a reader of the written program returns."""
        out: list[Action] = []
        for ins in self.instructions:
            if isinstance(ins, Gripper):
                out.extend(ins.expand())
            elif not isinstance(ins, (MoveInstr, Comment)):
                out.append(ins)
        return tuple(out)

    @property
    def cycle_time(self) -> float:
        """Return the sum of the moves' planned durations and the waits [s]."""
        t = sum(m.duration for m in self.moves)
        for a in self.actions():
            if isinstance(a, WaitTime):
                t += a.seconds
            elif isinstance(a, PulseOutput):
                t += 0.0
        return float(t)


# ---------------------------------------------------------------- the program as read back
# A reader cannot give a Cartesian target's joints (the robot model and the controller's IK
# choose them: `readback.to_robot_program`), so what it returns is this view of a RobotProgram:
# the same tools, work objects and actions, moves whose targets are as the text states them,
# plus the source lines and what the reader did not understand.


@dataclass(frozen=True, eq=False)
class ReadTarget:
    """A target as a program states it: controller `joints` (dof,) [rad] for a joint target, or
    a TCP pose `T_wobj_tcp` (4, 4) [m] with its `configuration` and the controller joint ranges
    (dof, 2) [rad] its turn data allow (None: not stated)."""

    name: str
    joints: FloatArray | None = None
    T_wobj_tcp: FloatArray | None = None
    configuration: ArmConfiguration | None = None
    controller_ranges: FloatArray | None = None


@dataclass(frozen=True, eq=False)
class ReadMove:
    """A move as read: kind, target (and `via` for circular), `speed` (joint: fraction of max,
    linear/circular: TCP m/s; None when the program gives only a time), `zone` [m], `tool`
    and `wobj` names, `duration` [s] when the program states one (RAPID \\T), source `line`,
    `force` [N] a force-controlled move presses with (RAPID FCPress1LStart / FCPressL)."""

    kind: MoveKind
    target: ReadTarget
    speed: float | None
    zone: float
    tool: str
    wobj: str
    duration: float | None = None
    via: ReadTarget | None = None
    line: int = 0
    force: float = 0.0

    @property
    def name(self) -> str:
        """Return the target's name."""
        return self.target.name


@dataclass(frozen=True, eq=False)
class ReadProgram:
    """A program read back: name, tools, work objects (as declared in the file), instructions
    (moves and low-level actions, in order), and the lines the reader did not understand
    (`unknown`: (line number, text)), never dropped silently."""

    name: str
    tools: tuple[ToolData, ...]
    work_objects: tuple[WorkObject, ...]
    instructions: tuple[ReadMove | Action, ...]
    unknown: tuple[tuple[int, str], ...] = ()
    notes: tuple[str, ...] = ()

    @property
    def moves(self) -> tuple[ReadMove, ...]:
        """Return the moves, in order."""
        return tuple(i for i in self.instructions if isinstance(i, ReadMove))

    def actions(self) -> tuple[Action, ...]:
        """Return the actions, in order."""
        return tuple(i for i in self.instructions if not isinstance(i, ReadMove))


@dataclass(frozen=True, eq=False)
class PressSignals:
    """A press brake's robot interface: the robot's `start` output (held on until the press
    reports `clamped`), the press's `clamped` input (the ram reached the clamping point: the
    sheet is held) and `top` input (the ram is back at top dead centre, open), and the longest
    wait for either [s] (longer is a fault that stops the program)."""

    start: Signal
    clamped: Signal
    top: Signal
    timeout: float = 30.0


@dataclass(frozen=True, eq=False)
class ProgramSettings:
    """What a workflow's program builder needs of the project, in SI: the robot's `tool`, its
    motion `limits`, the gripper's `close` and `open` actions (None: the project has no
    gripper), the named digital `outputs` and `inputs`, and per robot (by name) its `sync`
    handshake signals (output, input), and the press brake's signals (None: the project names
    none)."""

    tool: ToolData
    limits: MotionLimits = field(default_factory=MotionLimits)
    close: Gripper | None = None
    open: Gripper | None = None
    outputs: dict[str, Signal] = field(default_factory=dict)
    inputs: dict[str, Signal] = field(default_factory=dict)
    sync: dict[str, tuple[Signal, Signal]] = field(default_factory=dict)
    press: PressSignals | None = None


def move_label(program: RobotProgram, index: int, move: MoveInstr) -> str:
    """Return how errors name a move: 'program main, move 3 (p_above)'."""
    return f"program {program.name}, move {index}" + (f" ({move.name})" if move.name else "")


def check_program(program: RobotProgram, *, needs_mass: bool = False) -> None:
    """Refuse (InputError naming the move) what no controller should be told: a speed, zone
    or duration that is not finite or outside `program.limits`, an unknown tool or work object,
    joints of the wrong length, and (`needs_mass`, RAPID's tooldata) a tool without mass and
    centre of gravity."""
    lim = program.limits
    if not program.moves:
        raise InputError(f"program {program.name}: it has no moves; add at least one")
    used_tools = set()
    for k, mv in enumerate(program.moves):
        where = move_label(program, k, mv)
        used_tools.add(mv.tool)
        program.tool(mv.tool)
        program.work_object(mv.wobj)
        for tgt in (mv.target, mv.via):
            if tgt is None:
                continue
            q = np.asarray(tgt.q, float)
            if q.shape != (program.dof,) or not np.all(np.isfinite(q)):
                raise InputError(
                    f"target {tgt.name!r} needs {program.dof} finite joints", field=where
                )
            if tgt.T_wobj_tcp is not None and tgt.configuration is None:
                raise InputError(
                    f"Cartesian target {tgt.name!r} has no arm configuration", field=where
                )
        if mv.kind == "circular" and (
            mv.via is None or not mv.via.cartesian or not mv.target.cartesian
        ):
            raise InputError("a circular move needs Cartesian via and end targets", field=where)
        if mv.kind != "joint" and not mv.target.cartesian:
            raise InputError(f"a {mv.kind} move needs a Cartesian target", field=where)
        if not np.isfinite(mv.speed) or mv.speed <= 0:
            raise InputError(f"speed {mv.speed!r} must be positive and finite", field=where)
        if mv.kind == "joint" and mv.speed > 1.0 + 1e-12:
            raise InputError(
                f"joint speed {mv.speed * 100:g} % is over 100 % of the joints' maximum",
                field=where,
            )
        if mv.kind != "joint" and mv.speed > lim.max_tcp_speed:
            raise InputError(
                f"TCP speed {mv.speed * 1000:g} mm/s is over the robot's"
                f" {lim.max_tcp_speed * 1000:g} mm/s; lower the move's speed",
                field=where,
            )
        if not np.isfinite(mv.zone) or not 0.0 <= mv.zone <= lim.max_zone:
            raise InputError(
                f"zone {mv.zone * 1000:g} mm must be within [0, {lim.max_zone * 1000:g}] mm",
                field=where,
            )
        if not np.isfinite(mv.duration) or mv.duration < 0.0:
            raise InputError(f"planned duration {mv.duration!r} s must be >= 0", field=where)
        if not np.isfinite(mv.force) or mv.force < 0.0 or (mv.force and mv.kind != "linear"):
            raise InputError(
                f"contact force {mv.force!r} N: a linear move's force is finite and >= 0",
                field=where,
            )
    if needs_mass:
        for name in sorted(used_tools):
            t = program.tool(name)
            if t.mass is None or t.cog is None or not t.mass > 0:
                raise InputError(
                    f"tool {name!r}: RAPID's tooldata needs the tool's mass [kg] and centre of"
                    " gravity [mm]; set tool.mass and tool.cog in the project"
                )
