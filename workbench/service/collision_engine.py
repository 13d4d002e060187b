"""The open project's conservative collision engine: spheres + signed distance field, confirmed exactly."""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision import CollisionPolicy, plan_check
from workbench.collision.clearance import MAX_MARGIN, Clearance, plan_clearance
from workbench.collision.engine import CollisionEngine, ConfigCheck, EnginePathReport
from workbench.collision.plan_check import POLICY_MODES
from workbench.errors import InputError
from workbench.kinematics.dh_chain import joint_array, joint_vector
from workbench.project.collision import CollisionSpec

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

Progress = Callable[[float, str], None]
__all__ = ["CollisionService"]


class CollisionService:
    """`Workbench.collision`: fast conservative checks of the robot against the cell (SI units).

    Engines are built on first use, one per mode (``"spheres"``, ``"exact"``, ``"capsules"``);
    building the spheres mode fits the spheres and builds (or loads from the disk cache) the
    cell's distance field, reporting `progress(fraction, message)`.
    """

    def __init__(
        self,
        wb: Workbench,
        *,
        spheres_per_link: int | None = None,
        resolution: int | None = None,
        cache_dir: str | os.PathLike[str] | None = None,
    ) -> None:
        self.wb = wb
        self._spheres_per_link = spheres_per_link
        self._resolution = resolution
        self._cache_dir = Path(cache_dir) if cache_dir is not None else None

    def policy(self, mode: str = "spheres") -> CollisionPolicy:
        """Return the project's collision policy with `mode` and this service's parameters.

        An unknown mode raises InputError naming the modes (`CollisionPolicy` checks it).
        """
        base = self.wb.collision_policy
        return replace(
            base,
            mode=mode,  # type: ignore[arg-type]
            spheres_per_link=(
                base.spheres_per_link if self._spheres_per_link is None else self._spheres_per_link
            ),
            resolution=base.resolution if self._resolution is None else self._resolution,
            cache_dir=self._cache_dir if self._cache_dir is not None else base.cache_dir,
        )

    @property
    def modes(self) -> tuple[str, ...]:
        """Return the plan collision modes a project may choose (the GUI's options)."""
        return POLICY_MODES

    @property
    def mode(self) -> str:
        """Return the plan collision mode of the project (``"spheres"``, ``"exact"``, ``"capsules"``)."""
        return self.wb.collision_policy.mode

    def set_mode(self, mode: str) -> None:
        """Set the project's plan collision mode (its `collision` section); the next plan uses it.

        Refuses (InputError, nothing changed) a mode not in ``spheres``, ``exact``, ``capsules``.
        """
        if mode not in POLICY_MODES:
            raise InputError(f"collision.mode: {mode!r} is not one of {', '.join(POLICY_MODES)}")
        current = self.wb.project.collision or CollisionSpec()
        self.wb.project.collision = current.model_copy(update={"mode": mode})

    @property
    def margin(self) -> float:
        """Return the clearance margin [m] every plan keeps (the project's `collision.margin`)."""
        return self.wb.collision_policy.margin

    @property
    def max_margin(self) -> float:
        """Return the largest clearance margin [m] a project may ask for."""
        return MAX_MARGIN

    def set_margin(self, margin: float) -> None:
        """Set the project's clearance margin [m]; the next plan and export use it. Refuses
        (InputError naming `collision.margin`, nothing changed) NaN, negative, absurd values."""
        current = self.wb.project.collision or CollisionSpec()
        self.wb.project.collision = current.with_margin(float(margin))

    def clearance(self) -> Clearance:
        """Return the one clearance figure: the least distance over the latest Motion plan with
        its pair (`EnginePathReport.nearest`), else at the current joints, against the margin."""
        plan = self.wb.last_plan
        near = None if plan is None else plan.collision_report.nearest
        if near is not None:
            return replace(near, margin=self.margin)
        q = self.wb.joints
        here = plan_clearance(self.wb.checker, np.zeros(1), q[None], margin=self.margin)
        return replace(here, time=None, index=None)

    @property
    def spheres_per_link(self) -> int:
        """Return the spheres engine's spheres per link."""
        return self.policy().spheres_per_link

    @property
    def resolution(self) -> int:
        """Return the spheres engine's coarse SDF resolution."""
        return self.policy().resolution

    @property
    def cache_dir(self) -> Path:
        """Return the engines' cache folder."""
        return self.policy().cache()

    def engine(self, mode: str = "spheres", *, progress: Progress | None = None) -> CollisionEngine:
        """Return the engine of `mode`, building it on first use (shared with the plans)."""
        return plan_check.engine(self.wb.checker, self.policy(mode), progress=progress)

    @property
    def built(self) -> bool:
        """Return True once the spheres engine exists (no build is pending)."""
        return isinstance(self.wb.checker.engines.get(self.policy().key()), CollisionEngine)

    def check(self, q: ArrayLike | None = None, *, mode: str = "spheres") -> ConfigCheck:
        """Return the check of joints q (dof,) [rad] (default: the current joints)."""
        qq = self.wb.joints if q is None else joint_vector(q, self.wb.robot.dof, "q")
        return self.engine(mode).check(qq)

    def check_path(
        self,
        qs: ArrayLike,
        times: ArrayLike | None = None,
        *,
        deviation: ArrayLike | None = None,
        mode: str = "spheres",
    ) -> EnginePathReport:
        """Return the path report of samples qs (N, dof) [rad] at `times` (N,) [s], between samples too."""
        q = joint_array(qs, self.wb.robot.dof, "qs")
        if q.ndim != 2 or len(q) == 0:
            raise InputError(
                f"qs: expected shape (N, {self.wb.robot.dof}) with N >= 1 [rad], got {q.shape}"
            )
        return self.engine(mode).check_path(q, times, deviation=deviation)

    def spheres(
        self, q: ArrayLike | None = None
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], list[str]]:
        """Return world sphere centres (S, 3) [m], radii (S,) [m] and link names at q [rad]."""
        qq = self.wb.joints if q is None else joint_vector(q, self.wb.robot.dof, "q")
        return self.engine("spheres").spheres(qq)

    def sdf_slice(
        self, axis: str = "z", value: float = 0.5, *, size: int = 64
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Return (values (size, size) [m], corners (2, 3) [m]) of the cell's SDF on a plane.

        axis: "x", "y" or "z", the plane's normal; value [m] its world coordinate. The grid
        spans the field's bounds; values are the field's (negative inside, lower bounds far).
        """
        if axis not in ("x", "y", "z"):
            raise InputError(f"axis: {axis!r} must be 'x', 'y' or 'z'")
        if not np.isfinite(value):
            raise InputError(f"value: {value} m must be finite")
        if not 2 <= int(size) <= 1024:
            raise InputError(f"size: {size} must be 2..1024 samples per side")
        sdf = self.engine("spheres").sdf
        if sdf is None:
            raise InputError(
                "the cell has no obstacles to collide with: there is no distance field"
            )
        k = "xyz".index(axis)
        lo, hi = sdf.mesh_bounds[0] - 0.1, sdf.mesh_bounds[1] + 0.1
        u, w = [i for i in range(3) if i != k]
        a = np.linspace(lo[u], hi[u], int(size))
        b = np.linspace(lo[w], hi[w], int(size))
        A, B = np.meshgrid(a, b, indexing="ij")
        p = np.zeros(A.shape + (3,))
        p[..., u], p[..., w], p[..., k] = A, B, value
        corners = np.array([p[0, 0], p[-1, -1]])
        return sdf.query(p.reshape(-1, 3)).reshape(A.shape), corners
