"""Spheres mode: PSO spheres of every body against the cell's sparse SDF, sphere pairs for self pairs.

Seed 001. Each body's mesh is wrapped in spheres that hold its whole surface (`fit_spheres`);
the cell gets a sparse signed distance field whose band is the largest radius plus the
margin, so every sphere test reads an interpolated value. A sphere (c, r) is clear of the
cell by at least ``sdf(c) - r - max_error``, and two spheres by ``|c_a - c_b| - r_a - r_b``.

No false negatives: if a body's surface touches an obstacle at x, the sphere that holds x has
d(c) <= d(x) + |c - x| <= r (d is 1-Lipschitz), and the field is within max_error of d in
the band. Not covered by the spheres: an obstacle wholly inside a body (containment, which
the engine tests exactly). Items are grouped per body against the cell (one group per body:
its spheres stand for every obstacle pair of the body) and per self pair.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from workbench.collision.bodies import Pair, RobotBodies
from workbench.collision.padded_spheres import PaddedSpheres
from workbench.errors import InputError
from workbench.geometry.sdf import SparseSDF
from workbench.geometry.spheres import fit_spheres

FloatArray = NDArray[np.float64]
Progress = Callable[[float, str], None]
# Self pairs whose bounding spheres are farther apart than this [m] skip their sphere pairs
# in path checks (the bound between bounding spheres is their items' clearance).
FAR_PAIR = 0.1
_ONES3 = np.ones(3)


class SpheresMode:
    """The spheres items of `bodies` (SI units); see the module docstring.

    Attributes: `centres` (S, 3) [m] in body frames, `radii` (S,), `sphere_body` (S,),
    `sdf` (None for an empty cell), `cell_spheres` (indices of spheres checked against it).
    """

    name = "spheres"
    exact_confirmation = True  # flagged groups go to fcl; containment and pair tables apply

    def __init__(
        self,
        bodies: RobotBodies,
        *,
        margin: float,
        spheres_per_link: int,
        resolution: int,
        subdivisions: int,
        band: float | None,
        cache_dir: str | None,
        progress: Progress,
    ) -> None:
        if int(resolution) < 2:
            raise InputError(f"resolution: {resolution} must be >= 2 coarse cells")
        if spheres_per_link < 1:
            raise InputError(f"spheres_per_link: {spheres_per_link} must be a positive integer")
        self.bodies, self.margin = bodies, margin
        names = bodies.names
        cs, rs, owner = [], [], []
        for i, mesh in enumerate(bodies.meshes):
            progress(0.3 * i / len(names), f"fitting spheres to {names[i]}")
            s = fit_spheres(mesh, int(spheres_per_link), seed=0, cache_dir=cache_dir)
            cs.append(s.centres)
            rs.append(s.radii)
            owner.append(np.full(len(s.radii), i))
        self.centres = np.concatenate(cs)
        self.radii = np.concatenate(rs)
        self.sphere_body = np.concatenate(owner)
        self.sphere_lever = np.stack(
            [
                bodies.levers_of.levers(int(bodies.frame[b]), c[None])
                for b, c in zip(self.sphere_body, self.centres, strict=True)
            ]
        )
        self.cell_spheres = np.flatnonzero(np.isin(self.sphere_body, bodies.checked))
        pa, pb = [], []
        for a, b in bodies.self_pairs:
            sa = np.flatnonzero(self.sphere_body == bodies.index[a])
            sb = np.flatnonzero(self.sphere_body == bodies.index[b])
            pa.append(np.repeat(sa, len(sb)))
            pb.append(np.tile(sb, len(sa)))
        self.pair_a = np.concatenate(pa) if pa else np.zeros(0, np.int64)
        self.pair_b = np.concatenate(pb) if pb else np.zeros(0, np.int64)
        self.pair_levers = bodies.relative_levers(
            self.sphere_body[self.pair_a],
            self.sphere_body[self.pair_b],
            self.sphere_lever[self.pair_a],
            self.sphere_lever[self.pair_b],
        )
        self._one: tuple | None = None  # type: ignore[type-arg]  # items_one's index arrays
        self._padded = PaddedSpheres(self.centres, self.radii, self.sphere_body, len(names))
        self._bounding_spheres()
        self.sdf: SparseSDF | None = None
        cell = bodies.cell_mesh()
        if cell is not None:
            r = float(self.radii.max()) + margin if band is None else float(band)
            # Coarse cells from the cell's size, but at least r / 8: a small cell with a band
            # of many cells would mark (r / h)^3 cells per triangle.
            h = max(float(np.ptp(cell.vertices, axis=0).max()) / max(resolution, 1), r / 8)
            self.sdf = SparseSDF.from_mesh(
                cell,
                cell_size=h,
                subdivisions=subdivisions,
                band=r,
                cache_dir=cache_dir,
                progress=lambda f, m: progress(0.3 + 0.7 * f, m),
            )

    def _bounding_spheres(self) -> None:
        """Per body a sphere holding its spheres: centre the mean of their centres, radius the
        farthest reach (a rigid motion carries the mean along)."""
        nb = len(self.bodies.names)
        self._own = [np.flatnonzero(self.sphere_body == b) for b in range(nb)]
        r = np.zeros(nb)
        for b, own in enumerate(self._own):
            if own.size:
                mid = self.centres[own].mean(axis=0)
                reach = np.linalg.norm(self.centres[own] - mid, axis=1) + self.radii[own]
                r[b] = float(np.max(reach))
        self._bound_r = r
        blocks, start = [], 0
        for na, nb_ in self.bodies.self_pairs:
            ia, ib = self.bodies.index[na], self.bodies.index[nb_]
            size = len(self._own[ia]) * len(self._own[ib])
            blocks.append((start, start + size, ia, ib))
            start += size
        self._blocks = blocks

    def groups(self) -> list[tuple[list[Pair], int]]:
        """Return (exact pairs, item count) per group, in item order."""
        out: list[tuple[list[Pair], int]] = []
        b = self.bodies
        if self.sdf is not None:
            owners = self.sphere_body[self.cell_spheres]
            for body in np.unique(owners):
                name = b.names[body]
                out.append(([p for p in b.cell_pairs if p[0] == name], int(np.sum(owners == body))))
        for pa, pb in b.self_pairs:
            n = np.sum(self.sphere_body == b.index[pa]) * np.sum(self.sphere_body == b.index[pb])
            out.append(([(pa, pb)], int(n)))
        return out

    def sphere_centres(self, qs: FloatArray) -> FloatArray:
        """Return world sphere centres (N, S, 3) [m] at qs (N, dof) [rad]."""
        return self._padded.unpad(self._padded.place(self.bodies.poses(qs)))

    def cell_items(self, c: FloatArray) -> FloatArray:
        """Return (N, len(cell_spheres)): each cell sphere's clearance lower bound [m] (no margin)."""
        if self.sdf is None or not self.cell_spheres.size:
            return np.zeros((len(c), 0))
        d = self.sdf.query(c[:, self.cell_spheres].reshape(-1, 3)).reshape(len(c), -1)
        return d - self.radii[self.cell_spheres] - self.sdf.max_error  # type: ignore[no-any-return]

    def items(self, qs: FloatArray, *, far: float | None = None) -> tuple[FloatArray, FloatArray]:
        """Return clearance lower bounds (N, I) [m] (margin subtracted) and levers (I, dof).

        With `far` [m], self pairs whose bodies' bounding spheres are more than `far` apart
        get that (smaller, still valid) gap for all their sphere pairs.
        """
        c = self.sphere_centres(qs)
        n = len(c)
        cols, levers = [], []
        if self.sdf is not None and self.cell_spheres.size:
            cols.append(self.cell_items(c))
            levers.append(self.sphere_lever[self.cell_spheres])
        if self.pair_a.size:
            if far is None:
                gap = np.linalg.norm(c[:, self.pair_a] - c[:, self.pair_b], axis=2)
                cols.append(gap - self.radii[self.pair_a] - self.radii[self.pair_b])
            else:
                cols.append(self._far_pair_gaps(c, far))
            levers.append(self.pair_levers)
        if not cols:
            return np.full((n, 1), np.inf), np.zeros((1, self.bodies.dof))
        return np.concatenate(cols, axis=1) - self.margin, np.concatenate(levers)

    def items_one(self, poses: FloatArray) -> FloatArray:
        """Return `items` of one configuration (I,) [m], the bodies at world poses (B, 4, 4).

        The same values (to rounding) in a dozen numpy calls on index arrays built once: one
        matmul places every sphere, one fused look-up of all cell spheres' centres in the
        field (`SparseSDF.query_fast`), one gather-and-norm for all sphere pairs.
        """
        if self._one is None:
            slot = self._padded.slot
            cell = self.sdf is not None and self.cell_spheres.size > 0
            err = self.sdf.max_error if self.sdf is not None else 0.0
            nc = len(self.cell_spheres) if cell else 0
            np_ = len(self.pair_a)
            # One gather: the cell spheres' slots, then both ends of every sphere pair.
            rows = np.concatenate(
                [slot[self.cell_spheres][:nc], slot[self.pair_a], slot[self.pair_b]]
            )
            radius = np.concatenate(
                [
                    self.radii[self.cell_spheres][:nc] + err + self.margin,
                    self.radii[self.pair_a] + self.radii[self.pair_b] + self.margin,
                ]
            )
            self._one = (rows, radius, nc, np_)
        rows, radius, nc, np_ = self._one
        if not nc and not np_:
            return np.full(1, np.inf)
        w = np.matmul(poses[:, :3, :], self._padded._h)  # (B, 3, K)
        x = w.transpose(0, 2, 1).reshape(-1, 3).take(rows, axis=0)  # (nc + 2 * pairs, 3)
        out = np.empty(nc + np_)
        if nc:
            out[:nc] = self.sdf.query_fast(x[:nc])  # type: ignore[union-attr]
        if np_:
            d = x[nc : nc + np_] - x[nc + np_ :]
            d *= d
            out[nc:] = np.sqrt(d @ _ONES3)
        out -= radius
        return out

    def path_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return `items` for the path certifier: far self pairs by their bounding spheres."""
        return self.items(qs, far=FAR_PAIR)

    def _far_pair_gaps(self, c: FloatArray, far: float) -> FloatArray:
        """Return sphere-pair gaps (N, pairs) [m]: exact where the bodies are near, else a bound.

        Every sphere of a body lies in the body's bounding sphere, so
        |cb_a - cb_b| - R_a - R_b bounds every sphere pair's gap from below.
        """
        mid = {b: c[:, own].mean(axis=1) for b, own in enumerate(self._own) if own.size}
        out = np.empty((len(c), len(self.pair_a)))
        for s0, s1, ia, ib in self._blocks:
            bound = (
                np.linalg.norm(mid[ia] - mid[ib], axis=1) - self._bound_r[ia] - self._bound_r[ib]
            )
            near = np.flatnonzero(bound <= far)
            out[:, s0:s1] = bound[:, None]
            if near.size:
                pa, pb = self.pair_a[s0:s1], self.pair_b[s0:s1]
                cn = c[near]
                gap = np.linalg.norm(cn[:, pa] - cn[:, pb], axis=2)
                out[near, s0:s1] = gap - self.radii[pa] - self.radii[pb]
        return out

    def cell_clearance(
        self, qs: FloatArray, *, early_exit: bool = False
    ) -> tuple[FloatArray, NDArray[np.int64]]:
        """Return the least cell item per configuration (N,) [m] and its body (N,).

        The body-against-cell check alone (no self pairs, no margin): a configuration may touch
        the cell only where the clearance is <= 0. early_exit: first one bounding sphere per
        body (centre cb, radius R): since d is 1-Lipschitz and the field is within max_error
        of it, ``d(c) - r >= sdf(cb) - max_error - R`` for each of the body's spheres, whose
        own look-ups are skipped where that bound (less max_error) clears 0. No contact is
        missed either way, and both values are lower bounds of the true clearance; the
        early-exit value is not a bound of the full one (the field is not 1-Lipschitz itself:
        a settled body's bound can exceed its spheres' least by up to 2 * max_error).
        """
        if self.sdf is None or not self.cell_spheres.size:
            n = len(np.atleast_2d(qs))
            return np.full(n, np.inf), np.zeros(n, np.int64)
        c = self.sphere_centres(qs)
        owners = self.sphere_body[self.cell_spheres]
        if not early_exit:
            d = self.cell_items(c)
        else:
            bodies = np.unique(owners)
            mid = np.stack([c[:, self._own[b]].mean(axis=1) for b in bodies], axis=1)
            db = self.sdf.query(mid.reshape(-1, 3)).reshape(len(c), -1)
            db = db - self._bound_r[bodies] - self.sdf.max_error
            d = db[:, np.searchsorted(bodies, owners)]
            for k, b in enumerate(bodies):
                rows = np.flatnonzero(db[:, k] <= 0.0)
                if rows.size:
                    own = np.flatnonzero(owners == b)
                    s = self.cell_spheres[own]
                    val = self.sdf.query(c[rows][:, s].reshape(-1, 3)).reshape(len(rows), -1)
                    d[np.ix_(rows, own)] = val - self.radii[s] - self.sdf.max_error
        worst = np.argmin(d, axis=1)
        return d[np.arange(len(d)), worst], owners[worst]
