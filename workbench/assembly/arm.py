"""A robot of the assembly cell: its setup (model, frames, meshes), checker and home joints."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.assembly.carry import carry_ik
from workbench.collision import RobotCollisionChecker, Solid
from workbench.kinematics import PathIK, RobotModel


class ArmSetup(Protocol):
    """What the workcell needs of a robot setup: its model, frames [m] and meshes."""

    @property
    def model(self) -> RobotModel: ...
    @property
    def link_meshes(self) -> list[trimesh.Trimesh]: ...
    @property
    def T_world_base(self) -> NDArray[np.float64]: ...
    @property
    def T_flange_tcp(self) -> NDArray[np.float64]: ...
    @property
    def tool_mesh(self) -> trimesh.Trimesh | None: ...


@dataclass(frozen=True, eq=False)
class AssemblyArm:
    """A robot of the cell: its setup, its robot-versus-cell checker and its home joints [rad]."""

    name: str
    setup: ArmSetup
    checker: RobotCollisionChecker
    q_home: NDArray[np.float64]
    color: tuple[int, int, int]
    main: bool

    @classmethod
    def build(
        cls,
        name: str,
        setup: ArmSetup,
        q_home: NDArray[np.float64],
        cell: list[tuple[Solid, NDArray[np.float64]]],
        color: tuple[int, int, int],
    ) -> AssemblyArm:
        """Return a further arm of the cell: its checker against `cell` (solids, world poses)."""
        checker = RobotCollisionChecker(
            setup.model,
            setup.link_meshes,
            T_world_base=setup.T_world_base,
            tool=setup.tool_mesh,
            cell=cell,
            q_reference=q_home,
        )
        return cls(name, setup, checker, q_home, color, main=False)

    def link_poses(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        """Return the world poses (..., dof + 1, 4, 4) [m] of the links (base first) at joints q [rad]."""
        return self.setup.T_world_base @ self.setup.model.link_transforms(q)

    def tcp_poses(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        """Return the world TCP poses (..., 4, 4) [m] at joints q (..., dof) [rad]."""
        s = self.setup
        return s.T_world_base @ s.model.fk(q) @ s.T_flange_tcp

    def follow(self, T_world_tcp: NDArray[np.float64], q_near: NDArray, what: str) -> PathIK:
        """Return the joints putting the TCP on every pose (M, 4, 4) [m] in one arm configuration."""
        s = self.setup
        return carry_ik(s.model, s.T_world_base, s.T_flange_tcp, T_world_tcp, q_near, what=what)
