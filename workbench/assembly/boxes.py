"""Oriented box overlap by the separating-axis theorem, vectorised over pairs.

The cell stage of the interference check compares the moving part's cells (boxes that
rotate with the part) against an obstacle's cells (boxes fixed in the world), so both
are treated as oriented boxes (OBBs).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

_EPS = 1e-12


def boxes_overlap(
    center_a: ArrayLike,
    rotation_a: ArrayLike,
    half_a: ArrayLike,
    center_b: ArrayLike,
    rotation_b: ArrayLike,
    half_b: ArrayLike,
) -> NDArray[np.bool_]:
    """Return True where two oriented boxes overlap (touching counts), broadcast over pairs.

    center_*: (..., 3) box centres [m]; rotation_*: (..., 3, 3) box axes as columns;
    half_*: (..., 3) half extents [m]. The 15 separating axes of Gottschalk's OBB test
    are tried; a tiny tolerance keeps the answer conservative for parallel edges.
    """
    ca = np.asarray(center_a, dtype=float)
    cb = np.asarray(center_b, dtype=float)
    Ra = np.asarray(rotation_a, dtype=float)
    Rb = np.asarray(rotation_b, dtype=float)
    ha = np.asarray(half_a, dtype=float)
    hb = np.asarray(half_b, dtype=float)
    # B's axes and the centre offset expressed in A's frame.
    R = np.swapaxes(Ra, -1, -2) @ Rb
    t = (np.swapaxes(Ra, -1, -2) @ (cb - ca)[..., None])[..., 0]
    absR = np.abs(R) + _EPS
    ha, hb = np.broadcast_arrays(ha, hb)
    sep = np.zeros(np.broadcast_shapes(t.shape[:-1], absR.shape[:-2]), dtype=bool)
    # A's face normals.
    ra = ha
    rb = (absR @ hb[..., None])[..., 0]
    sep |= np.any(np.abs(t) > ra + rb, axis=-1)
    # B's face normals.
    ra = (np.swapaxes(absR, -1, -2) @ ha[..., None])[..., 0]
    tb = (np.swapaxes(R, -1, -2) @ t[..., None])[..., 0]
    sep |= np.any(np.abs(tb) > ra + hb, axis=-1)
    # Edge-edge cross products A_i x B_j.
    for i in range(3):
        i1, i2 = (i + 1) % 3, (i + 2) % 3
        for j in range(3):
            j1, j2 = (j + 1) % 3, (j + 2) % 3
            ra = ha[..., i1] * absR[..., i2, j] + ha[..., i2] * absR[..., i1, j]
            rb = hb[..., j1] * absR[..., i, j2] + hb[..., j2] * absR[..., i, j1]
            d = np.abs(t[..., i2] * R[..., i1, j] - t[..., i1] * R[..., i2, j])
            sep |= d > ra + rb
    return ~sep


def obb_aabb_overlap(
    center_a: NDArray[np.float64],
    rotation_a: NDArray[np.float64],
    half_a: float,
    center_b: NDArray[np.float64],
    half_b: float,
) -> NDArray[np.bool_]:
    """Return True where cubes (M, 3) centres, (M, 3, 3) axes, half side [m] touch axis-aligned cubes.

    The same 15-axis test as `boxes_overlap`, specialised to cubes and a world-aligned
    second box, for the cell stage's many pairs.
    """
    R = rotation_a
    absR = np.abs(R) + _EPS
    t = center_b - center_a  # in world (= B's) axes
    ha, hb = float(half_a), float(half_b)
    sep = np.any(np.abs(t) > hb + ha * absR.sum(axis=2), axis=1)
    ta = np.einsum("mij,mi->mj", R, t)  # offset in A's axes
    sep |= np.any(np.abs(ta) > ha + hb * absR.sum(axis=1), axis=1)
    # Edge axes W_i x A_j with A_j = R[:, :, j]: |t . (W_i x A_j)| vs projected radii.
    for i in range(3):
        i1, i2 = (i + 1) % 3, (i + 2) % 3
        for j in range(3):
            d = np.abs(t[:, i2] * R[:, i1, j] - t[:, i1] * R[:, i2, j])
            rb = hb * (absR[:, i1, j] + absR[:, i2, j])
            ra = ha * (absR[:, i, (j + 1) % 3] + absR[:, i, (j + 2) % 3])
            sep |= d > ra + rb
    return ~sep


def box_triangle_overlap(
    center: ArrayLike, half: float, triangles: ArrayLike, *, tol: float = 0.0
) -> NDArray[np.bool_]:
    """Return True where axis-aligned cubes touch triangles (Akenine-Möller SAT), per pair.

    center: (M, 3) cube centres [m]; half: cube half side [m]; triangles: (M, 3, 3)
    vertices [m]; tol [m] grows the cube so borderline contacts count as overlap.
    The 13 axes are tested in turn on the pairs no earlier axis separated (the verdict is
    the same as testing every axis on every pair: a pair overlaps iff no axis separates it).
    """
    v = np.asarray(triangles, dtype=float) - np.asarray(center, dtype=float)[:, None, :]
    h = float(half) + tol
    m = len(v)
    # Box face axes: per coordinate, the triangle's extent against [-h, h].
    lo = np.minimum(np.minimum(v[:, 0], v[:, 1]), v[:, 2])
    hi = np.maximum(np.maximum(v[:, 0], v[:, 1]), v[:, 2])
    sep = (lo > h) | (hi < -h)
    live = np.flatnonzero(~(sep[:, 0] | sep[:, 1] | sep[:, 2]))
    out = np.zeros(m, dtype=bool)
    if live.size == 0:
        return out
    v = v[live]
    e = np.stack([v[:, 1] - v[:, 0], v[:, 2] - v[:, 1], v[:, 0] - v[:, 2]], axis=1)
    n = np.cross(e[:, 0], e[:, 1])
    keep = ~(np.abs(np.einsum("mi,mi->m", n, v[:, 0])) > h * np.abs(n).sum(axis=1))
    live, v, e = live[keep], v[keep], e[keep]
    for k in range(3):
        for ax in range(3):
            if live.size == 0:
                return out
            # axis = unit_ax x e_k
            a = np.zeros_like(e[:, k])
            a1, a2 = (ax + 1) % 3, (ax + 2) % 3
            a[:, a1] = -e[:, k, a2]
            a[:, a2] = e[:, k, a1]
            p = np.einsum("mvi,mi->mv", v, a)
            r = h * np.abs(a).sum(axis=1)
            pmin = np.minimum(np.minimum(p[:, 0], p[:, 1]), p[:, 2])
            pmax = np.maximum(np.maximum(p[:, 0], p[:, 1]), p[:, 2])
            keep = ~((pmin > r) | (pmax < -r))
            live, v, e = live[keep], v[keep], e[keep]
    out[live] = True
    return out
