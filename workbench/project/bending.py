"""The project file's `bending` section: press-brake bending (seed 000): part, bend sequence, grasp, cell.

Millimetres and degrees. The part is given inline (`part`) or as a path to a part JSON
(`part_file`, e.g. ``parts/seed_part.json``) with the same fields. `BendingSpec.to_si`
returns the section in SI units (`BendingSI`), the only form the service uses.

Two fields hold a bend sequence, with one meaning: the part's `sequence` is the order the
part comes with (a part file may be shared by projects); the section's `sequence` is this
project's order and replaces it when given (the API's `set_sequence` writes it). The rule
both must satisfy is `workbench.sheetmetal.sequence` (every bend exactly once).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Literal

import numpy as np
from numpy.typing import NDArray
from pydantic import AfterValidator, Field, ValidationError, model_validator

from workbench.errors import ProjectError
from workbench.project import bounds as B
from workbench.project.common import Angle, Coordinate, Pose, StrictModel, Vec3mm
from workbench.project.paths import ProjectFolders
from workbench.project.units import DEG, MM
from workbench.sheetmetal.die import Die
from workbench.sheetmetal.grasp import Grasp
from workbench.sheetmetal.kfactor import MIN_R_OVER_T
from workbench.sheetmetal.sequence import sequence_problem
from workbench.sheetmetal.transfer import Transfer


def _polygon(v: list[list[float]]) -> list[list[float]]:
    if len(v) < 3 or len(v) > B.MAX_ITEMS or any(len(p) != 2 for p in v):
        raise ValueError(
            f"expected at least 3 points [x, y] in mm (counter-clockwise), got {len(v)} point(s)"
        )
    return v


def _positive_mm(v: float) -> float:
    if not v > 0:
        raise ValueError(f"must be > 0 mm, got {v:g}")
    return B.span(B.THICKNESS_MM, "mm").check(v)


def _included(v: float) -> float:
    if not 0.0 < v < 180.0:
        raise ValueError(f"must be in (0, 180) deg (180 = flat, 90 = a right angle), got {v:g}")
    return v


def _unique(v: list[str]) -> list[str]:
    problem = sequence_problem(v)  # the bends are not known here: repeats only
    if problem is not None:
        raise ValueError(problem)
    return v


def _check_sequence(seq: list[str], bends: list[str], where: str) -> None:
    problem = sequence_problem(seq, bends)
    if problem is not None:
        raise ValueError(f"{where}: {problem}")


class FlangeSpec(StrictModel):
    """A planar flange: a counter-clockwise polygon [mm] in its own frame."""

    name: str
    polygon: Annotated[list[list[Coordinate]], AfterValidator(_polygon)]


class BendSpec(StrictModel):
    """A bend joining edge `parent_edge` of flange `parent` to edge `child_edge` of `child`."""

    name: str
    parent: str
    parent_edge: Annotated[int, Field(ge=0, le=B.MAX_INDEX)]
    child: str
    child_edge: Annotated[int, Field(ge=0, le=B.MAX_INDEX)]
    included_angle: Annotated[float, AfterValidator(_included)]  # deg, (0, 180); 180 = flat
    inner_radius: Annotated[float, B.span(B.INNER_RADIUS_MM, "mm")]  # >= 0.5 x thickness
    direction: Literal["up", "down"] = "up"
    k_factor: Annotated[float, Field(ge=0, le=1)] | None = None  # overrides Table 1


class PartSpec(StrictModel):
    """A sheet-metal part (seed 000 Fig. 7 shape): thickness, flanges, bends [mm, deg]."""

    name: str = "part"
    units: Literal["mm/deg"] = "mm/deg"
    note: str = ""
    thickness: Annotated[float, AfterValidator(_positive_mm)]  # mm
    k_factor: Annotated[float, Field(ge=0, le=1)] | None = None  # K for every bend
    flanges: Annotated[list[FlangeSpec], Field(max_length=B.MAX_ITEMS)]
    bends: Annotated[list[BendSpec], Field(max_length=B.MAX_ITEMS)] = Field(default_factory=list)
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

    def to_si(self, sequence: list[str] | None = None) -> PartSI:
        """Return the part in SI units; `sequence` (the project's) replaces the part's own."""
        seq = sequence if sequence is not None else self.sequence
        return PartSI(
            name=self.name,
            thickness=self.thickness * MM,
            k_factor=self.k_factor,
            flanges=tuple(FlangeSI(f.name, np.asarray(f.polygon) * MM) for f in self.flanges),
            bends=tuple(
                BendSI(
                    name=b.name,
                    parent=b.parent,
                    parent_edge=b.parent_edge,
                    child=b.child,
                    child_edge=b.child_edge,
                    included_angle=b.included_angle * DEG,
                    inner_radius=b.inner_radius * MM,
                    direction=b.direction,
                    k_factor=b.k_factor,
                )
                for b in self.bends
            ),
            sequence=None if seq is None else tuple(seq),
        )


@dataclass(frozen=True, eq=False)
class FlangeSI:
    """A flange in SI: its polygon (n, 2) [m]."""

    name: str
    polygon: NDArray[np.float64]


@dataclass(frozen=True)
class BendSI:
    """A bend in SI: included angle [rad], inner radius [m]."""

    name: str
    parent: str
    parent_edge: int
    child: str
    child_edge: int
    included_angle: float
    inner_radius: float
    direction: str
    k_factor: float | None


@dataclass(frozen=True, eq=False)
class PartSI:
    """The part in SI (m, rad): the plain spec of `SheetMetalPart.from_spec`, as a dataclass."""

    name: str
    thickness: float
    k_factor: float | None
    flanges: tuple[FlangeSI, ...]
    bends: tuple[BendSI, ...]
    sequence: tuple[str, ...] | None  # the bend order used: the project's, else the part's


class GraspSpec(StrictModel):
    """Where the gripper holds the part: a flange and an offset in its plane [mm, deg]."""

    flange: str = "1"
    offset: Annotated[list[Coordinate], Field(min_length=2, max_length=2)] | None = None
    # [x, y] mm in the flange's polygon frame; None = the polygon's centroid
    yaw: Angle = 0.0  # deg, gripper rotation about the flange normal

    def to_si(self) -> Grasp:
        """Return the grasp in SI: offset [m] (None: the centroid), yaw [rad]."""
        off = None if self.offset is None else np.asarray(self.offset, float) * MM
        return Grasp(self.flange, off, self.yaw * DEG)

    def set_si(self, grasp: Grasp, *, keep_yaw: bool = False) -> None:
        """Store `grasp` (SI) in this section (mm, deg); `keep_yaw` leaves the yaw as it is."""
        self.flange = grasp.flange
        self.offset = None if grasp.offset is None else [float(v / MM) for v in grasp.offset]
        if not keep_yaw:
            self.yaw = float(grasp.yaw / DEG)


class DieSpec(StrictModel):
    """The press brake's die: `pose` of its bend line (x along the line, z up, robot on -y)."""

    pose: Pose = Field(default_factory=Pose)
    length: Annotated[float, B.span(B.DIE_LENGTH_MM, "mm")] = 1000.0
    # mm: the longest bend line that fits


class BendingSpec(StrictModel):
    """The `bending` section (mm, deg): part, sequence, grasp, die, transfer to the pallet."""

    part: PartSpec | None = None
    part_file: str | None = None  # path to a part JSON (mm/deg), relative to the project file
    sequence: Annotated[list[str], AfterValidator(_unique)] | None = None  # overrides the part's
    grasp: GraspSpec = Field(default_factory=GraspSpec)
    die: DieSpec = Field(default_factory=DieSpec)
    retract: Vec3mm = Field(default_factory=lambda: [0.0, -250.0, 60.0])  # in the die frame
    transfer: Annotated[list[Pose], Field(max_length=B.MAX_ITEMS)] = Field(default_factory=list)
    # TCP via poses in the world
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

    def read_part(self, base_dir: Path | ProjectFolders) -> PartSpec:
        """Return the part section: inline, or read from `part_file` (relative to `base_dir`).

        ProjectError names `bending.part_file` when the file cannot be read or is invalid;
        InputError when it leaves the project's folders (`ProjectFolders.read`).
        """
        if self.part is not None:
            return self.part
        from workbench.project.io import problems_from  # io imports the models: not at the top

        assert self.part_file is not None
        p = self.part_file
        raw = ProjectFolders.of(base_dir).read(p, "bending.part_file", kind="part")[1]
        try:
            data = json.loads(raw)
        except (UnicodeDecodeError, RecursionError):
            raise ProjectError(f"bending.part_file: {p} is not UTF-8 JSON text") from None
        except json.JSONDecodeError as exc:
            raise ProjectError(f"bending.part_file: {p} is not valid JSON: {exc}") from None
        try:
            return PartSpec.model_validate(data)
        except ValidationError as exc:
            problems = [(f"bending.part_file:{path}", m) for path, m in problems_from(exc)]
            lines = "; ".join(f"{a}: {b}" for a, b in problems)
            raise ProjectError(f"bending.part_file ({p}): {lines}", problems) from None

    def to_si(self, part: PartSpec) -> BendingSI:
        """Return the section in SI units, with `part` (from `read_part`) and its sequence."""
        return BendingSI(
            part=part.to_si(self.sequence),
            grasp=self.grasp.to_si(),
            die=Die(self.die.pose.to_si(), self.die.length * MM, "bending.die.length"),
            transfer=Transfer(
                retract=np.asarray(self.retract) * MM,
                T_world_vias=np.array([p.to_si() for p in self.transfer]).reshape(-1, 4, 4),
                T_world_pallet=self.pallet.to_si(),
                where="bending",
            ),
            frames=int(self.frames),
        )


@dataclass(frozen=True, eq=False)
class BendingSI:
    """The `bending` section in SI units (m, rad): the part, the grasp, the die, the transfer."""

    part: PartSI
    grasp: Grasp
    die: Die
    transfer: Transfer
    frames: int  # transfer frames checked
