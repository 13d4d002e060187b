"""One collision checker with three modes, the same reports, and a guarantee between samples.

Modes (one object each, the same interface: `groups`, `items`, `path_items`):
- ``"exact"`` (`ExactMode`): python-fcl meshes plus a containment test (`RobotCollisionChecker`).
- ``"spheres"`` (`SpheresMode`): every link and the tool wrapped in PSO-fitted spheres against
  the cell's sparse SDF, and sphere pairs for self-collision (seed 001).
- ``"capsules"`` (`CapsulesMode`): every link as a capsule holding all its vertices, obstacles
  as their oriented boxes, whose faces are rectangles (seed 002, exact distances).

Each mode gives, per configuration, "items" with a clearance lower bound [m] (a body, sphere
or capsule against the cell, or a self pair) and levers (dof,) [m/rad] (`JointLevers`): along
a joint step dq an item's clearance changes by at most ``|dq| @ lever``. What the fast modes
flag is confirmed exactly (`ExactPairs`), with containment tests (`Containment`) and pair
tables (`PairTables`) alongside; `PathCertifier` certifies the motion between samples.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.collision.bodies import Pair, RobotBodies
from workbench.collision.capsules_mode import CapsulesMode
from workbench.collision.containment import Containment
from workbench.collision.exact_mode import ExactMode
from workbench.collision.exact_pairs import ExactPairs
from workbench.collision.pair_table import TABLE_TOL, PairTable, PairTables
from workbench.collision.path_check import MAX_DEPTH, AccelerationBound, PathCertifier
from workbench.collision.report import ConfigCheck, EnginePathReport, path_report
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.collision.spheres_mode import FAR_PAIR, SpheresMode
from workbench.errors import InputError
from workbench.geometry.sdf import SparseSDF

FloatArray = NDArray[np.float64]
Mode = Literal["exact", "spheres", "capsules"]
MODES: tuple[str, ...] = ("exact", "spheres", "capsules")
Progress = Callable[[float, str], None]
__all__ = [
    "FAR_PAIR",
    "MODES",
    "TABLE_TOL",
    "CollisionEngine",
    "ConfigCheck",
    "EnginePathReport",
]


class CollisionEngine:
    """Checks a robot against its cell and itself in one of `MODES` (SI units).

    Built from the exact checker (its bodies, cell and enabled self-collision pairs).
    margin [m]: clearance demanded. spheres_per_link, resolution, subdivisions, cache_dir:
    sphere and SDF parameters (spheres mode; fits, fields and pair tables are cached in
    cache_dir). band [m]: the field's band, default the largest sphere radius + margin.
    progress(fraction, message) during builds. Also the path certifier's oracle
    (`path_check.PathOracle`).
    """

    def __init__(
        self,
        exact: RobotCollisionChecker,
        mode: str = "spheres",
        *,
        margin: float = 0.0,
        spheres_per_link: int = 8,
        resolution: int = 64,
        subdivisions: int = 4,
        band: float | None = None,
        cache_dir: str | None = None,
        progress: Progress | None = None,
    ) -> None:
        if mode not in MODES:
            raise InputError(f"mode: {mode!r} is not one of {', '.join(MODES)}")
        if not np.isfinite(margin) or margin < 0:
            raise InputError(f"margin: {margin} m must be a length >= 0")
        report = progress or (lambda _f, _m: None)
        self.exact, self.mode, self.margin = exact, mode, float(margin)
        self.bodies = bodies = RobotBodies(exact)
        self.dof = bodies.dof
        self.checker: SpheresMode | CapsulesMode | ExactMode
        if mode == "spheres":
            self.checker = SpheresMode(
                bodies,
                margin=self.margin,
                spheres_per_link=spheres_per_link,
                resolution=resolution,
                subdivisions=subdivisions,
                band=band,
                cache_dir=cache_dir,
                progress=report,
            )
        elif mode == "capsules":
            self.checker = CapsulesMode(bodies, margin=self.margin)
        else:
            self.checker = ExactMode(bodies, margin=self.margin)
        groups = self.checker.groups()
        self.group_pairs: list[list[Pair]] = [g for g, _ in groups]
        self.item_group = np.repeat(np.arange(len(groups)), [n for _, n in groups]).astype(np.int64)
        self.group_start = np.flatnonzero(np.r_[True, np.diff(self.item_group) != 0]).astype(
            np.int64
        )
        fast = self.checker.exact_confirmation
        self.containment = Containment(bodies, enabled=fast)
        self.always_pairs = self.containment.pairs
        self.pair_lever = bodies.pair_lever
        self.pairs = ExactPairs(bodies, self.margin)
        self.tables = PairTables(
            bodies, self.pairs.node_distances, margin=self.margin, cache_dir=cache_dir, enabled=fast
        )
        self._twin: CollisionEngine | None = self if mode == "exact" else None
        self._group_tables: list[list[tuple[Pair, PairTable | None]]] | None = None
        report(1.0, "collision engine ready")

    # -- what the modes hold ---------------------------------------------------------
    @property
    def body_names(self) -> list[str]:
        """Return the moving bodies' names (links, then the tool)."""
        return self.bodies.names

    @property
    def body_lever(self) -> FloatArray:
        """Return per-body levers (B, dof) [m/rad]."""
        return self.bodies.lever

    @property
    def sdf(self) -> SparseSDF | None:
        """Return the cell's distance field (spheres mode with obstacles), else None."""
        return self.checker.sdf

    @property
    def pair_tables(self) -> dict[Pair, PairTable]:
        """Return the pair tables of the fast modes (pair -> table)."""
        return self.tables.tables

    def _spheres(self) -> SpheresMode:
        if not isinstance(self.checker, SpheresMode):
            raise InputError(f"spheres: the {self.mode} mode has no spheres; use mode 'spheres'")
        return self.checker

    @property
    def centres(self) -> FloatArray:
        """Return sphere centres (S, 3) [m] in their bodies' frames (spheres mode)."""
        return self._spheres().centres

    @property
    def radii(self) -> FloatArray:
        """Return sphere radii (S,) [m] (spheres mode)."""
        return self._spheres().radii

    @property
    def sphere_body(self) -> NDArray[np.int64]:
        """Return each sphere's body index (S,) (spheres mode)."""
        return self._spheres().sphere_body

    def spheres(self, q: ArrayLike) -> tuple[FloatArray, FloatArray, list[str]]:
        """Return world sphere centres (S,3) [m], radii (S,) [m] and each sphere's body name."""
        s = self._spheres()
        c = s.sphere_centres(np.atleast_2d(np.asarray(q, float)))[0]
        return c, s.radii.copy(), [self.body_names[b] for b in s.sphere_body]

    def body_poses(self, qs: ArrayLike) -> FloatArray:
        """Return world poses (N, B, 4, 4) of every body (links, tool) at qs (N, dof) [rad]."""
        return self.bodies.poses(qs)

    def items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return clearance lower bounds (N, I) [m] (margin subtracted) and levers (I, dof)."""
        return self.checker.items(qs)

    def exact_twin(self) -> CollisionEngine:
        """Return an exact-mode engine on the same checker (built once)."""
        if self._twin is None:
            self._twin = CollisionEngine(self.exact, "exact", margin=self.margin)
        return self._twin

    def save_tables(self) -> None:
        """Write the pair tables that gained nodes to their cache files (if any)."""
        self.tables.save()

    def penetration(self, q: FloatArray, a: str, b: str) -> float:
        """Return the depth [m] of the deepest vertex of body a inside b or of b inside a."""
        return self.pairs.penetration(q, a, b)

    def contained(self, qs: FloatArray) -> NDArray[np.bool_]:
        """Return (N, len(always_pairs)): whether one body of the pair holds the other's probe."""
        return self.containment.contained(qs)

    # -- the path certifier's oracle ---------------------------------------------------
    def path_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return the items for the path certifier (the exact mode leaves every pair to fcl)."""
        return self.checker.path_items(qs)

    def poses(self, qs: FloatArray) -> FloatArray:
        """Return world poses (N, B, 4, 4) of the moving bodies, for `place`."""
        return self.bodies.poses(qs)

    def place(self, poses: FloatArray) -> None:
        """Set the world poses (B, 4, 4) of the moving bodies; each is placed when first used."""
        self.pairs.place(poses)

    def aabb_gaps(self, poses: FloatArray) -> FloatArray:
        """Return (N, P): bounding-box gaps [m] of every exact pair, less the margin."""
        return self.pairs.aabb_gaps(poses)

    def table_bounds(self, qs: FloatArray, mask: NDArray[np.bool_]) -> FloatArray:
        """Return (N, P): pair-table lower bounds [m], less the margin (see `PairTables.bounds`)."""
        return self.tables.bounds(qs, mask)

    def pair_collides(self, pair: Pair) -> bool:
        """Return the exact verdict (fcl collide, then containment) of a pair as placed."""
        return self.pairs.collides(pair)

    def pair_distance(self, pair: Pair) -> float:
        """Return the pair's surface distance [m] as placed, less the margin."""
        return self.pairs.distance(pair)

    # -- checks -----------------------------------------------------------------------
    def check(self, q: ArrayLike) -> ConfigCheck:
        """Return the check of one configuration q (dof,) [rad]; flagged ones confirmed exactly.

        Fast modes: the items of q; a group with an item <= 0 is flagged and its exact pairs
        are settled one by one: by their pair table's lower bound (scalar look-up), else
        fcl's collide and, when free, fcl's distance. Containment is tested at every q. The
        verdict is the exact one, the clearance the least lower bound (unflagged groups'
        items, flagged pairs' table bounds or fcl distances).
        """
        qq = np.asarray(q, float).reshape(1, -1)
        if self.mode != "exact":
            return self._check_fast(qq)
        clr, _ = self.items(qq)
        low = float(clr.min())
        flagged = low <= 0.0
        if self.mode == "exact" or flagged:
            rep = self.exact.check(qq[0], distance=False)
            if rep.in_collision:
                a, b = rep.colliding[0]
                return ConfigCheck(True, True, 0.0, a, b, self.penetration(qq[0], a, b), rep)
            if self.mode != "exact":
                low = float(self.exact_twin().items(qq)[0].min())
            return ConfigCheck(False, flagged, max(low, 0.0), exact=rep)
        return ConfigCheck(False, False, low)

    def _check_fast(self, qq: FloatArray) -> ConfigCheck:
        """Return `check` of one configuration qq (1, dof) [rad] in a fast mode.

        One row's path throughout: the scalar FK (`RobotBodies.poses_one`), the mode's
        `items_one` where it has one (spheres), the containment batch of one configuration,
        then the flagged groups' pair tables in scalar math (the lists built once).
        """
        poses = self.bodies.poses_one(qq[0])
        one = getattr(self.checker, "items_one", None)
        clr = one(poses) if one is not None else self.items(qq)[0][0]
        gmin = np.minimum.reduceat(clr, self.group_start).tolist()
        held = self.containment.contained_one(poses).tolist()
        low = min(gmin)
        if low > 0.0 and True not in held:
            return ConfigCheck(False, False, low)
        flagged = [g for g, v in enumerate(gmin) if v <= 0.0]
        low = min((v for v in gmin if v > 0.0), default=np.inf)
        qv = qq[0].tolist()
        self.pairs.place(poses)
        if self._group_tables is None:
            tables = self.tables.tables
            self._group_tables = [[(p, tables.get(p)) for p in g] for g in self.group_pairs]
        margin = self.margin
        unsettled: list[Pair] = []
        for g in flagged:
            for pair, table in self._group_tables[g]:
                lb = table.bound_one(qv) - margin if table is not None else -np.inf
                if lb > 0.0:
                    low = min(low, lb)
                else:
                    unsettled.append(pair)
        if True in held:
            unsettled += [p for p, h in zip(self.always_pairs, held, strict=True) if h]
        for pair in dict.fromkeys(unsettled):  # in order, once each
            if self.pairs.collides(pair):
                a, b = pair
                return ConfigCheck(True, True, 0.0, a, b, self.penetration(qq[0], a, b))
        for pair in dict.fromkeys(unsettled):
            low = min(low, self.pairs.distance(pair))
        return ConfigCheck(False, bool(flagged), max(low, 0.0))

    def check_path(
        self,
        qs: ArrayLike,
        times: ArrayLike | None = None,
        *,
        deviation: ArrayLike | None = None,
        sampler: Callable[[FloatArray], FloatArray] | None = None,
        acceleration: ArrayLike | AccelerationBound | None = None,
        max_depth: int = MAX_DEPTH,
        progress: Progress | None = None,
    ) -> EnginePathReport:
        """Return the report of the path through samples qs (N, dof) [rad], between samples too.

        times (N,) [s] (default 0, 1, 2, ...). Between samples the motion is either the
        straight joint segment, or within deviation (dof,) [rad] of it, or (with `sampler`,
        times -> (M, dof) [rad], the real motion) within ``acceleration * h**2 / 8`` of it,
        acceleration (dof,) [rad/s^2] bounding |q''| (or a function (t0, t1) -> (M, dof)
        bounding it on each interval [t0, t1]). Intervals that cannot be certified are
        bisected, each on its own, up to `max_depth` times (the finest subdivision; no
        budget shared across the path, so the cost per sample does not grow with its length);
        one still not certified there is reported as such (`uncertified_indices`). All
        samples go through the fast items at once; what they flag is confirmed exactly, pair
        by pair, so `colliding_indices` equals the dense exact check of every sample.
        """
        q = np.atleast_2d(np.asarray(qs, float))
        self.body_poses(q)  # validates the shape
        n = len(q)
        t = np.arange(n, dtype=float) if times is None else np.asarray(times, float).reshape(-1)
        if t.shape != (n,) or not np.all(np.isfinite(t)):
            raise InputError(f"times: expected {n} finite values [s], got shape {t.shape}")
        dev = np.zeros(self.dof) if deviation is None else np.abs(np.asarray(deviation, float))
        acc: FloatArray | AccelerationBound | None = None
        if callable(acceleration):
            acc = acceleration
        elif acceleration is not None:
            acc = np.abs(np.asarray(acceleration, float))
        if dev.shape != (self.dof,) or (isinstance(acc, np.ndarray) and acc.shape != (self.dof,)):
            raise InputError(f"deviation/acceleration: expected {self.dof} values per joint")
        if sampler is not None and acc is None:
            raise InputError("acceleration: a sampler needs the bound on |q''| [rad/s^2]")
        out = PathCertifier(self).run(
            q,
            t,
            sampler=sampler,
            acceleration=acc,
            deviation=dev,
            max_depth=max_depth,
            progress=progress,
        )
        self.save_tables()
        return path_report(
            out,
            q,
            t,
            mode=self.mode,
            pairs_checked=len(self.exact.scene.pairs),
            penetration=self.penetration,
        )
