"""`Workbench.bending`: the open project's press-brake bending (seed 000).

Builds the domain objects of `workbench.sheetmetal` from the project's `bending` section
(in SI through `BendingSpec.to_si`), calls them and returns their results (SI units).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision import check_trajectory
from workbench.errors import InputError
from workbench.kinematics import follow_path
from workbench.motion import SampledMotion, smooth_joint_path
from workbench.project.bending import BendingSI, BendingSpec, PartSI, PartSpec
from workbench.project.program_io import program_settings
from workbench.service.section import SectionService
from workbench.sheetmetal import FoldedState, OBBTree, SheetMetalPart
from workbench.sheetmetal.check_cost import CheckCost, check_cost
from workbench.sheetmetal.die import (
    DiePlacement,
    bend_on_die,
    die_part_pose,
    die_placements,
    die_targets,
)
from workbench.sheetmetal.grasp import (
    Grasp,
    T_flange_grasp,
    check_flange,
    checked_grasp,
    grasp_point,
)
from workbench.sheetmetal.obstacles import Obstacles, cell_obstacles
from workbench.sheetmetal.plan import BendingPlan, first_collision, robot_frames
from workbench.sheetmetal.plan import playback as sample_playback
from workbench.sheetmetal.program import RobotProgram, bending_program
from workbench.sheetmetal.sequence import check_sequence
from workbench.sheetmetal.transfer import (
    base_flange_poses,
    carried_poses,
    check_part,
    transfer_poses,
    world_tcp,
)

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

Progress = Callable[[float, str], None]


class BendingService(SectionService[BendingSpec]):
    """`Workbench.bending`: the bending workflow of the open project (SI units)."""

    section = "bending"
    missing = "add one (see docs)"

    def __init__(self, wb: Workbench) -> None:
        super().__init__(wb)
        self._part: SheetMetalPart | None = None
        self._part_spec: PartSpec | None = None
        self._plan: BendingPlan | None = None

    # -- project section ------------------------------------------------------------------
    def part_spec(self) -> PartSpec:
        """Return the part section (inline, or read from `part_file`, validated)."""
        if self._part_spec is None:
            self._part_spec = self.spec.read_part(self.wb.folders)
        return self._part_spec

    def si(self) -> BendingSI:
        """Return the `bending` section in SI units (its part and sequence resolved)."""
        return self.spec.to_si(self.part_spec())

    @property
    def part(self) -> SheetMetalPart:
        """Return the part with the project's bend sequence (checked: no flange bent into another)."""
        if self._part is None:
            si = self.si()
            part = self._build_part(si.part)
            check_flange(part, si.grasp.flange, "bending.grasp.flange")
            self._part = part
        return self._part

    def _build_part(self, spec: PartSI) -> SheetMetalPart:
        try:
            return SheetMetalPart.from_spec(spec)
        except InputError as exc:
            raise InputError(f"bending.part: {exc}") from None

    @property
    def sequence(self) -> list[str]:
        """Return the bend names in sequence order."""
        return [b.name for b in self.part.bends]

    def set_sequence(self, names: Sequence[str]) -> None:
        """Use bend sequence `names`; InputError if it repeats, misses or names unknown bends, or is infeasible."""
        part_si = self.si().part
        names = check_sequence([str(n).strip() for n in names], [b.name for b in part_si.bends])
        part = self._build_part(replace(part_si, sequence=tuple(names)))  # raises when infeasible
        self.spec.sequence = names
        self._part, self._plan = part, None

    # -- grasp --------------------------------------------------------------------------
    @property
    def grasp(self) -> Grasp:
        """Return the grasp (SI): flange, offset [m] or None (centroid), yaw [rad]."""
        return self.spec.grasp.to_si()

    @property
    def grasp_flange(self) -> str:
        """Return the name of the gripped flange."""
        return self.spec.grasp.flange

    def grasp_offset(self) -> NDArray[np.float64]:
        """Return the grasp point (2,) [m] in the gripped flange's polygon frame."""
        return grasp_point(self.part, self.grasp)

    def set_grasp(
        self, flange: str, offset: ArrayLike | None = None, yaw: float | None = None
    ) -> None:
        """Grip `flange` at `offset` (2,) [m] in its polygon frame (None: centroid), gripper `yaw` [rad]."""
        grasp = checked_grasp(self.part, flange, offset, 0.0 if yaw is None else yaw)
        self.spec.grasp.set_si(grasp, keep_yaw=yaw is None)
        self._plan = None

    def T_flange_grasp(self) -> NDArray[np.float64]:
        """Return the TCP pose (4, 4) [m] in the gripped flange's frame: on its top face, z into the sheet."""
        return T_flange_grasp(self.part, self.grasp)

    # -- part states and cell -------------------------------------------------------------
    def fold(self, step: float) -> FoldedState:
        """Return the part after `step` bends of the sequence (float: partway, for animation)."""
        return self.part.fold(step)

    def tree(self, step: int | None = None) -> OBBTree:
        """Return the OBB tree of the part after `step` bends (default: all), rooted at the grasp."""
        s = len(self.part.bends) if step is None else step
        return self.part.fold(s).obb_tree(self.grasp_flange)

    def tree_depth(self) -> int:
        """Return the number of levels of the deepest OBB tree of the folded part (any grasp)."""
        return self.part.fold(len(self.part.bends)).tree_depth()

    def obstacles(self) -> Obstacles:
        """Return the cell's colliding objects as OBBs [m] (cylinders and meshes confirmed exactly)."""
        return cell_obstacles((b.name, b.solid, b.T_world_body) for b in self.wb.cell if b.collide)

    # -- process ------------------------------------------------------------------------
    def bend_on_die(self, step: float) -> int:
        """Return the sequence index of the bend on the die with the part folded to `step`."""
        return bend_on_die(step, len(self.part.bends))

    def die_part_pose(self, step: int) -> NDArray[np.float64]:
        """Return T_world_part (4, 4) [m] with bend `step` on the die (`sheetmetal.die`)."""
        return die_part_pose(self.part, step, self.si().die, self.grasp)

    def _world_tcp(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        setup = self.wb.setup
        return world_tcp(self.wb.robot, setup.T_world_base, setup.T_flange_tcp, q)

    def _ik(
        self,
        T_world_tcp: NDArray[np.float64],
        names: list[str],
        q_start: NDArray[np.float64],
        what: str,
    ) -> tuple[NDArray[np.float64], str]:
        """Return joints (N, dof) reaching the TCP poses (N, 4, 4) with one arm configuration."""
        setup = self.wb.setup
        path = follow_path(
            self.wb.robot,
            base_flange_poses(setup.T_world_base, setup.T_flange_tcp, T_world_tcp),
            q_start,
            labels=names,
            what=what,
            cost="total",
            points=T_world_tcp[:, :3, 3],
            hint=f"the grasp is on flange {self.grasp_flange!r}; move the die or pallet, "
            "change the grasp or the sequence",
        )
        return path.q, path.configuration

    def placements(self) -> tuple[tuple[DiePlacement, ...], str]:
        """Return each bend's die placement with one arm configuration, and its label.

        Raises UnreachableError naming the bend the robot cannot hold on the die.
        """
        part = self.part
        T_part, T_tcp, names = die_targets(part, self.si().die, self.grasp)
        q, label = self._ik(T_tcp, names, self.wb.joints, "bending.die")
        return die_placements(part, T_part, T_tcp, q), label

    def transfer_poses(self, last: DiePlacement) -> tuple[NDArray[np.float64], list[str]]:
        """Return TCP poses (N, 4, 4) [m] of the transfer: retract, via poses, pallet; with names."""
        si = self.si()
        return transfer_poses(si.transfer, si.die, last, self.part, si.grasp)

    def plan(self, *, progress: Progress | None = None) -> BendingPlan:
        """Place every bend on the die, then plan and check the transfer to the pallet.

        The transfer is a jerk-limited (ruckig) joint trajectory; `frames` (>= 22) evenly
        timed frames are checked: the part with its OBB tree against the cell (leaf hits on
        cylinders and meshes confirmed with python-fcl) and the robot's links and tool under
        the project's collision policy (`check_trajectory` with `wb.collision_policy`; by
        default spheres + SDF at every frame, what it flags confirmed with python-fcl, the
        motion between frames certified on the trajectory). `progress(fraction, message)`
        reports the stages.
        """
        report = progress or (lambda f, m: None)
        model, part, grasp = self.wb.robot, self.part, self.grasp
        report(0.0, "placing each bend line on the die")
        placements, label = self.placements()
        report(0.25, "planning the transfer")
        T_tcp, names = self.transfer_poses(placements[-1])
        q_way, _ = self._ik(T_tcp, names, placements[-1].q, "bending transfer")
        traj = smooth_joint_path(
            q_way,
            model.max_velocity,
            model.max_acceleration,
            model.max_jerk,
            position_limits=model.limits,
            exact_stop=[0, len(q_way) - 1],
        )
        F = self.si().frames
        times = np.linspace(0.0, traj.duration, F)
        q = traj.at(times)[0]
        T_world_grasp, T_world_part = carried_poses(self._world_tcp(q), part, grasp)
        report(0.4, f"checking {F} frames with the OBB tree")
        obst = self.obstacles()
        rep = check_part(self.tree(), obst, T_world_grasp)
        report(0.7, "checking the robot against the cell")
        # The checker holds the robot's links and tool, not the part: the tool and the part it
        # grips are never a pair, and the part's own checks are the tree's above.
        checker = self.wb.checker
        path = check_trajectory(
            traj,
            times,
            q,
            checker,
            self.wb.collision_policy,
            progress=lambda f, m: report(0.7 + 0.25 * f, m),
        )
        robot_hit, robot_between = robot_frames(path, F)
        first = first_collision(
            times,
            rep,
            robot_hit,
            path,
            [f.name for f in part.flanges],
            obst.names,
            lambda f: checker.check(q[f], distance=False).colliding,
        )
        self._plan = BendingPlan(
            placements=placements,
            configuration=label,
            trajectory=traj,
            times=times,
            joints=q,
            T_world_grasp=T_world_grasp,
            T_world_part=T_world_part,
            part_report=rep,
            part_colliding=rep.collides,
            robot_colliding=robot_hit,
            first_collision=first,
            obstacle_names=obst.names,
            robot_report=path,
            robot_between=robot_between,
        )
        report(1.0, "done")
        return self._plan

    @property
    def last_plan(self) -> BendingPlan | None:
        """Return the latest plan (None before `plan`, or after the sequence or grasp changed)."""
        return self._plan

    def robot_programs(self, plan: BendingPlan | None = None) -> list[RobotProgram]:
        """Return the plan (default: the last) as a robot program (`sheetmetal.program`)."""
        plan, s = plan or self.last_plan or self.plan(), program_settings(self.wb.project)
        return [bending_program(plan, self.wb.setup, self.si(), s, self.wb.joints)]

    def check_cost(self, plan: BendingPlan, repeat: int = 3) -> CheckCost:
        """Return OBB tests and check times per frame, tree vs flat loop (Fig. 12), on request."""
        return check_cost(self.tree(), self.obstacles().boxes, plan.T_world_grasp, repeat)

    def part_pose_at(self, plan: BendingPlan, t: float) -> NDArray[np.float64]:
        """Return T_world_part (4, 4) [m] of the folded part carried by the robot at time `t` [s]."""
        q = plan.trajectory.at([t])[0][0]
        return carried_poses(self._world_tcp(q), self.part, self.grasp)[1]

    def playback(self, plan: BendingPlan, dt: float = 0.02) -> SampledMotion:
        """Return the transfer sampled every `dt` [s] for the timeline, frames' verdicts carried over."""
        return sample_playback(plan, self._world_tcp, dt)
