"""A robot checker's moving bodies (links, tool) as the fast modes see them: frames, pairs, levers.

Every mode checks the same bodies against the same obstacles and self pairs as the exact
checker (`RobotCollisionChecker`), places them by one batched forward kinematics, and bounds
their motion by `JointLevers`: along a joint step dq a point of body b moves at most
``|dq| @ lever[b]``. A body pair's distance changes only with the joints after the nearer
body's frame (`relative_levers`).
"""

from __future__ import annotations

import math

import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.collision.motion_bound import JointLevers
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.errors import InputError

FloatArray = NDArray[np.float64]
Pair = tuple[str, str]


class RobotBodies:
    """The moving bodies of `exact` (links 0..n, then the tool) and the pairs checked on them.

    Attributes: `names` (B,), `frame` (B,) the link frame each body rides on, `index`
    (name -> body), `meshes`, `self_pairs` / `cell_pairs` (the exact checker's pairs, split),
    `obstacles` (static names), `lever` (B, dof) [m/rad] per body, `checked` (bodies with a
    cell pair), `pair_lever` (exact pair -> (dof,) [m/rad], in `scene.pairs` order).
    """

    def __init__(self, exact: RobotCollisionChecker) -> None:
        self.exact = exact
        self.scene = exact.scene
        self.robot = exact.robot
        self.dof: int = self.robot.dof
        self.T_world_base = exact.T_world_base
        self.names = list(exact.link_names) + (["tool"] if exact.has_tool else [])
        self.frame = np.array(list(range(self.dof + 1)) + ([self.dof] if exact.has_tool else []))
        self.index = {n: i for i, n in enumerate(self.names)}
        self.meshes: list[trimesh.Trimesh] = [self.scene.moving[n].mesh for n in self.names]
        moving = set(self.names)
        pairs = self.scene.pairs
        self.self_pairs: list[Pair] = [(a, b) for a, b in pairs if a in moving and b in moving]
        self.cell_pairs: list[Pair] = [(a, b) for a, b in pairs if b not in moving]
        self.obstacles = list(self.scene.static)
        self.levers_of = JointLevers(self.robot)
        self.checked = sorted({self.index[a] for a, _ in self.cell_pairs})
        self.lever = np.stack(
            [
                self.levers_of.levers(int(self.frame[i]), m.vertices)
                for i, m in enumerate(self.meshes)
            ]
        )
        self.pair_lever = {p: self.lever_of_pair(p, self.lever) for p in pairs}
        self._last: tuple[FloatArray, FloatArray] | None = None

    def poses(self, qs: ArrayLike) -> FloatArray:
        """Return world poses (N, B, 4, 4) of every body at qs (N, dof) [rad] (read-only)."""
        q = np.atleast_2d(np.asarray(qs, float))
        if q.ndim != 2 or q.shape[1] != self.dof or not np.all(np.isfinite(q)):
            raise InputError(
                f"q: expected finite joints of shape (N, {self.dof}) [rad], got {q.shape}"
            )
        # The path certifier asks for the same configurations' poses several times in a row
        # (items, containment, bounding boxes): the last answer is kept, read-only.
        last = self._last
        if last is not None and last[0].shape == q.shape and np.array_equal(last[0], q):
            return last[1]
        T = (self.T_world_base @ self.robot.link_transforms(q))[:, self.frame]
        T.flags.writeable = False
        self._last = (q.copy(), T)
        return T

    def poses_one(self, q: FloatArray) -> FloatArray:
        """Return world poses (B, 4, 4) at one configuration q (dof,) float64 [rad] (not kept).

        The scalar DH chain (`link_transforms` of one row), no batch bookkeeping; a q of
        the wrong shape or not finite raises as `poses` does.
        """
        if q.shape != (self.dof,) or not math.isfinite(sum(q.tolist())):
            return self.poses(q[None])[0]  # raises InputError
        return np.matmul(self.T_world_base, self.robot.link_transforms(q)).take(self.frame, axis=0)

    def relative_levers(
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
        fa, fb = self.frame[body_a], self.frame[body_b]
        low = np.minimum(fa, fb)
        joint = np.arange(1, self.dof + 1)[None]
        far = np.where((fa >= fb)[:, None], lev_a, lev_b)
        near = np.where((fa >= fb)[:, None], lev_b, lev_a)
        same = (fa == fb)[:, None]
        out = np.where(joint > low[:, None], far, 0.0)
        return np.where(same, 0.0, out) + 0.0 * near  # type: ignore[no-any-return]

    def lever_of_pair(self, pair: Pair, lever: FloatArray) -> FloatArray:
        """Return the levers (dof,) [m/rad] of an exact pair from per-body levers (B, dof).

        A body against a static obstacle moves with its own levers; two bodies by their
        relative levers.
        """
        ia = self.index[pair[0]]
        if pair[1] not in self.index:
            return lever[ia]  # type: ignore[no-any-return]
        ib = self.index[pair[1]]
        return self.relative_levers(np.array([ia]), np.array([ib]), lever[[ia]], lever[[ib]])[0]

    def cell_mesh(self) -> trimesh.Trimesh | None:
        """Return the checked obstacles as one world mesh [m] (None for an empty cell)."""
        parts = []
        for name in self.obstacles:
            e = self.scene.static[name]
            m = e.mesh.copy()
            m.apply_transform(e.T)
            parts.append(m)
        merged: trimesh.Trimesh | None = trimesh.util.concatenate(parts) if parts else None  # type: ignore[assignment]
        return merged
