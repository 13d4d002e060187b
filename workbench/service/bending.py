"""The open project's press-brake bending (seed 000): the part, its bend sequence, the grasp, OBB-tree checks and the plan.

SI units (m, rad, s). The project's `bending` section (mm, deg) is converted here.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import shapely
from numpy.typing import ArrayLike, NDArray
from pydantic import ValidationError

from workbench.collision.engine import EnginePathReport
from workbench.errors import InputError, ProjectError, UnreachableError
from workbench.geometry.obb import OBB, obb_overlap
from workbench.geometry.transforms import invert_transform, make_transform, rot_x, rot_z
from workbench.motion import Trajectory, smooth_joint_path
from workbench.project.bending import BendingSpec, PartSpec
from workbench.project.io import problems_from
from workbench.service.convert import DEG, MM, pose_to_matrix
from workbench.service.motion_plan import check_trajectory
from workbench.sheetmetal import FoldedState, FramesReport, OBBTree, SheetMetalPart
from workbench.sheetmetal.obstacles import ExactShape, Obstacles, confirm_exact

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

Progress = Callable[[float, str], None]


@dataclass(frozen=True, eq=False)
class DiePlacement:
    """The robot holding the part with bend `bend` (sequence index `step`) on the die."""

    bend: str
    step: int
    T_world_part: NDArray[np.float64]  # (4, 4) [m]
    T_world_tcp: NDArray[np.float64]  # (4, 4) [m]
    q: NDArray[np.float64]  # (dof,) [rad]


@dataclass(frozen=True)
class FirstCollision:
    """The first colliding transfer frame: what hit what (part flanges or robot bodies).

    `between`: the robot collides (or could not be certified free: no bodies named) between
    frame `frame` and the next, at `time` [s]; the frames themselves are free.
    """

    frame: int
    time: float  # [s]
    kind: str  # "part" or "robot"
    flanges: tuple[str, ...]
    obstacles: tuple[str, ...]
    between: bool = False

    def describe(self) -> str:
        """Return one line naming the frame, the flange(s) or robot body and the obstacle(s)."""
        what = (
            f"flange {', '.join(repr(f) for f in self.flanges)}"
            if self.kind == "part"
            else f"robot {', '.join(self.flanges)}"
        )
        where = (
            f"between frames {self.frame + 1} and {self.frame + 2}"
            if self.between
            else f"frame {self.frame + 1}"
        )
        if self.between and not self.flanges:
            return (
                f"{where} (t = {self.time:.3f} s): robot clearance below what the check"
                " resolves; treat it as touching"
            )
        return (
            f"{where} (t = {self.time:.3f} s): {what} hits "
            f"{', '.join(repr(o) for o in self.obstacles)}"
        )


@dataclass(frozen=True, eq=False)
class BendingPlan:
    """Die placements for every bend, and the checked transfer from the press brake to the pallet.

    Per transfer frame (F,): `times` [s], `joints` (F, dof) [rad], `T_world_grasp` (F, 4, 4)
    [m] of the gripped flange, OBB tests of the tree and of the flat per-flange loop, and the
    check times [s] of both. The part is checked by its OBB tree; the robot (links and tool,
    not the part it holds) by the conservative engine: `robot_colliding` is the exact verdict
    of each frame, `robot_between` (F,) marks frames whose interval to the next collides (or
    could not be certified), and `robot_report` (an `EnginePathReport`) states the guarantee
    between frames or the first failure.
    """

    placements: tuple[DiePlacement, ...]
    configuration: str
    trajectory: Trajectory = field(repr=False)
    times: NDArray[np.float64]
    joints: NDArray[np.float64]
    T_world_grasp: NDArray[np.float64]
    T_world_part: NDArray[np.float64]
    part_report: FramesReport
    tree_tests: NDArray[np.int64]
    flat_tests: NDArray[np.int64]
    tree_seconds: NDArray[np.float64]
    flat_seconds: NDArray[np.float64]
    part_colliding: NDArray[np.bool_]
    robot_colliding: NDArray[np.bool_]
    first_collision: FirstCollision | None
    obstacle_names: tuple[str, ...]
    robot_report: EnginePathReport | None = None
    robot_between: NDArray[np.bool_] | None = None

    @property
    def colliding(self) -> NDArray[np.bool_]:
        """Return (F,) frames where the part or the robot collides (at the frame or up to the next)."""
        out = self.part_colliding | self.robot_colliding
        return out if self.robot_between is None else out | self.robot_between

    @property
    def ok(self) -> bool:
        """Return True when every transfer frame is collision-free."""
        return self.first_collision is None

    def summary(self) -> str:
        """Return a short human summary (markdown)."""
        F = len(self.times)
        free = ~self.part_colliding
        ratio = (
            self.tree_tests[free].sum() / max(self.flat_tests[free].sum(), 1) if free.any() else 0
        )
        head = (
            f"{len(self.placements)} bends placed on the die ({self.configuration}); transfer "
            f"{self.trajectory.duration:.2f} s, {F} frames checked. OBB tests on free frames: "
            f"tree/flat = {ratio:.2f}."
        )
        robot = f" Robot: {self.robot_report.message}." if self.robot_report is not None else ""
        if self.first_collision is None:
            return head + " Collision-free." + robot
        return head + f" First collision: {self.first_collision.describe()}." + robot


@dataclass(frozen=True, eq=False)
class Playback:
    """The transfer sampled for the timeline: times [s], joints, velocities, accelerations, TCP speed [m/s]."""

    times: NDArray[np.float64]
    positions: NDArray[np.float64]
    velocities: NDArray[np.float64]
    accelerations: NDArray[np.float64]
    tcp_speed: NDArray[np.float64]
    colliding: NDArray[np.bool_]


def part_spec_to_si(spec: PartSpec, sequence: Sequence[str] | None) -> dict[str, Any]:
    """Return the SI spec of `SheetMetalPart.from_spec` from a part section in mm/deg."""
    return {
        "thickness": spec.thickness * MM,
        "k_factor": spec.k_factor,
        "flanges": [{"name": f.name, "polygon": np.asarray(f.polygon) * MM} for f in spec.flanges],
        "bends": [
            {
                "name": b.name,
                "parent": b.parent,
                "parent_edge": b.parent_edge,
                "child": b.child,
                "child_edge": b.child_edge,
                "included_angle": b.included_angle * DEG,
                "inner_radius": b.inner_radius * MM,
                "direction": b.direction,
                "k_factor": b.k_factor,
            }
            for b in spec.bends
        ],
        "sequence": list(sequence) if sequence is not None else spec.sequence,
    }


def flat_loop(tree: OBBTree, obstacles: OBB, T_world_grasp: NDArray[np.float64]) -> bool:
    """Return the seed's baseline verdict of one pose (4, 4): a loop over flanges, each box vs every obstacle."""
    leaves = tree.boxes[tree.leaves].transformed(T_world_grasp)
    hit = False
    for k in range(len(tree.leaves)):
        hit |= bool(obb_overlap(leaves[k], obstacles).any())
    return hit


def _time_checks(
    tree: OBBTree, obstacles: OBB, T: NDArray[np.float64], repeat: int = 3
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return per-frame check times [s] (best of `repeat`) of the tree DFS and the flat loop."""
    F = len(T)
    tree_s, flat_s = np.full(F, np.inf), np.full(F, np.inf)
    for _ in range(repeat):
        for f in range(F):
            t0 = time.perf_counter()
            tree.collide(obstacles, T[f])
            t1 = time.perf_counter()
            flat_loop(tree, obstacles, T[f])
            t2 = time.perf_counter()
            tree_s[f], flat_s[f] = min(tree_s[f], t1 - t0), min(flat_s[f], t2 - t1)
    return tree_s, flat_s


class BendingService:
    """`Workbench.bending`: the bending workflow of the open project (SI units)."""

    def __init__(self, wb: Workbench) -> None:
        self.wb = wb
        self._part: SheetMetalPart | None = None
        self._part_spec: PartSpec | None = None
        self._plan: BendingPlan | None = None

    # -- project section ------------------------------------------------------------------
    @property
    def spec(self) -> BendingSpec:
        """Return the project's `bending` section; InputError when the project has none."""
        spec = self.wb.project.bending
        if spec is None:
            raise InputError("bending: the project has no 'bending' section; add one (see docs)")
        return spec

    @property
    def available(self) -> bool:
        """Return True when the project has a `bending` section."""
        return self.wb.project.bending is not None

    def part_spec(self) -> PartSpec:
        """Return the part section (inline, or read from `part_file`, validated)."""
        if self._part_spec is None:
            spec = self.spec
            if spec.part is not None:
                self._part_spec = spec.part
            else:
                assert spec.part_file is not None
                p = Path(spec.part_file)
                p = p if p.is_absolute() else self.wb.base_dir / p
                try:
                    data = json.loads(p.read_text())
                except OSError:
                    raise ProjectError(
                        f"bending.part_file: cannot read {p}; fix the path (relative to the project file)"
                    ) from None
                except json.JSONDecodeError as exc:
                    raise ProjectError(f"bending.part_file: {p} is not valid JSON: {exc}") from None
                try:
                    self._part_spec = PartSpec.model_validate(data)
                except ValidationError as exc:
                    problems = [(f"bending.part_file:{path}", m) for path, m in problems_from(exc)]
                    lines = "; ".join(f"{a}: {b}" for a, b in problems)
                    raise ProjectError(f"bending.part_file ({p}): {lines}", problems) from None
        return self._part_spec

    @property
    def part(self) -> SheetMetalPart:
        """Return the part with the project's bend sequence (checked: no flange bent into another)."""
        if self._part is None:
            part = self._build_part(self.spec.sequence)
            names = [f.name for f in part.flanges]
            if self.spec.grasp.flange not in names:
                raise InputError(
                    f"bending.grasp.flange: no flange {self.spec.grasp.flange!r}; flanges are {names}"
                )
            self._part = part
        return self._part

    def _build_part(self, sequence: Sequence[str] | None) -> SheetMetalPart:
        ps = self.part_spec()
        try:
            return SheetMetalPart.from_spec(part_spec_to_si(ps, sequence))
        except InputError as exc:
            raise InputError(f"bending.part: {exc}") from None

    @property
    def sequence(self) -> list[str]:
        """Return the bend names in sequence order."""
        return [b.name for b in self.part.bends]

    def set_sequence(self, names: Sequence[str]) -> None:
        """Use bend sequence `names`; InputError if it repeats, misses or names unknown bends, or is infeasible."""
        names = [str(n).strip() for n in names]
        bends = [b.name for b in self.part_spec().bends]
        dup = sorted({n for n in names if names.count(n) > 1})
        missing = [n for n in bends if n not in names]
        unknown = [n for n in names if n not in bends]
        if dup or missing or unknown:
            raise InputError(
                f"sequence: must name every bend exactly once; repeated {dup}, missing {missing}, "
                f"unknown {unknown} (bends are {bends})"
            )
        part = self._build_part(names)  # raises when a flange is bent into another
        self.spec.sequence = names
        self._part, self._plan = part, None

    @property
    def grasp_flange(self) -> str:
        """Return the name of the gripped flange."""
        return self.spec.grasp.flange

    def grasp_offset(self) -> NDArray[np.float64]:
        """Return the grasp point (2,) [m] in the gripped flange's polygon frame."""
        g = self.spec.grasp
        if g.offset is not None:
            return np.asarray(g.offset, float) * MM
        poly = self.part.flanges[self.part.flange_index(g.flange)].polygon
        c = shapely.Polygon(poly).centroid
        return np.array([c.x, c.y])

    def set_grasp(
        self, flange: str, offset: ArrayLike | None = None, yaw: float | None = None
    ) -> None:
        """Grip `flange` at `offset` (2,) [m] in its polygon frame (None: centroid), gripper `yaw` [rad]."""
        names = [f.name for f in self.part.flanges]
        if flange not in names:
            raise InputError(f"grasp.flange: no flange {flange!r}; flanges are {names}")
        off = None
        if offset is not None:
            off = np.asarray(offset, float)
            if off.shape != (2,) or not np.all(np.isfinite(off)):
                raise InputError(f"grasp.offset: expected 2 finite numbers [m], got {offset!r}")
            poly = shapely.Polygon(self.part.flanges[names.index(flange)].polygon)
            if not poly.buffer(1e-9).contains(shapely.Point(*off)):
                raise InputError(
                    f"grasp.offset: ({off[0] / MM:.1f}, {off[1] / MM:.1f}) mm lies outside flange "
                    f"{flange!r}; pick a point on it"
                )
        if yaw is not None and not np.isfinite(yaw):
            raise InputError(f"grasp.yaw: must be finite, got {yaw!r}")
        g = self.spec.grasp
        g.flange = flange
        g.offset = None if off is None else [float(v / MM) for v in off]
        if yaw is not None:
            g.yaw = float(yaw / DEG)
        self._plan = None

    # -- part states --------------------------------------------------------------------
    def fold(self, step: float) -> FoldedState:
        """Return the part after `step` bends of the sequence (float: partway, for animation)."""
        return self.part.fold(step)

    def tree(self, step: int | None = None) -> OBBTree:
        """Return the OBB tree of the part after `step` bends (default: all), rooted at the grasp."""
        s = len(self.part.bends) if step is None else step
        return self.part.fold(s).obb_tree(self.grasp_flange)

    def T_flange_grasp(self) -> NDArray[np.float64]:
        """Return the TCP pose (4, 4) [m] in the gripped flange's frame: on its top face, z into the sheet."""
        off = self.grasp_offset()
        R = rot_z(self.spec.grasp.yaw * DEG) @ rot_x(np.pi)
        return make_transform(R, [off[0], off[1], self.part.thickness / 2])

    # -- obstacles ----------------------------------------------------------------------
    def obstacles(self) -> Obstacles:
        """Return the cell's colliding objects as OBBs [m] (cylinders and meshes confirmed exactly)."""
        names, centers, rots, halves, exact = [], [], [], [], []
        for body in self.wb.cell:
            if not body.collide:
                continue
            T, s = body.T_world_body, body.solid
            if s.kind == "box":
                assert s.size is not None
                c, R, h = T[:3, 3], T[:3, :3], np.asarray(s.size) / 2
                shape = None
            elif s.kind == "cylinder":
                assert s.radius is not None and s.height is not None
                c, R, h = T[:3, 3], T[:3, :3], np.array([s.radius, s.radius, s.height / 2])
                shape = ExactShape(s.fcl_geometry(), T)
            else:
                mesh = s.to_trimesh().copy()
                mesh.apply_transform(T)
                box = OBB.from_points(mesh.vertices)
                c, R, h = box.center, box.rotation, box.half_extents
                shape = ExactShape(s.fcl_geometry(), T, mesh if mesh.is_watertight else None)
            names.append(body.name)
            centers.append(c)
            rots.append(R)
            halves.append(h)
            exact.append(shape)
        if not names:
            return Obstacles((), OBB(np.zeros((0, 3)), np.zeros((0, 3, 3)), np.zeros((0, 3))), ())
        return Obstacles(
            tuple(names), OBB(np.array(centers), np.array(rots), np.array(halves)), tuple(exact)
        )

    # -- process ------------------------------------------------------------------------
    def die_part_pose(self, step: int) -> NDArray[np.float64]:
        """Return T_world_part (4, 4) [m] with bend number `step` of the sequence on the die.

        The bend line (the middle of its bend zone) lies on the die's x axis, the sheet's outer
        side on the die, the inner side up (towards the punch); the gripped flange on the
        robot's (-y) side. Raises InputError when the bend line is longer than the die.
        """
        part = self.part
        if not 0 <= step < len(part.bends):
            raise InputError(f"step: must be in 0..{len(part.bends) - 1}, got {step}")
        b = part.bends[step]
        die = self.spec.die
        if part.bend_lengths[step] > die.length * MM + 1e-9:
            raise InputError(
                f"bend {b.name!r}: its bend line is {part.bend_lengths[step] / MM:.1f} mm long; the die "
                f"is {die.length:g} mm (bending.die.length): it does not fit"
            )
        state = part.fold(step)
        geo = state.bend_cross_section(step)
        w = geo["w"]
        mid = (geo["pa"] + geo["pb"]) / 2 + geo["n"] * part.bend_allowances[step] / 2
        T_parent_line = make_transform(
            np.column_stack([geo["d"], np.cross(w, geo["d"]), w]), mid - w * part.thickness / 2
        )
        T_part_line = state.T_part_flange[b.parent] @ T_parent_line
        g = part.flange_index(self.grasp_flange)
        grasp = state.T_part_flange[g] @ self.T_flange_grasp()
        if (invert_transform(T_part_line) @ grasp)[1, 3] > 0:
            T_part_line = T_part_line @ make_transform(rot_z(np.pi), np.zeros(3))
        return pose_to_matrix(die.pose) @ invert_transform(T_part_line)

    def _T_part_tcp(self, step: int) -> NDArray[np.float64]:
        state = self.part.fold(step)
        g = self.part.flange_index(self.grasp_flange)
        return state.T_part_flange[g] @ self.T_flange_grasp()

    def _ik(
        self, T_world_tcp: NDArray[np.float64], names: list[str], q_start: NDArray[np.float64]
    ) -> tuple[NDArray[np.float64], str]:
        """Return joints (N, dof) reaching the TCP poses (N, 4, 4) with one arm configuration."""
        setup, model = self.wb.setup, self.wb.robot
        Tb = (
            invert_transform(setup.T_world_base)
            @ T_world_tcp
            @ invert_transform(setup.T_flange_tcp)
        )
        if getattr(model, "is_analytic", False):
            from workbench.kinematics import branch_name

            qb, valid = model.ik_batch(Tb, q_near=q_start)
            none = [names[i] for i in range(len(names)) if not valid[i].any()]
            if none:
                raise UnreachableError(
                    f"{none[0]}: unreachable within the joint limits with the grasp on flange "
                    f"{self.grasp_flange!r}; move the die/pallet, change the grasp or the sequence"
                )
            common = np.flatnonzero(valid.all(axis=0))
            if len(common) == 0:
                best = int(np.argmax(valid.sum(axis=0)))
                bad = [names[i] for i in range(len(names)) if not valid[i, best]]
                raise UnreachableError(
                    f"{bad[0]}: no single arm configuration reaches every pose "
                    f"(configuration {branch_name(best)} misses {bad}); change the grasp or the die pose"
                )
            cost = [float(np.linalg.norm(qb[:, b] - q_start, axis=1).sum()) for b in common]
            b = int(common[int(np.argmin(cost))])
            q = np.array(qb[:, b])
            # Re-solve one by one so wide joints take the turn nearest the previous pose.
            for i in range(1, len(q)):
                qi, ok = model.ik_batch(Tb[i : i + 1], q_near=q[i - 1])
                if ok[0, b]:
                    q[i] = qi[0, b]
            return q, branch_name(b)
        rows = []
        near = q_start
        for T, name in zip(Tb, names, strict=True):
            sol = np.asarray(model.ik(T, q_near=near), float).reshape(-1, model.dof)
            if len(sol) == 0:
                raise UnreachableError(f"{name}: unreachable within the joint limits")
            near = sol[0]
            rows.append(near)
        return np.array(rows), "numeric IK"

    def placements(self) -> tuple[tuple[DiePlacement, ...], str]:
        """Return each bend's die placement with one arm configuration, and its label.

        Raises UnreachableError naming the bend the robot cannot hold on the die.
        """
        part = self.part
        steps = range(len(part.bends))
        T_part = [self.die_part_pose(s) for s in steps]
        T_tcp = np.array([T_part[s] @ self._T_part_tcp(s) for s in steps])
        names = [f"bend {part.bends[s].name!r} (step {s + 1}) on the die" for s in steps]
        q, label = self._ik(T_tcp, names, self.wb.joints)
        return tuple(
            DiePlacement(part.bends[s].name, s, T_part[s], T_tcp[s], q[s]) for s in steps
        ), label

    def transfer_poses(self, last: DiePlacement) -> tuple[NDArray[np.float64], list[str]]:
        """Return TCP poses (N, 4, 4) [m] of the transfer: retract, via poses, pallet; with names."""
        spec = self.spec
        R_die = pose_to_matrix(spec.die.pose)[:3, :3]
        ret = last.T_world_tcp.copy()
        ret[:3, 3] += R_die @ (np.asarray(spec.retract) * MM)
        vias = [pose_to_matrix(p) for p in spec.transfer]
        n = len(self.part.bends)
        drop = pose_to_matrix(spec.pallet) @ self._T_part_tcp(n)
        names = (
            ["bending.retract"]
            + [f"bending.transfer[{i}]" for i in range(len(vias))]
            + ["bending.pallet"]
        )
        return np.array([ret, *vias, drop]), names

    def plan(self, *, progress: Progress | None = None) -> BendingPlan:
        """Place every bend on the die, then plan and check the transfer to the pallet.

        The transfer is a jerk-limited (ruckig) joint trajectory; `frames` (>= 22) evenly
        timed frames are checked: the part with its OBB tree against the cell (leaf hits on
        cylinders and meshes confirmed with python-fcl) and the robot's links and tool by the
        conservative engine (`check_trajectory`: spheres + SDF at every frame, what it flags
        confirmed with python-fcl, the motion between frames certified on the trajectory).
        `progress(fraction, message)` reports the stages.
        """
        report = progress or (lambda f, m: None)
        model = self.wb.robot
        report(0.0, "placing each bend line on the die")
        placements, label = self.placements()
        report(0.25, "planning the transfer")
        T_tcp, names = self.transfer_poses(placements[-1])
        q_way, _ = self._ik(T_tcp, names, placements[-1].q)
        traj = smooth_joint_path(
            q_way,
            model.max_velocity,
            model.max_acceleration,
            model.max_jerk,
            position_limits=model.limits,
            exact_stop=[0, len(q_way) - 1],
        )
        F = int(self.spec.frames)
        times = np.linspace(0.0, traj.duration, F)
        q = traj.at(times)[0]
        setup = self.wb.setup
        T_world_tcp = setup.T_world_base @ model.fk(q) @ setup.T_flange_tcp
        T_world_grasp = T_world_tcp @ invert_transform(self.T_flange_grasp())
        n = len(self.part.bends)
        T_world_part = T_world_tcp @ invert_transform(self._T_part_tcp(n))
        report(0.4, f"checking {F} frames with the OBB tree")
        tree = self.tree()
        obst = self.obstacles()
        rep = confirm_exact(
            tree, tree.collide_frames(obst.boxes, T_world_grasp), obst, T_world_grasp
        )
        flat = tree.flat_collide_frames(obst.boxes, T_world_grasp)
        tree_s, flat_s = _time_checks(tree, obst.boxes, T_world_grasp)
        report(0.7, "checking the robot against the cell")
        # The checker holds the robot's links and tool, not the part: the tool and the part it
        # grips are never a pair, and the part's own checks are the tree's above.
        path = check_trajectory(
            traj, times, q, self.wb.checker, progress=lambda f, m: report(0.7 + 0.25 * f, m)
        )
        robot_hit = np.zeros(F, dtype=bool)
        robot_hit[list(path.colliding_indices)] = True
        robot_between = np.zeros(F, dtype=bool)
        robot_between[list(path.between_indices)] = True
        first = None
        hit_frames = np.flatnonzero(rep.collides | robot_hit)
        if path.between and path.first_index is not None and path.first_time is not None:
            # The robot's first failure lies between two free frames, before any frame hit.
            if not len(hit_frames) or path.first_time < times[hit_frames[0]]:
                first = FirstCollision(
                    path.first_index,
                    float(path.first_time),
                    "robot",
                    (path.link,) if path.link else (),
                    (path.obstacle,) if path.obstacle else (),
                    between=True,
                )
        if len(hit_frames) and first is None:
            f0 = int(hit_frames[0])
            if rep.collides[f0]:
                fr = rep.frame(f0)
                first = FirstCollision(
                    f0,
                    float(times[f0]),
                    "part",
                    tuple(self.part.flanges[i].name for i in fr.hit_flanges),
                    tuple(obst.names[i] for i in fr.hit_obstacles),
                )
            else:
                rr = self.wb.checker.check(q[f0], distance=False)
                first = FirstCollision(
                    f0,
                    float(times[f0]),
                    "robot",
                    tuple(a for a, _ in rr.colliding),
                    tuple(b for _, b in rr.colliding),
                )
        plan = BendingPlan(
            placements=placements,
            configuration=label,
            trajectory=traj,
            times=times,
            joints=q,
            T_world_grasp=T_world_grasp,
            T_world_part=T_world_part,
            part_report=rep,
            tree_tests=rep.n_obb_tests,
            flat_tests=flat.n_obb_tests,
            tree_seconds=tree_s,
            flat_seconds=flat_s,
            part_colliding=rep.collides,
            robot_colliding=robot_hit,
            first_collision=first,
            obstacle_names=obst.names,
            robot_report=path,
            robot_between=robot_between,
        )
        self._plan = plan
        report(1.0, "done")
        return plan

    @property
    def last_plan(self) -> BendingPlan | None:
        """Return the latest plan (None before `plan`, or after the sequence or grasp changed)."""
        return self._plan

    def part_pose_at(self, plan: BendingPlan, t: float) -> NDArray[np.float64]:
        """Return T_world_part (4, 4) [m] of the folded part carried by the robot at time `t` [s]."""
        q = plan.trajectory.at([t])[0][0]
        setup = self.wb.setup
        T_tcp = setup.T_world_base @ self.wb.robot.fk(q) @ setup.T_flange_tcp
        return T_tcp @ invert_transform(self._T_part_tcp(len(self.part.bends)))  # type: ignore[no-any-return]

    def playback(self, plan: BendingPlan, dt: float = 0.02) -> Playback:
        """Return the transfer sampled every `dt` [s] for the timeline, frames' verdicts carried over."""
        t, p, v, a = plan.trajectory.sample(dt)
        setup = self.wb.setup
        tcp = (setup.T_world_base @ self.wb.robot.fk(p) @ setup.T_flange_tcp)[:, :3, 3]
        speed = np.r_[0.0, np.linalg.norm(np.diff(tcp, axis=0), axis=1) / np.diff(t)]
        k = np.clip(np.searchsorted(plan.times, t, side="right") - 1, 0, len(plan.times) - 1)
        return Playback(t, p, v, a, speed, plan.colliding[k])
