"""Whether a vacuum cup holds the part: suction force against weight and acceleration.

SI units. The cup pulls with F = Δp · A (pressure difference [Pa] times the cup's area
[m²]); it must carry the part's weight and the robot's peak acceleration with a safety
factor: F ≥ m · (g + a) · S (load case I, "suction cup horizontal, direction of force
vertical", of Schmalz's "Theoretical Holding Force of a Suction Cup", schmalz.com, vacuum
knowledge > system design > calculation example: "The safety factor has a minimum value of 1.5
for smooth and dense workpieces").

`VACUUM_DIFFERENCE` = 60 kPa: Schmalz's glossary, "Holding force" (schmalz.com/en/glossary):
"It is usual to state the holding force of a suction cup with a relative vacuum of 60%" (60 % of
the 101.3 kPa atmosphere, rounded down to 60 kPa). `DENSITY` = 7850 kg/m³: structural steel
(EN 1991-1-1 Table A.4 gives 77–78.5 kN/m³). Both are defaults; a project that knows better
passes its own.
"""

from __future__ import annotations

from dataclasses import dataclass

from workbench.errors import InputError
from workbench.pressbrake.grasp_footprint import Footprint
from workbench.sheetmetal.part import SheetMetalPart

G = 9.80665
"""Standard gravity [m/s²] (CGPM 1901)."""
VACUUM_DIFFERENCE = 60e3
"""Pressure difference across the cup [Pa] (see the module docstring)."""
SAFETY = 1.5
"""Safety factor on the needed force (see the module docstring)."""
DENSITY = 7850.0
"""Density of the sheet [kg/m³] (steel; see the module docstring)."""


@dataclass(frozen=True)
class Holding:
    """Suction force `available` and `needed` [N] for a part of `mass` [kg] at `accel` [m/s²]."""

    available: float
    needed: float
    mass: float
    accel: float

    @property
    def holds(self) -> bool:
        """Return whether the cup holds (available >= needed)."""
        return self.available >= self.needed

    def report(self) -> str:
        """Return a line for the plan: the two forces and the verdict."""
        verdict = "holds" if self.holds else "does NOT hold"
        return (
            f"vacuum cup {verdict}: {self.available:.1f} N available (Δp × area) against "
            f"{self.needed:.1f} N needed (part {self.mass:.3g} kg × (g + {self.accel:.3g} m/s²) "
            f"× safety {SAFETY:g})"
        )


def holding(
    part: SheetMetalPart,
    footprint: Footprint,
    peak_accel: float,
    *,
    vacuum_difference: float = VACUUM_DIFFERENCE,
    density: float = DENSITY,
    safety: float = SAFETY,
) -> Holding:
    """Return the holding check of `footprint` (one cup) lifting `part` at `peak_accel` [m/s²]."""
    for name, v in (("peak_accel", peak_accel), ("vacuum_difference", vacuum_difference)):
        if not (v >= 0 and v < float("inf")):
            raise InputError(f"must be finite and >= 0, got {v!r}", field=name)
    mass = part.blank_area() * part.thickness * density
    return Holding(
        available=vacuum_difference * footprint.area,
        needed=mass * (G + peak_accel) * safety,
        mass=mass,
        accel=peak_accel,
    )
