"""Robot–robot and robot–part contacts of the timeline: the bodies, their pairs, and their poses.

Bodies: every robot's moving bodies ("MZ07/link3", "MZ07/tool") and every part ("part
screw_2"). Pairs: each robot's bodies against every other robot's, and each robot's moving
bodies (not its base) against every part. A carrying robot's tool touches its own part from
the approach to the retreat of that task by design: that one pair is excused during the task.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.contacts import Bodies, Contact
from workbench.assembly.part import AssemblyPart
from workbench.collision import Solid

if TYPE_CHECKING:
    from workbench.assembly.tasks import TaskPlan

FloatArray = NDArray[np.float64]


def cell_bodies(arms: Mapping[str, AssemblyArm], parts: Mapping[str, AssemblyPart]) -> Bodies:
    """Return every robot body and part as `Bodies`, with the robot–robot and robot–part pairs."""
    solids: list[Solid] = []
    owner: list[str] = []
    for name, arm in arms.items():
        for body, entry in arm.checker.scene.moving.items():
            solids.append(Solid(f"{name}/{body}", "mesh", mesh=entry.mesh))
            owner.append(name)
    for part in parts.values():
        solids.append(Solid(f"part {part.name}", "mesh", mesh=part.mesh))
        owner.append("")
    names = [sol.name for sol in solids]
    base = {f"{n}/{a.checker.link_names[0]}" for n, a in arms.items()}
    pairs = []
    for i, a in enumerate(names):
        for j in range(i + 1, len(names)):
            if owner[i] and owner[j] and owner[i] != owner[j]:
                pairs.append((a, names[j]))  # robot - robot
            elif owner[i] and not owner[j] and a not in base:
                pairs.append((a, names[j]))  # robot - part
    return Bodies(solids, pairs)


def cross_contacts(
    bodies: Bodies,
    arms: Mapping[str, AssemblyArm],
    parts: Mapping[str, AssemblyPart],
    tasks: Sequence[TaskPlan],
    times: FloatArray,
    joints: Mapping[str, FloatArray],
    part_poses: Mapping[str, FloatArray],
) -> tuple[Contact, ...]:
    """Return the robot–robot and robot–part contacts of sampled motions, in time order.

    bodies: `cell_bodies(arms, parts)`; joints[robot] (N, dof) [rad] and part_poses[part]
    (N, 4, 4) [m] at times (N,) [s]; tasks: their carrying tool and part are excused from
    t0 to t1.
    """
    N = len(times)
    P = np.empty((N, len(bodies.names), 4, 4))
    k = 0
    for name, arm in arms.items():
        L = arm.link_poses(joints[name])
        for body in arm.checker.scene.moving:
            frame = arm.checker.link_names.index(body) if body != "tool" else L.shape[1] - 1
            P[:, k] = L[:, frame]
            k += 1
    for part in parts.values():
        P[:, k] = part_poses[part.name]
        k += 1
    active = np.ones((N, len(bodies.pa)), dtype=bool)
    pairs = bodies.pairs
    for task in tasks:
        key = (f"{task.robot}/tool", f"part {task.part}")
        if key in pairs:
            during = (times >= task.t0) & (times <= task.t1)
            active[during, pairs.index(key)] = False
    return tuple(
        Contact(n, float(times[n]), *pairs[p]) for n, p in bodies.contacts(P, active=active)
    )
