"""Robot-versus-cell and robot self-collision checks for joint configurations."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.collision.fcl_checker import CollisionScene, ContactReport
from workbench.collision.shapes import Solid
from workbench.kinematics.model import RobotModel


@dataclass(frozen=True)
class PathReport:
    """Result of checking a sampled joint path: the first colliding sample, if any."""

    collision_free: bool
    first_index: int | None
    first_report: ContactReport | None
    min_distance: float
    samples: int
    colliding_indices: tuple[int, ...]


class RobotCollisionChecker:
    """Checks a serial robot (links 0..n, an optional tool on the flange) against a static cell.

    Self-collision pairs are all non-adjacent link pairs, less those already in contact at
    the reference (home) configuration, as MoveIt's setup assistant disables "default"
    collisions; the disabled pairs are listed in `disabled_pairs`.
    """

    def __init__(
        self,
        robot: RobotModel,
        link_meshes: list[trimesh.Trimesh],
        *,
        T_world_base: NDArray[np.float64] | None = None,
        tool: trimesh.Trimesh | None = None,
        cell: list[tuple[Solid, NDArray[np.float64]]] = (),  # type: ignore[assignment]
        q_reference: NDArray[np.float64] | None = None,
        link_names: list[str] | None = None,
        ignore: list[tuple[str, str]] = (),  # type: ignore[assignment]
    ) -> None:
        self.robot = robot
        n = robot.dof
        if len(link_meshes) != n + 1:
            raise ValueError(
                f"expected {n + 1} link meshes (base + {n} links), got {len(link_meshes)}"
            )
        self.link_names = link_names or ["base"] + [f"link{i}" for i in range(1, n + 1)]
        self.T_world_base = np.eye(4) if T_world_base is None else np.asarray(T_world_base, float)
        moving = [
            Solid(nm, "mesh", mesh=m) for nm, m in zip(self.link_names, link_meshes, strict=True)
        ]
        self.has_tool = tool is not None
        if tool is not None:
            moving.append(Solid("tool", "mesh", mesh=tool))
        names = [s.name for s in moving]
        # Adjacent bodies share a joint; the tool sits on the last link.
        chain = names[: n + 1] + (["tool"] if self.has_tool else [])
        adjacent = {frozenset((chain[i], chain[i + 1])) for i in range(len(chain) - 1)}
        candidates = [
            (a, b)
            for i, a in enumerate(names)
            for b in names[i + 1 :]
            if frozenset((a, b)) not in adjacent
        ]
        # The base never moves: it is bolted to whatever it stands on.
        # `ignore`: further (moving, static) pairs never checked (a tool in contact by design).
        ignore = [(names[0], s.name) for s, _ in cell] + list(ignore)
        probe = CollisionScene(moving, [], self_pairs=candidates)
        q0 = np.zeros(n) if q_reference is None else np.asarray(q_reference, float)
        home = probe.check(self._poses(q0), distance=False)
        touching = {frozenset(p) for p in home.colliding}
        self.disabled_pairs = tuple(p for p in candidates if frozenset(p) in touching) + tuple(
            tuple(sorted(p)) for p in adjacent
        )
        self_pairs = [p for p in candidates if frozenset(p) not in touching]
        self.scene = CollisionScene(moving, list(cell), self_pairs=self_pairs, ignore=ignore)
        # Fast engines built on this checker, per policy key (`plan_check.engine`), or the
        # error their build raised; they go with the checker (a new project, a new checker).
        self.engines: dict[tuple[str, int, int, str], object] = {}

    def _poses(self, q: NDArray[np.float64]) -> dict[str, NDArray[np.float64]]:
        Ts = self.T_world_base @ self.robot.link_transforms(np.asarray(q, float))
        poses = {name: Ts[i] for i, name in enumerate(self.link_names)}
        if self.has_tool:
            poses["tool"] = Ts[-1]
        return poses

    def world_poses(self, q: NDArray[np.float64]) -> dict[str, NDArray[np.float64]]:
        """Return the world pose of every moving body (links, tool) at `q`."""
        return self._poses(q)

    def check(self, q: NDArray[np.float64], *, distance: bool = True) -> ContactReport:
        """Return the collision report of configuration `q` [rad]."""
        return self.scene.check(self._poses(q), distance=distance)

    def check_path(
        self,
        qs: NDArray[np.float64],
        *,
        distance: bool = False,
        progress: Callable[[float, str], None] | None = None,
    ) -> PathReport:
        """Return the report of a sampled path (N, dof): every sample is checked exactly.

        `min_distance` is the clearance over the samples when `distance` is set (0 where one
        collides, inf when distances were not asked for). `progress(fraction, message)` is
        called every 50 samples.
        """
        qs = np.atleast_2d(np.asarray(qs, float))
        hits: list[int] = []
        first: ContactReport | None = None
        dmin = np.inf
        for i, q in enumerate(qs):
            if progress is not None and i % 50 == 0:
                progress(i / len(qs), f"collision check {i}/{len(qs)}")
            rep = self.check(q, distance=distance)
            dmin = min(dmin, rep.min_distance)
            if rep.in_collision:
                hits.append(i)
                first = first or rep
        return PathReport(
            collision_free=not hits,
            first_index=hits[0] if hits else None,
            first_report=first,
            min_distance=float(dmin),
            samples=len(qs),
            colliding_indices=tuple(hits),
        )
