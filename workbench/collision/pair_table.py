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

from collections.abc import Callable
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.npz_cache import load_entry, store_entry

FloatArray = NDArray[np.float64]
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
