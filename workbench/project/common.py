"""Building blocks of the project file's models: strict base model, vectors, poses, colours,
errors at a field."""

from __future__ import annotations

from typing import Annotated

import numpy as np
from numpy.typing import NDArray
from pydantic import AfterValidator, BaseModel, ConfigDict, Field, ValidationError
from pydantic_core import InitErrorDetails, PydanticCustomError

from workbench.project import bounds as B


class StrictModel(BaseModel):
    """Base of every project model: unknown fields and non-finite numbers are errors."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, validate_assignment=True)


Loc = tuple[str | int, ...]  # a location below a model: field names and list indices


def field_error(problems: list[tuple[Loc, str, object]]) -> ValidationError:
    """Return a validation error at each `loc` below the model that raises it (pydantic adds
    the model's own path), so a rule across fields names the field it is about."""
    return ValidationError.from_exception_data(
        "bending",
        [
            InitErrorDetails(type=PydanticCustomError("value_error", msg), loc=loc, input=value)
            for loc, msg, value in problems
        ],
    )


def dotted(loc: Loc) -> str:
    """Return `loc` as a dotted path: ("steps", 0, "bend") -> "steps[0].bend"."""
    return "".join(f"[{k}]" if isinstance(k, int) else f".{k}" for k in loc).lstrip(".")


def _vector(n: int, what: str) -> AfterValidator:
    def check(v: list[float]) -> list[float]:
        if len(v) != n:
            raise ValueError(f"expected {n} numbers {what}, got {len(v)}")
        return v

    return AfterValidator(check)


Coordinate = Annotated[float, B.symmetric(B.CELL_HALF_EXTENT_MM, "mm")]  # a position [mm]
Angle = Annotated[float, B.symmetric(B.ANGLE_DEG, "deg")]  # an orientation angle [deg]
JointAngle = Annotated[float, B.symmetric(B.JOINT_DEG, "deg")]  # a joint value or limit [deg]
SizeMM = Annotated[float, B.span(B.SIZE_MM, "mm")]  # an edge length, radius or height [mm]
MeshScale = Annotated[float, B.span(B.MESH_SCALE)]  # mesh units -> m
Seed = Annotated[int, B.span((0, B.MAX_SEED))]  # a random seed
Vec3mm = Annotated[list[Coordinate], _vector(3, "[mm, mm, mm]")]  # a position
Size3mm = Annotated[list[SizeMM], _vector(3, "[mm, mm, mm] edge lengths")]  # a box
ToolSizeMM = Annotated[float, B.span(B.TOOL_SIZE_MM, "mm")]
ToolSize3mm = Annotated[list[ToolSizeMM], _vector(3, "[mm, mm, mm] edge lengths")]  # a tool box
Vec3deg = Annotated[list[Angle], _vector(3, "[roll, pitch, yaw] in degrees")]
Joints = Annotated[list[JointAngle], Field(max_length=B.MAX_DOF)]  # per joint [deg]
Positive = Annotated[float, Field(gt=0)]


def _color(v: list[int]) -> list[int]:
    if len(v) != 3 or any(not 0 <= c <= 255 for c in v):
        raise ValueError(f"expected 3 integers 0..255 [r, g, b], got {v}")
    return v


Color = Annotated[list[int], AfterValidator(_color)]


class Pose(StrictModel):
    """A rigid pose: position [mm] and R = Rz(yaw) Ry(pitch) Rx(roll) [deg]."""

    xyz: Vec3mm = Field(default_factory=lambda: [0.0, 0.0, 0.0])
    rpy: Vec3deg = Field(default_factory=lambda: [0.0, 0.0, 0.0])

    def to_si(self) -> NDArray[np.float64]:
        """Return the pose as a (4, 4) transform [m]."""
        from workbench.project.units import pose_to_matrix

        return pose_to_matrix(self)
