"""The multi-robot timeline: every robot's joints and every part's pose on one time axis.

Each robot rests at home except during its tasks; a later task takes over from its start.
A part stands where the planner saw it (assembled if it comes before the plan's first part
in the sequence, else at its start), is held by its robot from pick to place, and stays at
its goal after.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from workbench.assembly.arm import AssemblyArm
from workbench.assembly.contacts import Contact
from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.part import AssemblyPart
from workbench.assembly.tasks import TaskPlan
from workbench.assembly.workcell import assembled_before
from workbench.collision.engine import EnginePathReport
from workbench.geometry.transforms import invert_transform
from workbench.motion import SampledMotion

FloatArray = NDArray[np.float64]


def colliding_samples(
    n: int, *index_sets: Iterable[tuple[int, ...]], contacts: Sequence[Contact] = ()
) -> NDArray[np.bool_]:
    """Return (n,) True at every sample index of `index_sets` (dicts' values) and of `contacts`."""
    out = np.zeros(n, dtype=bool)
    for sets in index_sets:
        for idx in sets:
            out[list(idx)] = True
    out[[c.index for c in contacts]] = True
    return out


@dataclass(frozen=True, eq=False)
class AssemblyPlan:
    """The whole sequence on one time axis: samples every dt [s] of every robot and part.

    times (N,) [s]; motions[robot]: its `SampledMotion` (joints, velocities, accelerations,
    world TCP poses, colliding samples) on `times`; part_poses[part] (N, 4, 4) [m];
    robot_collisions[robot] and part_interference[part]: sample indices where the timed
    motion hits the cell (robot) or an obstacle (part); contacts: every robot–robot and
    robot–part contact (both bodies, e.g. "MZ07/link3" and "part screw_2", sample index and
    time [s]). robot_reports[robot]: the robot's `EnginePathReport` over its active samples
    (indices of this plan's samples; its `message` states the guarantee between samples or
    the first failure); robot_between[robot]: samples i whose interval to i+1 collides, or
    could not be certified, between them.
    """

    tasks: tuple[TaskPlan, ...]
    times: FloatArray = field(repr=False)
    motions: dict[str, SampledMotion] = field(repr=False)
    part_poses: dict[str, FloatArray] = field(repr=False)
    robot_collisions: dict[str, tuple[int, ...]]
    part_interference: dict[str, tuple[int, ...]]
    contacts: tuple[Contact, ...] = ()
    robot_reports: dict[str, EnginePathReport] = field(default_factory=dict, repr=False)
    robot_between: dict[str, tuple[int, ...]] = field(default_factory=dict)

    @property
    def joints(self) -> dict[str, FloatArray]:
        """Return each robot's joints (N, dof) [rad] at `times`."""
        return {n: m.joints for n, m in self.motions.items()}

    @property
    def velocities(self) -> dict[str, FloatArray]:
        """Return each robot's joint velocities (N, dof) [rad/s] at `times`."""
        return {n: m.velocity for n, m in self.motions.items()}

    @property
    def accelerations(self) -> dict[str, FloatArray]:
        """Return each robot's joint accelerations (N, dof) [rad/s^2] at `times`."""
        return {n: m.acceleration for n, m in self.motions.items()}

    @property
    def duration(self) -> float:
        """Return the cycle time of the whole sequence [s]."""
        return float(self.times[-1])

    @property
    def colliding(self) -> NDArray[np.bool_]:
        """Return (N,) True at samples where any robot collides (at the sample or up to the next)
        or any carried part interferes."""
        return colliding_samples(
            len(self.times),
            self.robot_collisions.values(),
            self.robot_between.values(),
            self.part_interference.values(),
            contacts=self.contacts,
        )

    @property
    def ok(self) -> bool:
        """Return True when no sample collides and every robot keeps the clearance margin."""
        margins = all(r.keeps_margin for r in self.robot_reports.values())
        return margins and not bool(self.colliding.any())

    def summary(self) -> str:
        """Return a one-line human summary."""
        order = " → ".join(t.part for t in self.tasks)
        hits = int(self.colliding.sum())
        state = "collision-free at every sample" if hits == 0 else f"{hits} colliding samples"
        if self.contacts:
            state += f" (first contact: {self.contacts[0].describe()})"
        robots = "".join(f"; {n}: {r.message}" for n, r in self.robot_reports.items())
        return (
            f"{len(self.tasks)} part moves ({order}); cycle time {self.duration:.3f} s;"
            f" {state}{robots}"
        )

    def index_at(self, t: float) -> int:
        """Return the index of the last sample at or before time t [s] (clamped to the samples),
        as `SampledMotion.index_at` does."""
        k = np.searchsorted(self.times, float(t), side="right") - 1
        return int(np.clip(k, 0, len(self.times) - 1))

    def part_pose(self, name: str, t: float) -> FloatArray:
        """Return part `name`'s world pose (4, 4) at time t [s] (the sample at or before t)."""
        return self.part_poses[name][self.index_at(t)]

    def joints_at(self, robot: str, t: float) -> FloatArray:
        """Return robot `robot`'s joints [rad] at time t [s] (linear between samples)."""
        return self.motions[robot].at(t)


def sample_times(total: float, dt: float) -> FloatArray:
    """Return times (N,) [s] every dt from 0, ending with `total`."""
    n = int(np.floor(total / dt + 1e-9))
    times: FloatArray = np.arange(n + 1, dtype=np.float64) * dt
    if times[-1] < total - 1e-12:
        times = np.append(times, total)
    return times


def arm_motion(
    tasks: Sequence[TaskPlan], q_home: FloatArray, times: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Return joints, velocities, accelerations (N, dof) of one arm through its `tasks` at `times`.

    At rest at home before its first task; each task's trajectory from its t0 (a later task
    takes over from its start), at rest (velocity and acceleration 0) after its end.
    """
    t = np.asarray(times, float).reshape(-1)
    q = np.tile(q_home, (len(t), 1))
    v = np.zeros((len(t), len(q_home)))
    a = np.zeros((len(t), len(q_home)))
    for task in tasks:
        sel = t >= task.t0
        if not sel.any():
            continue
        p_, v_, a_ = task.trajectory.at(t[sel] - task.t0)
        after = t[sel] > task.t1
        v_[after] = 0.0
        a_[after] = 0.0
        q[sel], v[sel], a[sel] = p_, v_, a_
    return q, v, a


def part_poses(
    part: AssemblyPart,
    tasks: Sequence[TaskPlan],
    arms: Mapping[str, AssemblyArm],
    joints: Mapping[str, FloatArray],
    times: FloatArray,
    order: Sequence[str],
) -> tuple[FloatArray, NDArray[np.int64] | None]:
    """Return part `part`'s world poses (N, 4, 4) [m] at `times`, and the samples it is held at.

    Held (the sample indices, None when no task of `tasks` moves it): its robot's TCP
    times the inverse grasp from pick to place; at its goal after. Before, where the
    planner saw it (`order`: the sequence).
    """
    done = assembled_before(order, part.name, tasks[0].part)
    P = np.tile(part.goal if done else part.start, (len(times), 1, 1))
    held_idx = None
    for task in tasks:
        if task.part != part.name:
            continue
        arm = arms[task.robot]
        held = (times >= task.t_pick) & (times <= task.t_place)
        P[held] = arm.tcp_poses(joints[task.robot][held]) @ invert_transform(part.T_part_tcp)
        P[times > task.t_place] = part.goal
        held_idx = np.flatnonzero(held)
    return P, held_idx


def interfering(checker: InterferenceChecker, poses: FloatArray) -> tuple[int, ...]:
    """Return the indices of every pose (P, 4, 4) at which the part interferes."""
    hits: list[int] = []
    s = 0
    while s < len(poses):
        i = checker.first_interference(poses[s:])
        if i < 0:
            break
        hits.append(s + i)
        s += i + 1
    return tuple(hits)
