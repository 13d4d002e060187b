"""`BendingResult`: what every bending result offers, the transfer-only `BendingPlan` and the
press cycle `BendingCycle` alike: its checked frames, its verdict and summary, its playback,
the part and the press at any time of it for the scene, and its robot program.

SI units (m, rad, s). The service and the GUI use a result through this interface only, so
neither asks which kind of result it holds.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.motion.programs.controller_program import ProgramSettings, RobotProgram
from workbench.motion.sampled import SampledMotion
from workbench.pressbrake.press import PressBrake
from workbench.pressbrake.program import BendingCell, RobotAt

F64 = NDArray[np.float64]
WorldTcp = Callable[[F64], F64]  # joints (N, dof) [rad] -> TCP world poses (N, 4, 4) [m]


@runtime_checkable
class BendingResult(Protocol):
    """A planned bending: checked frames (F,), a trajectory, a verdict and a program."""

    @property
    def times(self) -> F64:
        """Return the checked frames' times (F,) [s]."""
        ...

    @property
    def joints(self) -> F64:
        """Return the joints (F, dof) [rad] at the checked frames."""
        ...

    @property
    def duration(self) -> float:
        """Return the planned motion's duration [s]."""
        ...

    @property
    def ok(self) -> bool:
        """Return True when every checked frame (and the motion between them) is free."""
        ...

    @property
    def colliding(self) -> NDArray[np.bool_]:
        """Return (F,) frames that collide (at the frame or up to the next)."""
        ...

    @property
    def first_problem_time(self) -> float | None:
        """Return the time [s] of the first collision (None: free)."""
        ...

    @property
    def grasp_frames(self) -> F64 | None:
        """Return the gripped flange's poses (F, 4, 4) [m] where one OBB tree rooted at the
        grasp checks the part at every frame (None: the part is checked per state)."""
        ...

    def frame_at(self, t: ArrayLike) -> NDArray[np.intp]:
        """Return, per time [s], the index of the last checked frame at or before it."""
        ...

    def summary(self) -> str:
        """Return a short human summary (markdown)."""
        ...

    def playback(self, world_tcp: WorldTcp, dt: float = 0.02) -> SampledMotion:
        """Return the motion sampled every `dt` [s] for the timeline, the frames' verdicts
        carried over; `world_tcp(q)` gives TCP world poses (N, 4, 4) at joints (N, dof)."""
        ...

    def part_pose_at(self, t: float, world_tcp: WorldTcp) -> F64:
        """Return T_world_part (4, 4) [m] of the part at time `t` [s]."""
        ...

    def part_step_at(self, t: float) -> float:
        """Return how far the part is folded at time `t` [s] (bends done, fractions partway)."""
        ...

    def press_poses_at(self, t: float, press: PressBrake | None) -> dict[str, F64]:
        """Return the world poses (4, 4) [m] of the press's moving bodies at time `t` [s] by
        their display names (empty: the result moves no press)."""
        ...

    def tree_check_at(self, t: float) -> tuple[tuple[int, ...], tuple[int, ...]] | None:
        """Return the OBB tree's (tested, hit) nodes at the frame nearest time `t` [s] (None:
        no single tree checks the part)."""
        ...

    def robot_program(
        self, robot_at: RobotAt, cell: BendingCell, settings: ProgramSettings, q_start: F64
    ) -> RobotProgram:
        """Return the result as a robot program (`bending_program` or `cycle_program`)."""
        ...
