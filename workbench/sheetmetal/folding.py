"""Folded state of a sheet-metal part: flange poses after a prefix of the bend sequence.

A bend partway folded to angle θ' keeps its neutral length BA = θ·(r + K·t), so its
current inner radius is r' = BA/θ' − K·t (air bending: the radius shrinks as it folds).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any

import fcl
import numpy as np
from numpy.typing import NDArray

from workbench.collision.shapes import bvh_model, fcl_transform
from workbench.errors import InputError
from workbench.geometry.obb import OBB
from workbench.geometry.polygon import min_area_rect
from workbench.sheetmetal.kfactor import flange_rise

if TYPE_CHECKING:
    import trimesh

    from workbench.sheetmetal.obbtree import OBBTree
    from workbench.sheetmetal.part import SheetMetalPart


def axis_angle(axis: NDArray[np.float64], angle: float) -> NDArray[np.float64]:
    """Return the (3, 3) rotation about unit `axis` by `angle` [rad] (Rodrigues)."""
    k = axis / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * (K @ K)


def edge_frame(poly: NDArray[np.float64], e: int) -> tuple[NDArray[np.float64], ...]:
    """Return (start, unit direction, outward unit normal) (2,) of edge `e` of a CCW polygon."""
    a, b = poly[e], poly[(e + 1) % len(poly)]
    d = (b - a) / np.linalg.norm(b - a)
    return a, d, np.array([d[1], -d[0]])


def bend_profile(theta: float, radius: float, t: float, ba: float) -> tuple[int, float, float]:
    """Return (segments N, thinning σ [m], largest outer radius [m]) of a bend's cross-section.

    Outer radius ρ_i = r + t − σ·sin(π i/N); σ makes the N-gon cross-section's area equal
    t·BA exactly, so bending keeps the volume (the sheet thins where K < 0.5).
    """
    if theta <= 0:
        return 1, 0.0, radius + t
    n = max(2, int(np.ceil(theta / (np.pi / 24))))
    b = np.sin(np.pi * np.arange(n + 1) / n)
    a = radius + t
    s0 = n * (a * a - radius * radius)
    s1 = a * float(np.sum(b[:-1] + b[1:]))
    s2 = float(np.sum(b[:-1] * b[1:]))
    c = s0 - 2.0 * t * ba / np.sin(theta / n)
    sigma = (s1 - np.sqrt(max(s1 * s1 - 4 * s2 * c, 0.0))) / (2 * s2)
    return n, float(sigma), a - min(sigma, 0.0)


@dataclass(frozen=True, eq=False)
class FoldedState:
    """Flange poses `T_part_flange` (F, 4, 4) with current bend `angles` [rad] and `radii` [m]."""

    part: SheetMetalPart
    step: float
    angles: NDArray[np.float64]
    radii: NDArray[np.float64]
    T_part_flange: NDArray[np.float64]
    _trees: dict[int, Any] = field(default_factory=dict, repr=False)

    def bend_cross_section(self, i: int) -> dict[str, Any]:
        """Return bend `i`'s geometry in its parent's frame: edge ends, axes, centre [m]."""
        b = self.part.bends[i]
        t = self.part.thickness
        a2, d2, n2 = edge_frame(self.part.flanges[b.parent].polygon, b.parent_edge)
        pa = np.array([a2[0], a2[1], 0.0])
        d, n = np.array([d2[0], d2[1], 0.0]), np.array([n2[0], n2[1], 0.0])
        w = np.array([0.0, 0.0, float(b.direction)])
        L = self.part.bend_lengths[i]
        r = self.radii[i] if np.isfinite(self.radii[i]) else 0.0  # flat bends have no centre
        return dict(pa=pa, pb=pa + L * d, d=d, n=n, w=w, center=pa + (r + t / 2) * w)

    def flange_obbs(self) -> OBB:
        """Return one OBB per flange (batch (F,)) in the part frame [m] covering flange + half bends."""
        return self._flange_obbs_and_origins[0]

    def flange_records(self) -> NDArray[np.float64]:
        """Return (F, 18) seed records: origin on the flange's mid-surface, axes, six offsets [m]."""
        obbs, origins = self._flange_obbs_and_origins
        return obbs.record(origins)

    @cached_property
    def _flange_obbs_and_origins(self) -> tuple[OBB, NDArray[np.float64]]:
        part, t = self.part, self.part.thickness
        nf = len(part.flanges)
        centers, rots, halves, origins = [], [], [], []
        for f in range(nf):
            poly = part.flanges[f].polygon
            pts = [poly]
            up, down = t / 2, t / 2
            for i, b in enumerate(part.bends):
                if f not in (b.parent, b.child):
                    continue
                edge = b.parent_edge if f == b.parent else b.child_edge
                a2, d2, n2 = edge_frame(poly, edge)
                th, r = self.angles[i], self.radii[i]
                _, _, rho_max = bend_profile(th, r, t, part.bend_allowances[i])
                ext = part.bend_allowances[i] / 2 if th <= 0 else rho_max * np.sin(th / 2)
                rise = 0.0 if th <= 0 else float(flange_rise(r, th))
                grow = 0.0 if th <= 0 else rho_max - (r + t)
                L = part.bend_lengths[i]
                pts.append(np.stack([a2 + ext * n2, a2 + L * d2 + ext * n2]))
                if b.direction > 0:
                    up, down = max(up, t / 2 + rise), max(down, t / 2 + grow)
                else:
                    down, up = max(down, t / 2 + rise), max(up, t / 2 + grow)
            axes, c2, h2 = min_area_rect(np.concatenate(pts))
            R = np.eye(3)
            R[:2, :2] = axes
            T = self.T_part_flange[f]
            centers.append(T[:3, :3] @ np.array([c2[0], c2[1], (up - down) / 2]) + T[:3, 3])
            origins.append(T[:3, :3] @ np.array([c2[0], c2[1], 0.0]) + T[:3, 3])
            rots.append(T[:3, :3] @ R)
            halves.append([h2[0], h2[1], (up + down) / 2])
        return OBB(np.array(centers), np.array(rots), np.array(halves)), np.array(origins)

    def solid(self) -> trimesh.Trimesh:
        """Return the watertight folded solid in the part frame [m], bends as real arcs."""
        from workbench.sheetmetal.solid import build_solid

        return build_solid(self)

    def obb_tree(self, grasp_flange: int | str) -> OBBTree:
        """Return the hierarchical OBB tree rooted at `grasp_flange`, poses in its frame (cached)."""
        from workbench.sheetmetal.obbtree import build_obb_tree

        g = self.part.flange_index(grasp_flange)
        if g not in self._trees:
            self._trees[g] = build_obb_tree(self, g)
        return self._trees[g]

    def tree_depth(self) -> int:
        """Return the number of levels of the deepest OBB tree over every choice of grasp flange."""
        return 1 + max(int(self.obb_tree(f).level.max()) for f in range(len(self.part.flanges)))


def _T_parent_child(
    part: SheetMetalPart, i: int, theta: float, radius: float
) -> NDArray[np.float64]:
    b = part.bends[i]
    t = part.thickness
    pa, d, n = edge_frame(part.flanges[b.parent].polygon, b.parent_edge)
    ca, dc, nc = edge_frame(part.flanges[b.child].polygon, b.child_edge)
    cb = ca + part.bend_lengths[i] * dc
    # Zero-gap flat placement: the child's edge runs backwards along the parent's edge.
    Q = np.column_stack([-d, -n]) @ np.vstack([dc, nc])
    G = np.eye(4)
    G[:2, :2] = Q
    G[:2, 3] = pa - Q @ cb
    B = np.eye(4)
    n3 = np.array([n[0], n[1], 0.0])
    if theta <= 0:
        B[:3, 3] = part.bend_allowances[i] * n3
    else:
        w = np.array([0.0, 0.0, float(b.direction)])
        C = np.array([pa[0], pa[1], 0.0]) + (radius + t / 2) * w
        R = axis_angle(np.cross(n3, w), theta)
        B[:3, :3] = R
        B[:3, 3] = C - R @ C
    return B @ G


def fold_state(
    part: SheetMetalPart, step: float, fraction: float = 0.0, *, check: bool = True
) -> FoldedState:
    """Return the folded state after `step` bends (+ `fraction` of the next); see SheetMetalPart.fold."""
    nb = len(part.bends)
    s = float(step) + float(fraction)
    if not np.isfinite(s) or s < 0 or s > nb or not 0 <= float(fraction) <= 1:
        raise InputError(
            f"step: must be in [0, {nb}] (bends done) with fraction in [0, 1], got step={step!r}, fraction={fraction!r}"
        )
    frac = np.clip(s - np.arange(nb), 0.0, 1.0)
    angles = frac * np.array([b.angle for b in part.bends])
    full_r = np.array([b.inner_radius for b in part.bends])
    kt = np.array([b.k for b in part.bends]) * part.thickness
    with np.errstate(divide="ignore", invalid="ignore"):
        radii = np.where(frac > 0, (full_r + kt) / np.maximum(frac, 1e-300) - kt, np.inf)
    T = np.zeros((len(part.flanges), 4, 4))
    T[0] = np.eye(4)
    for f in part.order[1:]:
        i = int(part.parent_bend[f])
        T[f] = T[part.bends[i].parent] @ _T_parent_child(part, i, angles[i], radii[i])
    state = FoldedState(part, s, angles, radii, T)
    if check:
        _check_intersections(part, state)
    return state


def _prism_bvh(part: SheetMetalPart, f: int) -> fcl.BVHModel:
    from workbench.geometry.polygon import triangulate

    cache = part.__dict__.setdefault("_prism_cache", {})
    if f not in cache:
        poly = part.flanges[f].polygon
        n, t = len(poly), part.thickness
        V = np.concatenate([np.c_[poly, np.full(n, t / 2)], np.c_[poly, np.full(n, -t / 2)]])
        caps = triangulate(poly)
        j = np.arange(n)
        walls = np.concatenate(
            [np.c_[j, (j + 1) % n, n + j], np.c_[(j + 1) % n, n + (j + 1) % n, n + j]]
        )
        tris = np.concatenate([caps, caps[:, ::-1] + n, walls])
        cache[f] = bvh_model(V, tris)
    return cache[f]


def _check_intersections(part: SheetMetalPart, state: FoldedState) -> None:
    nf = len(part.flanges)
    adjacent = {(b.parent, b.child) for b in part.bends} | {(b.child, b.parent) for b in part.bends}
    objs = [
        fcl.CollisionObject(
            _prism_bvh(part, f),
            fcl_transform(state.T_part_flange[f]),
        )
        for f in range(nf)
    ]
    for i in range(nf):
        for j in range(i + 1, nf):
            if (i, j) in adjacent:
                continue
            if fcl.collide(objs[i], objs[j], fcl.CollisionRequest()) > 0:
                k = int(np.ceil(state.step)) - 1
                after = (
                    f"after bend '{part.bends[k].name}' (step {state.step:g})"
                    if k >= 0
                    else "in the flat blank"
                )
                raise InputError(
                    f"flanges '{part.flanges[i].name}' and '{part.flanges[j].name}' "
                    f"intersect {after}; change the sequence, angles or flange sizes",
                    field="bend sequence",
                )
