"""Conservative robot-versus-cell check: link spheres against the cell's sparse SDF (seed 001, step 4).

Each link mesh is wrapped in PSO-fitted spheres that contain its whole surface exactly
(`fit_spheres`); the cell gets a sparse signed distance field whose band r is at least the
largest sphere radius plus the margin. For a batch of configurations (N, dof) the sphere
centres are placed by forward kinematics and looked up in the field; a configuration is
reported colliding when some sphere has ``sdf(c) <= radius + margin + sdf.max_error``.

No false negatives: if a link's surface touches or enters an obstacle at x, the sphere that
holds x has d(c) <= d(x) + |c - x| <= radius (d is 1-Lipschitz), and the field is within
max_error of d there (|d| <= band) or a correctly signed value otherwise. Not covered: an
obstacle entirely inside a link without touching its surface (the spheres hold the surface).
False positives come from the spheres' overshoot and from max_error.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.geometry.sdf import SparseSDF
from workbench.geometry.spheres import fit_spheres

FloatArray = NDArray[np.float64]


class _Robot(Protocol):
    dof: int

    def link_transforms(self, q: ArrayLike) -> FloatArray: ...


@dataclass(frozen=True)
class ConservativeReport:
    """Per configuration (N,): colliding flag, least sphere clearance [m], and its link index.

    clearance = min over spheres of (sdf(centre) - radius); the true clearance of the links is
    at least clearance - max_error (where clearance <= band - radius).
    """

    collides: NDArray[np.bool_]
    clearance: FloatArray
    link: NDArray[np.int64]


class ConservativeChecker:
    """Fast conservative check of a robot's links against one static cell mesh."""

    def __init__(
        self,
        robot: _Robot,
        link_meshes: Sequence[Any],
        cell_mesh: Any,
        *,
        links: Sequence[int] | None = None,
        spheres_per_link: int = 6,
        margin: float = 0.0,
        resolution: int = 64,
        subdivisions: int = 4,
        cache_dir: str | Path | None = None,
        seed: int = 0,
        progress: Callable[[float, str], None] | None = None,
    ) -> None:
        """Fit spheres to `link_meshes` (each in its ``link_transforms`` frame) and build the SDF.

        links: indices of the links to check (default 1..n: the base usually stands on the
        cell). margin [m]: extra clearance demanded.
        """
        if not np.isfinite(margin) or margin < 0:
            raise InputError(f"margin must be a length >= 0 m, got {margin}")
        chosen = list(range(1, len(link_meshes))) if links is None else list(links)
        if not chosen or min(chosen) < 0 or max(chosen) >= len(link_meshes):
            raise InputError(
                f"links must index link_meshes 0..{len(link_meshes) - 1}, got {chosen}"
            )
        self.robot, self.margin, self.links = robot, float(margin), chosen
        centres, radii, owner = [], [], []
        for i in chosen:
            s = fit_spheres(link_meshes[i], spheres_per_link, seed=seed)
            centres.append(s.centres)
            radii.append(s.radii)
            owner.append(np.full(len(s.radii), i))
        self.centres: FloatArray = np.concatenate(centres)
        self.radii: FloatArray = np.concatenate(radii)
        self.sphere_link: NDArray[np.int64] = np.concatenate(owner)
        band = float(self.radii.max()) + self.margin
        self.sdf = SparseSDF.from_mesh(
            cell_mesh,
            resolution=resolution,
            subdivisions=subdivisions,
            band=band,
            cache_dir=cache_dir,
            progress=progress,
        )

    def sphere_centres(self, q: ArrayLike) -> FloatArray:
        """Return world sphere centres (N, S, 3) [m] for configurations q (N, dof) [rad]."""
        qa = np.atleast_2d(np.asarray(q, dtype=float))
        if qa.ndim != 2 or qa.shape[1] != self.robot.dof:
            raise InputError(f"q must have shape (N, {self.robot.dof}) [rad], got {np.shape(q)}")
        T = self.robot.link_transforms(qa)[:, self.sphere_link]  # (N, S, 4, 4)
        return np.einsum("nsij,sj->nsi", T[..., :3, :3], self.centres) + T[..., :3, 3]

    def check(self, q: ArrayLike) -> ConservativeReport:
        """Return the report for configurations q (N, dof) [rad]; never misses a contact."""
        c = self.sphere_centres(q)
        n, s = c.shape[:2]
        d = self.sdf.query(c.reshape(-1, 3)).reshape(n, s) - self.radii
        worst = np.argmin(d, axis=1)
        clearance = d[np.arange(n), worst]
        collides = np.any(d <= self.margin + self.sdf.max_error, axis=1)
        return ConservativeReport(collides, clearance, self.sphere_link[worst])
