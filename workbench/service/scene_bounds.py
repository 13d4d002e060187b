"""The boxes the 3D view frames: the cell, the robot, the bending part on the die.

`scene_bounds(wb, focus)` returns world-space axis-aligned bounds [m] of what the view should
show; the GUI places its camera from them (display only). Flat bodies such as a floor plate
are left out of the cell's box, so a 2.4 m floor does not shrink the robot on the screen.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError, WorkbenchError
from workbench.geometry.aabb import aabb_union, world_aabb
from workbench.pressbrake.die import die_boxes

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

FOCUS = ("all", "robot", "cell", "bending")
"""What `scene_bounds` frames: everything, the robot (with its tool), the cell's bodies, the
bending die with the part on it."""
FLAT_RATIO = 0.05
"""A body whose height is under this fraction of its width counts as flat (a floor)."""


@dataclass(frozen=True)
class SceneBounds:
    """An axis-aligned world box: `lo`, `hi` (3,) [m]."""

    lo: NDArray[np.float64]
    hi: NDArray[np.float64]

    @property
    def centre(self) -> NDArray[np.float64]:
        """Return the box's centre (3,) [m]."""
        return (self.lo + self.hi) / 2

    @property
    def size(self) -> NDArray[np.float64]:
        """Return the box's edge lengths (3,) [m]."""
        return self.hi - self.lo


def _robot(wb: Workbench) -> list[NDArray[np.float64]]:
    poses = wb.link_poses()
    boxes = [
        world_aabb(m.vertices, T)
        for m, T in zip(wb.setup.link_meshes, poses, strict=True)
        if len(m.vertices)
    ]
    if wb.setup.tool_mesh is not None:
        boxes.append(world_aabb(wb.setup.tool_mesh.vertices, poses[-1]))
    boxes.append(world_aabb(wb.tcp_pose()[None, :3, 3]))
    return boxes


def _cell(wb: Workbench) -> list[NDArray[np.float64]]:
    boxes = [world_aabb(b.mesh().vertices, b.T_world_body) for b in wb.cell]
    upright = [b for b in boxes if (b[1, 2] - b[0, 2]) >= FLAT_RATIO * np.ptp(b[:, :2], 0).max()]
    return upright or boxes


def _bending(wb: Workbench) -> list[NDArray[np.float64]]:
    svc = wb.bending
    return die_boxes(svc.part, svc.si().die, svc.grasp)


def scene_bounds(wb: Workbench, focus: str = "all") -> SceneBounds:
    """Return the world box [m] the view should frame for `focus` (one of `FOCUS`).

    "bending" needs the project's bending section (InputError otherwise); "all" holds the
    cell, the robot at its current joints and, when there is one, the bending part on the die.
    """
    if focus not in FOCUS:
        raise InputError(f"focus: {focus!r} is not one of {', '.join(FOCUS)}")
    boxes: list[NDArray[np.float64]] = []
    if focus in ("all", "robot"):
        boxes += _robot(wb)
    if focus in ("all", "cell"):
        boxes += _cell(wb)
    if focus == "bending" or (focus == "all" and wb.bending.available):
        try:
            boxes += _bending(wb)
        except WorkbenchError:
            if focus == "bending":
                raise
    if not boxes:
        raise InputError(f"focus {focus!r}: nothing to frame in this project")
    box = aabb_union(boxes)
    return SceneBounds(box[0], box[1])
