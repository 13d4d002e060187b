"""The project file's `cad` section: how the CAD (STEP) files a project names become meshes.

``{"linear_tolerance": 0.05, "angular_tolerance": 5}`` [mm, deg], the defaults, also when the
section is absent. Every STEP file the project names (cell objects, the tool, link meshes,
assembly parts, the polishing workpiece) is tessellated with these tolerances: every vertex
lies on the exact surface, every triangle within `linear_tolerance` of it, and the normals of
neighbouring triangles on one face differ by at most `angular_tolerance` (docs/cad.md).

A STEP file carries its own length unit and is read in mm, so the `scale` (mesh units to m)
given with it must be 0.001, the default: any other value is refused at load
(`check_step_scale`), where for an STL it would silently make the part 1000x too large.
"""

from __future__ import annotations

import math
from typing import Annotated

from workbench.cad.step import DEFAULT_ANGULAR_DEG, DEFAULT_LINEAR_MM, StepTolerance, is_step
from workbench.project import bounds as B
from workbench.project.common import StrictModel, field_error
from workbench.project.units import DEG, MM

LinearTolerance = Annotated[float, B.span(B.LINEAR_TOLERANCE_MM, "mm")]
AngularTolerance = Annotated[float, B.span(B.ANGULAR_TOLERANCE_DEG, "deg")]


class CadSpec(StrictModel):
    """The tessellation tolerances of the project's STEP files [mm, deg]."""

    linear_tolerance: LinearTolerance = DEFAULT_LINEAR_MM  # mm, chordal deviation
    angular_tolerance: AngularTolerance = DEFAULT_ANGULAR_DEG  # deg, between neighbouring normals

    def to_si(self) -> StepTolerance:
        """Return the tolerances in SI: linear [m], angular [rad]."""
        return StepTolerance(
            linear=self.linear_tolerance * MM, angular=self.angular_tolerance * DEG
        )


def step_tolerance(spec: CadSpec | None) -> StepTolerance:
    """Return the STEP tolerances of a project's `cad` section (None: the defaults) in SI."""
    return (spec or CadSpec()).to_si()


def check_step_scale(path: str | None, scale: float, field: str) -> None:
    """Raise a validation error at `field` when `path` is a STEP file and `scale` is not 0.001.

    For a model validator: the error names the field below the model that raises it.
    """
    if is_step(path) and not math.isclose(scale, MM, rel_tol=1e-9):
        msg = (
            f"{scale:g} does not apply to a STEP file: STEP carries its own length unit and is"
            f" read in mm, so '{field}' must be 0.001 (mm to m, the default); remove '{field}'"
        )
        raise field_error([((field,), msg, scale)])
