"""Watertight triangle mesh of a folded sheet-metal part: flange prisms joined by bend arcs.

A flange's holes go through its prism: its caps are triangulated around them and each hole
has its own wall.

Vertices are shared by index (no merging by distance): a bend's first cross-section reuses
its parent's edge corners and its last one the child's, so the mesh closes exactly.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import trimesh

from workbench.geometry.polygon import triangulate
from workbench.sheetmetal.folding import axis_angle, bend_profile
from workbench.sheetmetal.holes import cap_triangles

if TYPE_CHECKING:
    from workbench.sheetmetal.folding import FoldedState


def build_solid(state: FoldedState) -> trimesh.Trimesh:
    """Return the folded part as a watertight `trimesh.Trimesh` in the part frame [m]."""
    part = state.part
    t = part.thickness
    verts: list[np.ndarray] = []
    faces: list[np.ndarray] = []
    base: list[int] = []  # first vertex index of each flange: n top, then n bottom
    count = 0
    bend_edges = {(b.parent, b.parent_edge) for b in part.bends} | {
        (b.child, b.child_edge) for b in part.bends
    }
    ring_count: list[int] = []  # vertices per face of each flange: outline then its holes
    for f, fl in enumerate(part.flanges):
        poly = fl.polygon
        n = len(poly)
        pts = np.concatenate([poly, *fl.holes]) if fl.holes else poly
        m = len(pts)
        local = np.concatenate([np.c_[pts, np.full(m, t / 2)], np.c_[pts, np.full(m, -t / 2)]])
        T = state.T_part_flange[f]
        verts.append(local @ T[:3, :3].T + T[:3, 3])
        base.append(count)
        ring_count.append(m)
        caps = cap_triangles(poly, fl.holes) if fl.holes else triangulate(poly)
        faces.append(caps + count)
        faces.append(caps[:, ::-1] + count + m)
        for e in range(n):
            if (f, e) in bend_edges:
                continue
            a, b = e, (e + 1) % n
            faces.append(np.array([[a + m, b + m, b], [a + m, b, a]]) + count)
        start = n
        for h in fl.holes:  # hole walls face into the hole: opposite winding to the outline's
            nh = len(h)
            ha = start + np.arange(nh)
            hb = start + (np.arange(nh) + 1) % nh
            faces.append(np.concatenate([np.c_[ha + m, hb, hb + m], np.c_[ha + m, ha, hb]]) + count)
            start += nh
        count += 2 * m

    for i, bd in enumerate(part.bends):
        npar = len(part.flanges[bd.parent].polygon)
        nch = len(part.flanges[bd.child].polygon)
        mpar, mch = ring_count[bd.parent], ring_count[bd.child]
        top = bd.direction > 0  # inner surface is the +z (top) face when bending up
        p0, p1 = bd.parent_edge, (bd.parent_edge + 1) % npar
        c_a, c_b = (
            (bd.child_edge + 1) % nch,
            bd.child_edge,
        )  # child corner at the parent's a / b end

        def corner(f: int, v: int, m: int, inner: bool, top: bool = top) -> int:
            return base[f] + v + (0 if inner == top else m)

        geo = state.bend_cross_section(i)
        th, r = state.angles[i], state.radii[i]
        N, sigma, _ = bend_profile(th, r, t, part.bend_allowances[i])
        T = state.T_part_flange[bd.parent]
        rows = np.empty((N + 1, 4), dtype=np.int64)  # inner_a, inner_b, outer_a, outer_b
        rows[0] = [
            corner(bd.parent, p0, mpar, True),
            corner(bd.parent, p1, mpar, True),
            corner(bd.parent, p0, mpar, False),
            corner(bd.parent, p1, mpar, False),
        ]
        rows[N] = [
            corner(bd.child, c_a, mch, True),
            corner(bd.child, c_b, mch, True),
            corner(bd.child, c_a, mch, False),
            corner(bd.child, c_b, mch, False),
        ]
        if N > 1:
            k = np.arange(1, N)
            phi = th * k / N
            rho_out = r + t - sigma * np.sin(np.pi * k / N)
            axis = np.cross(geo["n"], geo["w"])
            dirs = np.stack([axis_angle(axis, p) @ (-geo["w"]) for p in phi])  # (N-1, 3)
            L = geo["pb"] - geo["pa"]
            c = geo["center"]
            pts = np.concatenate(
                [
                    c + r * dirs,
                    c + L + r * dirs,
                    c + rho_out[:, None] * dirs,
                    c + L + rho_out[:, None] * dirs,
                ]
            )
            verts.append(pts @ T[:3, :3].T + T[:3, 3])
            m = N - 1
            rows[1:N] = count + np.stack([k - 1, m + k - 1, 2 * m + k - 1, 3 * m + k - 1], axis=1)
            count += 4 * m
        ia, ib, oa, ob = rows[:-1].T
        ja, jb, pa, pb = rows[1:].T
        block = np.concatenate(
            [
                np.c_[ia, ib, jb],
                np.c_[ia, jb, ja],  # inner surface
                np.c_[oa, pb, ob],
                np.c_[oa, pa, pb],  # outer surface
                np.c_[ia, ja, pa],
                np.c_[ia, pa, oa],  # end cap at a
                np.c_[ib, pb, jb],
                np.c_[ib, ob, pb],  # end cap at b
            ]
        )
        # The inner cap runs a -> b along the bend edge when it is the top (+z) cap: the
        # bend's faces must run b -> a there, so flip the block for up-bends.
        faces.append(block[:, ::-1] if top else block)
    mesh = trimesh.Trimesh(np.concatenate(verts), np.concatenate(faces), process=False)
    if mesh.volume < 0:  # cannot happen for a consistent build; keep outward normals anyway
        mesh.invert()
    return mesh
