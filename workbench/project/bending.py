"""The project file's `bending` section: press-brake bending (seed 000): part, bend sequence, grasp, cell.

Millimetres and degrees. The part is given inline (`part`) or as a path to a part JSON
(`part_file`, e.g. ``parts/seed_part.json``) with the same fields, or to a CAD file: a STEP of
the bent part or a DXF flat pattern, read with the settings `part_import` (`part_import.py`). `BendingSpec.to_si`
returns the section in SI units (`BendingSI`), the only form the service uses.

Two fields hold a bend sequence, with one meaning: the part's `sequence` is the order the
part comes with (a part file may be shared by projects); the section's `sequence` is this
project's order and replaces it when given (the API's `set_sequence` writes it). The rule
both must satisfy is `workbench.sheetmetal.sequence` (every bend exactly once).

The press brake (`press`: punch, V-die, tool stations, back-gauge, ram, frame) is optional; a
bend without `inner_radius` takes the air-bending radius of the press's V-opening. The bend
process (`steps`: the grasp and tool station of each bend in sequence order, `blank`,
`regrip`, `approach`, `lift`, `follow`) has defaults that need no press.
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
from workbench.pressbrake.die import Die
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.grasp_grid import GridSettings
from workbench.pressbrake.press import PressBrake
from workbench.pressbrake.transfer import Transfer
from workbench.project import bounds as B
from workbench.project.bend_steps import BendStepSI, BendStepSpec, GraspSpec, step_problems
from workbench.project.common import Coordinate, Loc, Pose, StrictModel, Vec3mm, dotted, field_error
from workbench.project.grasp_grid import GraspGridSpec
from workbench.project.part_import import PartImportSpec, cad_kind, import_part
from workbench.project.paths import ProjectFolders
from workbench.project.press import (
    AxisRangeMM,
    BackGaugeSpec,
    DieToolSpec,
    PressFrameMM,
    PressRadiusMM,
    PressSpec,
    PressToolMM,
    PunchSpec,
    RamSpec,
    RamSpeed,
    StationSpec,
    ToolAngle,
    ToolLengthMM,
)
from workbench.project.units import DEG, MM
from workbench.sheetmetal.kfactor import MIN_R_OVER_T
from workbench.sheetmetal.sequence import sequence_problem

__all__ = [  # the models moved to `press` and `bend_steps` are still importable from here
    "AxisRangeMM",
    "BackGaugeSpec",
    "BendSI",
    "BendSpec",
    "BendStepSI",
    "BendStepSpec",
    "BendingSI",
    "BendingSpec",
    "DieSpec",
    "DieToolSpec",
    "FlangeSI",
    "FlangeSpec",
    "GraspSpec",
    "Loc",
    "PartSI",
    "PartSpec",
    "PressFrameMM",
    "PressRadiusMM",
    "PressSpec",
    "PressToolMM",
    "PunchSpec",
    "RamSpec",
    "RamSpeed",
    "StationSpec",
    "ToolAngle",
    "ToolLengthMM",
]


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


def _holes(v: list[list[list[float]]] | None) -> list[list[list[float]]] | None:
    if v is not None and len(v) > B.MAX_ITEMS:
        raise ValueError(f"at most {B.MAX_ITEMS} holes per flange, got {len(v)}")
    return v


class FlangeSpec(StrictModel):
    """A planar flange: a counter-clockwise polygon [mm] in its own frame, and its holes.

    `holes` are inner loops [mm] in the same frame, each a polygon of at least 3 points (cut
    through the sheet; `workbench.sheetmetal.holes` checks where they may lie); None: none.
    """

    name: str
    polygon: Annotated[list[list[Coordinate]], AfterValidator(_polygon)]
    holes: (
        Annotated[
            list[Annotated[list[list[Coordinate]], AfterValidator(_polygon)]],
            AfterValidator(_holes),
        ]
        | None
    ) = None


class BendSpec(StrictModel):
    """A bend joining edge `parent_edge` of flange `parent` to edge `child_edge` of `child`."""

    name: str
    parent: str
    parent_edge: Annotated[int, Field(ge=0, le=B.MAX_INDEX)]
    child: str
    child_edge: Annotated[int, Field(ge=0, le=B.MAX_INDEX)]
    included_angle: Annotated[float, AfterValidator(_included)]  # deg, (0, 180); 180 = flat
    inner_radius: Annotated[float, B.span(B.INNER_RADIUS_MM, "mm")] | None = None
    # mm, >= 0.5 x thickness; None: the air-bending radius of the press's V-opening
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
            if b.inner_radius is not None and b.inner_radius < MIN_R_OVER_T * self.thickness - 1e-9:
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

    @classmethod
    def checked(cls, data: object, field: str, shown: str) -> PartSpec:
        """Return the part `data` (parsed JSON, mm/deg) validated; ProjectError names each bad
        field as `field`:path (``bending.part_file:flanges[1].polygon``), `shown` the source."""
        from workbench.project.io import problems_from  # io imports the models: not at the top

        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            problems = [(f"{field}:{path}", m) for path, m in problems_from(exc)]
            lines = "; ".join(f"{a}: {b}" for a, b in problems)
            raise ProjectError(f"{shown}: {lines}", problems) from None

    def radius_problem(
        self, air_radius: float | None, v_opening: float | None = None
    ) -> str | None:
        """Return why a bend without `inner_radius` cannot take `air_radius` [m] (None: no
        press), or None; `v_opening` [m] is the V-opening it came from, for the message."""
        if air_radius is None:
            return "give inner_radius, or a press (bending.press) whose V-opening sets it"
        r, lo = air_radius / MM, MIN_R_OVER_T * self.thickness
        if r >= lo - 1e-9:
            return None
        src = f"the air-bending radius is {r:.4g} mm"
        if v_opening is not None:
            src = (
                f"the die's V-opening {v_opening / MM:g} mm gives {r:.4g} mm "
                f"({100 * air_radius / v_opening:.3g} % of it)"
            )
        return (
            f"not given, and {src}: below Table 1's minimum {MIN_R_OVER_T} x thickness = "
            f"{lo:g} mm; use a wider die or set inner_radius"
        )

    def to_si(
        self,
        sequence: list[str] | None = None,
        *,
        air_radius: float | None = None,
        v_opening: float | None = None,
        where: str = "bending.part.",
    ) -> PartSI:
        """Return the part in SI units; `sequence` (the project's) replaces the part's own.

        A bend without `inner_radius` gets `air_radius` [m] (the press's air-bending radius of
        its V-opening `v_opening` [m]); ProjectError names ``{where}bends[i].inner_radius``
        when there is none or it is below Table 1's minimum.
        """
        seq = sequence if sequence is not None else self.sequence
        radii: list[float] = []
        for i, b in enumerate(self.bends):
            if b.inner_radius is not None:
                radii.append(b.inner_radius * MM)
                continue
            problem = self.radius_problem(air_radius, v_opening)
            if problem is not None:
                field = f"{where}bends[{i}].inner_radius"
                raise ProjectError(f"{problem}", [(field, problem)], field=field)
            assert air_radius is not None
            radii.append(float(air_radius))
        return PartSI(
            name=self.name,
            thickness=self.thickness * MM,
            k_factor=self.k_factor,
            flanges=tuple(
                FlangeSI(
                    f.name,
                    np.asarray(f.polygon) * MM,
                    tuple(np.asarray(h) * MM for h in f.holes or ()),
                )
                for f in self.flanges
            ),
            bends=tuple(
                BendSI(
                    name=b.name,
                    parent=b.parent,
                    parent_edge=b.parent_edge,
                    child=b.child,
                    child_edge=b.child_edge,
                    included_angle=b.included_angle * DEG,
                    inner_radius=r,
                    direction=b.direction,
                    k_factor=b.k_factor,
                )
                for b, r in zip(self.bends, radii, strict=True)
            ),
            sequence=None if seq is None else tuple(seq),
        )


@dataclass(frozen=True, eq=False)
class FlangeSI:
    """A flange in SI: its polygon (n, 2) [m] and its holes, each (k, 2) [m]."""

    name: str
    polygon: NDArray[np.float64]
    holes: tuple[NDArray[np.float64], ...] = ()


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


class DieSpec(StrictModel):
    """The press brake's die: `pose` of its bend line (x along the line, z up, robot on -y)."""

    pose: Pose = Field(default_factory=Pose)
    length: Annotated[float, B.span(B.DIE_LENGTH_MM, "mm")] = 1000.0
    # mm: the longest bend line that fits


class BendingSpec(StrictModel):
    """The `bending` section (mm, deg): part, sequence, grasp, die, press, bend process,
    transfer to the pallet."""

    part: PartSpec | None = None
    part_file: str | None = None  # path to a part JSON (mm/deg), relative to the project file,
    # or a CAD file: a STEP of the bent part (.step/.stp) or a DXF flat pattern (.dxf)
    part_import: PartImportSpec | None = None  # what a CAD part file does not say (mm)
    sequence: Annotated[list[str], AfterValidator(_unique)] | None = None  # overrides the part's
    grasp: GraspSpec = Field(default_factory=GraspSpec)
    die: DieSpec = Field(default_factory=DieSpec)
    press: PressSpec | None = None  # None: no press model
    steps: Annotated[list[BendStepSpec], Field(max_length=B.MAX_ITEMS)] | None = None
    # one per bend in sequence order; None: `grasp` for every bend, the first station
    blank: Pose = Field(default_factory=Pose)  # the flat blank's part frame on the stack (world)
    regrip: Pose = Field(default_factory=Pose)  # where the part lies on the regrip station (world)
    approach: Vec3mm = Field(default_factory=lambda: [0.0, -80.0, 30.0])
    # mm, die frame: offset of the pose before the part slides against the back-gauge
    lift: Annotated[float, B.span(B.LIFT_MM_OPEN, "mm", lo_open=True)] = 80.0
    # mm: vertical approach / retreat at the blank stack, the regrip station and the pallet
    grasp_grid: GraspGridSpec = Field(default_factory=GraspGridSpec)  # the search's candidates
    follow: bool = True  # the robot follows the rising flange (False: releases, re-grips)
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
        if self.part_import is not None and cad_kind(self.part_file) is None:
            raise ValueError(
                "part_import: only for a CAD part_file (.step, .stp or .dxf); remove it, or"
                " name a CAD file in part_file"
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

    @model_validator(mode="after")
    def _process(self) -> BendingSpec:
        problems = self._step_problems(self.part)
        if self.part is not None:
            problems = self._radius_problems(self.part) + problems
        if problems:
            raise field_error(problems)
        return self

    def sequence_of(self, part: PartSpec) -> list[str]:
        """Return the bend order in use: the section's, else the part's, else the bends'."""
        if self.sequence is not None:
            return list(self.sequence)
        if part.sequence is not None:
            return list(part.sequence)
        return [b.name for b in part.bends]

    def _radius_problems(self, part: PartSpec) -> list[tuple[Loc, str, object]]:
        air = None if self.press is None else self.press.air_radius()
        v = None if self.press is None else self.press.die.v_opening * MM
        out: list[tuple[Loc, str, object]] = []
        for i, b in enumerate(part.bends):
            problem = None if b.inner_radius is not None else part.radius_problem(air, v)
            if problem is not None:
                out.append((("part", "bends", i, "inner_radius"), problem, None))
        return out

    def _step_problems(self, part: PartSpec | None) -> list[tuple[Loc, str, object]]:
        """Return the problems of `steps` (locations in this section): unknown stations; with
        `part`, bends not in sequence order and unknown flanges."""
        if self.steps is None:
            return []
        stations = ["S1"] if self.press is None else self.press.station_names()
        if part is None:
            return step_problems(self.steps, stations)
        flanges = [f.name for f in part.flanges]
        return step_problems(self.steps, stations, self.sequence_of(part), flanges)

    def read_part(self, base_dir: Path | ProjectFolders) -> PartSpec:
        """Return the part section: inline, or read from `part_file` (relative to `base_dir`):
        a part JSON, or a STEP / DXF file recognised with `part_import` (`project.part_import`).

        ProjectError names `bending.part_file` when the file cannot be read or is invalid
        (MeshError, naming the face, when a STEP solid is not sheet metal); InputError when it
        leaves the project's folders (`ProjectFolders.read`).
        """
        if self.part is not None:
            return self.part

        assert self.part_file is not None
        p = self.part_file
        raw = ProjectFolders.of(base_dir).read(p, "bending.part_file", kind="part")[1]
        if cad_kind(p) is not None:
            return import_part(raw, p, self.part_import)
        try:
            data = json.loads(raw)
        except (UnicodeDecodeError, RecursionError):
            raise ProjectError(f"bending.part_file: {p} is not UTF-8 JSON text") from None
        except json.JSONDecodeError as exc:
            raise ProjectError(f"bending.part_file: {p} is not valid JSON: {exc}") from None
        return PartSpec.checked(data, "bending.part_file", f"bending.part_file ({p})")

    def _die_si(self) -> Die:
        return Die(self.die.pose.to_si(), self.die.length * MM, "bending.die.length")

    def press_si(self) -> PressBrake | None:
        """Return the press brake in SI (None: the section has no press model)."""
        return None if self.press is None else self.press.to_si(self._die_si())

    def set_steps_si(self, sequence: list[str], steps: list[BendStepSI]) -> None:
        """Store a plan: the bend order and, per bend, its grasp (SI: m, rad) and station."""
        self.steps = None  # the old steps would not match the new order
        self.sequence = [str(s) for s in sequence]
        specs = []
        for st in steps:
            grasp = GraspSpec(flange=st.grasp.flange)
            grasp.set_si(st.grasp)
            grasp.yaw = round(grasp.yaw, 9)
            if grasp.offset is not None:
                grasp.offset = [round(v, 9) for v in grasp.offset]
            specs.append(BendStepSpec(bend=st.bend, grasp=grasp, station=st.station))
        self.steps = specs

    def to_si(self, part: PartSpec) -> BendingSI:
        """Return the section in SI units, with `part` (from `read_part`) and its sequence.

        The press is built first: a bend without `inner_radius` takes its air-bending radius.
        ProjectError names the field when a bend has no radius (no press), or a step names a
        bend out of sequence order, an unknown flange or an unknown station.
        """
        die = self._die_si()
        press = self.press_si()
        part_si = part.to_si(
            self.sequence,
            air_radius=None if self.press is None else self.press.air_radius(),
            v_opening=None if press is None else press.die.v_opening,
            where="bending.part." if self.part is not None else "bending.part_file:",
        )
        found = [(f"bending.{dotted(loc)}", m) for loc, m, _ in self._step_problems(part)]
        if found:
            raise ProjectError("; ".join(f"{a}: {b}" for a, b in found), found)
        first = "S1" if press is None else press.stations[0].name
        steps = None
        if self.steps is not None:
            steps = tuple(st.to_si(first) for st in self.steps)
        return BendingSI(
            part=part_si,
            grasp=self.grasp.to_si(),
            die=die,
            transfer=Transfer(
                retract=np.asarray(self.retract) * MM,
                T_world_vias=np.array([p.to_si() for p in self.transfer]).reshape(-1, 4, 4),
                T_world_pallet=self.pallet.to_si(),
                where="bending",
            ),
            frames=int(self.frames),
            press=press,
            steps=steps,
            blank=self.blank.to_si(),
            regrip=self.regrip.to_si(),
            approach=np.asarray(self.approach, float) * MM,
            lift=self.lift * MM,
            follow=bool(self.follow),
            grasp_grid=self.grasp_grid.to_si(),
        )


@dataclass(frozen=True, eq=False)
class BendingSI:
    """The `bending` section in SI units (m, rad): the part, the grasp, the die, the transfer,
    the press and the bend process."""

    part: PartSI
    grasp: Grasp
    die: Die
    transfer: Transfer
    frames: int  # transfer frames checked
    press: PressBrake | None  # None: no press model
    steps: tuple[BendStepSI, ...] | None  # one per bend in sequence order; None: not given
    blank: NDArray[np.float64]  # (4, 4) T_world_part of the flat blank on the stack [m]
    regrip: NDArray[np.float64]  # (4, 4) T_world_part on the regrip station [m]
    approach: NDArray[np.float64]  # (3,) [m] in the die frame, before the back-gauge
    lift: float  # [m] vertical approach / retreat at the stack, regrip station and pallet
    follow: bool  # the robot follows the rising flange during the bend
    grasp_grid: GridSettings  # the sequence search's candidate grasps
