"""One robot of the timeline checked against the cell and itself over its tasks, on the plan's samples.

The check runs on the robot's active samples (those within its tasks) plus the tasks'
start and end times (they fall between samples); its report is mapped back to the plan's
sample indices: an extra sample, or an interval, maps to the plan's sample at or before it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.part_moves import Progress
from workbench.assembly.tasks import TaskPlan
from workbench.assembly.timeline import arm_motion
from workbench.collision import CollisionPolicy, check_motion
from workbench.collision.engine import EnginePathReport
from workbench.motion.validation import acceleration_bound

FloatArray = NDArray[np.float64]


def check_arm(
    arm: AssemblyArm,
    tasks: Sequence[TaskPlan],
    times: FloatArray,
    policy: CollisionPolicy,
    *,
    joints: FloatArray | None = None,
    progress: Progress | None = None,
) -> EnginePathReport | None:
    """Return `arm`'s check over its tasks among `tasks` at the plan's `times` (N,) [s] (None if none).

    policy: how to check (`workbench.collision.check_motion`). joints (N, dof) [rad]: the
    plan's joints (default from the tasks' trajectories). Under a fast mode the real timed
    motion is certified between samples (each task's trajectory from its `t0`, at rest at
    home between tasks; |q''| bounded by the largest of the tasks' exact bounds: each task
    starts and ends at rest, so the motion is C1); the exact mode checks the samples only. The report's indices are
    indices into `times`: `colliding_indices` the colliding samples, `between_indices`
    samples i whose interval to i+1 collides or could not be certified, `first_index`
    likewise.
    """
    mine = [t for t in tasks if t.robot == arm.name]
    t_all = np.asarray(times, float)
    active = np.zeros(len(t_all), dtype=bool)
    for task in mine:
        active |= (t_all >= task.t0) & (t_all <= task.t1)
    idx = np.flatnonzero(active)
    if not len(idx):
        return None

    def motion(t: FloatArray) -> FloatArray:
        return arm_motion(mine, arm.q_home, t)[0]

    # The tasks' ends as extra samples: the stretches before the first active sample and
    # after the last one are then between samples too.
    ends = np.array([x for task in mine for x in (task.t0, task.t1)])
    ends = ends[np.min(np.abs(ends[:, None] - t_all[idx][None]), axis=1) > 1e-12]
    t_ext = np.concatenate([t_all[idx], ends])
    order = np.argsort(t_ext, kind="stable")
    t_ext = t_ext[order]
    g_ext = np.concatenate([idx, np.full(len(ends), -1)])[order]  # plan index or -1
    q_ext = motion(t_ext)
    if joints is not None:
        rows = g_ext >= 0
        q_ext[rows] = np.asarray(joints, float)[g_ext[rows]]
    acc = np.max([acceleration_bound(task.trajectory) for task in mine], axis=0)
    rep = check_motion(
        t_ext, q_ext, arm.checker, policy, sampler=motion, acceleration=acc, progress=progress
    )

    def before(i: int) -> int:
        return int(np.clip(np.searchsorted(t_all, t_ext[i], side="right") - 1, 0, None))

    hits = tuple(int(g_ext[i]) for i in rep.colliding_indices if g_ext[i] >= 0)
    between = sorted(
        {before(i) for i in rep.between_indices}
        | {before(i) for i in rep.colliding_indices if g_ext[i] < 0}
    )
    first, is_between = rep.first_index, rep.between
    if first is not None:
        if g_ext[first] < 0 or is_between:
            first, is_between = before(first), True
        else:
            first = int(g_ext[first])
    return dataclasses.replace(
        rep,
        samples=len(idx),
        colliding_indices=hits,
        between_indices=tuple(between),
        first_index=first,
        between=is_between,
    )
