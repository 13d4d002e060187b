"""The cell as the service sees it: named solids at world poses with display colours."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.collision import Solid
from workbench.pressbrake.bend_setup import press_display_bodies, robot_obstacles
from workbench.pressbrake.press import PressBrake
from workbench.project.cad import CadSpec, step_tolerance
from workbench.project.models import CellObject, CellObjectSI
from workbench.project.paths import ProjectFolders
from workbench.service.mesh_files import load_mesh_file


@dataclass(frozen=True)
class CellBody:
    """One cell object: its solid in its own frame [m], world pose, colour and collision flag."""

    name: str
    solid: Solid
    T_world_body: NDArray[np.float64] = field(repr=False)
    color: tuple[int, int, int]
    collide: bool
    group: str = "cell"  # "cell": the project's objects; "press": the bending press's
    display: bool = True  # False: an envelope the robot is checked against, not drawn

    def mesh(self) -> trimesh.Trimesh:
        """Return the body's triangle mesh in its own frame [m]."""
        return self.solid.to_trimesh()


def build_cell(
    objects: Sequence[CellObject | CellObjectSI],
    base_dir: Path | ProjectFolders,
    cad: CadSpec | None = None,
) -> list[CellBody]:
    """Return the cell bodies of the project's objects; meshes are loaded relative to `base_dir`
    (STEP files tessellated with the project's `cad` tolerances)."""
    tolerance = step_tolerance(cad)
    bodies = []
    for i, spec in enumerate(objects):
        obj = spec.to_si() if isinstance(spec, CellObject) else spec
        where = f"cell.objects[{i}]"
        if obj.shape == "box":
            assert obj.size is not None
            solid = Solid(obj.name, "box", size=obj.size)
        elif obj.shape == "cylinder":
            assert obj.radius is not None and obj.height is not None
            solid = Solid(obj.name, "cylinder", radius=obj.radius, height=obj.height)
        else:
            assert obj.path is not None
            mesh = load_mesh_file(
                obj.path, base_dir, obj.scale, f"{where}.path", tolerance=tolerance
            )
            solid = Solid(obj.name, "mesh", mesh=mesh)
        bodies.append(
            CellBody(
                name=obj.name,
                solid=solid,
                T_world_body=obj.T_world_body,
                color=obj.color,
                collide=obj.collide,
            )
        )
    return bodies


#: Colours of the press's bodies: frame, tools, back-gauge.
PRESS_FRAME, PRESS_TOOL, PRESS_GAUGE = (90, 110, 140), (200, 200, 210), (220, 120, 40)
#: Press bodies drawn but not in the robot's checks (they move: the timeline places them).
MOVING = ("punch", "back-gauge finger")


def press_cell(press: PressBrake | None) -> list[CellBody]:
    """Return the press brake's bodies for the cell (`group` "press"): what the robot is
    checked against (frame, bed, dies, the ram's stroke and the back-gauge's reach, the last
    two not drawn), and the moving punch and fingers, drawn and placed by the timeline."""
    if press is None:
        return []
    out = []
    for name, solid, T in robot_obstacles(press):
        envelope = name.startswith(("ram stroke", "beam stroke", "back-gauge"))
        color = PRESS_GAUGE if name.startswith("back-gauge") else PRESS_FRAME
        if name.startswith("die"):
            color = PRESS_TOOL
        out.append(CellBody(f"press {name}", solid, T, color, True, "press", not envelope))
    for name, solid, T in press_display_bodies(press):
        color = PRESS_GAUGE if name.startswith("back-gauge") else PRESS_TOOL
        color = PRESS_FRAME if name == "upper beam" else color
        out.append(CellBody(f"press {name}", solid, T, color, False, "press", True))
    return out
