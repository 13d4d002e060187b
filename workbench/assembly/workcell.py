"""The assembly workcell: its parts, arms and fixed obstacles, and what each part's move sees.

A part move is planned among the cell's fixed objects and the other parts: those earlier in
the sequence stand assembled (at their goal), the later ones wait at their start. Each
part has its interference checker among them (cached: several plans share it), the
subdivision cell size it uses, and, held by its robot, a joint-space validity test.
"""

from __future__ import annotations

import threading
from collections.abc import Sequence

import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.cells import check_cell_size
from workbench.assembly.contacts import Bodies
from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.part import AssemblyPart
from workbench.assembly.planners.joint_rrt import CarrySpace
from workbench.assembly.robot_pairs import cell_bodies
from workbench.collision import Solid
from workbench.errors import InputError

Obstacles = list[tuple[str, trimesh.Trimesh]]


def assembled_before(order: Sequence[str], name: str, first: str) -> bool:
    """Return True when part `name` comes before part `first` in the sequence `order` (it is in place)."""
    me = order.index(first) if first in order else len(order)
    return name in order and order.index(name) < me


class Workcell:
    """Parts and arms by name, fixed obstacles (name, world mesh [m]) and the sequence `order`.

    cell_size [m]: the section's subdivision cell side (None: 1/20 of each part), named
    `cell_size_field` in messages; parts_field: the parts' list, in messages (`where`).
    """

    def __init__(
        self,
        parts: dict[str, AssemblyPart],
        arms: dict[str, AssemblyArm],
        fixed: Obstacles,
        order: Sequence[str],
        *,
        cell_size: float | None = None,
        cell_size_field: str = "cell_size",
        parts_field: str = "parts",
    ) -> None:
        self.parts, self.arms, self.fixed = parts, arms, fixed
        self.order = list(order)
        self.default_cell_size, self.cell_size_field = cell_size, cell_size_field
        self.parts_field = parts_field
        self._lock = threading.RLock()
        self._checkers: dict[tuple[str, tuple[str, ...], float], InterferenceChecker] = {}
        self._bodies: Bodies | None = None

    def part(self, name: str) -> AssemblyPart:
        """Return the part called `name`; InputError listing the parts if there is none."""
        if name not in self.parts:
            raise InputError(f"part {name!r} does not exist; the parts are {list(self.parts)}")
        return self.parts[name]

    def where(self, name: str) -> str:
        """Return the field of part `name` for messages, e.g. "assembly.parts[2]"."""
        return f"{self.parts_field}[{list(self.parts).index(name)}]"

    def move(self, name: str, which: str, T_world_part: NDArray[np.float64]) -> None:
        """Replace part `name`'s `which` ("start" or "goal") pose (4, 4) [m]."""
        with self._lock:
            self.parts[name] = self.part(name).moved(which, T_world_part)

    def obstacles_for(self, name: str) -> Obstacles:
        """Return (name, world mesh) around part `name`: the cell, earlier parts at goal, the rest at start."""
        out = list(self.fixed)
        for other in self.parts.values():
            if other.name == name:
                continue
            done = assembled_before(self.order, other.name, name)
            T = other.goal if done else other.start
            out.append((other.name, other.mesh.copy().apply_transform(T)))
        return out

    def cell_size(self, name: str, cell_size: float | None = None) -> float:
        """Return the subdivision cell side [m] for part `name` (given, the section's, or 1/20 of it)."""
        part = self.part(name)
        c, field = cell_size, "cell_size"
        if c is None and self.default_cell_size is not None:
            c, field = self.default_cell_size, self.cell_size_field
        if c is None:
            return float(np.max(part.mesh.extents)) / 20.0
        return check_cell_size(c, part.mesh, field, part=name)

    def checker(self, name: str, cell_size: float | None = None) -> InterferenceChecker:
        """Return the interference checker of part `name` among its obstacles (cached)."""
        c = self.cell_size(name, cell_size)
        obstacles = self.obstacles_for(name)
        placed = tuple(f"{n}:{np.round(m.bounds, 9).tobytes().hex()}" for n, m in obstacles)
        key = (name, placed, c)
        with self._lock:
            if key not in self._checkers:
                if len(self._checkers) > 32:
                    self._checkers.clear()
                self._checkers[key] = InterferenceChecker(
                    self.part(name).mesh, [m for _, m in obstacles], c
                )
            return self._checkers[key]

    def interference(self, name: str, T_world_part: ArrayLike) -> list[str]:
        """Return the names of the obstacles part `name` interferes with at pose (4, 4) [m]."""
        names = [n for n, _ in self.obstacles_for(name)]
        return [names[k] for k in self.checker(name).colliding_obstacles(T_world_part)]

    def carry_space(
        self,
        name: str,
        cell_size: float | None = None,
        *,
        resolution: float | None = None,
        robot_resolution: float | None = None,
    ) -> CarrySpace:
        """Return the joint-space validity test of part `name` held by its robot (SI units).

        The part against its obstacles (interference checker), the robot's links and tool
        against the cell, itself and the other parts where they stand (python-fcl).
        resolution, robot_resolution [m]: largest travel of a point of the part / the robot
        between two checks (default the cell size). InputError if no robot carries the part.
        """
        part = self.part(name)
        if part.robot is None:
            raise InputError(
                f"{self.where(name)}.robot: part {name!r} has no robot, so it cannot be "
                f"planned in joint space; name one of {list(self.arms)} or pick a pose planner"
            )
        arm = self.arms[part.robot]
        fixed = {n for n, _ in self.fixed}
        obstacles = self.obstacles_for(name)
        return CarrySpace(
            arm.checker,
            self.checker(name, cell_size),
            arm.setup.T_flange_tcp,
            part.T_part_tcp,
            extra=[
                (Solid(f"part {n}", "mesh", mesh=m), np.eye(4))
                for n, m in obstacles
                if n not in fixed
            ],
            obstacle_names=[n for n, _ in obstacles],
            resolution=resolution,
            robot_resolution=robot_resolution,
        )

    def bodies(self) -> Bodies:
        """Return every robot body ("robot/link3", "robot/tool") and part ("part name") as `Bodies`."""
        with self._lock:
            if self._bodies is None:
                self._bodies = cell_bodies(self.arms, self.parts)
            return self._bodies
