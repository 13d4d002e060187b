"""The project file's `bending.grasp_grid`: the candidate grasps a sequence search tries.

Per flange its centroid and a square grid of `spacing` [mm] at least `inset` [mm] inside its
polygon, each with every yaw [deg] and face listed (`workbench.pressbrake.grasp_grid`).
`GraspGridSpec.to_si` returns the `GridSettings` in SI units. `cup_diameter` [mm] or `pad`
[length, width mm] name the gripper's footprint: candidates whose cup or pad covers a hole
or hangs over an edge by more than `max_overhang` (a fraction of its area; default 0, since
a vacuum cup must rest whole on the part: `workbench.pressbrake.grasp_footprint`) are left
out, each listed in the search's rejected table. Neither given: no footprint check.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import AfterValidator, Field, model_validator

from workbench.pressbrake.grasp_footprint import MAX_OVERHANG, Footprint
from workbench.pressbrake.grasp_grid import GridSettings
from workbench.project import bounds as B
from workbench.project.common import Angle, StrictModel
from workbench.project.units import DEG, MM

Face = Literal["top", "bottom"]


def _distinct(v: list[object]) -> list[object]:
    if len(set(v)) != len(v):
        raise ValueError(f"lists a value twice: {v}; give each once")
    return v


class GraspGridSpec(StrictModel):
    """Candidate grasps of the sequence search: grid `spacing` and `inset` [mm], the gripper's
    `yaws` [deg] about the flange normal, the `faces` held ("top": the flange's +z face)."""

    # the defaults are `GridSettings()`'s in mm and deg (tested)
    spacing: Annotated[float, B.span(B.GRASP_SPACING_MM_OPEN, "mm", lo_open=True)] = 25.0
    inset: Annotated[float, B.span(B.GRASP_INSET_MM, "mm")] = 8.0
    yaws: Annotated[
        list[Angle], Field(min_length=1, max_length=B.GRASP_YAWS_MAX), AfterValidator(_distinct)
    ] = Field(default_factory=lambda: [0.0, 90.0, 180.0, -90.0])
    faces: Annotated[list[Face], Field(min_length=1, max_length=2), AfterValidator(_distinct)] = (
        Field(default_factory=lambda: list[Face](["top"]))
    )

    cup_diameter: Annotated[float, Field(gt=0, le=1000)] | None = None
    pad: (
        Annotated[list[Annotated[float, Field(gt=0, le=1000)]], Field(min_length=2, max_length=2)]
        | None
    ) = None
    max_overhang: Annotated[float, Field(ge=0, le=1)] | None = None  # None: MAX_OVERHANG

    @model_validator(mode="after")
    def _one_footprint(self) -> GraspGridSpec:
        if self.cup_diameter is not None and self.pad is not None:
            raise ValueError("give cup_diameter or pad, not both")
        return self

    def to_si(self) -> GridSettings:
        """Return the grid in SI units (m, rad; faces +1 top, -1 bottom)."""
        footprint = None
        if self.cup_diameter is not None:
            footprint = Footprint.cup(self.cup_diameter * MM)
        elif self.pad is not None:
            footprint = Footprint.pad(self.pad[0] * MM, self.pad[1] * MM)
        return GridSettings(
            spacing=self.spacing * MM,
            inset=self.inset * MM,
            yaws=tuple(y * DEG for y in self.yaws),
            faces=tuple(1 if f == "top" else -1 for f in self.faces),
            footprint=footprint,
            max_overhang=MAX_OVERHANG if self.max_overhang is None else self.max_overhang,
        )
