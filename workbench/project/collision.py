"""The project file's `collision` section: how every plan checks its motion for collisions.

``{"mode": "spheres"}`` (the default, also when the section is absent): spheres + signed
distance field, what they flag confirmed by python-fcl, certified between samples.
``"exact"``: every sample checked with python-fcl, nothing certified between samples.
``"capsules"``: capsules against the obstacles' oriented boxes, confirmed and certified as
the spheres mode. See docs/collision-engine.md ("Plan collision policy").
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from workbench.collision import CollisionPolicy
from workbench.collision.plan_check import RESOLUTION, SPHERES_PER_LINK
from workbench.project.common import StrictModel


class CollisionSpec(StrictModel):
    """The plan collision policy: mode, and the spheres engine's parameters."""

    mode: Literal["spheres", "exact", "capsules"] = "spheres"
    spheres_per_link: Annotated[int, Field(ge=1, le=64)] = SPHERES_PER_LINK  # per link
    resolution: Annotated[int, Field(ge=2, le=512)] = RESOLUTION  # coarse SDF cells, largest extent

    def to_si(self) -> CollisionPolicy:
        """Return the policy the plans use (no units to convert: counts and a mode)."""
        return CollisionPolicy(
            mode=self.mode, spheres_per_link=self.spheres_per_link, resolution=self.resolution
        )
