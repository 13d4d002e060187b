"""The project file's `assembly` section: virtual assembly (seed 003): parts, start and goal poses, planner.

Millimetres and degrees. Each part is a mesh file (or a box or cylinder) with its start and
goal poses in the world, the TCP pose in the part's frame while it is held (`grasp`), and
the robot that carries it: the project's `robot` (by its name) or one of `robots`, extra
arms of the cell. `sequence` orders the part moves (pick, approach, insert, retreat);
by default the parts in the order listed.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from workbench.project.common import Color, Pose, Positive, StrictModel, Vec3mm


class AssemblyRobotSpec(StrictModel):
    """A further arm of the assembly cell: a preset placed at `base`, with a box gripper."""

    name: str
    preset: Literal["mz07"] = "mz07"
    base: Pose = Field(default_factory=Pose)
    joints: list[float] | None = None  # home configuration [deg]; default all zero
    tcp: Pose = Field(default_factory=lambda: Pose(xyz=[0.0, 0.0, 150.0]))  # flange -> TCP
    tool_size: Vec3mm | None = Field(default_factory=lambda: [60.0, 80.0, 120.0])  # box [mm]
    color: Color = Field(default_factory=lambda: [200, 215, 235])


class AssemblyPartSpec(StrictModel):
    """One part: its shape, start and goal poses (world), grasp (TCP in the part frame), robot."""

    name: str
    shape: Literal["mesh", "box", "cylinder"] = "mesh"
    path: str | None = None  # mesh file relative to the project file (must be closed)
    scale: Positive = 0.001  # mesh units -> m
    size: Vec3mm | None = None  # box [mm]
    radius: Positive | None = None  # cylinder [mm]
    height: Positive | None = None  # cylinder [mm]
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
        return self


class AssemblyPlannerSpec(StrictModel):
    """The part path planner and its parameters."""

    name: Literal["ant", "rrt_connect", "joint_rrt_connect"] = "ant"
    cell_size: Positive | None = None  # subdivision cell [mm]; default 1/20 of each part
    step: Annotated[int, Field(ge=1)] = 20  # ant: segments along the dominant axis
    dis: Positive | None = None  # ant: grid spacing on a cutting plane [mm]
    seed: Annotated[int, Field(ge=0)] = 0  # rrt_connect, joint_rrt_connect: random seed
    max_time: Positive = 10.0  # rrt_connect, joint_rrt_connect: time limit [s]
    # joint_rrt_connect: largest travel of a robot point between two checks [mm]; default cell_size
    robot_resolution: Positive | None = None


class AssemblyTaskSpec(StrictModel):
    """One part move: pick (after an approach), carry and insert, release and retreat."""

    part: str
    approach: Annotated[float, Field(ge=0)] = 50.0  # pre-grasp distance back along the TCP z [mm]
    retreat: Annotated[float, Field(ge=0)] = 50.0  # after release, back along the TCP z [mm]


class AssemblySpec(StrictModel):
    """The `assembly` section (mm, deg)."""

    robots: list[AssemblyRobotSpec] = Field(default_factory=list)
    parts: list[AssemblyPartSpec] = Field(default_factory=list)
    planner: AssemblyPlannerSpec = Field(default_factory=AssemblyPlannerSpec)
    sequence: list[AssemblyTaskSpec] | None = None  # default: every part, in the listed order
    speed: Annotated[float, Field(gt=0, le=100)] = 50.0  # % of the robots' joint speed limits

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
