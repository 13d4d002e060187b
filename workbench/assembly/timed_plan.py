"""The timed sequence sampled on one time axis and checked: robots, carried parts, contacts.

Each robot's samples become its `SampledMotion` (joints, derivatives, world TCP poses and
the plan's colliding samples: the one TCP-speed formula of the timeline's plots).

Each robot against the cell and itself under a collision policy (`arm_check`), each
carried part against everything while held (its interference checker), robots against
each other and against the parts (`robot_pairs`).
"""

from __future__ import annotations

from collections.abc import Sequence

from workbench.assembly.arm_check import check_arm
from workbench.assembly.robot_pairs import cross_contacts
from workbench.assembly.tasks import TaskPlan
from workbench.assembly.timeline import (
    AssemblyPlan,
    arm_motion,
    colliding_samples,
    interfering,
    part_poses,
    sample_times,
)
from workbench.assembly.workcell import Workcell
from workbench.collision import CollisionPolicy
from workbench.motion import SampledMotion


def timed_plan(
    cell: Workcell, tasks: Sequence[TaskPlan], dt: float, policy: CollisionPolicy
) -> AssemblyPlan:
    """Return the plan of `tasks` sampled every dt [s] in `cell`, checked under `policy`."""
    times = sample_times(tasks[-1].t1, dt)
    motions = {
        n: arm_motion([t for t in tasks if t.robot == n], a.q_home, times)
        for n, a in cell.arms.items()
    }
    joints = {n: m[0] for n, m in motions.items()}
    poses, part_hits = {}, {}
    for part in cell.parts.values():
        poses[part.name], held = part_poses(part, tasks, cell.arms, joints, times, cell.order)
        if held is not None:
            hits = interfering(cell.checker(part.name), poses[part.name][held])
            part_hits[part.name] = tuple(int(held[h]) for h in hits)
    reports = {
        n: check_arm(a, tasks, times, policy, joints=joints[n]) for n, a in cell.arms.items()
    }
    robot_hits = {n: r.colliding_indices if r else () for n, r in reports.items()}
    between = {n: r.between_indices if r else () for n, r in reports.items()}
    contacts = cross_contacts(cell.bodies(), cell.arms, cell.parts, tasks, times, joints, poses)
    hit = colliding_samples(
        len(times), robot_hits.values(), between.values(), part_hits.values(), contacts=contacts
    )
    return AssemblyPlan(
        tasks=tuple(tasks),
        times=times,
        motions={
            n: SampledMotion(times, q, v, a, tcp=cell.arms[n].tcp_poses(q), colliding=hit, name=n)
            for n, (q, v, a) in motions.items()
        },
        part_poses=poses,
        robot_collisions=robot_hits,
        part_interference=part_hits,
        contacts=contacts,
        robot_reports={n: r for n, r in reports.items() if r is not None},
        robot_between=between,
    )
