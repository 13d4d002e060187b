"""The project file's `polishing` section: polishing free-form surfaces (seed 004).

Millimetres, degrees, newtons and seconds, as in the rest of the file; the contact
stiffness is in N/m (seed 004 prints N/m², a typo). The workpiece is a mesh file (STL,
OBJ or PLY) or a STEP file relative to the project file, placed in the world at `pose`;
`faces` picks the faces of a STEP solid to polish (the rest of the solid is an obstacle).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Annotated, Any

import numpy as np
from numpy.typing import NDArray
from pydantic import Field, ValidationError, ValidationInfo, field_validator, model_validator

from workbench.errors import InputError
from workbench.polishing.choices import MeshUnits, Pattern
from workbench.polishing.force_control import HybridForceParams
from workbench.polishing.orientation import instability_message
from workbench.project import bounds as B
from workbench.project.common import Pose, Seed, StrictModel
from workbench.project.units import MM, pose_to_matrix

Gain = Annotated[float, B.span(B.GAIN)]  # >= 0, in the gain's own unit
F64 = NDArray[np.float64]


class OrientationLoopSpec(StrictModel):
    """The tool-axis orientation loop (seed 004, eq. 7): PID on the tilt of the tool z from
    the surface normal, ω = ω_d + kp e + kd de/dt + ki ∫ e dt (e the tilt's rotation vector).

    A constant tilt decays with the time constant (1 + kd)/kp when ki = 0. The gains are
    rates per angle (unit-free in deg or rad); the speed limit is in deg/s. Gains that make
    the loop unstable at the controller's rate and latency are refused (`ForceControllerSpec`)."""

    enabled: bool = True  # off: the tool z is held along the planned normal
    kp: Gain = 40.0  # [1/s]
    kd: Gain = 0.05  # [-] on the error rate
    ki: Gain = 0.0  # [1/s²]
    max_speed: Annotated[float, B.span(B.ANGULAR_SPEED_DEG_S, "deg/s")] = 90.0
    # [deg/s] limit on the commanded angular velocity

    @model_validator(mode="after")
    def _some_gain(self) -> OrientationLoopSpec:
        if self.enabled and self.kp == 0 and self.ki == 0:
            raise ValueError(
                "kp and ki are both 0: the orientation loop would not correct a tilt; give "
                "kp > 0 [1/s] or ki > 0 [1/s²], or set enabled to false"
            )
        return self


class ForceControllerSpec(StrictModel):
    """Gains of the force/position hybrid controller (seed 004, eqs. 5-7) and robot limits."""

    control_rate: Annotated[float, B.span(B.CONTROL_RATE_HZ, "Hz")] = 250.0
    # [Hz] controller and speedl command rate
    latency: Annotated[float, B.span(B.LATENCY_MS, "ms")] = 8.0  # [ms] from command to motion
    kpp: Gain = 8.0  # [1/s] position loop P gain
    kpd: Gain = 0.05  # [-] position loop D gain (on the error rate)
    kfp: Gain = 6.0  # [(mm/s)/N] force loop P gain
    kfi: Gain = 50.0  # [(mm/s)/(N s)] force loop I gain
    max_speed: Annotated[float, B.span(B.FEED_MM_S, "mm/s")] = 250.0
    # [mm/s] speed limit of the commanded TCP velocity
    max_accel: Annotated[float, B.span(B.TCP_ACCEL_MM_S2, "mm/s²")] = 4000.0
    # [mm/s²] limit on the change of the command
    orientation: OrientationLoopSpec = Field(default_factory=OrientationLoopSpec)

    @field_validator("orientation")
    @classmethod
    def _stable_orientation(
        cls, v: OrientationLoopSpec, info: ValidationInfo
    ) -> OrientationLoopSpec:
        rate, latency = info.data.get("control_rate"), info.data.get("latency")
        if not v.enabled or rate is None or latency is None:
            return v  # off, or the rate or latency is already refused by its own field
        cycles = rate * latency * 1e-3
        if cycles > B.LATENCY_MAX_CYCLES:
            raise ValueError(
                f"latency {latency:g} ms at control_rate {rate:g} Hz is {cycles:.3g} control "
                f"cycles, above the {B.LATENCY_MAX_CYCLES} the stability check handles "
                "(workbench.project.bounds.LATENCY_MAX_CYCLES); lower the latency or the rate"
            )
        msg = instability_message(v.kp, v.kd, v.ki, rate, latency * 1e-3, ("kp", "kd", "ki"))
        if msg is not None:
            raise ValueError(msg)
        return v

    @model_validator(mode="after")
    def _some_force_gain(self) -> ForceControllerSpec:
        if self.kfp == 0 and self.kfi == 0:
            raise ValueError(
                "kfp and kfi are both 0: the force loop would do nothing; give kfp > 0 "
                "[(mm/s)/N] or kfi > 0 [(mm/s)/(N s)]"
            )
        return self


class ContactSpec(StrictModel):
    """The compliant contact of the simulation: spring-damper, friction, form error, sensor."""

    stiffness: Annotated[float, B.span(B.STIFFNESS_N_M, "N/m")] = 5000.0
    # k [N/m]; the force offset is D = F/k
    damping: Annotated[float, B.span(B.DAMPING_N_S_M, "N s/m")] = 10.0  # c [N s/m]
    friction: Annotated[float, B.span(B.FRICTION)] = 0.3  # mu [-], Coulomb
    lateral_stiffness: Annotated[float, B.span(B.STIFFNESS_N_M, "N/m")] = 2.0e5
    # [N/m] tool tip compliance against friction
    form_error: Annotated[float, B.span(B.FORM_ERROR_MM, "mm")] = 0.3
    # [mm] amplitude of the surface form error along the normal
    form_wavelength: Annotated[float, B.span(B.WAVELENGTH_MM, "mm")] = 60.0
    # [mm] its wavelength along the path
    noise_std: Annotated[float, B.span(B.NOISE_N, "N")] = 0.5
    # [N] force sensor noise, standard deviation
    filter_cutoff: Annotated[float, B.span(B.CUTOFF_HZ, "Hz")] = 40.0
    # [Hz] first-order low-pass of the force sensor
    seed: Seed = 0  # noise generator seed


class PolishingSpec(StrictModel):
    """The `polishing` section (mm, deg, N, s)."""

    workpiece: str  # mesh file (STL, OBJ, PLY) or STEP, relative to the project file
    units: MeshUnits = "mm"  # units of the mesh file
    faces: list[int] | None = None
    # a STEP solid's faces to polish (indices, `workbench polishing-faces`); None: the whole file
    pose: Pose = Field(default_factory=Pose)  # workpiece frame in the world
    pattern: Pattern = "spiral"
    step: Annotated[float, B.span(B.PATH_STEP_MM, "mm")] = 2.0
    # [mm] chord between consecutive path points
    spacing: Annotated[float, B.span(B.PASS_SPACING_MM, "mm")] = 10.0
    # [mm] distance between neighbouring passes on the surface
    tool_radius: Annotated[float, B.span(B.TOOL_RADIUS_MM, "mm")] = 6.0
    # [mm] radius of the polishing pad (coverage)
    lead_height: Annotated[float, B.span(B.LEAD_HEIGHT_MM, "mm")] = 10.0
    # [mm] height of the first lead-in / last lead-out point
    n_lead: Annotated[int, Field(ge=1, le=50)] = 3  # lead-in and lead-out points each
    feed: Annotated[float, B.span(B.FEED_MM_S, "mm/s")] = 10.0  # [mm/s] feed along the path
    dwell: Annotated[float, B.span(B.DWELL_S, "s")] = 0.5
    # [s] at the first point before the feed starts (force build-up)
    max_force: Annotated[float, B.span(B.FORCE_N, "N")] = 100.0  # [N] the tool's force limit
    force: float = 20.0  # [N] target contact force, in (0, max_force]
    controller: ForceControllerSpec = Field(default_factory=ForceControllerSpec)
    contact: ContactSpec = Field(default_factory=ContactSpec)

    @field_validator("force")
    @classmethod
    def _force_in_range(cls, v: float, info: ValidationInfo) -> float:
        limit = info.data.get("max_force")
        if not v >= B.FORCE_N[0]:
            raise ValueError(
                f"must be > 0 N (at least {B.FORCE_N[0]:g} N, the target contact force), got {v:g}"
            )
        if limit is not None and v > limit:
            raise ValueError(
                f"{v:g} N is above the tool's limit max_force = {limit:g} N; give a force in "
                f"(0, {limit:g}] N or raise max_force if the tool allows it"
            )
        return v

    @field_validator("faces")
    @classmethod
    def _some_faces(cls, v: list[int] | None) -> list[int] | None:
        if v is None:
            return v
        if not v:
            raise ValueError(
                "is empty: pick at least one face of the STEP solid (indices from `workbench "
                "polishing-faces` or the Polishing tab), or remove the field to polish the "
                "whole file"
            )
        if min(v) < 0:
            raise ValueError(f"face indices count from 0, got {min(v)}")
        if len(set(v)) != len(v):
            twice = sorted({i for i in v if v.count(i) > 1})
            raise ValueError(f"face {twice[0]} is picked twice; list each face once")
        return v

    @model_validator(mode="after")
    def _feed_below_limit(self) -> PolishingSpec:
        if self.feed > self.controller.max_speed:
            raise ValueError(
                f"feed = {self.feed:g} mm/s is above controller.max_speed = "
                f"{self.controller.max_speed:g} mm/s; lower the feed"
            )
        if self.force > self.max_force:
            raise ValueError(
                f"force = {self.force:g} N is above the tool's limit max_force = "
                f"{self.max_force:g} N; give a force in (0, {self.max_force:g}] N"
            )
        return self

    # -- SI -----------------------------------------------------------------------------
    def to_si(self) -> PolishingSI:
        """Return the section in SI (m, rad, s, N), checked as a whole.

        The section is validated again first: `validate_assignment` checks one field at a
        time, so gains changed one by one on the live model can make a loop unstable that
        no single field refuses. Raises `InputError` naming the field (as on load)."""
        s = _validated(self.model_dump())
        c, k, o = s.controller, s.contact, s.controller.orientation
        return PolishingSI(
            workpiece=s.workpiece,
            units=s.units,
            faces=None if s.faces is None else tuple(s.faces),
            T_world_workpiece=pose_to_matrix(s.pose),
            pattern=s.pattern,
            step=s.step * MM,
            spacing=s.spacing * MM,
            tool_radius=s.tool_radius * MM,
            lead_height=s.lead_height * MM,
            n_lead=s.n_lead,
            feed=s.feed * MM,
            dwell=s.dwell,
            max_force=s.max_force,
            force=s.force,
            control=HybridForceParams(
                control_rate=c.control_rate,
                latency=c.latency * 1e-3,
                kpp=c.kpp,
                kpd=c.kpd,
                kfp=c.kfp * MM,
                kfi=c.kfi * MM,
                stiffness=k.stiffness,
                damping=k.damping,
                friction=k.friction,
                lateral_stiffness=k.lateral_stiffness,
                form_error=k.form_error * MM,
                form_wavelength=k.form_wavelength * MM,
                noise_std=k.noise_std,
                filter_cutoff=k.filter_cutoff,
                max_speed=c.max_speed * MM,
                max_accel=c.max_accel * MM,
                max_force=s.max_force,
                seed=k.seed,
                orientation_loop=o.enabled,
                kop=o.kp,
                kod=o.kd,
                koi=o.ki,
                max_angular_speed=math.radians(o.max_speed),
            ),
        )

    def updated(
        self,
        *,
        pattern: str | None = None,
        step: float | None = None,
        spacing: float | None = None,
        force: float | None = None,
        feed: float | None = None,
        tool_radius: float | None = None,
    ) -> PolishingSpec:
        """Return a copy with the given path and process values in SI (m, N, m/s), stored in
        the file's units (mm, N, mm/s) and validated as a whole.

        Raises `InputError` naming the field, with the message the file would get."""
        new = self.model_dump()
        if pattern is not None:
            new["pattern"] = pattern
        for name, val in (
            ("step", step),
            ("spacing", spacing),
            ("feed", feed),
            ("tool_radius", tool_radius),
        ):
            if val is not None:
                new[name] = float(val) / MM
        if force is not None:
            new["force"] = float(force)
        return _validated(new)


@dataclass(frozen=True)
class PolishingSI:
    """The `polishing` section in SI: lengths [m], speeds [m/s], forces [N], times [s].

    `T_world_workpiece` (4, 4) [m] places the workpiece; `control` holds the hybrid force
    controller's gains and the contact model (`HybridForceParams`, SI)."""

    workpiece: str  # mesh file, relative to the project file
    units: MeshUnits
    faces: tuple[int, ...] | None  # a STEP solid's faces to polish; None: the whole file
    T_world_workpiece: F64 = field(repr=False)
    pattern: Pattern
    step: float  # [m]
    spacing: float  # [m]
    tool_radius: float  # [m]
    lead_height: float  # [m]
    n_lead: int
    feed: float  # [m/s]
    dwell: float  # [s]
    max_force: float  # [N]
    force: float  # [N]
    control: HybridForceParams


def _validated(data: dict[str, Any]) -> PolishingSpec:
    """Return `data` validated as a `polishing` section; `InputError` naming the first field."""
    # Imported here: project.io imports the project model, which imports this module.
    from workbench.project.io import problems_from

    try:
        return PolishingSpec.model_validate(data)
    except ValidationError as exc:
        where, msg = problems_from(exc)[0]
        where = "polishing" if where == "(top level)" else f"polishing.{where}"
        raise InputError(f"{msg}", field=where) from None
