"""The project file's `bending.press` section: the press brake (mm, deg, mm/s).

The punch (a profile, or a straight punch), the V-die, the tool stations along the bed, the
back-gauge, the ram, the air-bending radius ratio and the frame. `PressSpec.to_si` returns the
press in SI units (`workbench.pressbrake.press.PressBrake`), placed by the die's bend line.
"""

from __future__ import annotations

from typing import Annotated

import numpy as np
import shapely
from numpy.typing import NDArray
from pydantic import AfterValidator, Field, model_validator

from workbench.errors import InputError
from workbench.geometry.polygon import signed_area
from workbench.motion.trajectory import MAX_SAMPLES
from workbench.pressbrake.airbend import air_bend_radius
from workbench.pressbrake.cycle_path import FRAME_DT
from workbench.pressbrake.die import Die
from workbench.pressbrake.press import (
    BackGauge,
    DieTool,
    PressBrake,
    Punch,
    Ram,
    Station,
    punch_profile,
)
from workbench.project import bounds as B
from workbench.project.common import Coordinate, Loc, StrictModel, field_error
from workbench.project.units import DEG, MM

PressToolMM = Annotated[float, B.span(B.PRESS_TOOL_MM, "mm")]
PressRadiusMM = Annotated[float, B.span(B.PRESS_RADIUS_MM, "mm")]
PressFrameMM = Annotated[float, B.span(B.PRESS_FRAME_MM, "mm")]
ToolLengthMM = Annotated[float, B.span(B.DIE_LENGTH_MM, "mm")]
RamSpeed = Annotated[float, B.span(B.RAM_SPEED_MM_S_OPEN, "mm/s", lo_open=True)]  # mm/s


def _below_flat(v: float) -> float:
    if not v < 180.0:
        raise ValueError(f"must be < 180 deg (180 is flat), got {v:g}")
    return v


ToolAngle = Annotated[  # deg, (0, 180): a tool's included angle
    float, B.span(B.PRESS_ANGLE_DEG_OPEN, "deg", lo_open=True), AfterValidator(_below_flat)
]


def _sized(n: int, what: str) -> AfterValidator:
    def check(v: list[float]) -> list[float]:
        if len(v) != n:
            raise ValueError(f"expected {n} numbers {what}, got {len(v)}")
        return v

    return AfterValidator(check)


def _axis_range(v: list[float]) -> list[float]:
    if len(v) != 2 or v[0] > v[1]:
        raise ValueError(f"expected [min, max] in mm with min <= max, got {v}")
    return v


AxisRangeMM = Annotated[list[Coordinate], AfterValidator(_axis_range)]  # [min, max] mm


def _punch_profile(v: list[list[float]]) -> list[list[float]]:
    if len(v) < 3 or len(v) > B.MAX_ITEMS or any(len(p) != 2 for p in v):
        raise ValueError(
            f"expected at least 3 points [y, z] in mm (counter-clockwise, tip at [0, 0]), "
            f"got {len(v)} point(s)"
        )
    p = np.asarray(v, float)
    if not shapely.Polygon(p).is_valid:
        raise ValueError("must be a simple polygon: its edges cross or it has no area")
    if signed_area(p) <= 0:
        raise ValueError(
            "must be counter-clockwise (y to the right, z up, seen from +x); "
            "these points go clockwise: reverse them"
        )
    z_min = float(p[:, 1].min())
    if abs(z_min) > 1e-6:
        raise ValueError(f"the tip must be the lowest point, at z = 0 mm; got min z = {z_min:g} mm")
    if not np.any(np.all(np.abs(p) <= 1e-6, axis=1)):
        low = sorted(float(y) for y in p[np.abs(p[:, 1]) <= 1e-6, 0])
        raise ValueError(
            f"the tip must be a vertex at [0, 0]; the points at z = 0 have y = {low} mm"
        )
    return v


class PunchSpec(StrictModel):
    """The punch: a profile [[y, z], ...] mm (CCW, tip at [0, 0]) or a straight punch of
    `width` x `height` whose flanks meet at `tip_angle` [deg]; `tip_radius` [mm]."""

    profile: Annotated[list[list[Coordinate]], AfterValidator(_punch_profile)] | None = None
    width: PressToolMM = 26.0
    height: PressToolMM = 120.0
    tip_angle: ToolAngle = 86.0  # deg, the sharpest bend it makes (also with a profile)
    tip_radius: PressRadiusMM = 1.0

    @model_validator(mode="after")
    def _flanks_fit(self) -> PunchSpec:
        if self.profile is None:
            try:
                self.profile_si()
            except InputError as exc:
                raise ValueError(
                    f"{exc.detail}; make the punch taller or narrower, "
                    "its tip angle wider, or give its profile"
                ) from None
        return self

    def profile_si(self) -> NDArray[np.float64]:
        """Return the profile (n, 2) [m] (y, z): the given one, or the straight punch's."""
        if self.profile is not None:
            return np.asarray(self.profile, float) * MM
        return punch_profile(self.width * MM, self.height * MM, self.tip_angle * DEG)


class DieToolSpec(StrictModel):
    """The V-die: `v_opening` < `width`, `shoulder_radius`, V `angle` [deg], block `width` x
    `height` [mm]."""

    v_opening: PressToolMM = 12.0
    shoulder_radius: PressRadiusMM = 1.0
    angle: ToolAngle = 86.0
    width: PressToolMM = 40.0
    height: PressToolMM = 60.0

    @model_validator(mode="after")
    def _groove_fits(self) -> DieToolSpec:
        problems: list[tuple[Loc, str, object]] = []
        if self.v_opening >= self.width:
            problems.append(
                (
                    ("v_opening",),
                    f"must be < the die's width {self.width:g} mm, got {self.v_opening:g}",
                    self.v_opening,
                )
            )
        depth = self.v_opening / 2.0 / np.tan(self.angle * DEG / 2.0)
        if depth >= self.height:
            problems.append(
                (
                    ("angle",),
                    f"a {self.angle:g} deg V {self.v_opening:g} mm wide is {depth:.1f} mm deep, "
                    f"not within the die's height {self.height:g} mm; widen the angle or make "
                    "the die taller",
                    self.angle,
                )
            )
        if problems:
            raise field_error(problems)
        return self


class StationSpec(StrictModel):
    """A tool station: punch and die segments [mm] centred at `x` [mm] along the bed."""

    name: str
    x: Coordinate = 0.0
    punch_length: ToolLengthMM
    die_length: ToolLengthMM


class BackGaugeSpec(StrictModel):
    """Back-gauge fingers (depth y, width x, height z) [mm] and the ranges [min, max] [mm] of
    its axes: X (stop depth from the bend line), R (finger bottom over the die), Z (along the bed)."""

    finger: Annotated[list[PressToolMM], _sized(3, "[depth, width, height] in mm")] = Field(
        default_factory=lambda: [20.0, 30.0, 40.0]
    )
    x: AxisRangeMM = Field(default_factory=lambda: [5.0, 600.0])
    r: AxisRangeMM = Field(default_factory=lambda: [0.0, 100.0])
    z: AxisRangeMM = Field(default_factory=lambda: [-400.0, 400.0])
    fingers: Annotated[int, B.span(B.BACKGAUGE_FINGERS)] = 2


class RamSpec(StrictModel):
    """The ram: `open` gap [mm] over the sheet, approach / bending / return speeds [mm/s]."""

    open: Annotated[float, B.span(B.RAM_OPEN_MM_OPEN, "mm", lo_open=True)] = 150.0
    approach_speed: RamSpeed = 100.0
    bending_speed: RamSpeed = 10.0
    return_speed: RamSpeed = 100.0


class PressSpec(StrictModel):
    """The press brake (mm, deg, mm/s): tools, stations, back-gauge, ram, air bending, frame."""

    punch: PunchSpec = Field(default_factory=PunchSpec)
    die: DieToolSpec = Field(default_factory=DieToolSpec)
    stations: Annotated[list[StationSpec], Field(min_length=1, max_length=B.MAX_ITEMS)] | None = (
        None  # None: one station "S1" at x 0, both tools as long as bending.die.length
    )
    backgauge: BackGaugeSpec = Field(default_factory=BackGaugeSpec)
    ram: RamSpec = Field(default_factory=RamSpec)
    radius_ratio: Annotated[float, B.span(B.AIR_RADIUS_RATIO_OPEN, lo_open=True)] = 0.16
    # inner radius / V-opening in air bending
    tolerance: Annotated[float, B.span(B.CONTACT_TOLERANCE_MM_OPEN, "mm", lo_open=True)] = 0.5
    frame_gap: PressFrameMM = 100.0
    housing: Annotated[list[PressFrameMM], _sized(2, "[depth, width] in mm")] = Field(
        default_factory=lambda: [300.0, 80.0]
    )
    beam_height: PressFrameMM = 250.0

    @model_validator(mode="after")
    def _ram_frames(self) -> PressSpec:
        """Refuse a ram speed whose stroke takes more checked frames of the cycle
        (`pressbrake.cycle_path.FRAME_DT` apart) than one trajectory may have
        (`motion.trajectory.MAX_SAMPLES`), naming the least speed that fits: the work is
        counted here, before a cycle allocates its frames."""
        longest = FRAME_DT * (MAX_SAMPLES - 2)  # [s] of one stroke
        v_depth = self.die.v_opening / 2.0 / np.tan(self.die.angle * DEG / 2.0)
        strokes = {
            "approach_speed": self.ram.open,
            "bending_speed": v_depth,
            "return_speed": self.ram.open + v_depth,
        }
        problems: list[tuple[Loc, str, object]] = []
        for name, stroke in strokes.items():
            speed = getattr(self.ram, name)
            if stroke / speed > longest:
                problems.append(
                    (
                        ("ram", name),
                        f"{speed:g} mm/s takes {stroke / speed:.3g} s over its {stroke:.3g} mm"
                        f" stroke: {stroke / speed / FRAME_DT:.3g} checked frames every"
                        f" {FRAME_DT:g} s, above the budget of {MAX_SAMPLES:,}"
                        " (workbench.motion.trajectory.MAX_SAMPLES); use at least"
                        f" {stroke / longest:.2g} mm/s",
                        speed,
                    )
                )
        if problems:
            raise field_error(problems)
        return self

    @model_validator(mode="after")
    def _unique_stations(self) -> PressSpec:
        seen: set[str] = set()
        for j, st in enumerate(self.stations or []):
            if st.name in seen:
                raise field_error(
                    [
                        (
                            ("stations", j, "name"),
                            f"repeats the station {st.name!r}; names must be unique",
                            st.name,
                        )
                    ]
                )
            seen.add(st.name)
        return self

    def station_names(self) -> list[str]:
        """Return the names of the tool stations (["S1"] when `stations` is None)."""
        return ["S1"] if self.stations is None else [st.name for st in self.stations]

    def air_radius(self) -> float:
        """Return the inner radius [m] an air bend takes in this press's V-die."""
        return air_bend_radius(self.die.v_opening * MM, self.radius_ratio)

    def to_si(self, die: Die) -> PressBrake:
        """Return the press in SI units, placed by the bend line of `die` (its length [m] is
        the tools' length when `stations` is None)."""
        bg, ram = self.backgauge, self.ram
        if self.stations is None:
            stations: tuple[Station, ...] = (Station("S1", 0.0, die.length, die.length),)
        else:
            stations = tuple(
                Station(st.name, st.x * MM, st.punch_length * MM, st.die_length * MM)
                for st in self.stations
            )
        f = [v * MM for v in bg.finger]
        return PressBrake(
            T_world_die=np.asarray(die.T_world_die, float),
            punch=Punch(
                self.punch.profile_si(), self.punch.tip_radius * MM, self.punch.tip_angle * DEG
            ),
            die=DieTool(
                self.die.v_opening * MM,
                self.die.shoulder_radius * MM,
                self.die.angle * DEG,
                self.die.width * MM,
                self.die.height * MM,
            ),
            stations=stations,
            backgauge=BackGauge(
                finger=(f[0], f[1], f[2]),
                x_range=(bg.x[0] * MM, bg.x[1] * MM),
                r_range=(bg.r[0] * MM, bg.r[1] * MM),
                z_range=(bg.z[0] * MM, bg.z[1] * MM),
                fingers=int(bg.fingers),
            ),
            ram=Ram(
                ram.open * MM,
                ram.approach_speed * MM,
                ram.bending_speed * MM,
                ram.return_speed * MM,
            ),
            radius_ratio=float(self.radius_ratio),
            tolerance=self.tolerance * MM,
            frame_gap=self.frame_gap * MM,
            housing=(self.housing[0] * MM, self.housing[1] * MM),
            beam_height=self.beam_height * MM,
            where="bending.press",
        )
