"""Conservative distance tables of body pairs that depend on one or two joints.

The distance between two links of a serial chain depends only on the joints between their
frames (a self pair of frames a < b: joints a+1..b), and a link's distance to the fixed cell
only on the joints up to its frame. For pairs with one or two such joints (the wrist pairs
link4–link6, link5–tool, link4–tool, link2–link4; link1 or link2 against the cell) the exact
distance is a function on a rectangle of at most two joint values. A `PairTable` stores fcl's
distance at the nodes of a grid over that rectangle (filled lazily, when a query first needs
a node) and turns it into a lower bound anywhere by the pair's levers (`JointLevers`): along
a joint step dq the distance changes by at most ``|dq| @ lever``, so with g a grid node

    d(q) >= d(g) - sum_j lever_j * |q_j - g_j|,

and the bound at q uses the nearest node g. The grid step of joint j is at most
``tol / (k * lever_j)`` (k: the pair's joint count), so |q_j - g_j| <= step_j / 2 and, since
d(g) >= d(q) - lever @ |q - g| too, the bound is at most ``2 * lever @ |q - g| <= tol`` below
the exact distance. Outside the joint limits the nearest node on the border is used (still
valid, looser).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from workbench.collision.bodies import Pair, RobotBodies
from workbench.collision.path_check import NO_BOUND
from workbench.errors import InputError
from workbench.geometry.npz_cache import cache_path, load_entry, store_entry

FloatArray = NDArray[np.float64]
# Grid step of the engine's pair tables: their bound is at most TABLE_TOL [m] below fcl's distance.
TABLE_TOL = 0.006
# Most nodes along one joint: a step below range / MAX_NODES would make a huge, sparse table.
MAX_NODES = 4096
# Stored in every cache entry; bump when the entry changes (2: npz_cache, format field), so
# entries of older versions are ignored rather than misread.
_FORMAT = 2


class PairTable:
    """Lazily filled grid of a pair's exact distance [m] over its joints, read as a lower bound.

    joints (k,) indices into q (k = 1 or 2); lower/upper (k,) [rad] the grid's range (the
    joint limits); lever (k,) [m/rad] the pair's lever per joint; tol [m]: the grid step
    makes the bound at most tol below the exact distance within the range.
    distance(q_nodes (M, dof)) -> (M,) [m] gives the exact distance (0 when touching) at node
    configurations (joints outside `joints` are 0 there; the distance does not depend on them).
    """

    def __init__(
        self,
        joints: NDArray[np.int64],
        lower: FloatArray,
        upper: FloatArray,
        lever: FloatArray,
        dof: int,
        distance: Callable[[FloatArray], FloatArray],
        *,
        tol: float = 0.006,
    ) -> None:
        self.joints = np.asarray(joints, np.int64).reshape(-1)
        k = len(self.joints)
        if k not in (1, 2):
            raise InputError(f"joints: a pair table covers 1 or 2 joints, got {k}")
        if not tol > 0:
            raise InputError(f"tol: {tol} m must be > 0")
        self.lower = np.asarray(lower, float).reshape(k)
        upper = np.asarray(upper, float).reshape(k)
        self.lever = np.asarray(lever, float).reshape(k)
        if np.any(upper <= self.lower) or np.any(self.lever <= 0):
            raise InputError("lower/upper/lever: need lower < upper and levers > 0 per joint")
        span = upper - self.lower
        step = tol / (k * self.lever)
        self.count = np.minimum(np.ceil(span / step).astype(np.int64), MAX_NODES - 1) + 1
        self.step = span / (self.count - 1)
        self.dof = int(dof)
        self._distance = distance
        self.values = np.full(tuple(self.count), np.nan)
        self.filled = 0  # nodes computed with fcl so far
        self.path: Path | None = None
        self._saved = 0
        self._scalar: list[tuple[int, float, float, int, float]] | None = None

    def attach(self, path: Path) -> None:
        """Keep the table's nodes in the file `path` (.npz): load what is there, `save` later.

        The caller names the file by a digest of everything the distances depend on (meshes,
        kinematics, grid); a file of another grid shape is ignored.
        """
        self.path = path
        d = load_entry(path, required=("values", "format"))
        fmt = None if d is None else d["format"]
        if d is None or fmt is None or fmt.shape != () or fmt.dtype.kind not in "iu":
            return  # none or unreadable: computed again and overwritten
        if int(fmt) != _FORMAT:
            return  # another version: computed again and overwritten
        values = np.asarray(d["values"], float)
        if values.shape == self.values.shape:
            self.values = np.where(np.isnan(self.values), values, self.values)
            self._saved = self.filled

    def save(self) -> None:
        """Write the nodes to the attached file when new ones were computed (atomic).

        `store_entry` writes a temporary file of a unique name and renames it over the
        entry: processes filling the same table never rename each other's half-written file.
        """
        if self.path is None or self.filled == self._saved:
            return
        store_entry(self.path, {"values": self.values, "format": np.asarray(_FORMAT, np.int64)})
        self._saved = self.filled

    def bound_one(self, q: list[float]) -> float:
        """Return `bound` at one configuration q (dof floats) [rad], in scalar math (~2 us).

        The same nearest node and lever bound as `bound`; a node not computed yet is computed
        (one fcl distance) and kept, as there.
        """
        if self._scalar is None:
            self._scalar = list(
                zip(
                    self.joints.tolist(),
                    self.lower.tolist(),
                    self.step.tolist(),
                    self.count.tolist(),
                    self.lever.tolist(),
                    strict=True,
                )
            )
        flat, slack = 0, 0.0
        for j, lo, st, n, lev in self._scalar:
            x = q[j]
            i = min(max(round((x - lo) / st), 0), n - 1)  # round half to even, like np.rint
            flat = flat * n + i
            slack += abs(x - (lo + i * st)) * lev
        v = self.values.item(flat)  # a Python float, no array scalar
        if v != v:  # NaN: not computed yet
            return float(self.bound(np.asarray([q], float))[0])
        return v - slack

    def _nodes_q(self, idx: NDArray[np.int64]) -> FloatArray:
        q = np.zeros((len(idx), self.dof))
        q[:, self.joints] = self.lower + idx * self.step
        return q

    def bound(self, qs: FloatArray, *, max_new: int | None = None) -> FloatArray:
        """Return lower bounds (N,) [m] of the pair's distance at qs (N, dof) [rad].

        max_new: when the queries need more new nodes than this, none are computed and every
        bound is -inf (no information): the caller's own exact distances are then cheaper.
        """
        qj = np.asarray(qs, float)[:, self.joints]  # (N, k)
        # The nearest node only: one node per query (the corners of the cell would give a
        # slightly tighter bound for up to 2^k nodes each, where paths seldom share them).
        node = np.clip(np.rint((qj - self.lower) / self.step), 0, self.count - 1).astype(np.int64)
        flat = np.ravel_multi_index(tuple(node.T), tuple(self.count))
        vals = self.values.reshape(-1)
        need = np.unique(flat[np.isnan(vals[flat])])
        if max_new is not None and need.size > max_new:
            return np.full(len(qj), -np.inf)
        if need.size:
            idx = np.stack(np.unravel_index(need, tuple(self.count)), axis=1)
            vals[need] = np.asarray(self._distance(self._nodes_q(idx)), float)
            self.filled += int(need.size)
        g = self.lower + node * self.step  # (N, k) node joint values
        return vals[flat] - np.abs(qj - g) @ self.lever


def pair_joints(frame_a: int, frame_b: int | None) -> NDArray[np.int64]:
    """Return the joint indices (0-based) a pair's distance depends on.

    frame_b None: body of frame_a against the fixed cell (joints 1..frame_a); else a self
    pair (joints min+1..max).
    """
    if frame_b is None:
        return np.arange(0, frame_a, dtype=np.int64)
    lo, hi = sorted((frame_a, frame_b))
    return np.arange(lo, hi, dtype=np.int64)


class PairTables:
    """A `PairTable` for every exact pair of `bodies` whose distance depends on one or two joints.

    Tables fill lazily and are kept, so later paths reuse the nodes computed so far; with
    `cache_dir` also on disk (``table-<sha256>.npz``: digest of both meshes, the bodies' poses
    at probe configurations (kinematics, base, tool) and the grid), written by `save`.
    distance(pair, qs (M, dof)) -> (M,) [m] gives the exact distance at node configurations.
    """

    def __init__(
        self,
        bodies: RobotBodies,
        distance: Callable[[Pair, FloatArray], FloatArray],
        *,
        margin: float,
        cache_dir: str | None,
        enabled: bool = True,
    ) -> None:
        self.bodies, self.margin = bodies, margin
        self.tables: dict[Pair, PairTable] = {}
        limits = np.asarray(bodies.robot.limits, float)
        for a, b in bodies.scene.pairs if enabled else []:
            fa = int(bodies.frame[bodies.index[a]])
            fb = int(bodies.frame[bodies.index[b]]) if b in bodies.index else None
            joints = pair_joints(fa, fb)
            lever = bodies.pair_lever[(a, b)][joints]
            if not 1 <= len(joints) <= 2 or not np.all(lever > 0):
                continue
            table = PairTable(
                joints,
                limits[joints, 0],
                limits[joints, 1],
                lever,
                bodies.dof,
                functools.partial(distance, (a, b)),
                tol=TABLE_TOL,
            )
            if cache_dir is not None:
                table.attach(self._path(cache_dir, (a, b), table))
            self.tables[(a, b)] = table
        pairs = list(bodies.pair_lever)
        self._cols = [(pairs.index(p), t) for p, t in self.tables.items()]

    def _path(self, cache_dir: str | Path, pair: Pair, table: PairTable) -> Path:
        """Return the cache entry of a pair table, keyed by everything its values depend on."""
        b = self.bodies
        probes = np.random.default_rng(0).uniform(-1.0, 1.0, (3, b.dof))
        T = b.poses(probes)
        inputs: list[NDArray] = []
        kinds = []
        for name in pair:
            e = b.scene.entry(name)
            pose = T[:, b.index[name]] if name in b.index else e.T
            inputs += [np.asarray(e.mesh.vertices, float), np.asarray(e.mesh.faces, np.int64)]
            inputs.append(np.asarray(pose, float))
            kinds.append(str(e.solid.kind))
        inputs += [table.joints, table.lower, table.step, table.count]
        return cache_path(cache_dir, "table", inputs, {"kinds": kinds, "format": 2})

    def save(self) -> None:
        """Write the tables that gained nodes to their cache files (if any)."""
        for table in self.tables.values():
            table.save()

    def bounds(self, qs: FloatArray, mask: NDArray[np.bool_]) -> FloatArray:
        """Return (N, P): lower bounds [m] of the exact pairs' distances, less the margin.

        qs (N, dof) [rad]; mask (N, P) says which entries are wanted (pairs in `pair_lever`
        order). Wanted entries of pairs without a table get NO_BOUND (no information);
        entries not wanted are NaN. Only wanted entries fill table nodes.
        """
        out = np.full(mask.shape, np.nan)
        out[mask] = NO_BOUND
        for col, table in self._cols:
            rows = np.flatnonzero(mask[:, col])
            if rows.size:
                # A table that would need more new nodes (fcl distances) than the queries it
                # answers costs more than they do: it says nothing this time (not filled).
                b = table.bound(qs[rows], max_new=rows.size)
                out[rows, col] = np.maximum(b - self.margin, NO_BOUND)
        return out
