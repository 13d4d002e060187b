"""Pydantic models of the project file (schema version 2): millimetres and degrees.

Joint values in the file (robot.joints, program.start, joint moves, assembly robots) are in
the robot controller's convention (`Robot.convention`); `to_si()` returns the kinematic
model's [rad].

Every model forbids unknown fields and non-finite numbers, so a typo or a NaN in a
project file is reported with its JSON path instead of being ignored.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Annotated, Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray
from pydantic import Field, model_validator

from workbench.errors import InputError
from workbench.kinematics.joint_convention import JointConvention
from workbench.kinematics.robot_library import LIBRARY, ROBOT_NAMES
from workbench.kinematics.target_configuration import TargetConfiguration
from workbench.project import bounds as B
from workbench.project import program_io as io_
from workbench.project.assembly import AssemblySpec
from workbench.project.bending import BendingSpec
from workbench.project.cad import CadSpec, check_step_scale
from workbench.project.collision import CollisionSpec
from workbench.project.common import (
    Angle,
    Color,
    Coordinate,
    JointAngle,
    Joints,
    MeshScale,
    Pose,
    Size3mm,
    SizeMM,
    StrictModel,
    ToolSize3mm,
)
from workbench.project.planning import PlanningSpec
from workbench.project.polishing import PolishingSpec
from workbench.project.target_configuration import ConfigurationSpec, check_turns
from workbench.project.units import DEG, MM, pose_to_matrix

FloatArray = NDArray[np.float64]
JointSpeed = Annotated[float, B.span(B.JOINT_SPEED_DEG_S, "deg/s")]
JointAccel = Annotated[float, B.span(B.JOINT_ACCEL_DEG_S2, "deg/s²")]
JointJerk = Annotated[float, B.span(B.JOINT_JERK_DEG_S3, "deg/s³")]

SCHEMA_VERSION = 2
PRESETS = ROBOT_NAMES
"""The robot presets: the robot library's names (`workbench.kinematics.robot_library`)."""
PresetName = Literal["irb1200_7_70", "kr6_r900_2", "m10ia", "ur5e", "mz07"]
"""The preset names as a type (the schema's enum); a test checks it lists `PRESETS`."""
PRESET_CONVENTIONS = {name: robot.convention for name, robot in LIBRARY.items()}
"""Each preset's controller joint convention (robots given by DH rows or a URDF: identity)."""


class DHRow(StrictModel):
    """One standard DH row Rz(theta + offset) Tz(d) Tx(a) Rx(alpha) with its joint limits."""

    theta_offset: Angle = 0.0  # deg
    d: Coordinate  # mm
    a: Coordinate  # mm
    alpha: Angle  # deg
    min: JointAngle  # deg
    max: JointAngle  # deg

    @model_validator(mode="after")
    def _limits_ordered(self) -> DHRow:
        if not self.min < self.max:
            raise ValueError(f"joint limits need min < max, got min={self.min}, max={self.max}")
        return self


def _per_joint(values: list[float] | None) -> FloatArray | None:
    return None if values is None else np.asarray(values, float) * DEG


def joints_to_model(
    values: list[float] | None, convention: JointConvention | None
) -> FloatArray | None:
    """Return controller joints [deg] as the model's [rad] (None convention: the same values).

    A list of the wrong length is returned unconverted: the caller's length check names it.
    """
    q = _per_joint(values)
    if q is None or convention is None or len(q) != convention.dof:
        return q
    return convention.to_model(q)


@dataclass(frozen=True, eq=False)
class RobotSI:
    """The robot section in SI: DH rows (n, 4) [rad, m, m, rad] and limits (n, 2) [rad] (or
    None for a preset or URDF), base pose (4, 4) [m], stored joints [rad], rates [rad/s,
    rad/s^2, rad/s^3] per joint (None: the model's defaults), mesh files per link."""

    name: str
    preset: str | None
    dh: FloatArray | None
    limits: FloatArray | None
    urdf: str | None
    T_world_base: FloatArray
    joints: FloatArray | None
    max_velocity: FloatArray | None
    max_acceleration: FloatArray | None
    max_jerk: FloatArray | None
    link_meshes: tuple[str | None, ...] | None
    link_mesh_scale: float = MM  # link mesh files are in mm


class Robot(StrictModel):
    """The robot: exactly one of `preset`, `dh` or `urdf`, placed at `base` in the world.

    `joints` and the DH rows' `min`/`max` are the controller's values (`convention()`).
    """

    name: str = "robot"
    preset: PresetName | None = None  # a robot of the library, see PRESETS
    dh: Annotated[list[DHRow], Field(max_length=B.MAX_DOF)] | None = None
    urdf: str | None = None  # path, relative to the project file
    base: Pose = Field(default_factory=Pose)
    joints: Joints | None = None  # deg (rad for none): the stored configuration
    max_velocity: list[JointSpeed] | None = None  # deg/s per joint
    max_acceleration: list[JointAccel] | None = None  # deg/s^2 per joint
    max_jerk: list[JointJerk] | None = None  # deg/s^3 per joint
    link_meshes: Annotated[list[str | None], Field(max_length=B.MAX_DOF + 1)] | None = None
    # optional mesh per link (base first)
    max_tcp_speed: io_.TcpSpeed | None = None  # mm/s, what programs may ask (default 2000)
    max_zone: io_.ZoneLimit | None = None  # mm, largest blend radius (default 500)

    @model_validator(mode="after")
    def _one_source(self) -> Robot:
        given = [k for k in ("preset", "dh", "urdf") if getattr(self, k) is not None]
        if len(given) != 1:
            raise ValueError(
                f"give exactly one of 'preset' (one of {', '.join(PRESETS)}), 'dh' (rows of"
                " theta_offset, d, a, alpha, min, max) or 'urdf' (a file path);"
                f" got {given or 'none'}"
            )
        if self.dh is not None and len(self.dh) == 0:
            raise ValueError("'dh' needs at least one row")
        return self

    def convention(self) -> JointConvention | None:
        """Return the controller's joint convention of a preset (None: the model's own values)."""
        return None if self.preset is None else PRESET_CONVENTIONS[self.preset]

    def to_si(self) -> RobotSI:
        """Return the section in SI, joints in the model's convention (lengths of per-joint
        lists are checked against the model)."""
        dh = limits = None
        if self.dh is not None:
            dh = np.array(
                [[r.theta_offset * DEG, r.d * MM, r.a * MM, r.alpha * DEG] for r in self.dh]
            )
            limits = np.array([[r.min * DEG, r.max * DEG] for r in self.dh])
        return RobotSI(
            name=self.name,
            preset=self.preset,
            dh=dh,
            limits=limits,
            urdf=self.urdf,
            T_world_base=pose_to_matrix(self.base),
            joints=joints_to_model(self.joints, self.convention()),
            max_velocity=_per_joint(self.max_velocity),
            max_acceleration=_per_joint(self.max_acceleration),
            max_jerk=_per_joint(self.max_jerk),
            link_meshes=None if self.link_meshes is None else tuple(self.link_meshes),
        )

    def store_joints(self, q: ArrayLike) -> None:
        """Store model joints q (dof,) [rad] as the section's `joints` [deg, controller's]."""
        q = np.asarray(q, float)
        conv = self.convention()
        if conv is not None and q.shape == (conv.dof,):
            q = conv.to_controller(q)
        self.joints = [round(float(v), 9) for v in q / DEG]  # 1e-9 deg: no 14.999999999999998


@dataclass(frozen=True, eq=False)
class ToolSI:
    """The tool in SI: TCP in the flange frame (4, 4) [m], mesh file and its scale to m, or a
    box `size` (3,) [m] from the flange to the TCP, display colour."""

    name: str
    T_flange_tcp: FloatArray
    mesh: str | None
    mesh_scale: float
    size: FloatArray | None
    color: tuple[int, int, int]


class Tool(StrictModel):
    """The tool on the flange: TCP pose in the flange frame, optional mesh or box shape."""

    name: str = "tool"
    tcp: Pose = Field(default_factory=Pose)
    mesh: str | None = None  # path relative to the project file, in the flange frame
    mesh_scale: MeshScale = 0.001  # mesh units -> m (files are usually in mm)
    size: ToolSize3mm | None = None  # a box [mm] from the flange to the TCP when no mesh is given
    color: Color = Field(default_factory=lambda: [200, 200, 210])
    mass: io_.Mass | None = None  # kg (RAPID's tooldata needs it)
    cog: io_.Cog | None = None  # mm, centre of gravity in the flange frame

    @model_validator(mode="after")
    def _step_scale(self) -> Tool:
        check_step_scale(self.mesh, self.mesh_scale, "mesh_scale")
        return self

    def to_si(self) -> ToolSI:
        """Return the tool in SI."""
        return ToolSI(
            name=self.name,
            T_flange_tcp=pose_to_matrix(self.tcp),
            mesh=self.mesh,
            mesh_scale=self.mesh_scale,
            size=None if self.size is None else np.asarray(self.size, float) * MM,
            color=(int(self.color[0]), int(self.color[1]), int(self.color[2])),
        )


@dataclass(frozen=True, eq=False)
class CellObjectSI:
    """A cell object in SI: shape, world pose (4, 4) [m], box size [m], cylinder radius and
    height [m], mesh file and its scale to m, colour, whether it collides."""

    name: str
    shape: str
    T_world_body: FloatArray
    size: tuple[float, float, float] | None
    radius: float | None
    height: float | None
    path: str | None
    scale: float
    color: tuple[int, int, int]
    collide: bool


class CellObject(StrictModel):
    """A named obstacle or fixture of the cell: a box, a cylinder or a mesh, at `pose`."""

    name: str
    shape: Literal["box", "cylinder", "mesh"]
    pose: Pose = Field(default_factory=Pose)
    size: Size3mm | None = None  # box edge lengths [mm]
    radius: SizeMM | None = None  # cylinder [mm]
    height: SizeMM | None = None  # cylinder, along its z [mm]
    path: str | None = None  # mesh file, relative to the project file
    scale: MeshScale = 0.001  # mesh units -> m
    color: Color = Field(default_factory=lambda: [170, 170, 170])
    collide: bool = True

    @model_validator(mode="after")
    def _shape_fields(self) -> CellObject:
        need = {"box": ("size",), "cylinder": ("radius", "height"), "mesh": ("path",)}[self.shape]
        missing = [k for k in need if getattr(self, k) is None]
        if missing:
            raise ValueError(f"a {self.shape} needs {', '.join(repr(k) for k in missing)}")
        if self.size is not None and any(s <= 0 for s in self.size):
            raise ValueError(f"box size must be positive [mm], got {self.size}")
        check_step_scale(self.path, self.scale, "scale")
        return self

    def to_si(self) -> CellObjectSI:
        """Return the object in SI."""
        size = None
        if self.size is not None:
            x, y, z = (float(v) * MM for v in self.size)
            size = (x, y, z)
        return CellObjectSI(
            name=self.name,
            shape=self.shape,
            T_world_body=pose_to_matrix(self.pose),
            size=size,
            radius=None if self.radius is None else self.radius * MM,
            height=None if self.height is None else self.height * MM,
            path=self.path,
            scale=self.scale,
            color=(int(self.color[0]), int(self.color[1]), int(self.color[2])),
            collide=self.collide,
        )


class Cell(StrictModel):
    """Everything around the robot."""

    objects: Annotated[list[CellObject], Field(max_length=B.MAX_ITEMS)] = Field(
        default_factory=list
    )

    @model_validator(mode="after")
    def _unique_names(self) -> Cell:
        seen: set[str] = set()
        for obj in self.objects:
            if obj.name in seen:
                raise ValueError(f"object names must be unique; {obj.name!r} appears twice")
            seen.add(obj.name)
        return self

    def to_si(self) -> tuple[CellObjectSI, ...]:
        """Return the objects in SI, in file order."""
        return tuple(obj.to_si() for obj in self.objects)


@dataclass(frozen=True, eq=False)
class MoveSI:
    """A move in SI: joint target (dof,) [rad] or TCP target in the world (4, 4) [m]; speed
    as a fraction of the max joint speeds (joint moves) or [m/s] (linear); zone [m]; a pose
    target's stored arm `configuration` (None: the plan chooses one)."""

    name: str
    type: str
    joints: FloatArray | None
    T_world_tcp: FloatArray | None
    speed: float
    zone: float
    wobj: str = "base"
    configuration: TargetConfiguration | None = None


@dataclass(frozen=True, eq=False)
class ProgramSI:
    """A program in SI: name, start joints [rad] (None: the first move's target), moves."""

    name: str
    start: FloatArray | None
    moves: tuple[MoveSI, ...]


class MoveSpec(StrictModel):
    """One move of a robot program: a joint move (PTP/MoveJ) or a linear move (LIN/MoveL)."""

    name: str = ""
    type: Literal["joint", "linear"]
    joints: Joints | None = None  # deg, target of a joint move
    pose: Pose | None = None  # TCP target in the world (mm, deg); required for linear moves
    speed: Annotated[float, Field(gt=0)] = 100.0  # joint: % of max joint speed; linear: mm/s
    zone: Annotated[float, B.span(B.ZONE_MM, "mm")] = 0.0  # blend radius [mm]; 0 = exact stop
    wobj: io_.Name | None = None  # the work object the program states the target in (default base)
    configuration: ConfigurationSpec | None = None  # a pose target's IK branch and turns

    @model_validator(mode="after")
    def _target(self) -> MoveSpec:
        if (self.joints is None) == (self.pose is None):
            raise ValueError("give exactly one target: 'joints' [deg] or 'pose' {xyz mm, rpy deg}")
        if self.type == "linear" and self.pose is None:
            raise ValueError("a linear move needs a 'pose' target")
        if self.configuration is not None and self.pose is None:
            raise InputError(
                "only a pose target has an arm configuration; a joint target's joints are exact:"
                " remove 'configuration'",
                field="configuration",
            )
        speed = (
            B.span(B.JOINT_MOVE_PERCENT_OPEN, "%", lo_open=True)
            if self.type == "joint"
            else B.span(B.LINEAR_SPEED_MM_S, "mm/s")
        )
        try:
            speed.check(self.speed)
        except ValueError as exc:
            unit = "% of the joint speed limits" if self.type == "joint" else "mm/s"
            raise InputError(
                f"{exc} (a {self.type} move's speed is in {unit})", field="speed"
            ) from None
        return self

    def to_si(self, convention: JointConvention | None = None) -> MoveSI:
        """Return the move in SI; joints [deg, controller's] become the model's [rad] by the
        robot's `convention` (None: unchanged)."""
        return MoveSI(
            name=self.name,
            type=self.type,
            joints=joints_to_model(self.joints, convention),
            T_world_tcp=None if self.pose is None else pose_to_matrix(self.pose),
            speed=self.speed / 100.0 if self.type == "joint" else self.speed * MM,
            zone=self.zone * MM,
            wobj=self.wobj or io_.BASE_WOBJ,
            configuration=None
            if self.configuration is None
            else self.configuration.to_si(B.MAX_DOF if convention is None else convention.dof),
        )


if TYPE_CHECKING:
    ProgramItem = Any  # a MoveSpec or one of program_io's actions, told apart by "type"
else:
    ProgramItem = io_.program_item(MoveSpec)


class ProgramSpec(StrictModel):
    """A robot program: start joints and moves; planned into a jerk-limited trajectory."""

    name: str = "main"
    start: Joints | None = None  # deg; default: the first move's target (never the jog)
    moves: Annotated[list[ProgramItem], Field(max_length=B.MAX_ITEMS)] = Field(default_factory=list)
    # moves and actions (program_io: gripper, set_output, pulse_output, wait_input, wait, comment)

    @model_validator(mode="after")
    def _name(self) -> ProgramSpec:
        if not self.name.isidentifier() or len(self.name) > 24:
            raise ValueError(
                f"program name {self.name!r} must be a letter or _ followed by letters, digits or _"
                " (at most 24 characters), as robot controllers require"
            )
        return self

    def to_si(self, convention: JointConvention | None = None) -> ProgramSI:
        """Return the program in SI; joints [deg, controller's] become the model's [rad] by the
        robot's `convention` (`RobotModel.convention`; None: unchanged)."""
        start = joints_to_model(self.start, convention)
        moves = tuple(m.to_si(convention) for m in self.moves if isinstance(m, MoveSpec))
        return ProgramSI(self.name, start, moves)


class Project(StrictModel):
    """A workbench project file."""

    schema_version: Literal[2] = 2  # SCHEMA_VERSION
    name: str = "untitled"
    description: str = ""
    robot: Robot = Field(default_factory=lambda: Robot(preset="mz07"))
    tool: Tool = Field(default_factory=Tool)
    cell: Cell = Field(default_factory=Cell)
    program: ProgramSpec | None = None
    bending: BendingSpec | None = None
    assembly: AssemblySpec | None = None
    polishing: PolishingSpec | None = None
    collision: CollisionSpec | None = None  # plan collision policy; absent: spheres + SDF
    work_objects: Annotated[list[io_.WorkObjectSpec], Field(max_length=B.MAX_ITEMS)] | None = None
    io: io_.IOSpec | None = None  # digital I/O, gripper, sync signals
    cad: CadSpec | None = None  # STEP tessellation tolerances; absent: 0.05 mm, 5 deg
    planning: PlanningSpec | None = None  # each workflow's planning time limit; absent: 600 s

    @model_validator(mode="after")
    def _references(self) -> Project:
        io_.check_references(self)
        check_turns(self)
        return self

    def workflows(self) -> list[str]:
        """Return the workflows this project has the inputs of, in order: "motion" (a program
        with moves), "bending", "assembly" (with parts), "polishing"."""
        has = {
            "motion": self.program is not None and bool(self.program.moves),
            "bending": self.bending is not None,
            "assembly": self.assembly is not None and bool(self.assembly.parts),
            "polishing": self.polishing is not None,
        }
        return [name for name, present in has.items() if present]
