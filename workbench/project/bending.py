"""The project file's `bending` section: press-brake bending (seed 000): part, bend sequence, grasp, cell.

Millimetres and degrees. The part is given inline (`part`) or as a path to a part JSON
(`part_file`, e.g. ``parts/seed_part.json``) with the same fields.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import AfterValidator, Field, model_validator

from workbench.project.common import Pose, Positive, StrictModel, Vec3mm

#: Seed 000 Table 1 starts at r/t = 0.5: smaller inner radii are outside the table.
MIN_R_OVER_T = 0.5


def _polygon(v: list[list[float]]) -> list[list[float]]:
    if len(v) < 3 or any(len(p) != 2 for p in v):
        raise ValueError(
            f"expected at least 3 points [x, y] in mm (counter-clockwise), got {len(v)} point(s)"
        )
    return v


def _positive_mm(v: float) -> float:
    if not v > 0:
        raise ValueError(f"must be > 0 mm, got {v:g}")
    return v


def _included(v: float) -> float:
    if not 0.0 < v < 180.0:
        raise ValueError(f"must be in (0, 180) deg (180 = flat, 90 = a right angle), got {v:g}")
    return v


def _unique(v: list[str]) -> list[str]:
    dup = sorted({s for s in v if v.count(s) > 1})
    if dup:
        raise ValueError(f"each bend may appear once; repeated {dup}")
    return v


class FlangeSpec(StrictModel):
    """A planar flange: a counter-clockwise polygon [mm] in its own frame."""

    name: str
    polygon: Annotated[list[list[float]], AfterValidator(_polygon)]


class BendSpec(StrictModel):
    """A bend joining edge `parent_edge` of flange `parent` to edge `child_edge` of `child`."""

    name: str
    parent: str
    parent_edge: Annotated[int, Field(ge=0)]
    child: str
    child_edge: Annotated[int, Field(ge=0)]
    included_angle: Annotated[float, AfterValidator(_included)]  # deg, (0, 180); 180 = flat
    inner_radius: Positive  # mm, >= 0.5 x thickness (Table 1)
    direction: Literal["up", "down"] = "up"
    k_factor: Annotated[float, Field(ge=0, le=1)] | None = None  # overrides Table 1


class PartSpec(StrictModel):
    """A sheet-metal part (seed 000 Fig. 7 shape): thickness, flanges, bends [mm, deg]."""

    name: str = "part"
    units: Literal["mm/deg"] = "mm/deg"
    note: str = ""
    thickness: Annotated[float, AfterValidator(_positive_mm)]  # mm
    k_factor: Annotated[float, Field(ge=0, le=1)] | None = None  # K for every bend
    flanges: list[FlangeSpec]
    bends: list[BendSpec] = Field(default_factory=list)
    sequence: Annotated[list[str], AfterValidator(_unique)] | None = None

    @model_validator(mode="after")
    def _consistent(self) -> PartSpec:
        flanges = [f.name for f in self.flanges]
        if len(set(flanges)) != len(flanges):
            raise ValueError(f"flanges: names must be unique, got {flanges}")
        for i, b in enumerate(self.bends):
            if b.inner_radius < MIN_R_OVER_T * self.thickness - 1e-9:
                raise ValueError(
                    f"bends[{i}].inner_radius: {b.inner_radius:g} mm is below Table 1's range; "
                    f"the minimum is {MIN_R_OVER_T} x thickness = {MIN_R_OVER_T * self.thickness:g} mm"
                )
            for role in ("parent", "child"):
                if getattr(b, role) not in flanges:
                    raise ValueError(
                        f"bends[{i}].{role}: no flange {getattr(b, role)!r}; flanges are {flanges}"
                    )
        if self.sequence is not None:
            _check_sequence(self.sequence, [b.name for b in self.bends], "sequence")
        return self


def _check_sequence(seq: list[str], bends: list[str], where: str) -> None:
    missing = [n for n in bends if n not in seq]
    unknown = [s for s in seq if s not in bends]
    if missing or unknown:
        raise ValueError(
            f"{where}: must name every bend exactly once; missing {missing}, unknown {unknown}"
            f" (bends are {bends})"
        )


class GraspSpec(StrictModel):
    """Where the gripper holds the part: a flange and an offset in its plane [mm, deg]."""

    flange: str = "1"
    offset: Annotated[list[float], Field(min_length=2, max_length=2)] | None = None
    # [x, y] mm in the flange's polygon frame; None = the polygon's centroid
    yaw: float = 0.0  # deg, gripper rotation about the flange normal


class DieSpec(StrictModel):
    """The press brake's die: `pose` of its bend line (x along the line, z up, robot on -y)."""

    pose: Pose = Field(default_factory=Pose)
    length: Positive = 1000.0  # mm: the longest bend line that fits


class BendingSpec(StrictModel):
    """The `bending` section (mm, deg): part, sequence, grasp, die, transfer to the pallet."""

    part: PartSpec | None = None
    part_file: str | None = None  # path to a part JSON (mm/deg), relative to the project file
    sequence: Annotated[list[str], AfterValidator(_unique)] | None = None  # overrides the part's
    grasp: GraspSpec = Field(default_factory=GraspSpec)
    die: DieSpec = Field(default_factory=DieSpec)
    retract: Vec3mm = Field(default_factory=lambda: [0.0, -250.0, 60.0])  # in the die frame
    transfer: list[Pose] = Field(default_factory=list)  # TCP via poses in the world
    pallet: Pose = Field(default_factory=Pose)  # where the part frame is put down (world)
    frames: Annotated[int, Field(ge=22, le=2000)] = 40  # transfer frames checked

    @model_validator(mode="after")
    def _one_part(self) -> BendingSpec:
        if (self.part is None) == (self.part_file is None):
            raise ValueError(
                "give exactly one of 'part' (flanges, bends, thickness) or 'part_file' (a path)"
            )
        if self.part is not None:
            if self.sequence is not None:
                _check_sequence(self.sequence, [b.name for b in self.part.bends], "sequence")
            names = [f.name for f in self.part.flanges]
            if self.grasp.flange not in names:
                raise ValueError(
                    f"grasp.flange: no flange {self.grasp.flange!r}; flanges are {names}"
                )
        return self
