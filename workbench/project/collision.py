"""The project file's `collision` section: how every plan checks its motion for collisions.

``{"mode": "spheres"}`` (the default, also when the section is absent): spheres + signed
distance field, what they flag confirmed by python-fcl, certified between samples.
``"exact"``: every sample checked with python-fcl, nothing certified between samples.
``"capsules"``: capsules against the obstacles' oriented boxes, confirmed and certified as
the spheres mode. See docs/collision-engine.md ("Plan collision policy").

``margin`` [mm] (default `DEFAULT_MARGIN_MM`, also when the section is absent): the clearance
every plan must keep between the robot and the cell and between its own links; a plan that
comes closer is a problem naming the pair and the distance, and its export is refused unless
forced. ``exempt``: extra pairs of body names the margin does not apply to (the workflows add
the contacts their process needs). docs/collision-engine.md ("Clearance margin") says why
the default is what it is.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field, ValidationError, field_validator

from workbench.collision import CollisionPolicy
from workbench.collision.clearance import MAX_MARGIN
from workbench.collision.plan_check import RESOLUTION, SPHERES_PER_LINK
from workbench.errors import InputError
from workbench.project.common import StrictModel
from workbench.project.units import MM

#: The default clearance margin [mm]: see docs/collision-engine.md ("Clearance margin").
DEFAULT_MARGIN_MM = 0.5
MAX_MARGIN_MM = MAX_MARGIN / MM


class CollisionSpec(StrictModel):
    """The plan collision policy: mode, and the spheres engine's parameters."""

    mode: Literal["spheres", "exact", "capsules"] = "spheres"
    spheres_per_link: Annotated[int, Field(ge=1, le=64)] = SPHERES_PER_LINK  # per link
    resolution: Annotated[int, Field(ge=2, le=512)] = RESOLUTION  # coarse SDF cells, largest extent
    margin: float = DEFAULT_MARGIN_MM  # [mm] the clearance every plan keeps
    exempt: list[Annotated[list[str], Field(min_length=2, max_length=2)]] = []  # body-name pairs

    @field_validator("margin")
    @classmethod
    def _margin(cls, v: float) -> float:
        if not math.isfinite(v) or not 0.0 <= v <= MAX_MARGIN_MM:
            raise ValueError(
                f"{v!r} mm is not a clearance margin; give a length from 0 to"
                f" {MAX_MARGIN_MM:g} mm (default {DEFAULT_MARGIN_MM:g} mm)"
            )
        return v

    def to_si(self) -> CollisionPolicy:
        """Return the policy the plans use (the margin in m)."""
        return CollisionPolicy(
            mode=self.mode,
            spheres_per_link=self.spheres_per_link,
            resolution=self.resolution,
            margin=self.margin * MM,
            exempt=tuple((a, b) for a, b in self.exempt),
        )

    def with_margin(self, margin: float) -> CollisionSpec:
        """Return a copy with the clearance margin `margin` [m] (stored in mm), validated:
        InputError naming `collision.margin` for NaN, a negative or an absurd value."""
        try:
            return CollisionSpec.model_validate({**self.model_dump(), "margin": margin / MM})
        except (ValidationError, TypeError) as exc:
            raise InputError(
                f"{margin / MM:g} mm is not a clearance margin; give a length from 0 to"
                f" {MAX_MARGIN_MM:g} mm (default {DEFAULT_MARGIN_MM:g} mm)",
                field="collision.margin",
            ) from exc
