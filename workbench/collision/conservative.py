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

from workbench.collision.padded_spheres import PaddedSpheres
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
            s = fit_spheres(link_meshes[i], spheres_per_link, seed=seed, cache_dir=cache_dir)
            centres.append(s.centres)
            radii.append(s.radii)
            owner.append(np.full(len(s.radii), i))
        self.centres: FloatArray = np.concatenate(centres)
        self.radii: FloatArray = np.concatenate(radii)
        self.sphere_link: NDArray[np.int64] = np.concatenate(owner)
        # The same spheres padded per link (L, K): one batched matmul places all of them.
        self._pad = PaddedSpheres(
            self.centres,
            self.radii,
            np.repeat(np.arange(len(chosen)), [len(r) for r in radii]),
            len(chosen),
        )
        self._pad_c, self._pad_r, self._valid = self._pad.centres, self._pad.radii, self._pad.valid
        k = self._pad_r.shape[1]
        self._pad_link = np.repeat(np.array(chosen), k)
        # Per link a bounding sphere of its spheres: centre = mean of the sphere centres (as
        # weights (L, K, 1) on the padded centres), radius = farthest sphere surface.
        self._bound_w = (self._valid / self._valid.sum(axis=1, keepdims=True))[..., None]
        cb = np.einsum("lk,lki->li", self._bound_w[..., 0], self._pad_c)
        reach = np.linalg.norm(self._pad_c - cb[:, None], axis=2) + self._pad_r
        self._bound_r = np.where(self._valid, reach, -np.inf).max(axis=1) * (1 + 1e-12)
        band = float(self.radii.max()) + self.margin
        self.sdf = SparseSDF.from_mesh(
            cell_mesh,
            resolution=resolution,
            subdivisions=subdivisions,
            band=band,
            cache_dir=cache_dir,
            progress=progress,
        )

    def _placed(self, q: ArrayLike) -> FloatArray:
        """Return padded world sphere centres (N, L, K, 3) [m] for q (N, dof) [rad]."""
        qa = np.atleast_2d(np.asarray(q, dtype=float))
        if qa.ndim != 2 or qa.shape[1] != self.robot.dof:
            raise InputError(f"q must have shape (N, {self.robot.dof}) [rad], got {np.shape(q)}")
        return self._pad.place(self.robot.link_transforms(qa)[:, self.links, :3, :])

    def sphere_centres(self, q: ArrayLike) -> FloatArray:
        """Return world sphere centres (N, S, 3) [m] for configurations q (N, dof) [rad]."""
        return self._pad.unpad(self._placed(q))

    def check(self, q: ArrayLike, *, early_exit: bool = False) -> ConservativeReport:
        """Return the report for configurations q (N, dof) [rad]; never misses a contact.

        early_exit: first test one sphere per link that holds all its spheres (centre cb,
        radius R). The distance d is 1-Lipschitz and the field is within max_error of it
        (a lower bound of it outside the band), so d(c) - r >= sdf(cb) - max_error - R for
        each sphere (c, r) of the link: the link's spheres are only looked up where that
        bound does not clear the margin. No contact is missed, and the true clearance is still
        at least ``clearance - max_error``. It is not a bound of the full check, though: the
        field is only within max_error of d and not 1-Lipschitz itself, so a settled link's
        sdf(cb) - R can exceed its spheres' min sdf(c) - r by up to 2 * max_error, and a
        sphere the full check flags can be cleared by its link's bounding sphere.
        """
        c = self._placed(q)
        n, nl, k = c.shape[:3]
        if not early_exit:
            d = self.sdf.query(c.reshape(-1, 3)).reshape(n, -1) - self._pad_r.reshape(-1)
        else:
            limit = self.margin + self.sdf.max_error
            cb = np.matmul(c.swapaxes(2, 3), self._bound_w).reshape(n * nl, 3)
            db = self.sdf.query(cb).reshape(n, nl) - self._bound_r
            near = db <= limit
            d = np.repeat(db, k, axis=1)
            if np.any(near):
                rows, links = np.nonzero(near)
                sub = self.sdf.query(c[rows, links].reshape(-1, 3)).reshape(len(rows), k)
                d3 = d.reshape(n, nl, k)
                d3[rows, links] = sub - self._pad_r[links]
        worst = np.argmin(d, axis=1)
        clearance = d[np.arange(n), worst]
        collides = clearance <= self.margin + self.sdf.max_error
        return ConservativeReport(collides, clearance, self._pad_link[worst])
