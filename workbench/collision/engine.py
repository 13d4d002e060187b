"""One collision checker with three modes, the same reports, and a guarantee between samples.

Modes:
- ``"exact"``: python-fcl meshes plus a containment test (`RobotCollisionChecker`).
- ``"spheres"``: every link and the tool wrapped in PSO-fitted spheres against the cell's
  sparse SDF, and sphere pairs for self-collision (seed 001). Fast and conservative; what
  it flags is confirmed exactly with fcl, which also names the obstacle.
- ``"capsules"``: every link as a capsule holding all its vertices, obstacles as their
  oriented boxes, whose faces are rectangles (seed 002, exact segment-rectangle distance).

Each mode gives, per configuration, "items" with a clearance lower bound [m] (a body or
sphere or capsule against the cell, or a self-collision pair) and levers (dof,) [m/rad]
(`JointLevers`): along a joint step dq an item's clearance changes by at most
``|dq| @ lever``. An interval between two samples a, b is collision-free when every item has
``clr_a + clr_b > |q_b - q_a| @ lever + 2 * deviation @ lever`` (the point of the motion
nearest to an obstacle is within half the travel of one end); otherwise it is bisected.
`deviation` (dof,) [rad] bounds how far the real motion strays from the straight joint
segment between samples (0 for a path that is linear between samples).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import fcl
import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.collision.fcl_checker import CollisionReport
from workbench.collision.motion_bound import JointLevers
from workbench.collision.padded_spheres import PaddedSpheres
from workbench.collision.pair_table import PairTable, pair_joints
from workbench.collision.path_check import AccelerationBound, PathCertifier
from workbench.collision.robot_checker import PathReport, RobotCollisionChecker
from workbench.errors import InputError
from workbench.geometry.lbvh import LBVH
from workbench.geometry.npz_cache import cache_path
from workbench.geometry.sdf import SparseSDF
from workbench.geometry.spheres import fit_spheres

FloatArray = NDArray[np.float64]
Mode = Literal["exact", "spheres", "capsules"]
MODES: tuple[str, ...] = ("exact", "spheres", "capsules")
Progress = Callable[[float, str], None]
# Grid step of the pair tables: their bound is at most TABLE_TOL [m] below fcl's distance.
TABLE_TOL = 0.006
# Self pairs whose bounding spheres are farther apart than this [m] skip their sphere pairs
# in path checks (the bound between bounding spheres is their items' clearance).
FAR_PAIR = 0.1
# A lower bound that says nothing [m] (finite, so chord bounds stay free of inf - inf).
NO_BOUND = -1e9


@dataclass(frozen=True)
class ConfigCheck:
    """One configuration: verdict, clearance lower bound [m] and, when colliding, what touches.

    For the fast modes `colliding` is the exact (fcl) verdict on what the mode flagged;
    `flagged` says the fast test could not rule a contact out.
    """

    colliding: bool
    flagged: bool
    clearance: float
    link: str | None = None
    obstacle: str | None = None
    penetration: float = 0.0
    exact: CollisionReport | None = None


@dataclass(frozen=True)
class EnginePathReport(PathReport):
    """A joint path's report: `PathReport` fields plus the guarantee between samples.

    `colliding_indices`: samples in collision (the exact verdict of each sample);
    `between_indices`: samples i whose interval to i+1 collides (or could not be certified)
    between them. clearance [m]: lower bound over the whole path (samples and between) when
    collision-free. first_time [s] / first_q [rad]: where the first collision is (a sample
    or, `between`, between two); link/obstacle: the colliding pair's names; penetration [m]:
    deepest vertex of either body inside the other. `evaluated`: configurations checked,
    subdivisions included; `flagged_samples`: samples the fast mode sent to the exact check;
    `exact_pairs`: exact pair tests (collide or distance) run. `fallback`: why the fast mode
    was not used (the samples were then checked densely and exactly, not between them).
    """

    mode: str = "spheres"
    clearance: float = float("nan")
    first_time: float | None = None
    first_q: FloatArray | None = field(default=None, repr=False)
    link: str | None = None
    obstacle: str | None = None
    penetration: float = 0.0
    evaluated: int = 0
    certified: bool = True
    between: bool = False
    between_indices: tuple[int, ...] = ()
    flagged_samples: int = 0
    exact_pairs: int = 0
    fallback: str | None = None

    @property
    def message(self) -> str:
        """Return the report as one sentence for a user (mm)."""
        if self.fallback is not None:
            if self.collision_free:
                return (
                    f"collision-free at every sample ({self.samples} samples, exact check;"
                    f" not certified between samples: {self.fallback})"
                )
            return (
                f"collision at t = {self.first_time:.3f} s (sample {self.first_index}):"
                f" {self.link} hits {self.obstacle} (exact check of every sample;"
                f" {self.fallback})"
            )
        if self.collision_free:
            return (
                f"collision-free, including between samples, with clearance of at least"
                f" {self.clearance * 1e3:.1f} mm ({self.samples} samples,"
                f" {self.evaluated} configurations checked, {self.mode})"
            )
        if not self.certified and self.link is None:
            return (
                f"not certified between samples near t = {self.first_time:.3f} s: clearance"
                " below the subdivision limit; treat it as touching"
            )
        where = f"t = {self.first_time:.3f} s" if self.first_time is not None else "?"
        at = (
            f" (between samples {self.first_index} and {self.first_index + 1})"
            if self.between and self.first_index is not None
            else f" (sample {self.first_index})"
        )
        return (
            f"collision at {where}{at}: {self.link} hits {self.obstacle},"
            f" penetration {self.penetration * 1e3:.1f} mm"
        )


class CollisionEngine:
    """Checks a robot against its cell and itself in one of `MODES` (SI units).

    Built from the exact checker (its bodies, cell and enabled self-collision pairs).
    margin [m]: clearance demanded. spheres_per_link, resolution, subdivisions, cache_dir:
    sphere and SDF parameters (spheres mode; fits and fields are cached in cache_dir).
    band [m]: the field's band, default the largest sphere radius + margin (every sphere
    test then reads an interpolated value, not a far lower bound). progress(fraction,
    message) during builds.
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
        robot: Any = exact.robot
        self.dof = robot.dof
        self.T_world_base = exact.T_world_base
        names = list(exact.link_names) + (["tool"] if exact.has_tool else [])
        self.body_names = names
        self.body_frame = np.array(
            list(range(self.dof + 1)) + ([self.dof] if exact.has_tool else [])
        )
        self.meshes = [exact.scene.moving[n].mesh for n in names]
        moving = set(names)
        self.self_pairs = [(a, b) for a, b in exact.scene.pairs if a in moving and b in moving]
        self.cell_pairs = [(a, b) for a, b in exact.scene.pairs if b not in moving]
        self.obstacles = list(exact.scene.static)
        self.levers_of = JointLevers(robot)
        idx = {n: i for i, n in enumerate(names)}
        checked = sorted({idx[a] for a, _ in self.cell_pairs})
        self.body_lever = np.stack(
            [
                self.levers_of.levers(int(self.body_frame[i]), m.vertices)
                for i, m in enumerate(self.meshes)
            ]
        )
        self.sdf: SparseSDF | None = None
        if mode == "spheres":
            if int(resolution) < 2:
                raise InputError(f"resolution: {resolution} must be >= 2 coarse cells")
            if spheres_per_link < 1:
                raise InputError(f"spheres_per_link: {spheres_per_link} must be a positive integer")
            cs, rs, owner = [], [], []
            for k, i in enumerate(range(len(names))):
                report(0.3 * k / len(names), f"fitting spheres to {names[i]}")
                s = fit_spheres(self.meshes[i], int(spheres_per_link), seed=0, cache_dir=cache_dir)
                cs.append(s.centres)
                rs.append(s.radii)
                owner.append(np.full(len(s.radii), i))
            self.centres = np.concatenate(cs)
            self.radii = np.concatenate(rs)
            self.sphere_body = np.concatenate(owner)
            self.sphere_lever = np.stack(
                [
                    self.levers_of.levers(int(self.body_frame[b]), c[None])
                    for b, c in zip(self.sphere_body, self.centres, strict=True)
                ]
            )
            self.cell_spheres = np.flatnonzero(np.isin(self.sphere_body, checked))
            pa, pb = [], []
            for a, b in self.self_pairs:
                sa = np.flatnonzero(self.sphere_body == idx[a])
                sb = np.flatnonzero(self.sphere_body == idx[b])
                pa.append(np.repeat(sa, len(sb)))
                pb.append(np.tile(sb, len(sa)))
            self.pair_a = np.concatenate(pa) if pa else np.zeros(0, np.int64)
            self.pair_b = np.concatenate(pb) if pb else np.zeros(0, np.int64)
            cell = self.cell_mesh()
            if cell is not None:
                r = float(self.radii.max()) + self.margin if band is None else float(band)
                # Coarse cells from the cell's size, but at least r / 8: a small cell with a
                # band of many cells would mark (r / h)^3 cells per triangle.
                h = max(float(np.ptp(cell.vertices, axis=0).max()) / max(resolution, 1), r / 8)
                self.sdf = SparseSDF.from_mesh(
                    cell,
                    cell_size=h,
                    subdivisions=subdivisions,
                    band=r,
                    cache_dir=cache_dir,
                    progress=lambda f, m: report(0.3 + 0.7 * f, m),
                )
        if mode == "capsules":
            self._capsules(checked)
        self._groups(idx)
        self._body_index = idx
        self._pending = np.zeros((0, 4, 4))
        self._placed: set[str] = set()
        self._tables(idx, np.asarray(robot.limits, float), cache_dir)
        report(1.0, "collision engine ready")

    def _groups(self, idx: dict[str, int]) -> None:
        """Set which exact pairs each item stands for, and the pairs always checked exactly.

        Items are contiguous per group (`group_start`). A sphere against the cell stands for its
        body against every obstacle; a sphere pair, a capsule item and an exact item for one
        pair. `always_pairs`: pairs where one body could lie wholly inside the other (its
        largest extent is below the other's diagonal) without touching it; spheres hold
        surfaces, so those pairs get the exact test (collide, then containment) at every
        configuration.
        """
        groups: list[list[tuple[str, str]]] = []
        item_group: list[NDArray[np.int64]] = []
        if self.mode == "spheres":
            if self.sdf is not None:
                bodies = self.sphere_body[self.cell_spheres]
                for b in np.unique(bodies):
                    name = self.body_names[b]
                    item_group.append(np.full(int(np.sum(bodies == b)), len(groups)))
                    groups.append([p for p in self.cell_pairs if p[0] == name])
            for a, b in self.self_pairs:
                n = int(np.sum(self.sphere_body == idx[a]) * np.sum(self.sphere_body == idx[b]))
                item_group.append(np.full(n, len(groups)))
                groups.append([(a, b)])
        else:
            pairs = list(self.exact.scene.pairs) if self.mode == "exact" else self._cap_pairs
            for p in pairs:
                item_group.append(np.array([len(groups)]))
                groups.append([p])
        self.group_pairs = groups
        self.item_group = (
            np.concatenate(item_group).astype(np.int64) if item_group else np.zeros(0, np.int64)
        )
        self.group_start = np.flatnonzero(np.r_[True, np.diff(self.item_group) != 0]).astype(
            np.int64
        )
        scene = self.exact.scene
        size = {n: np.asarray(scene._entry(n).mesh.extents, float) for n in scene.moving}
        size.update({n: np.asarray(e.mesh.extents, float) for n, e in scene.static.items()})

        # A body wholly inside an obstacle has its surface inside, which the items catch; an
        # obstacle (or another body) wholly inside a body does not touch the body's spheres.
        # Such (inner, outer) pairs, where inner's largest extent is below outer's diagonal
        # (>= its diameter), get the containment test of the exact checker (inner's probe
        # vertex inside outer) at every configuration, batched in `contained`.
        def fits(a: str, b: str) -> bool:
            inner, outer = scene._entry(a), scene._entry(b)
            # fcl's collide already finds a mesh inside a primitive (a solid).
            return outer.closed and bool(
                np.max(inner.mesh.extents) <= np.linalg.norm(outer.mesh.extents)
            )

        self.always_pairs: list[tuple[str, str]] = []
        self._inside_tests: list[tuple[int, str, str]] = []  # (always pair, inner, outer)
        for a, b in scene.pairs if self.mode != "exact" else []:
            tests = [(b, a)] if fits(b, a) else []
            if b in scene.moving and fits(a, b):
                tests.append((a, b))
            if tests:
                self._inside_tests += [(len(self.always_pairs), i, o) for i, o in tests]
                self.always_pairs.append((a, b))
        self._convex = {n: scene._entry(n).halfspaces for _, _, n in self._inside_tests}
        self.pair_lever = {p: self._pair_lever(p, self.body_lever, idx) for p in scene.pairs}

    def _tables(self, idx: dict[str, int], limits: FloatArray, cache_dir: str | None) -> None:
        """Set a `PairTable` for every exact pair whose distance depends on one or two joints.

        The fast modes only (the exact mode stays the plain fcl reference). Tables fill lazily
        and are kept with the engine, so later paths reuse the nodes computed so far; with
        `cache_dir` also on disk (``table-<sha256>.npz``, digest of both meshes, the bodies'
        poses at probe configurations (kinematics, base, tool), the grid and the margin-free
        distance definition), written after each path check that computed new nodes.
        """
        self.pair_tables: dict[tuple[str, str], PairTable] = {}
        self._table_cols: list[tuple[int, PairTable]] = []
        if self.mode == "exact":
            return
        for a, b in self.exact.scene.pairs:
            fa = int(self.body_frame[idx[a]])
            fb = int(self.body_frame[idx[b]]) if b in idx else None
            joints = pair_joints(fa, fb)
            lever = self.pair_lever[(a, b)][joints]
            if not 1 <= len(joints) <= 2 or not np.all(lever > 0):
                continue
            table = PairTable(
                joints,
                limits[joints, 0],
                limits[joints, 1],
                lever,
                self.dof,
                functools.partial(self._node_distances, (a, b)),
                tol=TABLE_TOL,
            )
            if cache_dir is not None:
                table.attach(self._table_path(cache_dir, (a, b), table))
            self.pair_tables[(a, b)] = table
        pairs = list(self.pair_lever)
        self._table_cols = [(pairs.index(p), t) for p, t in self.pair_tables.items()]

    def _table_path(self, cache_dir: str | Path, pair: tuple[str, str], table: PairTable) -> Path:
        """Return the cache entry of a pair table, keyed by everything its values depend on."""
        scene = self.exact.scene
        probes = np.random.default_rng(0).uniform(-1.0, 1.0, (3, self.dof))
        T = self.body_poses(probes)
        inputs: list[NDArray] = []
        kinds = []
        for name in pair:
            e = scene._entry(name)
            pose = T[:, self._body_index[name]] if name in self._body_index else e.T
            inputs += [np.asarray(e.mesh.vertices, float), np.asarray(e.mesh.faces, np.int64)]
            inputs.append(np.asarray(pose, float))
            kinds.append(str(e.solid.kind))
        inputs += [table.joints, table.lower, table.step, table.count]
        return cache_path(cache_dir, "table", inputs, {"kinds": kinds, "format": 2})

    def save_tables(self) -> None:
        """Write the pair tables that gained nodes to their cache files (if any)."""
        for table in self.pair_tables.values():
            table.save()

    def _node_distances(self, pair: tuple[str, str], qs: FloatArray) -> FloatArray:
        """Return the pair's exact distance [m] at qs (M, dof): 0 when touching or held."""
        scene = self.exact.scene
        T = self.body_poses(qs)
        ia = self._body_index[pair[0]]
        ib = self._body_index.get(pair[1])
        out = np.empty(len(qs))
        for k in range(len(qs)):
            scene.moving[pair[0]].place(T[k, ia])
            if ib is not None:
                scene.moving[pair[1]].place(T[k, ib])
            out[k] = 0.0 if scene.collides(*pair) else scene.distance(*pair)
        self._placed = set()  # the path's pending poses must be placed again
        return out

    def table_bounds(self, qs: FloatArray, mask: NDArray[np.bool_]) -> FloatArray:
        """Return (N, P): pair-table lower bounds [m] of the exact pairs' distances, less the margin.

        qs (N, dof) [rad]; mask (N, P) says which entries are wanted (pairs in `pair_lever`
        order). Wanted entries of pairs without a table get NO_BOUND (a large negative value:
        no information); entries not wanted are NaN. Only wanted entries fill table nodes.
        """
        out = np.full(mask.shape, np.nan)
        out[mask] = NO_BOUND
        for col, table in self._table_cols:
            rows = np.flatnonzero(mask[:, col])
            if rows.size:
                # A table that would need more new nodes (fcl distances) than the queries it
                # answers costs more than they do: it says nothing this time (not filled).
                b = table.bound(qs[rows], max_new=rows.size)
                out[rows, col] = np.maximum(b - self.margin, NO_BOUND)
        return out

    # -- geometry ---------------------------------------------------------------------
    def cell_mesh(self) -> trimesh.Trimesh | None:
        """Return the checked obstacles as one world mesh [m] (None for an empty cell)."""
        parts = []
        for name in self.obstacles:
            e = self.exact.scene.static[name]
            m = e.mesh.copy()
            m.apply_transform(e.T)
            parts.append(m)
        merged: trimesh.Trimesh | None = trimesh.util.concatenate(parts) if parts else None  # type: ignore[assignment]
        return merged

    def _capsules(self, checked: list[int]) -> None:
        seg, rad = [], []
        for m in self.meshes:
            v = np.asarray(m.vertices, float)
            c = v.mean(axis=0)
            _, _, vt = np.linalg.svd(v - c, full_matrices=False)
            u = vt[0]
            t = (v - c) @ u
            p0, p1 = c + t.min() * u, c + t.max() * u
            d = v - c - np.outer(t, u)
            seg.append((p0, p1))
            rad.append(float(np.linalg.norm(d, axis=1).max()) * (1 + 1e-9))
        self.cap_seg = np.array(seg)  # (B, 2, 3) in body frames
        self.cap_radius = np.array(rad)
        self.cap_lever = np.stack(
            [self.levers_of.levers(int(self.body_frame[i]), s) for i, s in enumerate(self.cap_seg)]
        )
        self.cap_checked = checked
        self._cap_pairs = [
            (self.body_names[b], name)
            for b in checked
            for name in self.obstacles
            if (self.body_names[b], name) in self.cell_pairs
        ] + list(self.self_pairs)
        boxes = []
        for name in self.obstacles:
            e = self.exact.scene.static[name]
            obb = e.mesh.bounding_box_oriented
            T = e.T @ np.asarray(obb.primitive.transform, float)
            boxes.append((T, np.asarray(obb.primitive.extents, float) / 2))
        self.boxes = boxes

    def body_poses(self, qs: ArrayLike) -> FloatArray:
        """Return world poses (N, B, 4, 4) of every body (links, tool) at qs (N, dof) [rad]."""
        q = np.atleast_2d(np.asarray(qs, float))
        if q.ndim != 2 or q.shape[1] != self.dof or not np.all(np.isfinite(q)):
            raise InputError(
                f"q: expected finite joints of shape (N, {self.dof}) [rad], got {q.shape}"
            )
        # The path certifier asks for the same configurations' poses several times in a row
        # (items, containment, bounding boxes): the last answer is kept, read-only.
        last = getattr(self, "_last_poses", None)
        if last is not None and last[0].shape == q.shape and np.array_equal(last[0], q):
            return last[1]
        T = (self.T_world_base @ self.exact.robot.link_transforms(q))[:, self.body_frame]
        T.flags.writeable = False
        self._last_poses = (q.copy(), T)
        return T

    def spheres(self, q: ArrayLike) -> tuple[FloatArray, FloatArray, list[str]]:
        """Return world sphere centres (S,3) [m], radii (S,) [m] and each sphere's body name."""
        if self.mode != "spheres":
            raise InputError(f"spheres: the {self.mode} mode has no spheres; use mode 'spheres'")
        c = self.sphere_centres(np.atleast_2d(np.asarray(q, float)))[0]
        return c, self.radii.copy(), [self.body_names[b] for b in self.sphere_body]

    def _relative(
        self,
        body_a: NDArray[np.int64],
        body_b: NDArray[np.int64],
        lev_a: FloatArray,
        lev_b: FloatArray,
    ) -> FloatArray:
        """Return levers (P, dof) of body pairs: joints up to the lower frame move both rigidly.

        The distance between two bodies does not change when only joints at or before the
        frame of the one nearer the base turn; the rest moves the farther body relative to it.
        """
        fa, fb = self.body_frame[body_a], self.body_frame[body_b]
        low = np.minimum(fa, fb)
        joint = np.arange(1, self.dof + 1)[None]
        far = np.where((fa >= fb)[:, None], lev_a, lev_b)
        near = np.where((fa >= fb)[:, None], lev_b, lev_a)
        same = (fa == fb)[:, None]
        out = np.where(joint > low[:, None], far, 0.0)
        return np.where(same, 0.0, out) + 0.0 * near

    def _pair_lever(
        self, pair: tuple[str, str], lever: FloatArray, idx: dict[str, int]
    ) -> FloatArray:
        """Return the levers (dof,) [m/rad] of an exact pair from per-body levers (B, dof).

        A body against a static obstacle moves with its own levers; two bodies by their
        relative levers (`_relative`).
        """
        ia = idx[pair[0]]
        if pair[1] not in idx:
            return lever[ia]
        ib = idx[pair[1]]
        return self._relative(np.array([ia]), np.array([ib]), lever[[ia]], lever[[ib]])[0]

    # -- clearance items --------------------------------------------------------------
    def items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return clearance lower bounds (N, I) [m] (margin subtracted) and levers (I, dof)."""
        if self.mode == "spheres":
            return self._sphere_items(qs)
        if self.mode == "capsules":
            return self._capsule_items(qs)
        return self._exact_items(qs)

    def sphere_centres(self, qs: ArrayLike) -> FloatArray:
        """Return world sphere centres (N, S, 3) [m] at qs (N, dof) [rad] (spheres mode)."""
        if not hasattr(self, "_padded"):
            self._padded = PaddedSpheres(
                self.centres, self.radii, self.sphere_body, len(self.body_names)
            )
        return self._padded.unpad(self._padded.place(self.body_poses(qs)))

    def _sphere_items(
        self, qs: FloatArray, *, far: float | None = None
    ) -> tuple[FloatArray, FloatArray]:
        """Sphere items; with `far` [m], self pairs whose bodies' bounding spheres are more than
        `far` apart get that (smaller, still valid) gap for all their sphere pairs."""
        c = self.sphere_centres(qs)
        n = len(c)
        cols, levers = [], []
        if self.sdf is not None and self.cell_spheres.size:
            cc = c[:, self.cell_spheres].reshape(-1, 3)
            d = self.sdf.query(cc).reshape(n, -1)
            cols.append(d - self.radii[self.cell_spheres] - self.sdf.max_error)
            levers.append(self.sphere_lever[self.cell_spheres])
        if self.pair_a.size:
            if far is None:
                gap = np.linalg.norm(c[:, self.pair_a] - c[:, self.pair_b], axis=2)
                cols.append(gap - self.radii[self.pair_a] - self.radii[self.pair_b])
            else:
                cols.append(self._far_pair_gaps(c, far))
            if not hasattr(self, "_pair_levers"):
                self._pair_levers = self._relative(
                    self.sphere_body[self.pair_a],
                    self.sphere_body[self.pair_b],
                    self.sphere_lever[self.pair_a],
                    self.sphere_lever[self.pair_b],
                )
            levers.append(self._pair_levers)
        if not cols:
            return np.full((n, 1), np.inf), np.zeros((1, self.dof))
        return np.concatenate(cols, axis=1) - self.margin, np.concatenate(levers)

    def _far_pair_gaps(self, c: FloatArray, far: float) -> FloatArray:
        """Return sphere-pair gaps (N, pairs) [m]: exact where the bodies are near, else a bound.

        Every sphere of a body lies in the body's bounding sphere (centre: the mean of its
        sphere centres, which a rigid motion carries along; radius: the farthest sphere's
        reach), so |cb_a - cb_b| - R_a - R_b bounds every sphere pair's gap from below.
        """
        if not hasattr(self, "_bound_r"):
            nb = len(self.body_names)
            self._own = [np.flatnonzero(self.sphere_body == b) for b in range(nb)]
            r = np.zeros(nb)
            for b, own in enumerate(self._own):
                if own.size:
                    mid = self.centres[own].mean(axis=0)
                    r[b] = float(
                        np.max(np.linalg.norm(self.centres[own] - mid, axis=1) + self.radii[own])
                    )
            self._bound_r = r
            blocks, start = [], 0
            for na, nb_ in self.self_pairs:
                ia, ib = self._body_index[na], self._body_index[nb_]
                size = len(self._own[ia]) * len(self._own[ib])
                blocks.append((start, start + size, ia, ib))
                start += size
            self._blocks = blocks
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

    def _capsule_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        from workbench.geometry.distance import capsule_rectangle_distance, segment_segment_distance

        T = self.body_poses(qs)
        p = np.einsum("nbij,bkj->nbki", T[..., :3, :3], self.cap_seg) + T[..., None, :3, 3]
        n = len(p)
        cols, levers = [], []
        idx = {nm: i for i, nm in enumerate(self.body_names)}
        for b in self.cap_checked:
            for (Tb, half), name in zip(self.boxes, self.obstacles, strict=True):
                if (self.body_names[b], name) not in self.cell_pairs:
                    continue
                local = (p[:, b] - Tb[:3, 3]) @ Tb[:3, :3]  # (N, 2, 3) in the box frame
                inside = np.any(np.all(np.abs(local) <= half, axis=2), axis=1)
                best = np.full(n, np.inf)
                for k in range(3):
                    u, w = [i for i in range(3) if i != k]
                    axes = np.eye(3)[[u, w]]
                    for sgn in (-1.0, 1.0):
                        centre = np.zeros(3)
                        centre[k] = sgn * half[k]
                        d = capsule_rectangle_distance(
                            local[:, 0], local[:, 1], self.cap_radius[b], centre, axes, half[[u, w]]
                        )
                        best = np.minimum(best, d)
                cols.append(np.where(inside, -self.cap_radius[b], best))
                levers.append(self.cap_lever[b])
        for sa, sb in self.self_pairs:
            ia, ib = idx[sa], idx[sb]
            d = segment_segment_distance(p[:, ia, 0], p[:, ia, 1], p[:, ib, 0], p[:, ib, 1])
            cols.append(d - self.cap_radius[ia] - self.cap_radius[ib])
            levers.append(self._pair_lever((sa, sb), self.cap_lever, idx))
        if not cols:
            return np.full((n, 1), np.inf), np.zeros((1, self.dof))
        return np.stack(cols, axis=1) - self.margin, np.stack(levers)

    def _exact_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        scene = self.exact.scene
        idx = {nm: i for i, nm in enumerate(self.body_names)}
        out = np.zeros((len(qs), len(scene.pairs)))
        req, dreq = fcl.CollisionRequest(), fcl.DistanceRequest()
        for k, q in enumerate(qs):
            rep = self.exact.check(q, distance=False)
            hit = set(rep.colliding)
            for m, (a, b) in enumerate(scene.pairs):
                if (a, b) in hit:
                    out[k, m] = 0.0
                    continue
                ea, eb = scene._entry(a), scene._entry(b)
                if fcl.collide(ea.obj, eb.obj, req, fcl.CollisionResult()):
                    out[k, m] = 0.0
                else:
                    out[k, m] = max(fcl.distance(ea.obj, eb.obj, dreq, fcl.DistanceResult()), 0.0)
        levers = np.stack([self._pair_lever(p, self.body_lever, idx) for p in scene.pairs])
        return out - self.margin, levers

    def exact_twin(self) -> CollisionEngine:
        """Return an exact-mode engine on the same checker (built once)."""
        twin = getattr(self, "_twin", None)
        if twin is None:
            twin = (
                self
                if self.mode == "exact"
                else CollisionEngine(self.exact, "exact", margin=self.margin)
            )
            self._twin = twin
        return twin

    # -- checks -----------------------------------------------------------------------
    def check(self, q: ArrayLike) -> ConfigCheck:
        """Return the check of one configuration q (dof,) [rad]; flagged ones confirmed exactly."""
        qq = np.asarray(q, float).reshape(1, -1)
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

    def penetration(self, q: FloatArray, a: str, b: str) -> float:
        """Return the depth [m] of the deepest vertex of body a inside b or of b inside a."""
        scene = self.exact.scene
        self.exact.check(q, distance=False)  # places the moving bodies at q
        ea, eb = scene._entry(a), scene._entry(b)
        depth = 0.0
        for inner, outer in ((ea, eb), (eb, ea)):
            v = np.asarray(inner.mesh.vertices, float) @ inner.T[:3, :3].T + inner.T[:3, 3]
            local = (v - outer.T[:3, 3]) @ outer.T[:3, :3]
            bvh = LBVH(outer.mesh.vertices, outer.mesh.faces)
            inside = bvh.ray_crossings(local, np.array([0.5773, 0.5774, 0.5775])) % 2 == 1
            if np.any(inside):
                depth = max(depth, float(bvh.closest_points(local[inside])[1].max()))
        return depth

    def contained(self, qs: FloatArray) -> NDArray[np.bool_]:
        """Return (N, len(always_pairs)): whether one body of the pair holds the other's probe.

        The containment half of the exact checker's test, batched over configurations: the
        inner body's probe vertex tested against the outer body (half-spaces when convex,
        trimesh's ray test otherwise).
        """
        out = np.zeros((len(qs), len(self.always_pairs)), bool)
        if not self._inside_tests:
            return out
        scene = self.exact.scene
        T = self.body_poses(qs)
        idx = {nm: i for i, nm in enumerate(self.body_names)}

        def pose(name: str) -> FloatArray:
            if name in idx:
                return T[:, idx[name]]
            return np.broadcast_to(scene.static[name].T, (len(qs), 4, 4))

        for k, inner, outer in self._inside_tests:
            Ti, To = pose(inner), pose(outer)
            p = np.einsum("nij,j->ni", Ti[:, :3, :3], scene._entry(inner).probe) + Ti[:, :3, 3]
            local = np.einsum("nji,nj->ni", To[:, :3, :3], p - To[:, :3, 3])
            planes = self._convex[outer]
            if planes is not None:
                inside = np.all(local @ planes[0].T <= planes[1], axis=1)
            else:
                inside = np.asarray(scene._entry(outer).mesh.contains(local), bool)
            out[:, k] |= inside
        return out

    # -- the path certifier's oracle ----------------------------------------------------
    def path_items(self, qs: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return `items` for the path certifier; the exact mode leaves every pair to fcl."""
        if self.mode == "exact":
            lev = np.stack([self.pair_lever[p] for p in self.exact.scene.pairs])
            return np.full((len(qs), len(lev)), -1.0), lev  # flagged: every pair to fcl
        if self.mode == "spheres":
            # Far self pairs by their bodies' bounding spheres: the certifier needs a valid
            # bound, and one above FAR_PAIR seldom limits an interval.
            return self._sphere_items(qs, far=FAR_PAIR)
        return self.items(qs)

    def poses(self, qs: FloatArray) -> FloatArray:
        """Return world poses (N, B, 4, 4) of the moving bodies, for `place`."""
        return self.body_poses(qs)

    def place(self, poses: FloatArray) -> None:
        """Set the world poses (B, 4, 4) of the moving bodies; each is placed when first used."""
        self._pending = poses
        self._placed = set()

    def _ready(self, pair: tuple[str, str]) -> None:
        moving = self.exact.scene.moving
        for name in pair:
            if name in moving and name not in self._placed:
                moving[name].place(self._pending[self._body_index[name]])
                self._placed.add(name)

    def aabb_gaps(self, poses: FloatArray) -> FloatArray:
        """Return (N, P): gaps [m] between the world bounding boxes of every exact pair, less the margin.

        poses (N, B, 4, 4) of the moving bodies; pairs in `exact.scene.pairs` order. A gap is
        a lower bound of the pair's distance (0 where the boxes overlap).
        """
        scene = self.exact.scene
        if not hasattr(self, "_corners"):
            self._corners = np.stack([scene.moving[n].local_corners for n in self.body_names])
            self._pair_rows = [
                (self._body_index.get(a, -1), self._body_index.get(b, -1), a, b)
                for a, b in scene.pairs
            ]
        w = (
            np.einsum("nbij,bkj->nbki", poses[..., :3, :3], self._corners)
            + poses[:, :, None, :3, 3]
        )
        lo, hi = w.min(axis=2), w.max(axis=2)  # (N, B, 3)
        out = np.empty((len(poses), len(self._pair_rows)))
        for k, (ia, ib, _a, b) in enumerate(self._pair_rows):
            alo, ahi = lo[:, ia], hi[:, ia]
            if ib >= 0:
                blo, bhi = lo[:, ib], hi[:, ib]
            else:
                blo, bhi = scene.static[b].aabb
            gap = np.maximum(np.maximum(alo - bhi, blo - ahi), 0.0)
            out[:, k] = np.sqrt(np.einsum("ni,ni->n", gap, gap))
        return out - self.margin

    def pair_collides(self, pair: tuple[str, str]) -> bool:
        """Return the exact verdict (fcl collide, then containment) of a pair as placed."""
        self._ready(pair)
        return self.exact.scene.collides(*pair)

    def pair_distance(self, pair: tuple[str, str]) -> float:
        """Return the pair's surface distance [m] as placed, less the margin."""
        self._ready(pair)
        return self.exact.scene.distance(*pair) - self.margin

    def check_path(
        self,
        qs: ArrayLike,
        times: ArrayLike | None = None,
        *,
        deviation: ArrayLike | None = None,
        sampler: Callable[[FloatArray], FloatArray] | None = None,
        acceleration: ArrayLike | AccelerationBound | None = None,
        max_depth: int = 12,
        budget: int = 5000,
        progress: Progress | None = None,
    ) -> EnginePathReport:
        """Return the report of the path through samples qs (N, dof) [rad], between samples too.

        times (N,) [s] (default 0, 1, 2, ...). Between samples the motion is either the
        straight joint segment, or within deviation (dof,) [rad] of it, or (with `sampler`,
        times -> (M, dof) [rad], the real motion) within ``acceleration * h**2 / 8`` of it,
        acceleration (dof,) [rad/s^2] bounding |q''| (or a function (t0, t1) -> (M, dof)
        bounding it on each interval [t0, t1]). Intervals that cannot be certified are
        bisected up to `max_depth` times (at most `budget` configurations in all). All
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
            budget=budget,
            progress=progress,
        )
        self.save_tables()
        hits = sorted(out.sample_hits)
        between = sorted({e[1] for e in out.events})
        base: dict[str, Any] = {
            "collision_free": not hits and not out.events,
            "first_index": None,
            "first_report": None,
            "min_distance": 0.0,
            "samples": n,
            "colliding_indices": tuple(hits),
            "mode": self.mode,
            "clearance": 0.0,
            "evaluated": out.evaluated,
            "between_indices": tuple(between),
            "flagged_samples": out.flagged,
            "exact_pairs": out.exact_pairs,
        }
        if base["collision_free"]:
            clr = max(out.clearance, 0.0) if np.isfinite(out.clearance) else float("inf")
            base.update(min_distance=clr, clearance=clr)
            return EnginePathReport(**base)
        # The first event: a colliding sample or an interval (collision or not certified).
        cands: list[tuple[float, int | None, FloatArray, tuple[tuple[str, str], ...]]]
        cands = [(float(t[i]), i, q[i], out.sample_hits[i]) for i in hits[:1]]
        cands += [(e[0], None, e[2], e[3]) for e in out.events[:1]]
        first = min(cands, key=lambda c: c[0])
        tm, i0, qm, pairs = first
        extra: dict[str, object] = {
            "first_index": i0 if i0 is not None else int(np.searchsorted(t, tm) - 1),
            "first_time": tm,
            "first_q": qm,
            "between": i0 is None,
        }
        if pairs:
            a, b = pairs[0]
            extra.update(
                first_report=CollisionReport(pairs, 0.0, pairs[0], len(self.exact.scene.pairs)),
                link=a,
                obstacle=b,
                penetration=self.penetration(qm, a, b),
            )
        else:
            extra["certified"] = False
        base.update(extra)
        return EnginePathReport(**base)
