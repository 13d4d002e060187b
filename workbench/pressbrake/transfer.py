"""The transfer of the bent part from the press brake to the pallet, and the part's pose on the way.

SI units. After the last bend the robot retracts from the die (an offset in the die frame),
passes the via poses and puts the part frame down at the pallet pose. Along the way the
part's frames follow the TCP: T_world_part = T_world_tcp · T_part_tcp⁻¹.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel
from workbench.pressbrake.die import Die, DiePlacement
from workbench.pressbrake.grasp import Grasp, T_flange_grasp, T_part_grasp
from workbench.pressbrake.obstacles import Obstacles, confirm_exact
from workbench.sheetmetal.obbtree import FramesReport, OBBTree
from workbench.sheetmetal.part import SheetMetalPart


@dataclass(frozen=True, eq=False)
class Transfer:
    """The way to the pallet: `retract` (3,) [m] in the die frame, TCP via poses (N, 4, 4) [m]
    in the world, and where the part frame is put down (4, 4) [m].

    `where` prefixes the pose names (e.g. the project section) in error messages.
    """

    retract: NDArray[np.float64]
    T_world_vias: NDArray[np.float64]
    T_world_pallet: NDArray[np.float64]
    where: str = "transfer"


def transfer_poses(
    transfer: Transfer, die: Die, last: DiePlacement, part: SheetMetalPart, grasp: Grasp
) -> tuple[NDArray[np.float64], list[str]]:
    """Return TCP poses (N, 4, 4) [m] of the transfer: retract, via poses, pallet; with names."""
    ret = last.T_world_tcp.copy()
    ret[:3, 3] += die.T_world_die[:3, :3] @ transfer.retract
    vias = list(transfer.T_world_vias)
    drop = transfer.T_world_pallet @ T_part_grasp(part, grasp, len(part.bends))
    w = transfer.where
    names = [f"{w}.retract"] + [f"{w}.transfer[{i}]" for i in range(len(vias))] + [f"{w}.pallet"]
    return np.array([ret, *vias, drop]), names


def world_tcp(
    robot: RobotModel,
    T_world_base: NDArray[np.float64],
    T_flange_tcp: NDArray[np.float64],
    q: NDArray[np.float64],
) -> NDArray[np.float64]:
    """Return the TCP's world poses (..., 4, 4) [m] at joints (..., dof)."""
    return T_world_base @ robot.fk(q) @ T_flange_tcp  # type: ignore[no-any-return]


def carried_poses(
    T_world_tcp: NDArray[np.float64], part: SheetMetalPart, grasp: Grasp
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return (T_world_grasp, T_world_part) (..., 4, 4) [m] of the folded part held at TCP poses.

    T_world_grasp is the gripped flange's frame (the OBB tree's root frame).
    """
    T_world_grasp = T_world_tcp @ invert_transform(T_flange_grasp(part, grasp))
    T_world_part = T_world_tcp @ invert_transform(T_part_grasp(part, grasp, len(part.bends)))
    return T_world_grasp, T_world_part


def check_part(
    tree: OBBTree, obstacles: Obstacles, T_world_grasp: NDArray[np.float64]
) -> FramesReport:
    """Return the carried part's verdict per frame: the OBB tree (batched), leaf hits on
    cylinders and meshes confirmed exactly."""
    report = tree.collide_frames(obstacles.boxes, T_world_grasp)
    return confirm_exact(tree, report, obstacles, T_world_grasp)


def base_flange_poses(
    T_world_base: NDArray[np.float64],
    T_flange_tcp: NDArray[np.float64],
    T_world_tcp: NDArray[np.float64],
) -> NDArray[np.float64]:
    """Return the flange poses (..., 4, 4) [m] in the robot base frame that put the TCP at `T_world_tcp`."""
    return invert_transform(T_world_base) @ T_world_tcp @ invert_transform(T_flange_tcp)  # type: ignore[no-any-return]
