"""The project file's `assembly` section: virtual assembly (seed 003): parts, start and goal poses, planner.

Millimetres and degrees. Each part is a mesh file (or a box or cylinder) with its start and
goal poses in the world, the TCP pose in the part's frame while it is held (`grasp`), and
the robot that carries it: the project's `robot` (by its name) or one of `robots`, extra
arms of the cell. `sequence` orders the part moves (pick, approach, insert, retreat);
by default the parts in the order listed.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Annotated, Any, Literal

import numpy as np
from numpy.typing import NDArray
from pydantic import Field, ValidationError, model_validator

from workbench.errors import InputError
from workbench.project import bounds as B
from workbench.project import program_io as io_
from workbench.project.cad import check_step_scale
from workbench.project.common import (
    Color,
    Joints,
    MeshScale,
    Pose,
    Seed,
    Size3mm,
    SizeMM,
    StrictModel,
    ToolSize3mm,
)
from workbench.project.units import MM, matrix_to_pose, pose_to_matrix

if TYPE_CHECKING:
    from workbench.motion.programs.controller_program import ToolData
    from workbench.project.models import RobotSI, ToolSI


PlannerMM = Annotated[float, B.span(B.PLANNER_CELL_MM, "mm")]
Approach = Annotated[float, B.span(B.APPROACH_MM, "mm")]


def _mm(v: float | None) -> float | None:
    return None if v is None else v * MM


def _rgb(c: list[int]) -> tuple[int, int, int]:
    return (int(c[0]), int(c[1]), int(c[2]))


# -- the section in SI (m, rad, s; speed a fraction), what the service and the domain use ---------
@dataclass(frozen=True, eq=False)
class AssemblyRobotSI:
    """A further arm: its robot and tool sections in SI (built as the project's robot is)."""

    name: str
    robot: RobotSI
    tool: ToolSI
    color: tuple[int, int, int]


@dataclass(frozen=True, eq=False)
class AssemblyPartSI:
    """A part: shape (box `size`, cylinder `radius`/`height` [m], or a mesh file), poses (4, 4) [m]."""

    name: str
    shape: str
    path: str | None
    scale: float
    size: tuple[float, float, float] | None
    radius: float | None
    height: float | None
    start: NDArray[np.float64]
    goal: NDArray[np.float64]
    grasp: NDArray[np.float64]  # T_part_tcp
    robot: str | None
    color: tuple[int, int, int]


@dataclass(frozen=True)
class AssemblyPlannerSI:
    """The planner: name, cell_size, dis, robot_resolution [m] (None: automatic), step, seed, max_time [s]."""

    name: str
    cell_size: float | None
    step: int
    dis: float | None
    seed: int
    max_time: float
    robot_resolution: float | None

    def options(self, planner: str) -> dict[str, Any]:
        """Return the options of `planner` (step, dis [m]; seed, max_time [s]; robot_resolution [m])."""
        if planner == "ant":
            return {"step": self.step} | ({"dis": self.dis} if self.dis is not None else {})
        opts: dict[str, Any] = {"seed": self.seed, "max_time": self.max_time}
        if planner == "joint_rrt_connect" and self.robot_resolution is not None:
            opts["robot_resolution"] = self.robot_resolution
        return opts


@dataclass(frozen=True)
class AssemblyTaskSI:
    """One part move of the sequence: approach and retreat distances [m] along the TCP z."""

    part: str
    approach: float
    retreat: float


@dataclass(frozen=True, eq=False)
class AssemblySI:
    """The `assembly` section in SI; `sequence` is the one in effect (default: every part as listed)."""

    robots: tuple[AssemblyRobotSI, ...]
    parts: tuple[AssemblyPartSI, ...]
    planner: AssemblyPlannerSI
    sequence: tuple[AssemblyTaskSI, ...]
    speed: float  # fraction of the robots' joint velocity, acceleration and jerk limits


class AssemblyRobotSpec(StrictModel):
    """A further arm of the assembly cell: a preset placed at `base`, with a box gripper."""

    name: str
    preset: Literal["mz07"] = "mz07"
    base: Pose = Field(default_factory=Pose)
    joints: Joints | None = None  # home configuration [deg]; default all zero
    tcp: Pose = Field(default_factory=lambda: Pose(xyz=[0.0, 0.0, 150.0]))  # flange -> TCP
    tool_size: ToolSize3mm | None = Field(default_factory=lambda: [60.0, 80.0, 120.0])  # box [mm]
    color: Color = Field(default_factory=lambda: [200, 215, 235])
    mass: io_.Mass | None = None  # tool mass [kg] (RAPID's tooldata needs it)
    cog: io_.Cog | None = None  # tool centre of gravity [mm] in the flange frame

    def to_si(self) -> AssemblyRobotSI:
        """Return this arm in SI: a project `robot` (preset, base, joints) and `tool` (TCP, box)."""
        from workbench.project.models import Robot, Tool  # models imports this module

        robot = Robot(name=self.name, preset=self.preset, base=self.base, joints=self.joints)
        tool = Tool(tcp=self.tcp, size=self.tool_size)
        return AssemblyRobotSI(self.name, robot.to_si(), tool.to_si(), _rgb(self.color))

    def tool_data(self) -> ToolData:
        """Return this arm's tool for its robot program: "<name>_tool", TCP [m], mass, cog [m]."""
        from workbench.project.models import Tool  # models imports this module

        tool = Tool(name=f"{self.name}_tool", tcp=self.tcp, mass=self.mass, cog=self.cog)
        return io_.tool_data(tool)


def _vec(v: list[float]) -> tuple[float, float, float]:
    x, y, z = (float(c) for c in np.asarray(v, float) * MM)
    return (x, y, z)


class AssemblyPartSpec(StrictModel):
    """One part: its shape, start and goal poses (world), grasp (TCP in the part frame), robot."""

    name: str
    shape: Literal["mesh", "box", "cylinder"] = "mesh"
    path: str | None = None  # mesh file relative to the project file (must be closed)
    scale: MeshScale = 0.001  # mesh units -> m
    size: Size3mm | None = None  # box [mm]
    radius: SizeMM | None = None  # cylinder [mm]
    height: SizeMM | None = None  # cylinder [mm]
    start: Pose = Field(default_factory=Pose)
    goal: Pose = Field(default_factory=Pose)
    grasp: Pose = Field(default_factory=lambda: Pose(rpy=[180.0, 0.0, 0.0]))
    robot: str | None = None  # None: the part moves by itself (no robot carries it)
    color: Color = Field(default_factory=lambda: [90, 140, 210])

    @model_validator(mode="after")
    def _shape_fields(self) -> AssemblyPartSpec:
        need = {"box": ("size",), "cylinder": ("radius", "height"), "mesh": ("path",)}[self.shape]
        missing = [k for k in need if getattr(self, k) is None]
        if missing:
            raise ValueError(f"a {self.shape} part needs {', '.join(repr(k) for k in missing)}")
        if self.size is not None and any(s <= 0 for s in self.size):
            raise ValueError(f"box size must be positive [mm], got {self.size}")
        check_step_scale(self.path, self.scale, "scale")
        return self

    def to_si(self) -> AssemblyPartSI:
        """Return this part in SI."""
        return AssemblyPartSI(
            name=self.name,
            shape=self.shape,
            path=self.path,
            scale=self.scale,
            size=None if self.size is None else _vec(self.size),
            radius=_mm(self.radius),
            height=_mm(self.height),
            start=pose_to_matrix(self.start),
            goal=pose_to_matrix(self.goal),
            grasp=pose_to_matrix(self.grasp),
            robot=self.robot,
            color=_rgb(self.color),
        )

    def set_pose(self, which: Literal["start", "goal"], T_world_part: NDArray[np.float64]) -> None:
        """Set the `which` pose from a (4, 4) transform [m] (stored in mm and degrees); a pose
        outside the project's bounds is an InputError naming the part's field."""
        try:
            pose = matrix_to_pose(T_world_part)
        except ValidationError as exc:
            err = exc.errors()[0]
            where = ".".join(str(x) for x in err.get("loc", ()))
            raise InputError(
                f"assembly part {self.name!r}: {which}.{where}: {err.get('msg', exc)}"
            ) from None
        setattr(self, which, pose)


class AssemblyPlannerSpec(StrictModel):
    """The part path planner and its parameters."""

    name: Literal["ant", "rrt_connect", "joint_rrt_connect"] = "ant"
    cell_size: PlannerMM | None = None  # subdivision cell [mm]; default 1/20 of each part
    step: Annotated[int, B.span(B.PLANNER_STEPS)] = 20  # ant: segments along the dominant axis
    dis: PlannerMM | None = None  # ant: grid spacing on a cutting plane [mm]
    seed: Seed = 0  # rrt_connect, joint_rrt_connect: random seed
    max_time: Annotated[float, B.span(B.PLANNER_TIME_S_OPEN, "s", lo_open=True)] = 10.0
    # rrt_connect, joint_rrt_connect: time limit [s]
    # joint_rrt_connect: largest travel of a robot point between two checks [mm]; default cell_size
    robot_resolution: PlannerMM | None = None

    def to_si(self) -> AssemblyPlannerSI:
        """Return the planner's parameters in SI."""
        return AssemblyPlannerSI(
            name=self.name,
            cell_size=_mm(self.cell_size),
            step=self.step,
            dis=_mm(self.dis),
            seed=self.seed,
            max_time=self.max_time,
            robot_resolution=_mm(self.robot_resolution),
        )


class AssemblyTaskSpec(StrictModel):
    """One part move: pick (after an approach), carry and insert, release and retreat."""

    part: str
    approach: Approach = 50.0  # pre-grasp distance back along the TCP z [mm]
    retreat: Approach = 50.0  # after release, back along the TCP z [mm]

    def to_si(self) -> AssemblyTaskSI:
        """Return this part move with its distances in metres."""
        return AssemblyTaskSI(self.part, self.approach * MM, self.retreat * MM)


class AssemblySpec(StrictModel):
    """The `assembly` section (mm, deg)."""

    robots: Annotated[list[AssemblyRobotSpec], Field(max_length=B.MAX_ITEMS)] = Field(
        default_factory=list
    )
    parts: Annotated[list[AssemblyPartSpec], Field(max_length=B.MAX_ITEMS)] = Field(
        default_factory=list
    )
    planner: AssemblyPlannerSpec = Field(default_factory=AssemblyPlannerSpec)
    sequence: list[AssemblyTaskSpec] | None = None  # default: every part, in the listed order
    speed: Annotated[float, B.span(B.SPEED_PERCENT_OPEN, "%", lo_open=True)] = 50.0
    # % of the robots' joint speed limits

    @model_validator(mode="after")
    def _names(self) -> AssemblySpec:
        for what, names in (
            ("part", [p.name for p in self.parts]),
            ("robot", [r.name for r in self.robots]),
        ):
            dup = sorted({n for n in names if names.count(n) > 1})
            if dup:
                raise ValueError(f"{what} names must be unique; repeated {dup}")
        known = [p.name for p in self.parts]
        for t in self.sequence or []:
            if t.part not in known:
                raise ValueError(f"sequence names part {t.part!r}; the parts are {known}")
        seq = [t.part for t in self.sequence or []]
        dup = sorted({n for n in seq if seq.count(n) > 1})
        if dup:
            raise ValueError(f"each part may appear once in the sequence; repeated {dup}")
        return self

    def tasks(self, parts: list[str] | None = None) -> list[AssemblyTaskSpec]:
        """Return the part moves in order: `sequence`, or every part as listed (default distances).

        parts: only these parts' moves, in sequence order, then those the sequence does not
        list (default distances).
        """
        tasks = (
            list(self.sequence)
            if self.sequence is not None
            else [AssemblyTaskSpec(part=p.name) for p in self.parts]
        )
        if parts is None:
            return tasks
        listed = [t.part for t in tasks]
        return [t for t in tasks if t.part in parts] + [
            AssemblyTaskSpec(part=n) for n in parts if n not in listed
        ]

    def tools(self) -> dict[str, ToolData]:
        """Return the further robots' tools (TCP, mass, cog; `AssemblyRobotSpec.tool_data`) by name."""
        return {r.name: r.tool_data() for r in self.robots}

    def to_si(self) -> AssemblySI:
        """Return the section in SI."""
        return AssemblySI(
            robots=tuple(r.to_si() for r in self.robots),
            parts=tuple(p.to_si() for p in self.parts),
            planner=self.planner.to_si(),
            sequence=tuple(t.to_si() for t in self.tasks()),
            speed=self.speed / 100.0,
        )
