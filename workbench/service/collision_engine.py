"""The open project's conservative collision engine: spheres + signed distance field, confirmed exactly."""

from __future__ import annotations

import os
import weakref
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision import RobotCollisionChecker
from workbench.collision.engine import MODES, CollisionEngine, ConfigCheck, EnginePathReport
from workbench.errors import InputError, WorkbenchError

if TYPE_CHECKING:
    from workbench.service.workbench import Workbench

Progress = Callable[[float, str], None]
# Parameters of the spheres engine that plans and the GUI share (fits and fields are cached).
SPHERES_PER_LINK = 6
RESOLUTION = 32
# One engine (or the reason there is none) per exact checker and parameters; a checker is
# replaced with its project, which drops its engines.
_ENGINES: weakref.WeakKeyDictionary[
    RobotCollisionChecker, dict[tuple[int, int, str], CollisionEngine | str]
] = weakref.WeakKeyDictionary()


def default_cache_dir() -> Path:
    """Return where distance fields are cached (~/.cache/workbench/sdf, or $WORKBENCH_CACHE/sdf)."""
    root = os.environ.get("WORKBENCH_CACHE")
    return (Path(root) if root else Path.home() / ".cache" / "workbench") / "sdf"


def shared_engine(
    checker: RobotCollisionChecker,
    *,
    spheres_per_link: int = SPHERES_PER_LINK,
    resolution: int = RESOLUTION,
    cache_dir: str | os.PathLike[str] | None = None,
    progress: Progress | None = None,
) -> tuple[CollisionEngine | None, str | None]:
    """Return (the spheres engine of `checker`, None), or (None, why the fast mode cannot apply).

    Built on first use (sphere fits and the cell's field are cached on disk under
    `cache_dir`, default `default_cache_dir()`), then kept for the checker. The fast mode does
    not apply when the engine cannot be built (e.g. a joint that is not revolute) or when the
    cell's mesh is not watertight (its field is unsigned: a link wholly inside an obstacle
    would not be seen).
    """
    cache = str(Path(cache_dir) if cache_dir is not None else default_cache_dir())
    key = (int(spheres_per_link), int(resolution), cache)
    per = _ENGINES.setdefault(checker, {})
    open_meshes = [
        name for name, e in checker.scene.static.items() if e.solid.kind == "mesh" and not e.closed
    ]
    if open_meshes and key not in per:
        per[key] = (
            f"obstacle {open_meshes[0]!r} is not watertight, so the cell's distance field would"
            " have no inside"
        )
    if key not in per:
        try:
            eng = CollisionEngine(
                checker,
                "spheres",
                spheres_per_link=int(spheres_per_link),
                resolution=int(resolution),
                cache_dir=cache,
                progress=progress,
            )
        except WorkbenchError as exc:
            per[key] = f"the spheres engine could not be built ({exc})"
        else:
            per[key] = (
                "the cell's merged mesh is not watertight, so its distance field has no inside"
                if eng.sdf is not None and not eng.sdf.signed
                else eng
            )
    elif progress is not None:
        progress(1.0, "collision engine ready")
    found = per[key]
    return (None, found) if isinstance(found, str) else (found, None)


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
        spheres_per_link: int = SPHERES_PER_LINK,
        resolution: int = RESOLUTION,
        cache_dir: str | os.PathLike[str] | None = None,
    ) -> None:
        self.wb = wb
        self.spheres_per_link = spheres_per_link
        self.resolution = resolution
        self.cache_dir = Path(cache_dir) if cache_dir is not None else default_cache_dir()
        self._engines: dict[str, CollisionEngine] = {}

    def engine(self, mode: str = "spheres", *, progress: Progress | None = None) -> CollisionEngine:
        """Return the engine of `mode`, building it on first use."""
        if mode not in MODES:
            raise InputError(f"mode: {mode!r} is not one of {', '.join(MODES)}")
        if mode == "spheres" and mode not in self._engines:
            eng, _ = shared_engine(
                self.wb.checker,
                spheres_per_link=self.spheres_per_link,
                resolution=self.resolution,
                cache_dir=self.cache_dir,
                progress=progress,
            )
            if eng is not None:  # shared with the motion plans
                self._engines[mode] = eng
                return eng
        if mode not in self._engines:
            self._engines[mode] = CollisionEngine(
                self.wb.checker,
                mode,
                spheres_per_link=self.spheres_per_link,
                resolution=self.resolution,
                cache_dir=str(self.cache_dir),
                progress=progress,
            )
        elif progress is not None:
            progress(1.0, "collision engine ready")
        return self._engines[mode]

    @property
    def built(self) -> bool:
        """Return True once the spheres engine exists (no build is pending)."""
        return "spheres" in self._engines

    def check(self, q: ArrayLike | None = None, *, mode: str = "spheres") -> ConfigCheck:
        """Return the check of joints q (dof,) [rad] (default: the current joints)."""
        qq = self.wb.joints if q is None else np.asarray(q, float)
        if qq.shape != (self.wb.robot.dof,) or not np.all(np.isfinite(qq)):
            raise InputError(
                f"q: expected {self.wb.robot.dof} finite joint values [rad], got shape {qq.shape}"
            )
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
        q = np.asarray(qs, float)
        if q.ndim != 2 or q.shape[1] != self.wb.robot.dof or len(q) == 0:
            raise InputError(
                f"qs: expected shape (N, {self.wb.robot.dof}) with N >= 1 [rad], got {q.shape}"
            )
        if not np.all(np.isfinite(q)):
            raise InputError("qs: joint values must be finite")
        return self.engine(mode).check_path(q, times, deviation=deviation)

    def spheres(
        self, q: ArrayLike | None = None
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], list[str]]:
        """Return world sphere centres (S, 3) [m], radii (S,) [m] and link names at q [rad]."""
        qq = self.wb.joints if q is None else np.asarray(q, float)
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
