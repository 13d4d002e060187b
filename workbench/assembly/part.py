"""A part of the assembly: its closed mesh, start and goal poses in the world, and its grasp."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.assembly.cells import check_mesh
from workbench.errors import ProjectError


@dataclass(frozen=True, eq=False)
class AssemblyPart:
    """One part: mesh in its own frame [m], start and goal (4, 4) in the world, TCP in the part frame."""

    name: str
    mesh: trimesh.Trimesh
    start: NDArray[np.float64]
    goal: NDArray[np.float64]
    T_part_tcp: NDArray[np.float64]
    robot: str | None
    color: tuple[int, int, int]

    def check(self, where: str, robots: Sequence[str]) -> AssemblyPart:
        """Return this part after checking its mesh is closed and its robot one of `robots`.

        where: the part's field (e.g. "assembly.parts[2]"): MeshError names `where.path`,
        ProjectError `where.robot`.
        """
        check_mesh(self.mesh, f"{where}.path", require_closed=True, part=self.name)
        if self.robot is not None and self.robot not in robots:
            field = f"{where}.robot"
            raise ProjectError(
                f"{field}: no robot named {self.robot!r}; the robots are {list(robots)}",
                [(field, f"unknown robot {self.robot!r}")],
            )
        return self

    def moved(self, which: str, T_world_part: NDArray[np.float64]) -> AssemblyPart:
        """Return this part with its `which` ("start" or "goal") pose replaced."""
        return AssemblyPart(
            name=self.name,
            mesh=self.mesh,
            start=T_world_part if which == "start" else self.start,
            goal=T_world_part if which == "goal" else self.goal,
            T_part_tcp=self.T_part_tcp,
            robot=self.robot,
            color=self.color,
        )


def primitive_mesh(
    shape: str,
    size: tuple[float, float, float] | None = None,
    radius: float | None = None,
    height: float | None = None,
) -> trimesh.Trimesh:
    """Return the mesh [m] of a "box" (extents `size`) or a "cylinder" (`radius`, `height`, along z)."""
    if shape == "box":
        assert size is not None
        return trimesh.creation.box(extents=np.asarray(size))
    assert shape == "cylinder" and radius is not None and height is not None
    return trimesh.creation.cylinder(radius=radius, height=height, sections=32)
