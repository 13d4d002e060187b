"""The project's robot-program sections beside the moves (mm, deg, kg, s): the tool's load, the
work objects, the digital I/O with the gripper and the robots' sync signals, the program's
actions (gripper, outputs, waits, comments) and the robot's motion limits.

Every field is optional, so project files written before these sections load unchanged.
`check_references` (called when a project loads) checks every name a program uses (signals,
work objects, the gripper) and names the field that uses an unknown one.

`to_si` and the helpers below return the program model's objects (`motion.programs.controller_program`):
`ToolData`, `WorkObject` (in the robot base frame), `Signal`, the actions, `MotionLimits`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any, Literal, Union, cast

import numpy as np
from pydantic import Discriminator, Field, StringConstraints, Tag, model_validator

from workbench.geometry.transforms import invert_transform
from workbench.motion.programs.controller_program import (
    Action,
    Comment,
    Gripper,
    MotionLimits,
    PressSignals,
    ProgramSettings,
    PulseOutput,
    SetOutput,
    Signal,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
)
from workbench.project import bounds as B
from workbench.project.common import Pose, StrictModel, Vec3mm
from workbench.project.units import MM, pose_to_matrix

if TYPE_CHECKING:
    from workbench.project.models import Project, Robot, Tool

# Ranges of the numbers of these sections (the file's units).
MASS_KG_OPEN = (0.0, 10_000.0)
"""A tool's mass [kg]: > 0."""
SIGNAL_NUMBER = (0, 100_000)
"""A digital signal's number on the controller."""
WAIT_S = (0.0, 3_600.0)
"""A wait, a gripper's settle time [s]."""
TIMEOUT_S_OPEN = (0.0, 3_600.0)
"""A wait for an input: its timeout [s], > 0."""
PULSE_S_OPEN = (0.0, 60.0)
"""A pulse's length [s], > 0."""
COMMENT_CHARS = 200
"""Longest comment text."""

BASE_WOBJ = "base"
"""The work object every project has: the robot's base frame."""

Name = Annotated[str, StringConstraints(min_length=1, max_length=64, pattern=r"^[^\x00-\x1f]+$")]
Mass = Annotated[float, B.span(MASS_KG_OPEN, "kg", lo_open=True)]
TcpSpeed = Annotated[float, B.span(B.LINEAR_SPEED_MM_S, "mm/s")]
ZoneLimit = Annotated[float, B.span(B.ZONE_MM, "mm")]
Seconds = Annotated[float, B.span(WAIT_S, "s")]
Timeout = Annotated[float, B.span(TIMEOUT_S_OPEN, "s", lo_open=True)]
PulseLength = Annotated[float, B.span(PULSE_S_OPEN, "s", lo_open=True)]
CommentText = Annotated[
    str, StringConstraints(max_length=COMMENT_CHARS, pattern=r"^[^\x00-\x1f]*$")
]
Cog = Vec3mm  # a centre of gravity [mm] in the flange frame


class WorkObjectSpec(StrictModel):
    """A named frame (a fixture, a table) at `pose` in the world (mm, deg)."""

    name: Name
    pose: Pose = Field(default_factory=Pose)


class SignalSpec(StrictModel):
    """A digital signal: the name programs use and its number on the controller."""

    name: Name
    number: Annotated[int, B.span(SIGNAL_NUMBER)]

    def to_si(self) -> Signal:
        """Return the program model's `Signal`."""
        return Signal(self.name, self.number)


class GripperSpec(StrictModel):
    """The gripper: the output that drives it (`close_value` closes it), the inputs that confirm
    closed / opened (optional, waited for up to `timeout` [s]), and a `settle` time [s]."""

    output: Name
    close_value: bool = True
    closed_input: Name | None = None
    opened_input: Name | None = None
    timeout: Timeout | None = None
    settle: Seconds = 0.0


class SyncSignalsSpec(StrictModel):
    """One robot's handshake signals at sync points: it sets `output`, waits for `input`."""

    output: Name
    input: Name


class PressIOSpec(StrictModel):
    """The press brake's robot interface, by the names of io.outputs / io.inputs: the robot's
    `start` output (held on until the press reports clamping), the press's `clamped` input
    (the ram reached the clamping point: the sheet is held, the robot may follow the flange)
    and `top` input (the ram is back at top dead centre: the bend is done, the part is free);
    `timeout` [s] the longest wait for either, after which the program stops with a fault."""

    start: Name = "press_start"
    clamped: Name = "press_clamped"
    top: Name = "press_done"
    timeout: Timeout = 30.0


def _unique(items: list[SignalSpec], field: str) -> None:
    # names only: numbers repeat across robots (each controller counts its own I/O from 1)
    for key in ("name",):
        seen: set[object] = set()
        for k, s in enumerate(items):
            v = getattr(s, key)
            if v in seen:
                raise ValueError(
                    f"{field}[{k}].{key}: {v!r} is used twice; give each signal its own"
                )
            seen.add(v)


class IOSpec(StrictModel):
    """Digital I/O: named outputs and inputs with their numbers, the gripper, and per robot
    (by name) the sync signals of I/O handshakes between robots."""

    outputs: Annotated[list[SignalSpec], Field(max_length=B.MAX_ITEMS)] = Field(
        default_factory=list
    )
    inputs: Annotated[list[SignalSpec], Field(max_length=B.MAX_ITEMS)] = Field(default_factory=list)
    gripper: GripperSpec | None = None
    sync: dict[Name, SyncSignalsSpec] = Field(default_factory=dict)
    press: PressIOSpec | None = None

    @model_validator(mode="after")
    def _names(self) -> IOSpec:
        _unique(self.outputs, "outputs")
        _unique(self.inputs, "inputs")
        both = {s.name for s in self.outputs} & {s.name for s in self.inputs}
        if both:
            raise ValueError(f"{sorted(both)} name both an output and an input; rename one")
        refs: list[tuple[str, str | None, str]] = []
        if self.gripper is not None:
            g = self.gripper
            refs += [("gripper.output", g.output, "outputs")]
            refs += [("gripper.closed_input", g.closed_input, "inputs")]
            refs += [("gripper.opened_input", g.opened_input, "inputs")]
        for robot, s in self.sync.items():
            refs += [
                (f"sync.{robot}.output", s.output, "outputs"),
                (f"sync.{robot}.input", s.input, "inputs"),
            ]
        if self.press is not None:
            p = self.press
            refs += [("press.start", p.start, "outputs")]
            refs += [("press.clamped", p.clamped, "inputs"), ("press.top", p.top, "inputs")]
        for field, name, kind in refs:
            if name is not None:
                self.signal(name, kind, field)
        return self

    def signal(self, name: str, kind: str, field: str) -> Signal:
        """Return the output (`kind` "outputs") or input ("inputs") called `name`; ValueError
        naming `field` and the signals there are when there is none."""
        for s in self.outputs if kind == "outputs" else self.inputs:
            if s.name == name:
                return s.to_si()
        have = [s.name for s in (self.outputs if kind == "outputs" else self.inputs)]
        raise ValueError(
            f"{field}: {name!r} is not one of io.{kind} {have}; add it there or fix the name"
        )

    def gripper_action(self, close: bool, field: str) -> Gripper:
        """Return the gripper action that closes (or opens) the gripper."""
        g = self.gripper
        if g is None:
            raise ValueError(
                f"{field}: the project has no io.gripper; add one (its output, inputs)"
            )
        confirm = g.closed_input if close else g.opened_input
        return Gripper(
            close,
            self.signal(g.output, "outputs", "io.gripper.output"),
            g.close_value if close else not g.close_value,
            None if confirm is None else self.signal(confirm, "inputs", "io.gripper"),
            g.timeout,
            g.settle,
        )

    def press_signals(self) -> PressSignals | None:
        """Return the press brake's signals (`io.press`), None when the project names none."""
        p = self.press
        if p is None:
            return None
        return PressSignals(
            self.signal(p.start, "outputs", "io.press.start"),
            self.signal(p.clamped, "inputs", "io.press.clamped"),
            self.signal(p.top, "inputs", "io.press.top"),
            p.timeout,
        )

    def sync_signals(self, robot: str) -> tuple[Signal, Signal] | None:
        """Return robot `robot`'s (output, input) handshake signals, None when it has none."""
        s = self.sync.get(robot)
        if s is None:
            return None
        return (
            self.signal(s.output, "outputs", f"io.sync.{robot}.output"),
            self.signal(s.input, "inputs", f"io.sync.{robot}.input"),
        )


def _io(io: IOSpec | None) -> IOSpec:
    return io if io is not None else IOSpec()


class GripperItem(StrictModel):
    """Close or open the gripper (`io.gripper`): its output, then its confirming input and settle time."""

    type: Literal["gripper"]
    action: Literal["open", "close"]

    def to_si(self, io: IOSpec | None, field: str = "gripper") -> Action:
        """Return the program model's action."""
        return _io(io).gripper_action(self.action == "close", field)


class SetOutputItem(StrictModel):
    """Set a digital output (an `io.outputs` name) to `value`."""

    type: Literal["set_output"]
    signal: Name
    value: bool = True

    def to_si(self, io: IOSpec | None, field: str = "signal") -> Action:
        """Return the program model's action."""
        return SetOutput(_io(io).signal(self.signal, "outputs", f"{field}.signal"), self.value)


class PulseOutputItem(StrictModel):
    """Pulse a digital output (an `io.outputs` name) high for `duration` [s]."""

    type: Literal["pulse_output"]
    signal: Name
    duration: PulseLength = 0.2

    def to_si(self, io: IOSpec | None, field: str = "signal") -> Action:
        """Return the program model's action."""
        return PulseOutput(_io(io).signal(self.signal, "outputs", f"{field}.signal"), self.duration)


class WaitInputItem(StrictModel):
    """Wait until a digital input (an `io.inputs` name) equals `value`, at most `timeout` [s]."""

    type: Literal["wait_input"]
    signal: Name
    value: bool = True
    timeout: Timeout | None = None

    def to_si(self, io: IOSpec | None, field: str = "signal") -> Action:
        """Return the program model's action."""
        sig = _io(io).signal(self.signal, "inputs", f"{field}.signal")
        return WaitInput(sig, self.value, self.timeout)


class WaitItem(StrictModel):
    """Wait `seconds` [s]."""

    type: Literal["wait"]
    seconds: Seconds

    def to_si(self, io: IOSpec | None, field: str = "wait") -> Action:
        """Return the program model's action."""
        return WaitTime(self.seconds)


class CommentItem(StrictModel):
    """A comment line in the exported program."""

    type: Literal["comment"]
    text: CommentText

    def to_si(self, io: IOSpec | None, field: str = "comment") -> Action:
        """Return the program model's action."""
        return Comment(self.text)


ActionItem = GripperItem | SetOutputItem | PulseOutputItem | WaitInputItem | WaitItem | CommentItem
ACTION_ITEMS: dict[str, type] = {
    "gripper": GripperItem,
    "set_output": SetOutputItem,
    "pulse_output": PulseOutputItem,
    "wait_input": WaitInputItem,
    "wait": WaitItem,
    "comment": CommentItem,
}
ITEM_TAG = "item:"
"""Prefix of the union tags in pydantic's error locations (`io.field_path` leaves them out)."""


def _item_tag(v: Any) -> str | None:
    t = v.get("type") if isinstance(v, dict) else getattr(v, "type", None)
    if not isinstance(t, str):  # a list or object as the type: no item (the field is named)
        return None
    if t in ("joint", "linear"):
        return ITEM_TAG + "move"
    return ITEM_TAG + t if t in ACTION_ITEMS else None


def program_item(move_model: type) -> Any:
    """Return the type of one program item: a move (`move_model`, type joint or linear) or an
    action, told apart by its `type`."""
    members = [Annotated[move_model, Tag(ITEM_TAG + "move")]]
    members += [Annotated[cls, Tag(ITEM_TAG + name)] for name, cls in ACTION_ITEMS.items()]
    kinds = ", ".join(["joint", "linear", *ACTION_ITEMS])
    return Annotated[
        Union[tuple(members)],  # type: ignore[valid-type]  # noqa: UP007
        Discriminator(
            _item_tag,
            custom_error_type="program_item",
            custom_error_message=f"'type' must be one of {kinds}",
        ),
    ]


# -- the whole project ------------------------------------------------------------------------


def wobj_names(project: Project) -> list[str]:
    """Return the work objects' names: "base" (the robot base) and the project's."""
    return [BASE_WOBJ] + [w.name for w in project.work_objects or ()]


def check_references(project: Project) -> None:
    """Raise ValueError naming the field of the first unknown name: a work object, a program
    action's signal, the gripper; and work objects named twice or named "base"."""
    seen: set[str] = set()
    for k, w in enumerate(project.work_objects or ()):
        if w.name == BASE_WOBJ:
            raise ValueError(
                f"work_objects[{k}].name: 'base' is the robot base; choose another name"
            )
        if w.name in seen:
            raise ValueError(f"work_objects[{k}].name: {w.name!r} is used twice")
        seen.add(w.name)
    if project.program is None:
        return
    names = wobj_names(project)
    for k, item in enumerate(project.program.moves):
        field = f"program.moves[{k}]"
        if isinstance(item, tuple(ACTION_ITEMS.values())):
            cast(Any, item).to_si(project.io, field)
        elif getattr(item, "wobj", None) not in (None, *names):
            raise ValueError(
                f"{field}.wobj: {item.wobj!r} is not a work object; work objects: {names}"
            )


def program_items(project: Project, convention: Any = None) -> tuple[Any, ...]:
    """Return the program's items in order: each move's `MoveSI` (`to_si(convention)`) and each
    action as the program model's action (signals resolved through `io`)."""
    if project.program is None:
        return ()
    out: list[Any] = []
    for k, item in enumerate(project.program.moves):
        if isinstance(item, tuple(ACTION_ITEMS.values())):
            out.append(cast(Any, item).to_si(project.io, f"program.moves[{k}]"))
        else:
            out.append(item.to_si(convention))
    return tuple(out)


def tool_data(tool: Tool) -> ToolData:
    """Return the tool as the program model's `ToolData` (TCP [m], mass [kg], cog [m])."""
    cog = None if tool.cog is None else np.asarray(tool.cog, float) * MM
    return ToolData(tool.name, pose_to_matrix(tool.tcp), tool.mass, cog)


def work_objects(project: Project) -> tuple[WorkObject, ...]:
    """Return the work objects in the robot base frame [m]: "base" first, then the project's."""
    T_base_world = invert_transform(pose_to_matrix(project.robot.base))
    out = [WorkObject(BASE_WOBJ, np.eye(4))]
    for w in project.work_objects or ():
        out.append(WorkObject(w.name, T_base_world @ pose_to_matrix(w.pose)))
    return tuple(out)


def motion_limits(robot: Robot) -> MotionLimits:
    """Return the robot's `MotionLimits` [m/s, m]: `max_tcp_speed` [mm/s] and `max_zone` [mm]
    (defaults: `MotionLimits`' 2000 mm/s and 500 mm)."""
    default = MotionLimits()
    speed = default.max_tcp_speed if robot.max_tcp_speed is None else robot.max_tcp_speed * MM
    zone = default.max_zone if robot.max_zone is None else robot.max_zone * MM
    return MotionLimits(max_tcp_speed=speed, max_zone=zone)


def program_settings(project: Project) -> ProgramSettings:
    """Return what the workflows' program builders need (`ProgramSettings`): the tool, the
    robot's motion limits, the gripper actions, the named signals, the sync signals, the press
    brake's signals."""
    io = _io(project.io)
    grip = (
        [io.gripper_action(c, "io.gripper") for c in (True, False)] if io.gripper else [None, None]
    )
    sync = {r: s for r in io.sync if (s := io.sync_signals(r)) is not None}
    return ProgramSettings(
        tool_data(project.tool),
        motion_limits(project.robot),
        grip[0],
        grip[1],
        {s.name: s.to_si() for s in io.outputs},
        {s.name: s.to_si() for s in io.inputs},
        sync,
        io.press_signals(),
    )
