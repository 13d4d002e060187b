"""The cell as the service sees it: named solids at world poses with display colours."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.collision import Solid
from workbench.project.models import CellObject
from workbench.service.convert import MM, load_mesh_file, pose_to_matrix


@dataclass(frozen=True)
class CellBody:
    """One cell object: its solid in its own frame [m], world pose, colour and collision flag."""

    name: str
    solid: Solid
    T_world_body: NDArray[np.float64] = field(repr=False)
    color: tuple[int, int, int]
    collide: bool

    def mesh(self) -> trimesh.Trimesh:
        """Return the body's triangle mesh in its own frame [m]."""
        return self.solid.to_trimesh()


def build_cell(objects: list[CellObject], base_dir: Path) -> list[CellBody]:
    """Return the cell bodies of the project's objects; meshes are loaded relative to `base_dir`."""
    bodies = []
    for i, obj in enumerate(objects):
        where = f"cell.objects[{i}]"
        if obj.shape == "box":
            assert obj.size is not None
            solid = Solid(obj.name, "box", size=tuple(float(s) * MM for s in obj.size))  # type: ignore[arg-type]
        elif obj.shape == "cylinder":
            assert obj.radius is not None and obj.height is not None
            solid = Solid(obj.name, "cylinder", radius=obj.radius * MM, height=obj.height * MM)
        else:
            assert obj.path is not None
            mesh = load_mesh_file(obj.path, base_dir, obj.scale, f"{where}.path")
            solid = Solid(obj.name, "mesh", mesh=mesh)
        bodies.append(
            CellBody(
                name=obj.name,
                solid=solid,
                T_world_body=pose_to_matrix(obj.pose),
                color=(int(obj.color[0]), int(obj.color[1]), int(obj.color[2])),
                collide=obj.collide,
            )
        )
    return bodies
