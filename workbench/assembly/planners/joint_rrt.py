"""RRT-Connect in the joint space of a robot carrying a part, with IK for the grasp and shortcutting.

A pose-space path of the part may exist that the robot cannot follow without hitting
something (its arm sweeps through an obstacle the part passes by). This planner works on
the robot's joints instead: a configuration is valid when the carried part (at
T_world_base · fk(q) · T_flange_tcp · T_part_tcp⁻¹) interferes with nothing
(`InterferenceChecker`), the robot's links and tool touch neither the cell nor the
other parts nor each other (the pairs of `RobotCollisionChecker`), and the part touches
none of the robot's links that move relative to it (all but the flange link and the tool,
which are rigid with the grasp); python-fcl after an AABB broad phase, see `contacts.Bodies`.

Motions are straight in joint space. Along one, a point fixed on link k moves at most
Σ_j |Δq_j|·lever_kj [m] (`collision.motion_bound.JointLevers`: lever_kj bounds the point's
distance from joint j's axis over all configurations), so an edge is checked at
n = ceil(max(Σ_j |Δq_j|·lever_part_j / resolution, max_k Σ_j |Δq_j|·lever_kj / robot_resolution))
evenly spaced configurations: no point of the part moves more than `resolution` (the cell
size) and no point of the robot more than `robot_resolution` between two checks. The
samples of an edge are checked coarse to fine (bisection order), so a blocked edge is
usually refused after a few checks. The distance between configurations is the same
bound, Σ_j |Δq_j|·w_j with w_j the largest lever of joint j [m].
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.assembly.carry import carry_ik
from workbench.assembly.contacts import Bodies
from workbench.assembly.interference import InterferenceChecker
from workbench.assembly.motion import motion_samples
from workbench.assembly.plan import PartPath
from workbench.assembly.planners.common import check_options, retreat
from workbench.collision.motion_bound import JointLevers
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.collision.shapes import Solid
from workbench.errors import CollisionError, InputError, PlanningError, UnreachableError
from workbench.geometry import check_transform
from workbench.geometry.transforms import invert_transform
from workbench.kinematics import RobotModel
from workbench.kinematics.configurations import branch_solutions
from workbench.motion.joint_rrt import bisection_order, plan_joint_rrt_connect

FloatArray = NDArray[np.float64]
CARRIED_PART = "carried part"  # the held part's name among the bodies checked for contact


@dataclass(frozen=True, eq=False)
class CarriedPath(PartPath):
    """A `PartPath` planned in joint space: `joints` (K, dof) [rad] at the key poses, `branch`.

    Between consecutive key points the joints move linearly (not the part's pose):
    `poses[i]` is the part at `joints[i]`. `branch` is the IK branch of both ends
    (-1 where the robot's IK has no branches, or start and goal had to differ).
    """

    joints: FloatArray | None = None
    branch: int = -1


class CarrySpace:
    """Valid configurations and motions of a robot carrying one part (SI units)."""

    def __init__(
        self,
        robot_checker: RobotCollisionChecker,
        part_checker: InterferenceChecker,
        T_flange_tcp: ArrayLike,
        T_part_tcp: ArrayLike,
        *,
        extra: Sequence[tuple[Solid, ArrayLike]] = (),
        obstacle_names: Sequence[str] | None = None,
        resolution: float | None = None,
        robot_resolution: float | None = None,
    ) -> None:
        """Join the robot's checker (cell, self) and the part's checker into one validity test.

        T_flange_tcp, T_part_tcp (4, 4): the tool and the grasp (TCP in the part frame).
        extra: further static solids with world poses (other parts) the robot must not touch.
        obstacle_names: names of the part checker's obstacles, for messages.
        resolution [m]: largest travel of a point of the part between checks (default the
        cell size); robot_resolution [m]: the same for the robot's links and tool (default
        `resolution`).
        """
        self.robot_checker, self.part_checker = robot_checker, part_checker
        self.model: RobotModel = robot_checker.robot  # type: ignore[assignment]  # until the checker holds a RobotModel
        self.dof = int(self.model.dof)
        self.limits: FloatArray = np.asarray(self.model.limits, dtype=np.float64)
        self.T_world_base = np.asarray(robot_checker.T_world_base, float)
        self.T_flange_tcp = check_transform(T_flange_tcp, "T_flange_tcp")
        self.T_part_tcp = check_transform(T_part_tcp, "T_part_tcp")
        self.T_flange_part = self.T_flange_tcp @ invert_transform(self.T_part_tcp)
        self.resolution = part_checker.cell_size if resolution is None else float(resolution)
        self.robot_resolution = (
            self.resolution if robot_resolution is None else float(robot_resolution)
        )
        for name, v in (
            ("resolution", self.resolution),
            ("robot_resolution", self.robot_resolution),
        ):
            if not (np.isfinite(v) and v > 0):
                raise InputError(f"{name} must be a length > 0 m, got {v!r}")
        n_ob = len(part_checker.obstacles)
        self.obstacle_names = (
            list(obstacle_names)
            if obstacle_names is not None
            else [f"obstacle {k}" for k in range(n_ob)]
        )
        scene = robot_checker.scene
        moving = list(scene.moving)
        self.frames = [min(i, self.dof) for i in range(len(moving))]  # links 0..dof, tool on dof
        # The carried part is a body too, so a folding arm cannot sweep through what it holds.
        # It is paired with every robot body that moves relative to it: the tool and the
        # flange link are rigid with the grasp (their contact with the part cannot change).
        part = Solid(CARRIED_PART, "mesh", mesh=part_checker.moving.mesh)
        solids = (
            [scene.moving[n].solid for n in moving]
            + [part]
            + [e.solid for e in scene.static.values()]
        )
        fixed = [e.T for e in scene.static.values()]
        pairs = list(scene.pairs) + [
            (CARRIED_PART, n) for n, f in zip(moving, self.frames, strict=True) if f < self.dof
        ]
        for solid, T in extra:
            solids.append(solid)
            fixed.append(check_transform(T, f"extra {solid.name!r} pose"))
            pairs += [(m, solid.name) for m in moving[1:]]  # the base stands still
        self.bodies = Bodies(solids, pairs)
        self.n_moving = len(moving)
        self.fixed = np.asarray(fixed, float).reshape(-1, 4, 4)
        lev = JointLevers(self.model)
        self.body_levers = np.stack(
            [
                lev.levers(f, scene.moving[n].mesh.vertices)
                for f, n in zip(self.frames, moving, strict=True)
            ]
        )  # (moving, dof) [m/rad]
        pv: FloatArray = (
            part_checker.moving.mesh.vertices @ self.T_flange_part[:3, :3].T
            + self.T_flange_part[:3, 3]
        )
        self.part_lever = lev.levers(self.dof, pv)
        self.weights = np.maximum(self.body_levers.max(axis=0), self.part_lever)
        self.checks = 0

    # -- placement ----------------------------------------------------------------------
    def part_poses(self, q: ArrayLike) -> FloatArray:
        """Return the carried part's world poses (N, 4, 4) [m] at configurations q (N, dof) [rad]."""
        qa = np.atleast_2d(np.asarray(q, float))
        return self.T_world_base @ self.model.fk(qa) @ self.T_flange_part

    def body_poses(self, q: ArrayLike) -> FloatArray:
        """Return the poses (N, bodies, 4, 4) of the robot's bodies and the static solids."""
        qa = np.atleast_2d(np.asarray(q, float))
        L = self.T_world_base @ self.model.link_transforms(qa)  # (N, dof + 1, 4, 4)
        moving = L[:, self.frames]
        part = (L[:, self.dof] @ self.T_flange_part)[:, None]
        fixed = np.broadcast_to(self.fixed, (len(qa), *self.fixed.shape))
        return np.concatenate([moving, part, fixed], axis=1)

    def distance(self, qa: ArrayLike, qb: ArrayLike) -> FloatArray:
        """Return Σ_j |Δq_j|·w_j [m]: a bound on how far any checked point moves from qa to qb."""
        return np.abs(np.asarray(qb, float) - np.asarray(qa, float)) @ self.weights

    # -- validity -----------------------------------------------------------------------
    def in_limits(self, q: ArrayLike) -> bool:
        """Return True if q (dof,) [rad] is within the joint limits."""
        qa = np.asarray(q, float)
        return bool(
            np.all(qa >= self.limits[:, 0] - 1e-9) and np.all(qa <= self.limits[:, 1] + 1e-9)
        )

    def any_invalid(self, q: FloatArray) -> bool:
        """Return True if any configuration of q (N, dof) has the part or the robot in contact."""
        self.checks += len(q)
        if self.part_checker.first_interference(self.part_poses(q)) >= 0:
            return True
        return bool(self.bodies.contacts(self.body_poses(q), first=True))

    def valid(self, q: ArrayLike) -> bool:
        """Return True if the single configuration q (dof,) is within limits and contact-free."""
        qa = np.asarray(q, float)
        return self.in_limits(qa) and not self.any_invalid(qa[None])

    def explain(self, q: ArrayLike) -> str:
        """Return what touches what at configuration q (dof,), or "" if nothing does."""
        qa = np.asarray(q, float)
        out = []
        if not self.in_limits(qa):
            out.append("joint limits exceeded")
        hit = self.part_checker.colliding_obstacles(self.part_poses(qa)[0])
        if hit:
            out.append("the part interferes with " + ", ".join(self.obstacle_names[k] for k in hit))
        pairs = self.bodies.pairs
        for _, k in self.bodies.contacts(self.body_poses(qa)):
            out.append(f"{pairs[k][0]} hits {pairs[k][1]}")
        return "; ".join(out)

    def edge_samples(self, qa: ArrayLike, qb: ArrayLike) -> FloatArray:
        """Return configurations (n, dof) along qa -> qb (qb last, qa excluded) at the check spacing."""
        qa, qb = np.asarray(qa, float), np.asarray(qb, float)
        d = np.abs(qb - qa)
        n = max(
            1,
            int(np.ceil(float(d @ self.part_lever) / self.resolution)),
            int(np.ceil(float((self.body_levers @ d).max()) / self.robot_resolution)),
        )
        u = np.arange(1, n + 1) / n
        return qa + u[:, None] * (qb - qa)

    def motion_free(self, qa: ArrayLike, qb: ArrayLike, *, batch: int = 32) -> bool:
        """Return True if the straight joint motion qa -> qb (qa excluded) is contact-free."""
        S = self.edge_samples(qa, qb)
        S = S[bisection_order(len(S))]
        return not any(self.any_invalid(S[s : s + batch]) for s in range(0, len(S), batch))

    def path_samples(self, q: ArrayLike) -> FloatArray:
        """Return every configuration (M, dof) checked along a joint path (K, dof), start included."""
        Q = np.asarray(q, float)
        return np.concatenate(
            [Q[:1]] + [self.edge_samples(Q[i], Q[i + 1]) for i in range(len(Q) - 1)]
        )


# -- ends by inverse kinematics ---------------------------------------------------------
def _tcp_mm(T: FloatArray) -> str:
    return ", ".join(f"{v * 1000:.1f}" for v in T[:3, 3])


def _near_turn(q: FloatArray, ref: FloatArray, limits: FloatArray) -> FloatArray:
    """Return q with each joint shifted by whole turns toward ref, staying within limits."""
    out = q.copy()
    for j in range(len(q)):
        k = np.round((ref[j] - q[j]) / (2 * np.pi))
        for kk in (k, k - 1, k + 1, 0.0):
            c = q[j] + 2 * np.pi * kk
            if limits[j, 0] - 1e-9 <= c <= limits[j, 1] + 1e-9:
                out[j] = c
                break
    return out


def carry_ends(
    space: CarrySpace,
    start: ArrayLike,
    goal: ArrayLike,
    q_near: ArrayLike,
    *,
    q_start: ArrayLike | None = None,
) -> tuple[FloatArray, FloatArray, int]:
    """Return (q_start, q_goal, branch): valid IK configurations holding the part at start and goal.

    start, goal (4, 4): the part's world poses [m]. One arm configuration (IK branch) for
    both where one is valid at both; else the nearest valid pair (branch -1). q_near (dof,):
    the start is the valid solution nearest it. q_start: use this start configuration
    (e.g. where an approach ended); the goal then takes its branch where possible.
    Raises UnreachableError naming the end out of reach, CollisionError naming what
    touches when every solution at an end is in contact.
    """
    S, G = check_transform(start, "start"), check_transform(goal, "goal")
    ref = np.asarray(q_near, float)
    Tb = invert_transform(space.T_world_base)
    Tf = invert_transform(space.T_flange_part)
    ends = {"start": Tb @ S @ Tf, "goal": Tb @ G @ Tf}  # base -> flange
    tcp = {"start": S @ space.T_part_tcp, "goal": G @ space.T_part_tcp}  # world -> TCP
    model = space.model
    sols: dict[str, tuple[FloatArray, NDArray[np.int64]]] = {}
    for name, T in ends.items():
        rows, branches = branch_solutions(model, T, ref)
        if name == "goal" and q_start is not None:
            rows = np.array([_near_turn(r, np.asarray(q_start, float), space.limits) for r in rows])
        keep = [i for i, r in enumerate(rows) if space.in_limits(r)]
        rows, branches = rows[keep].reshape(-1, space.dof), branches[keep]
        if not len(rows):
            raise UnreachableError(
                f"{name}: the part's {name} pose is out of reach of the robot (TCP at "
                f"[{_tcp_mm(tcp[name])}] mm: "
                "no inverse-kinematics solution within the joint limits); move the "
                f"{name} pose closer to the robot, or change the grasp"
            )
        sols[name] = (rows, branches)
    if q_start is not None:
        qs0 = np.asarray(q_start, float).reshape(-1)
        if qs0.shape != (space.dof,) or np.abs(space.part_poses(qs0)[0] - S).max() > 1e-6:
            raise InputError(
                "q_start (controller joints"
                f" {np.round(np.degrees(space.model.convention.to_controller(qs0)), 2).tolist()}"
                " deg) does not hold the part "
                "at its start pose; give the configuration where the approach ended"
            )
        rs, bs = sols["start"]
        # Its branch: the IK row equal to it up to whole turns of the joints.
        turns = np.abs(np.angle(np.exp(1j * (rs - qs0))))
        same = np.flatnonzero(turns.max(axis=1) < 1e-6)
        sols["start"] = (qs0[None], bs[same[:1]] if len(same) else np.array([-1]))
    valid: dict[str, list[int]] = {}
    for name, (rows, _) in sols.items():
        valid[name] = [i for i, r in enumerate(rows) if space.valid(r)]
        if not valid[name]:
            first = rows[int(np.argmin(np.abs(rows - ref).sum(axis=1)))]
            raise CollisionError(
                f"{name}: every robot configuration holding the part at its {name} pose is in "
                f"contact ({len(rows)} IK solutions; the nearest: {space.explain(first)}); move "
                f"the {name} pose clear, or change the grasp"
            )
    (rs, bs), (rg, bg) = sols["start"], sols["goal"]
    best: tuple[tuple[int, float, float], FloatArray, FloatArray, int] | None = None
    for i in valid["start"]:
        for k in valid["goal"]:
            one = bool(bs[i] == bg[k] and bs[i] >= 0)
            key = (
                0 if one else 1,
                float(np.abs(rs[i] - ref).sum()),
                float(space.distance(rs[i], rg[k])),
            )
            if best is None or key < best[0]:
                best = (key, rs[i], rg[k], int(bs[i]) if one else -1)
    assert best is not None
    return best[1].copy(), best[2].copy(), best[3]


def plan_carried_path(
    space: CarrySpace,
    start: ArrayLike,
    goal: ArrayLike,
    q_near: ArrayLike,
    *,
    q_start: ArrayLike | None = None,
    **options: object,
) -> CarriedPath:
    """Return a CarriedPath taking the part from pose `start` to `goal` (4, 4) [m] in joint space.

    q_near, q_start: as for `carry_ends`; options: those of `plan_joint_rrt_connect`.
    The part's poses at the ends are the given ones (up to the IK's accuracy, ~1e-9 m).
    A part seated in a hole at an end is first withdrawn straight (as in the pose-space
    planners, `common.retreat`), the robot following by IK in the same configuration: a
    random joint-space search would hardly thread the narrow passage of an insertion.
    """
    check_options("joint_rrt_connect", plan_joint_rrt_connect, options)
    checks0, stats0 = (
        space.checks,
        (space.part_checker.stats.poses, space.part_checker.stats.exact_pairs),
    )
    t0 = time.perf_counter()
    S, G = check_transform(start, "start"), check_transform(goal, "goal")
    qs, qg, branch = carry_ends(space, S, G, q_near, q_start=q_start)
    ch, res = space.part_checker, space.resolution
    a = retreat(ch, S, G[:3, 3], res)
    b = retreat(ch, G, (S if a is None else a)[:3, 3], res)
    head = _withdrawal(space, S, a, qs, "start")
    tail = _withdrawal(space, G, b, qg, "goal")[::-1]
    q_mid, nodes = plan_joint_rrt_connect(space, head[-1], tail[0], **options)  # type: ignore[arg-type]
    q = np.concatenate([head[:-1], q_mid, tail[1:]])
    dt = time.perf_counter() - t0
    poses = space.part_poses(q)
    dense = space.part_poses(space.path_samples(q))
    length = float(np.linalg.norm(np.diff(dense[:, :3, 3], axis=0), axis=1).sum())
    return CarriedPath(
        poses=poses,
        planner="joint_rrt_connect",
        time_s=dt,
        setup_s=0.0,
        checks=space.checks - checks0,
        exact_checks=space.part_checker.stats.exact_pairs - stats0[1],
        nodes=int(nodes),
        length=length,
        resolution=space.resolution,
        cell_size=space.part_checker.cell_size,
        stats={"withdrawal_steps": len(head) + len(tail) - 2, "key_points": len(q)},
        joints=q,
        branch=branch,
    )


def _withdrawal(
    space: CarrySpace, T0: FloatArray, T1: FloatArray | None, q0: FloatArray, end: str
) -> FloatArray:
    """Return joints (n, dof) from q0 (part at T0) along the straight part motion T0 -> T1, checked.

    The part's poses every `resolution` of travel, the robot following by IK from q0 in one
    configuration; each joint step is validated as any edge, then the steps are merged where
    a longer straight joint motion is free too. Just q0 when T1 is None.
    """
    if T1 is None:
        return q0[None]
    P = motion_samples(T0, T1, space.part_checker.radius, space.resolution, include_start=True)
    T_world_tcp = P @ space.T_part_tcp
    ik = carry_ik(
        space.model,
        space.T_world_base,
        space.T_flange_tcp,
        T_world_tcp,
        q0,
        what=f"withdrawal from the {end}",
    )
    q = ik.q
    if np.abs(q[0] - q0).max() > 1e-6:
        q = np.concatenate([q0[None], q])
    for i in range(len(q) - 1):
        if not space.motion_free(q[i], q[i + 1]):
            raise PlanningError(
                f"{end}: the part is seated (it cannot leave its {end} pose by itself) and the "
                f"robot cannot follow its straight withdrawal (step {i + 1} of {len(q) - 1}: "
                f"{space.explain(q[i + 1]) or 'a contact between the checked samples'}); "
                "change the grasp or the approach"
            )
    # Keep only the configurations needed: from each kept one, the farthest next one that
    # a straight joint motion reaches freely (the steps above prove the path exists).
    kept = [0]
    while kept[-1] < len(q) - 1:
        j = kept[-1] + 1
        while j + 1 < len(q) and space.motion_free(q[kept[-1]], q[j + 1]):
            j += 1
        kept.append(j)
    return q[kept]
