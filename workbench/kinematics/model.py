"""RobotModel: what every robot model (DHRobot, URDFRobot) provides to the rest of the workbench."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.kinematics.joint_convention import JointConvention

if TYPE_CHECKING:
    import pinocchio as pin
    import trimesh

FloatArray = NDArray[np.float64]


@runtime_checkable
class RobotModel(Protocol):
    """A serial robot model: joint limits and rates, batched FK, per-pose and per-branch IK.

    Joint values are in the kinematic model's own convention [rad] (prismatic joints [m]);
    transforms are (..., 4, 4) [m] from the robot base. `is_analytic` says whether
    `ik_batch` is available: analytic models (OPW arms) return every branch of every pose
    at once; numeric models raise InputError there and callers solve pose by pose with `ik`.
    `convention` maps these values to the controller's (what the project file, the GUI and
    the programs show): q_ctrl = convention.to_controller(q_model).
    """

    name: str
    dof: int
    limits: FloatArray  # (dof, 2) [rad]
    max_velocity: FloatArray  # (dof,) [rad/s]
    max_acceleration: FloatArray  # (dof,) [rad/s^2]
    max_jerk: FloatArray  # (dof,) [rad/s^3]
    convention: JointConvention  # controller joint values against these (identity by default)

    @property
    def is_analytic(self) -> bool:
        """Return True when `ik_batch` gives every analytic branch (closed-form IK)."""
        ...

    def fk(self, q: ArrayLike) -> FloatArray:
        """Return base -> flange transforms (..., 4, 4) [m] for joints q (..., dof) [rad]."""
        ...

    def link_transforms(self, q: ArrayLike) -> FloatArray:
        """Return base -> link frame i (..., dof+1, 4, 4) for i = 0..dof; frame 0 = base."""
        ...

    def link_meshes(self) -> list[trimesh.Trimesh]:
        """Return dof+1 link meshes [m], mesh i in link frame i of `link_transforms`."""
        ...

    def ik(self, T: ArrayLike, *, q_near: ArrayLike | None = None) -> FloatArray:
        """Return IK solutions (k, dof) [rad] of one pose T (4, 4), nearest q_near first.

        Raises UnreachableError saying why when there is none.
        """
        ...

    def ik_batch(
        self, Ts: ArrayLike, *, q_near: ArrayLike | None = None
    ) -> tuple[FloatArray, NDArray[np.bool_]]:
        """Return (q (N, B, dof) [rad], valid (N, B)): every branch b of every pose (N, 4, 4).

        Analytic models only (`is_analytic`); rows of missing branches are NaN.
        """
        ...

    def jacobian(self, q: ArrayLike) -> FloatArray:
        """Return the flange Jacobian (6, dof): rows [v m/s; omega rad/s], LOCAL_WORLD_ALIGNED."""
        ...

    def pinocchio_model(self) -> tuple[pin.Model, pin.Data]:
        """Return (pin.Model, pin.Data) of the same chain (the peer library of the tests)."""
        ...
