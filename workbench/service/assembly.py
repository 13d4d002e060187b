"""The open project's virtual assembly (seed 003): parts, start and goal poses, planners, carried parts.

Everything here is SI (m, rad, s); the project's `assembly` section is in mm and degrees.
A part move is planned by `plan_part_path` among the cell's objects and the other parts
(earlier parts of the sequence at their goal, later ones at their start) and the robot that
carries it follows by inverse kinematics in one arm configuration, or (planner
"joint_rrt_connect") it is planned in the carrying robot's joint space, robot and part
checked together; the robot motion is timed by the motion module (ruckig, jerk-limited);
the timed motion is checked again: each robot against the cell and itself (the conservative
engine, spheres + SDF, what it flags confirmed with python-fcl, certified between samples),
each carried part against everything (interference checker), robots against each other and
robots against the parts (`contacts.Bodies`), the last two reported with both bodies and
the time.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.assembly import InterferenceChecker, PartPath, plan_part_path
from workbench.assembly.carry import CarryIK, carry_ik
from workbench.assembly.cells import check_cell_size, check_mesh
from workbench.assembly.contacts import Bodies, Contact
from workbench.assembly.motion import check_pose, interpolate, path_samples, pose_distance
from workbench.assembly.planners.joint_rrt import CarrySpace, plan_carried_path
from workbench.collision import RobotCollisionChecker, Solid
from workbench.collision.engine import EnginePathReport
from workbench.errors import (
    CollisionError,
    InputError,
    MeshError,
    ProjectError,
    UnreachableError,
    WorkbenchError,
)
from workbench.geometry.transforms import invert_transform, make_transform
from workbench.motion import Move, Program, Trajectory, smooth_joint_path
from workbench.motion.programs import csv_text, json_text, to_krl, to_ls, to_rapid, to_urscript
from workbench.motion.validation import acceleration_bound
from workbench.project.assembly import AssemblyPartSpec, AssemblySpec, AssemblyTaskSpec
from workbench.project.models import Robot, Tool
from workbench.service.convert import DEG, MM, load_mesh_file, matrix_to_pose, pose_to_matrix
from workbench.service.motion_plan import EXPORT_FORMATS, check_motion
from workbench.service.robot_setup import RobotSetup, build_robot

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

Progress = Callable[[float, str], None]
KEY_POINT_FORMATS = ("csv", "json")
#: Planners for a part move: the part's pose (seed 003's single ant, RRT-Connect in SE(3)), or
#: the carrying robot's joints (RRT-Connect in joint space, robot and part checked).
PLANNER_CHOICES = ("ant", "rrt_connect", "joint_rrt_connect")
#: Spacing [m] of the TCP samples handed to the motion module along approach, carry, retreat.
PATH_SPACING = 0.02


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


@dataclass(frozen=True, eq=False)
class AssemblyArm:
    """A robot of the cell: its setup, its robot-versus-cell checker and its home joints [rad]."""

    name: str
    setup: RobotSetup
    checker: RobotCollisionChecker
    q_home: NDArray[np.float64]
    color: tuple[int, int, int]
    main: bool


@dataclass(frozen=True, eq=False)
class PartPlan:
    """A planned part move: the planner's key poses, dense part poses, and the carrying robot's joints.

    `path.poses` (K, 4, 4) are the key points; `samples` (M, 4, 4) the part's poses every
    PATH_SPACING [m] of motion along them; `joints` (M, dof) [rad] the carrying robot's
    joints at those samples (None when no robot carries the part).
    """

    part: str
    robot: str | None
    path: PartPath
    samples: NDArray[np.float64]
    joints: NDArray[np.float64] | None
    branch: int

    @property
    def key_points(self) -> NDArray[np.float64]:
        """Return the key poses (K, 4, 4) [m] of the part from start to goal."""
        return self.path.poses


@dataclass(frozen=True, eq=False)
class TaskPlan:
    """One part move of the sequence, timed: robot trajectory from `t0` [s]; held from t_pick to t_place."""

    part: str
    robot: str
    t0: float
    t_pick: float
    t_place: float
    trajectory: Trajectory
    part_plan: PartPlan

    @property
    def t1(self) -> float:
        """Return the end time [s] of the task."""
        return self.t0 + float(self.trajectory.duration)


@dataclass(frozen=True, eq=False)
class AssemblyPlan:
    """The whole sequence on one time axis: samples every dt [s] of every robot and part.

    times (N,) [s]; joints[robot] (N, dof) [rad] (velocities/accelerations likewise);
    part_poses[part] (N, 4, 4) [m]; robot_collisions[robot] and part_interference[part]:
    sample indices where the timed motion hits the cell (robot) or an obstacle (part);
    contacts: every robot–robot and robot–part contact (both bodies, e.g. "MZ07/link3" and
    "part screw_2", sample index and time [s]). robot_reports[robot]: the robot's
    `EnginePathReport` over its active samples (indices of this plan's samples; its
    `message` states the guarantee between samples or the first failure); robot_between[robot]:
    samples i whose interval to i+1 collides, or could not be certified, between them.
    """

    tasks: tuple[TaskPlan, ...]
    times: NDArray[np.float64] = field(repr=False)
    joints: dict[str, NDArray[np.float64]] = field(repr=False)
    velocities: dict[str, NDArray[np.float64]] = field(repr=False)
    accelerations: dict[str, NDArray[np.float64]] = field(repr=False)
    part_poses: dict[str, NDArray[np.float64]] = field(repr=False)
    robot_collisions: dict[str, tuple[int, ...]]
    part_interference: dict[str, tuple[int, ...]]
    contacts: tuple[Contact, ...] = ()
    robot_reports: dict[str, EnginePathReport] = field(default_factory=dict, repr=False)
    robot_between: dict[str, tuple[int, ...]] = field(default_factory=dict)

    @property
    def duration(self) -> float:
        """Return the cycle time of the whole sequence [s]."""
        return float(self.times[-1])

    @property
    def colliding(self) -> NDArray[np.bool_]:
        """Return (N,) True at samples where any robot collides (at the sample or up to the next)
        or any carried part interferes."""
        out = np.zeros(len(self.times), dtype=bool)
        for idx in (
            *self.robot_collisions.values(),
            *self.robot_between.values(),
            *self.part_interference.values(),
        ):
            out[list(idx)] = True
        out[[c.index for c in self.contacts]] = True
        return out

    @property
    def ok(self) -> bool:
        """Return True when no sample collides."""
        return not bool(self.colliding.any())

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

    def part_pose(self, name: str, t: float) -> NDArray[np.float64]:
        """Return part `name`'s world pose (4, 4) at time t [s] (nearest sample)."""
        i = int(np.clip(np.searchsorted(self.times, t), 0, len(self.times) - 1))
        return self.part_poses[name][i]

    def joints_at(self, robot: str, t: float) -> NDArray[np.float64]:
        """Return robot `robot`'s joints [rad] at time t [s] (linear between samples)."""
        q = self.joints[robot]
        return np.array([np.interp(t, self.times, q[:, j]) for j in range(q.shape[1])])


def _interfering(checker: InterferenceChecker, poses: NDArray[np.float64]) -> tuple[int, ...]:
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


def _line(T0: NDArray[np.float64], T1: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return poses (n, 4, 4) from T0 to T1 (both included), every PATH_SPACING [m] of TCP travel."""
    n = max(1, int(np.ceil(float(pose_distance(T0, T1, 0.1)) / PATH_SPACING)))
    return interpolate(T0, T1, np.linspace(0.0, 1.0, n + 1))


class AssemblyService:
    """`Workbench.assembly`: the assembly workflow of the open project (SI units)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
        self._lock = threading.RLock()
        self._parts: dict[str, AssemblyPart] | None = None
        self._arms: dict[str, AssemblyArm] | None = None
        self._checkers: dict[tuple[str, tuple[str, ...], float | None], InterferenceChecker] = {}
        self._fixed: list[tuple[str, trimesh.Trimesh]] | None = None
        self._bodies: Bodies | None = None
        self.last_part_plan: PartPlan | None = None
        self.last_plan: AssemblyPlan | None = None

    # -- the section ---------------------------------------------------------------------
    @property
    def spec(self) -> AssemblySpec:
        """Return the project's `assembly` section; InputError if it has none."""
        spec = self.wb.project.assembly
        if spec is None:
            raise InputError("assembly: the project has no 'assembly' section; add parts to it")
        return spec

    @property
    def available(self) -> bool:
        """Return True when the project has an `assembly` section with at least one part."""
        return self.wb.project.assembly is not None and bool(self.wb.project.assembly.parts)

    @property
    def part_names(self) -> list[str]:
        """Return the part names in the order of the project file."""
        return [p.name for p in self.spec.parts]

    @property
    def parts(self) -> dict[str, AssemblyPart]:
        """Return every part by name, meshes loaded and checked closed (MeshError naming the field)."""
        with self._lock:
            if self._parts is None:
                self._parts = {
                    p.name: self._build_part(i, p) for i, p in enumerate(self.spec.parts)
                }
            return self._parts

    def part(self, name: str) -> AssemblyPart:
        """Return the part called `name`; InputError listing the parts if there is none."""
        parts = self.parts
        if name not in parts:
            raise InputError(f"part {name!r} does not exist; the parts are {list(parts)}")
        return parts[name]

    def _build_part(self, i: int, p: AssemblyPartSpec) -> AssemblyPart:
        where = f"assembly.parts[{i}]"
        if p.shape == "box":
            assert p.size is not None
            mesh = trimesh.creation.box(extents=np.asarray(p.size) * MM)
        elif p.shape == "cylinder":
            assert p.radius is not None and p.height is not None
            mesh = trimesh.creation.cylinder(
                radius=p.radius * MM, height=p.height * MM, sections=32
            )
        else:
            assert p.path is not None
            mesh = load_mesh_file(p.path, self.wb.base_dir, p.scale, f"{where}.path")
        try:
            check_mesh(mesh, f"{where}.path", require_closed=True)
        except MeshError as exc:
            raise MeshError(f"{exc} (part {p.name!r})") from None
        robot = p.robot
        if robot is not None and robot not in self.arms:
            raise ProjectError(
                f"{where}.robot: no robot named {robot!r}; the robots are {list(self.arms)}",
                [(f"{where}.robot", f"unknown robot {robot!r}")],
            )
        r, g, b = p.color
        return AssemblyPart(
            name=p.name,
            mesh=mesh,
            start=pose_to_matrix(p.start),
            goal=pose_to_matrix(p.goal),
            T_part_tcp=pose_to_matrix(p.grasp),
            robot=robot,
            color=(int(r), int(g), int(b)),
        )

    @property
    def arms(self) -> dict[str, AssemblyArm]:
        """Return the cell's robots by name: the project's robot first, then the section's `robots`."""
        with self._lock:
            if self._arms is None:
                wb = self.wb
                cell = [(b.solid, b.T_world_body) for b in wb.cell if b.collide]
                main = wb.project.robot.name
                arms = {
                    main: AssemblyArm(
                        main, wb.setup, wb.checker, wb.joints, (235, 235, 240), main=True
                    )
                }
                for i, r in enumerate(self.spec.robots):
                    where = f"assembly.robots[{i}]"
                    if r.name in arms:
                        raise ProjectError(
                            f"{where}.name: {r.name!r} is already the project's robot; rename it",
                            [(f"{where}.name", "duplicate robot name")],
                        )
                    setup = build_robot(
                        Robot(name=r.name, preset=r.preset, base=r.base, joints=r.joints),
                        Tool(tcp=r.tcp, size=r.tool_size),
                        wb.base_dir,
                    )
                    checker = RobotCollisionChecker(
                        setup.model,
                        setup.link_meshes,
                        T_world_base=setup.T_world_base,
                        tool=setup.tool_mesh,
                        cell=cell,
                        q_reference=setup.q0,
                    )
                    c = r.color
                    arms[r.name] = AssemblyArm(
                        r.name, setup, checker, setup.q0, (int(c[0]), int(c[1]), int(c[2])), False
                    )
                self._arms = arms
            return self._arms

    def fixed_obstacles(self) -> list[tuple[str, trimesh.Trimesh]]:
        """Return (name, world mesh [m]) of every colliding cell object."""
        if self._fixed is None:
            self._fixed = [
                (b.name, b.mesh().copy().apply_transform(b.T_world_body))
                for b in self.wb.cell
                if b.collide
            ]
        return self._fixed

    def sequence(self) -> list[AssemblyTaskSpec]:
        """Return the part moves in order (the section's `sequence`, or every part as listed)."""
        spec = self.spec
        if spec.sequence is not None:
            return list(spec.sequence)
        return [AssemblyTaskSpec(part=p.name) for p in spec.parts]

    def obstacles_for(self, name: str) -> list[tuple[str, trimesh.Trimesh]]:
        """Return (name, world mesh) around part `name`: the cell, earlier parts at goal, the rest at start."""
        order = [t.part for t in self.sequence()]
        me = order.index(name) if name in order else len(order)
        out = list(self.fixed_obstacles())
        for other in self.parts.values():
            if other.name == name:
                continue
            done = other.name in order and order.index(other.name) < me
            T = other.goal if done else other.start
            out.append((other.name, other.mesh.copy().apply_transform(T)))
        return out

    def cell_size(self, name: str, cell_size: float | None = None) -> float:
        """Return the subdivision cell side [m] for part `name` (given, the section's, or 1/20 of it)."""
        part = self.part(name)
        c = cell_size
        field_name = "cell_size"
        if c is None and self.spec.planner.cell_size is not None:
            c = self.spec.planner.cell_size * MM
            field_name = "assembly.planner.cell_size"
        if c is None:
            return float(np.max(part.mesh.extents)) / 20.0
        try:
            return check_cell_size(c, part.mesh, field_name)
        except InputError as exc:
            raise InputError(f"{exc} (part {name!r})") from None

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

    # -- editing -------------------------------------------------------------------------
    def set_pose(self, name: str, which: str, T_world_part: ArrayLike) -> None:
        """Set part `name`'s `which` ("start" or "goal") pose (4, 4) [m]; stored in the project in mm/deg."""
        if which not in ("start", "goal"):
            raise InputError(f"which must be 'start' or 'goal', got {which!r}")
        T = check_pose(T_world_part, which)
        part = self.part(name)
        i = self.part_names.index(name)
        setattr(self.spec.parts[i], which, matrix_to_pose(T))
        with self._lock:
            assert self._parts is not None
            self._parts[name] = AssemblyPart(
                name=part.name,
                mesh=part.mesh,
                start=T if which == "start" else part.start,
                goal=T if which == "goal" else part.goal,
                T_part_tcp=part.T_part_tcp,
                robot=part.robot,
                color=part.color,
            )
            self.last_plan = None

    def interference(self, name: str, T_world_part: ArrayLike | None = None) -> list[str]:
        """Return the names of the obstacles part `name` interferes with at a pose (default: its start)."""
        part = self.part(name)
        T = part.start if T_world_part is None else check_pose(T_world_part, "T_world_part")
        ch = self.checker(name)
        names = [n for n, _ in self.obstacles_for(name)]
        return [names[k] for k in ch.colliding_obstacles(T)]

    # -- planning ------------------------------------------------------------------------
    def planner_options(self, planner: str) -> dict[str, Any]:
        """Return the section's options for `planner` in SI (step, dis [m]; seed, max_time [s])."""
        p = self.spec.planner
        if planner == "ant":
            opts: dict[str, Any] = {"step": p.step}
            if p.dis is not None:
                opts["dis"] = p.dis * MM
            return opts
        opts = {"seed": p.seed, "max_time": p.max_time}
        if planner == "joint_rrt_connect" and p.robot_resolution is not None:
            opts["robot_resolution"] = p.robot_resolution * MM
        return opts

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
            i = self.part_names.index(name)
            raise InputError(
                f"assembly.parts[{i}].robot: part {name!r} has no robot, so it cannot be "
                f"planned in joint space; name one of {list(self.arms)} or pick a pose planner"
            )
        arm = self.arms[part.robot]
        fixed = {n for n, _ in self.fixed_obstacles()}
        others = [
            (Solid(f"part {n}", "mesh", mesh=m), np.eye(4))
            for n, m in self.obstacles_for(name)
            if n not in fixed
        ]
        return CarrySpace(
            arm.checker,
            self.checker(name, cell_size),
            arm.setup.T_flange_tcp,
            part.T_part_tcp,
            extra=others,
            obstacle_names=[n for n, _ in self.obstacles_for(name)],
            resolution=resolution,
            robot_resolution=robot_resolution,
        )

    def plan_part(
        self,
        name: str,
        planner: str | None = None,
        *,
        cell_size: float | None = None,
        progress: Progress | None = None,
        q_start: ArrayLike | None = None,
        **options: Any,
    ) -> PartPlan:
        """Return the PartPlan of part `name` from its start to its goal, with its robot's joints.

        planner: one of PLANNER_CHOICES (default: the section's): "ant" and "rrt_connect"
        plan the part's pose and the robot follows by IK; "joint_rrt_connect" plans the
        carrying robot's joints (options seed, max_time, max_nodes, range_,
        shortcut_iterations, resolution, robot_resolution [m]) from `q_start` [rad] (default:
        the IK solution nearest the robot's home at the part's start). cell_size [m];
        options override the section's planner options (SI). Raises CollisionError when the
        start or goal interferes (naming the obstacles or the robot's bodies), PlanningError
        when no path is found, UnreachableError when the carrying robot cannot follow in one
        configuration or the start or goal is out of its reach.
        """
        report = progress or (lambda f, m: None)
        part = self.part(name)
        planner = planner or self.spec.planner.name
        if planner not in PLANNER_CHOICES:
            raise InputError(f"planner must be one of {PLANNER_CHOICES}, got {planner!r}")
        report(0.05, f"{name}: subdividing into cells")
        ch = self.checker(name, cell_size)
        names = [n for n, _ in self.obstacles_for(name)]
        where = f"assembly.parts[{self.part_names.index(name)}]"
        for which, T in (("start", part.start), ("goal", part.goal)):
            hit = ch.colliding_obstacles(T)
            if hit:
                raise CollisionError(
                    f"{where}.{which}: part {name!r} at its {which} pose interferes with "
                    f"{[names[k] for k in hit]}; move the {which} clear of them"
                )
        report(0.3, f"{name}: planning ({planner})")
        opts = {**self.planner_options(planner), **options}
        if planner == "joint_rrt_connect":
            return self._plan_joint(name, cell_size, opts, q_start, report)
        path = plan_part_path(part.start, part.goal, part.mesh, [], planner, checker=ch, **opts)
        samples = path_samples(path.poses, ch.radius, PATH_SPACING)
        joints: NDArray[np.float64] | None = None
        branch = -1
        if part.robot is not None:
            report(0.7, f"{name}: {part.robot} follows by inverse kinematics")
            arm = self.arms[part.robot]
            ik = self._carry(arm, samples @ part.T_part_tcp, arm.q_home, f"{where} ({name}) path")
            joints, branch = ik.q, ik.branch
        plan = PartPlan(name, part.robot, path, samples, joints, branch)
        self.last_part_plan = plan
        report(1.0, f"{name}: {len(path.poses)} key points")
        return plan

    def _plan_joint(
        self,
        name: str,
        cell_size: float | None,
        opts: dict[str, Any],
        q_start: ArrayLike | None,
        report: Progress,
    ) -> PartPlan:
        space = self.carry_space(
            name,
            cell_size,
            resolution=opts.pop("resolution", None),
            robot_resolution=opts.pop("robot_resolution", None),
        )
        part = self.part(name)
        assert part.robot is not None  # carry_space refused a part without one
        arm = self.arms[part.robot]
        where = f"assembly.parts[{self.part_names.index(name)}]"
        try:
            path = plan_carried_path(
                space, part.start, part.goal, arm.q_home, q_start=q_start, **opts
            )
        except (CollisionError, UnreachableError) as exc:
            raise type(exc)(f"{where} ({name}) carried by {arm.name}: {exc}") from None
        assert path.joints is not None
        # Waypoints for the motion module along each straight joint segment, about every
        # PATH_SPACING of the part's motion (|Δp| + 0.1 m·angle, measured on 16 sub-steps),
        # as the pose planners' samples; the timed motion is checked again afterwards.
        K = path.joints
        dense = [K[:1]]
        u = np.linspace(0.0, 1.0, 17)[:, None]
        for a, b in zip(K[:-1], K[1:], strict=True):
            P = space.part_poses(a + u * (b - a))
            travel = float(np.sum(pose_distance(P[:-1], P[1:], 0.1)))
            n = max(1, int(np.ceil(travel / PATH_SPACING)))
            dense.append(a + (np.arange(1, n + 1) / n)[:, None] * (b - a))
        joints = np.concatenate(dense)
        plan = PartPlan(name, arm.name, path, space.part_poses(joints), joints, path.branch)
        self.last_part_plan = plan
        report(1.0, f"{name}: {len(path.poses)} key points (joint space)")
        return plan

    def _carry(
        self, arm: AssemblyArm, T_world_tcp: NDArray[np.float64], q_near: NDArray, what: str
    ) -> CarryIK:
        s = arm.setup
        return carry_ik(s.model, s.T_world_base, s.T_flange_tcp, T_world_tcp, q_near, what=what)

    def plan_sequence(
        self,
        parts: list[str] | None = None,
        planner: str | None = None,
        *,
        cell_size: float | None = None,
        dt: float = 0.04,
        progress: Progress | None = None,
        **options: Any,
    ) -> AssemblyPlan:
        """Plan the part moves of the sequence, time the robots (ruckig) and check the timed motion.

        parts: only these parts' tasks, in sequence order (default: all). planner, cell_size
        [m] and options as for `plan_part`. dt [s]: sample period of the result. Each task:
        a joint move to the approach pose, a straight approach to the grasp, the carried
        part path, a straight retreat; every robot starts from its home joints. Raises the
        errors of `plan_part` naming the part, InputError for a part with no robot.
        """
        if not (np.isfinite(dt) and 0 < dt <= 0.1):
            raise InputError(f"dt: {dt!r} s must be in (0, 0.1]")
        report = progress or (lambda f, m: None)
        tasks_spec = self.sequence()
        if parts is not None:
            for n in parts:
                self.part(n)
            listed = [t.part for t in tasks_spec]
            tasks_spec = [t for t in tasks_spec if t.part in parts] + [
                AssemblyTaskSpec(part=n) for n in parts if n not in listed
            ]
        if not tasks_spec:
            raise InputError("assembly.parts: there are no parts to assemble; add some")
        q_now = {n: a.q_home.copy() for n, a in self.arms.items()}
        speed = self.spec.speed / 100.0
        tasks: list[TaskPlan] = []
        t0 = 0.0
        n_tasks = len(tasks_spec)
        for k, task in enumerate(tasks_spec):
            part = self.part(task.part)
            if part.robot is None:
                i = self.part_names.index(part.name)
                raise InputError(
                    f"assembly.parts[{i}].robot: part {part.name!r} is in the sequence but no "
                    f"robot carries it; name one of {list(self.arms)}"
                )

            def sub(f: float, m: str, k: int = k) -> None:
                report((k + 0.8 * f) / n_tasks, m)

            arm = self.arms[part.robot]
            pick = part.start @ part.T_part_tcp
            place = part.goal @ part.T_part_tcp
            back = make_transform(np.eye(3), [0.0, 0.0, -task.approach * MM])
            up = make_transform(np.eye(3), [0.0, 0.0, -task.retreat * MM])
            approach = _line(pick @ back, pick)
            retreat = _line(place, place @ up)
            what = f"task {k + 1} ({part.name})"
            if (planner or self.spec.planner.name) == "joint_rrt_connect":
                # The joint path starts where the approach ends and the retreat starts where
                # it ends, so the three share the arm configuration at pick and place.
                ik_a = self._carry(arm, approach, q_now[arm.name], f"{what} approach")
                pp = self.plan_part(
                    part.name,
                    planner,
                    cell_size=cell_size,
                    progress=sub,
                    q_start=ik_a.q[-1],
                    **options,
                )
                assert pp.joints is not None
                ik_r = self._carry(arm, retreat, pp.joints[-1], f"{what} retreat")
                if np.abs(ik_r.q[0] - pp.joints[-1]).max() > 1e-6:
                    raise UnreachableError(
                        f"{what} retreat: the straight retreat from the goal needs another arm "
                        "configuration than the planned one; shorten the retreat or move the goal"
                    )
                q_task = np.concatenate([ik_a.q, pp.joints[1:], ik_r.q[1:]])
                i_pick = len(approach) - 1
                i_place = i_pick + len(pp.joints) - 1
            else:
                pp = self.plan_part(
                    part.name, planner, cell_size=cell_size, progress=sub, **options
                )
                carried = pp.samples @ part.T_part_tcp
                tcp = np.concatenate([approach, carried[1:], retreat[1:]])
                q_task = self._carry(arm, tcp, q_now[arm.name], what).q
                i_pick = len(approach) - 1
                i_place = i_pick + len(carried) - 1
            # Back home after the retreat: the arm leaves the shared workspace to the others.
            waypoints = np.concatenate([q_now[arm.name][None], q_task, arm.q_home[None]])
            model = arm.setup.model
            report((k + 0.85) / n_tasks, f"{part.name}: jerk-limited timing")
            traj = smooth_joint_path(
                waypoints,
                np.asarray(model.max_velocity) * speed,
                np.asarray(model.max_acceleration) * speed,
                np.asarray(model.max_jerk) * speed,
                position_limits=model.limits,
                exact_stop=[0, 1, i_pick + 1, i_place + 1, len(waypoints) - 2, len(waypoints) - 1],
            )
            wt = traj.waypoint_times
            tasks.append(
                TaskPlan(
                    part=part.name,
                    robot=arm.name,
                    t0=t0,
                    t_pick=t0 + float(wt[i_pick + 1]),
                    t_place=t0 + float(wt[i_place + 1]),
                    trajectory=traj,
                    part_plan=pp,
                )
            )
            t0 = tasks[-1].t1
            q_now[arm.name] = arm.q_home.copy()
        report(0.95, "checking the timed motion")
        plan = self._sample(tasks, dt)
        self.last_plan = plan
        report(1.0, plan.summary())
        return plan

    def _sample(self, tasks: list[TaskPlan], dt: float) -> AssemblyPlan:
        total = tasks[-1].t1
        n = int(np.floor(total / dt + 1e-9))
        times: NDArray[np.float64] = np.arange(n + 1, dtype=np.float64) * dt
        if times[-1] < total - 1e-12:
            times = np.append(times, total)
        joints, vel, acc = {}, {}, {}
        for name, arm in self.arms.items():
            dof = arm.setup.model.dof
            q = np.tile(arm.q_home, (len(times), 1))
            v = np.zeros((len(times), dof))
            a = np.zeros((len(times), dof))
            for task in tasks:
                if task.robot != name:
                    continue
                sel = times >= task.t0
                p_, v_, a_ = task.trajectory.at(times[sel] - task.t0)
                after = times[sel] > task.t1
                v_[after] = 0.0
                a_[after] = 0.0
                q[sel], v[sel], a[sel] = p_, v_, a_
            joints[name], vel[name], acc[name] = q, v, a
        poses = {}
        part_hits: dict[str, tuple[int, ...]] = {}
        # Parts outside this plan stand where the planner saw them: assembled if they come
        # before the plan's first part in the sequence, else at their start.
        order = [t.part for t in self.sequence()]
        first = order.index(tasks[0].part) if tasks[0].part in order else len(order)
        for part in self.parts.values():
            done = part.name in order and order.index(part.name) < first
            P = np.tile(part.goal if done else part.start, (len(times), 1, 1))
            mine = [t for t in tasks if t.part == part.name]
            for task in mine:
                arm = self.arms[task.robot]
                held = (times >= task.t_pick) & (times <= task.t_place)
                T_tcp = arm.setup.T_world_base @ arm.setup.model.fk(joints[task.robot][held])
                P[held] = T_tcp @ arm.setup.T_flange_tcp @ invert_transform(part.T_part_tcp)
                P[times > task.t_place] = part.goal
                idx = np.flatnonzero(held)
                hits = _interfering(self.checker(part.name), P[idx])
                part_hits[part.name] = tuple(int(idx[h]) for h in hits)
            poses[part.name] = P
        robot_hits: dict[str, tuple[int, ...]] = {}
        robot_between: dict[str, tuple[int, ...]] = {}
        reports: dict[str, EnginePathReport] = {}
        for name in self.arms:
            rep = self.check_robot(tasks, times, name, joints=joints[name])
            robot_hits[name] = rep.colliding_indices if rep is not None else ()
            robot_between[name] = rep.between_indices if rep is not None else ()
            if rep is not None:
                reports[name] = rep
        return AssemblyPlan(
            tasks=tuple(tasks),
            times=times,
            joints=joints,
            velocities=vel,
            accelerations=acc,
            part_poses=poses,
            robot_collisions=robot_hits,
            part_interference=part_hits,
            contacts=self.cross_contacts(tasks, times, joints, poses),
            robot_reports=reports,
            robot_between=robot_between,
        )

    def check_robot(
        self,
        tasks: list[TaskPlan] | tuple[TaskPlan, ...],
        times: NDArray[np.float64],
        robot: str,
        *,
        joints: NDArray[np.float64] | None = None,
        progress: Progress | None = None,
    ) -> EnginePathReport | None:
        """Return robot `robot`'s check against the cell and itself over its tasks (None if it has none).

        Checked: the plan's samples `times` (N,) [s] within the robot's tasks (its "active"
        samples; `joints` (N, dof) [rad] their joints, default from the tasks' trajectories),
        by the conservative engine with exact confirmation (`check_motion`): the verdict of
        each sample is the dense exact one, and the motion between them is certified on the
        real timed motion (each task's trajectory from its `t0`, at rest at home between
        tasks; |q''| bounded by the largest of the tasks' exact bounds: each task starts and
        ends at rest, so the motion is C1). The tasks' start and end times are checked too
        (they fall between samples). The report's indices are indices into `times`:
        `colliding_indices` the colliding samples, `between_indices` samples i whose interval
        to i+1 collides or could not be certified, `first_index` likewise.
        """
        arm = self.arms[robot]
        mine = [t for t in tasks if t.robot == robot]
        t_all = np.asarray(times, float)
        active = np.zeros(len(t_all), dtype=bool)
        for task in mine:
            active |= (t_all >= task.t0) & (t_all <= task.t1)
        idx = np.flatnonzero(active)
        if not len(idx):
            return None

        def motion(t: NDArray[np.float64]) -> NDArray[np.float64]:
            t = np.asarray(t, float).reshape(-1)
            q = np.tile(arm.q_home, (len(t), 1))
            for task in mine:  # as `_sample`: a later task takes over from its start
                sel = t >= task.t0
                if sel.any():
                    q[sel] = task.trajectory.at(t[sel] - task.t0)[0]
            return q

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
            t_ext, q_ext, arm.checker, sampler=motion, acceleration=acc, progress=progress
        )

        # Back to the plan's sample indices: an extra sample (or an interval) maps to the
        # plan's sample at or before its time.
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

    def cell_bodies(self) -> Bodies:
        """Return every robot body ("robot/link3", "robot/tool") and part ("part name") as `Bodies`.

        Pairs: each robot's bodies against every other robot's, and each robot's moving
        bodies (not its base) against every part.
        """
        with self._lock:
            if self._bodies is None:
                solids: list[Solid] = []
                owner: list[str] = []
                for name, arm in self.arms.items():
                    for body, entry in arm.checker.scene.moving.items():
                        solids.append(Solid(f"{name}/{body}", "mesh", mesh=entry.mesh))
                        owner.append(name)
                for part in self.parts.values():
                    solids.append(Solid(f"part {part.name}", "mesh", mesh=part.mesh))
                    owner.append("")
                names = [sol.name for sol in solids]
                base = {f"{n}/{a.checker.link_names[0]}" for n, a in self.arms.items()}
                pairs = []
                for i, a in enumerate(names):
                    for j in range(i + 1, len(names)):
                        if owner[i] and owner[j] and owner[i] != owner[j]:
                            pairs.append((a, names[j]))  # robot - robot
                        elif owner[i] and not owner[j] and a not in base:
                            pairs.append((a, names[j]))  # robot - part
                self._bodies = Bodies(solids, pairs)
            return self._bodies

    def cross_contacts(
        self,
        tasks: list[TaskPlan],
        times: NDArray[np.float64],
        joints: dict[str, NDArray[np.float64]],
        part_poses: dict[str, NDArray[np.float64]],
    ) -> tuple[Contact, ...]:
        """Return the robot–robot and robot–part contacts of sampled motions, in time order.

        joints[robot] (N, dof) [rad] and part_poses[part] (N, 4, 4) [m] at times (N,) [s].
        A carrying robot's tool touches its own part from the approach to the retreat of
        that task by design: that one pair is not checked during the task [t0, t1].
        """
        bodies = self.cell_bodies()
        N = len(times)
        P = np.empty((N, len(bodies.names), 4, 4))
        k = 0
        for name, arm in self.arms.items():
            L = arm.setup.T_world_base @ arm.setup.model.link_transforms(joints[name])
            for body in arm.checker.scene.moving:
                frame = arm.checker.link_names.index(body) if body != "tool" else L.shape[1] - 1
                P[:, k] = L[:, frame]
                k += 1
        for part in self.parts.values():
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

    # -- export --------------------------------------------------------------------------
    def robot_program(self, robot: str, plan: AssemblyPlan | None = None) -> Program:
        """Return robot `robot`'s part of the sequence (default: the last plan) as a `Program`.

        One joint move per waypoint the motion module timed (approach pose, approach, the
        carried path every 20 mm, retreat), at the section's speed; exact stops at the
        approach pose, the pick and the place, 5 mm blends elsewhere.
        """
        plan = plan or self.last_plan
        if plan is None:
            raise WorkbenchError("no sequence has been planned yet; plan the sequence first")
        if robot not in self.arms:
            raise InputError(f"robot {robot!r} does not exist; the robots are {list(self.arms)}")
        speed = self.spec.speed / 100.0
        moves = []
        for k, task in enumerate(plan.tasks):
            if task.robot != robot:
                continue
            wp = task.trajectory.waypoints
            stops = {1, len(wp) - 2, len(wp) - 1} | {
                int(np.argmin(np.abs(task.trajectory.waypoint_times - (t - task.t0))))
                for t in (task.t_pick, task.t_place)
            }
            for i in range(1, len(wp)):
                moves.append(
                    Move.joint(
                        wp[i],
                        speed=speed,
                        zone=0.0 if i in stops else 0.005,
                        name=f"t{k + 1}_{i}",
                    )
                )
        if not moves:
            raise InputError(f"robot {robot!r} carries no part in the planned sequence")
        name = "".join(c if c.isalnum() else "_" for c in f"assembly_{robot}")[:24]
        return Program(name, tuple(moves))

    def export_program(self, robot: str, fmt: str, plan: AssemblyPlan | None = None) -> str:
        """Return robot `robot`'s motion of the last sequence as rapid, krl, ls, urscript, csv or json.

        csv and json hold the timed joint samples [s, deg]; the others a robot program.
        """
        if fmt not in EXPORT_FORMATS:
            raise InputError(f"format: {fmt!r} is not one of {', '.join(EXPORT_FORMATS)}")
        plan = plan or self.last_plan
        program = self.robot_program(robot, plan)
        assert plan is not None
        if fmt == "csv":
            return csv_text(plan.times, plan.joints[robot])
        if fmt == "json":
            return json_text(plan.times, plan.joints[robot])
        post = {"rapid": to_rapid, "krl": to_krl, "ls": to_ls, "urscript": to_urscript}[fmt]
        return str(post(program))

    def export_key_points(self, fmt: str, plan: PartPlan | None = None) -> str:
        """Return the key points of a part plan (default: the last one) as CSV or JSON text (mm, deg).

        Columns: index, x, y, z [mm], roll, pitch, yaw [deg] (R = Rz·Ry·Rx), and for a carried
        part the carrying robot's joints [deg] at that key point.
        """
        if fmt not in KEY_POINT_FORMATS:
            raise InputError(f"fmt must be one of {KEY_POINT_FORMATS}, got {fmt!r}")
        plan = plan or self.last_part_plan
        if plan is None:
            raise WorkbenchError("no part has been planned yet; plan a part first")
        rows = []
        for i, T in enumerate(plan.key_points):
            pose = matrix_to_pose(T)
            row: dict[str, Any] = {
                "index": i,
                "x": pose.xyz[0],
                "y": pose.xyz[1],
                "z": pose.xyz[2],
                "roll": pose.rpy[0],
                "pitch": pose.rpy[1],
                "yaw": pose.rpy[2],
            }
            if plan.joints is not None:
                j = int(np.argmin(np.linalg.norm(plan.samples[:, :3, 3] - T[:3, 3], axis=1)))
                row.update({f"j{k + 1}": float(v / DEG) for k, v in enumerate(plan.joints[j])})
            rows.append(row)
        if fmt == "json":
            return json.dumps(
                {
                    "part": plan.part,
                    "planner": plan.path.planner,
                    "robot": plan.robot,
                    "units": {
                        "position": "mm",
                        "orientation": "deg (R = Rz(yaw) Ry(pitch) Rx(roll))",
                    },
                    "key_points": rows,
                },
                indent=2,
            )
        buf = io.StringIO()
        writer = csv.DictWriter(buf, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        for r in rows:
            writer.writerow({k: (f"{v:.4f}" if isinstance(v, float) else v) for k, v in r.items()})
        return buf.getvalue()
