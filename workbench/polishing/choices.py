"""The closed choices of a polishing job: the path patterns and the workpiece file's units.

One tuple each, used by the planner, the project file's schema and the GUI's option lists.
"""

from __future__ import annotations

from typing import Literal, get_args

Pattern = Literal["spiral", "raster"]
#: Path patterns: an inward spiral of offset rings, or back-and-forth raster passes.
PATTERNS: tuple[Pattern, ...] = get_args(Pattern)

MeshUnits = Literal["mm", "m", "auto"]
#: Units of a workpiece mesh file, the usual first; "auto" guesses from the part's size.
MESH_UNITS: tuple[MeshUnits, ...] = get_args(MeshUnits)
