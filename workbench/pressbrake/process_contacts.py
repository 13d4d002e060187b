"""The contacts a bending process needs: the gripper where it holds, takes or puts down the part.

Where the gripper grips or releases the part (the blank stack, the regrip station, the pallet)
and where it holds the part in the press (on the die, under the punch), its jaws come within a
sheet's thickness of the surface the part lies on. Those pairs (the tool and that obstacle)
are exempt from the clearance margin by name (`CollisionPolicy.exempt`); contact itself is
still checked (the margin exempts nothing from the collision check).
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np
from numpy.typing import NDArray

from workbench.collision.robot_checker import RobotCollisionChecker

#: The waypoint actions at which the gripper handles the part (`cycle_path.Waypoint.action`).
HANDLING = ("grip", "release", "press_close", "press_bend", "press_open")
#: How near [m] the tool comes to what the part lies on where it handles the part (a sheet's
#: thickness and the jaws, with room): an obstacle nearer than this there is a process contact.
PROCESS_GAP = 0.02


def gripper_contacts(
    checker: RobotCollisionChecker, q_handling: Iterable[NDArray[np.float64]]
) -> tuple[tuple[str, str], ...]:
    """Return the (tool, obstacle) pairs nearer than `PROCESS_GAP` at any of `q_handling` (dof,)
    [rad], the configurations where the gripper handles the part; () without a tool."""
    if not checker.has_tool:
        return ()
    scene = checker.scene
    pairs = [(a, b) for a, b in scene.pairs if a == "tool" and b in scene.static]
    found: list[tuple[str, str]] = []
    for q in q_handling:
        scene.place(checker.world_poses(np.asarray(q, float)))
        for a, b in pairs:
            if (a, b) in found or scene.aabb_gap(a, b) >= PROCESS_GAP:
                continue
            if scene.collides(a, b) or scene.distance(a, b) < PROCESS_GAP:
                found.append((a, b))
    return tuple(found)
