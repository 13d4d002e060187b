"""The gripper's process contacts: the tool and what it is within PROCESS_GAP of where it handles the part."""

from __future__ import annotations

import numpy as np
from block_cell import block_cell

from workbench.pressbrake.process_contacts import PROCESS_GAP, gripper_contacts
from workbench.service import Workbench


def _near(wb: Workbench, q: np.ndarray) -> set[tuple[str, str]]:
    """Twin: fcl's distance of every (tool, obstacle) pair at q, against PROCESS_GAP."""
    scene = wb.checker.scene
    scene.place(wb.checker.world_poses(q))
    return {
        (a, b)
        for a, b in scene.pairs
        if a == "tool" and b in scene.static and scene.distance(a, b) < PROCESS_GAP
    }


def test_only_the_obstacles_the_tool_handles_the_part_at_are_exempt() -> None:
    wb = Workbench.from_dict(block_cell())
    far = np.zeros(6)
    # Lower the tool towards the block until it is within the gap (a grip on a part lying there).
    grip = None
    for dz in np.linspace(-0.5, -0.75, 60):
        q = np.array([0.0, dz, -dz, 0.0, 0.0, 0.0])
        if _near(wb, q):
            grip = q
            break
    assert grip is not None
    assert gripper_contacts(wb.checker, [far]) == ()
    got = gripper_contacts(wb.checker, [far, grip])
    assert set(got) == _near(wb, grip) == {("tool", "block")}
    # Links are never exempt: only the tool's pairs.
    assert all(a == "tool" for a, _ in got)
