"""Grid points near triangles: the triangle–cube separating-axis test and plane-slab rasters.

A large triangle's bounding box holds many grid points far from the triangle. The rasters
here walk grid columns along the axis closest to the triangle's normal and keep, per
column, only the stretch whose distance to the triangle's plane is within a half-width
(`slab_points`), and for distances also within that reach of the three side planes through
its edges (`band_points`). Every point within the reach of the triangle is among them (the
triangle lies in its plane and inside its side planes), so a caller that applies an exact
test afterwards gets the same set as testing every point of the bounding box.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
# Side planes (and the plane-distance shortcut) only for triangles whose normal is accurate:
# |ab x ac| >= this * |ab| |ac|, i.e. the angle at the first vertex above ~0.006 degrees;
# the cross product's rounding then tilts the normal by < 1e-12 rad.
_WELL_SHAPED = 1e-4


def triangle_box_overlap(
    v0: FloatArray, v1: FloatArray, v2: FloatArray, centre: FloatArray, half: float
) -> NDArray[np.bool_]:
    """Return whether triangles (P,3)x3 overlap axis-aligned cubes (centre (P,3), half-size [m]).

    Separating-axis test of Akenine-Moller (2001): the triangle normal and the nine
    edge x box-axis products (the three box axes are assumed already tested by the caller).
    """
    a, b, c = v0 - centre, v1 - centre, v2 - centre
    n = np.cross(b - a, c - a)
    sep = np.abs(np.einsum("ij,ij->i", n, a)) > half * np.abs(n).sum(axis=1)
    for e in (b - a, c - b, a - c):
        for k in range(3):
            axis = np.zeros_like(e)  # unit_k x e
            axis[:, (k + 1) % 3] = -e[:, (k + 2) % 3]
            axis[:, (k + 2) % 3] = e[:, (k + 1) % 3]
            pa, pb, pc = (np.einsum("ij,ij->i", axis, x) for x in (a, b, c))
            r = half * np.abs(axis).sum(axis=1)
            sep |= (np.minimum(np.minimum(pa, pb), pc) > r) | (
                np.maximum(np.maximum(pa, pb), pc) < -r
            )
    return ~sep


def plane_slabs(
    tri: FloatArray, reach: FloatArray | float, *, cube: bool, scale: float
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Return (normals (T,3), offsets (T,), half-widths (T,)) of slabs around triangles (T,3,3).

    The slab |n·p - offset| <= half holds every point within `reach` [m] of the triangle
    (cube False), or every centre of an axis-aligned cube of half-size `reach` [m] that
    touches it (cube True: the reach along n is reach * |n|_1). The half-width adds the
    vertices' own offsets from the plane through the first one (rounding, slivers) and
    1e-9 * |n| * scale for the rounding of n·p at coordinates up to `scale` [m].
    """
    a = tri[:, 0]
    n = np.cross(tri[:, 1] - a, tri[:, 2] - a)
    offset = np.einsum("ij,ij->i", n, a)
    dev = np.maximum(
        np.abs(np.einsum("ij,ij->i", n, tri[:, 1]) - offset),
        np.abs(np.einsum("ij,ij->i", n, tri[:, 2]) - offset),
    )
    norm = np.abs(n).sum(axis=1) if cube else np.linalg.norm(n, axis=1)
    half = np.asarray(reach, dtype=float) * norm + dev + 1e-9 * np.linalg.norm(n, axis=1) * scale
    return n, offset, half


def slab_point_counts(
    lo: IntArray, hi: IntArray, normal: FloatArray, half: FloatArray, step: float
) -> FloatArray:
    """Return, per triangle, an upper bound of the points `slab_points` yields for it."""
    ar = np.arange(len(lo))
    k = np.argmax(np.abs(normal), axis=1)
    span = np.maximum(hi - lo + 1, 0).astype(float)
    nk = np.abs(normal[ar, k])
    thick = np.where(nk > 0, 2.0 * half / np.where(nk > 0, nk, 1.0) / step + 2.0, np.inf)
    return span[ar, (k + 1) % 3] * span[ar, (k + 2) % 3] * np.minimum(span[ar, k], thick)


class _Columns:
    """One chunk of grid columns along axis k: triangle ids and the two fixed indices."""

    def __init__(
        self, tid: IntArray, k: int, gi: IntArray, gj: IntArray, origin: FloatArray, step: float
    ) -> None:
        self.tid, self.k, self.gi, self.gj = tid, k, gi, gj
        self.i, self.j = (k + 1) % 3, (k + 2) % 3
        self.pi = origin[self.i] + gi * step
        self.pj = origin[self.j] + gj * step
        self.pk = float(origin[k])
        self.step = step

    def linear(self, u: FloatArray, c: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Return (A, B) with u[t]·p - c[t] = A + g B at the column's point of index g."""
        u_k = u[:, self.k].take(self.tid)
        a = u[:, self.i].take(self.tid) * self.pi + u[:, self.j].take(self.tid) * self.pj
        return a + u_k * self.pk - c.take(self.tid), u_k * self.step

    def along(self, x: IntArray) -> IntArray:
        """Return the columns' index range bound of (T,3) array `x` along the column axis."""
        return x[:, self.k].take(self.tid)


def _columns(
    lo: IntArray,
    hi: IntArray,
    normal: FloatArray,
    weight: FloatArray,
    origin: FloatArray,
    step: float,
    budget: int,
) -> Iterator[_Columns]:
    """Yield the columns of the triangles' index boxes along each one's dominant normal axis.

    Triangles are taken by axis; chunks hold about `budget` points by `weight` (points per
    triangle).
    """
    ax_k = np.argmax(np.abs(normal), axis=1)
    span = np.maximum(hi - lo + 1, 0)
    for k in range(3):
        ids = np.flatnonzero(ax_k == k)
        if ids.size == 0:
            continue
        i, j = (k + 1) % 3, (k + 2) % 3
        sj = span[ids, j]
        ncol = span[ids, i] * sj
        csum = np.cumsum(weight[ids])
        cuts = np.searchsorted(csum, np.arange(1, int(csum[-1]) // budget + 2) * float(budget))
        start = 0
        for end in np.unique(np.minimum(np.append(cuts + 1, len(ids)), len(ids))):
            sel = np.arange(start, int(end))
            start = int(end)
            nc = ncol[sel]
            local = np.repeat(sel, nc)
            if local.size == 0:
                continue
            c = np.arange(len(local)) - np.repeat(np.cumsum(nc) - nc, nc)
            sj_t = sj.take(local)
            tid = ids.take(local)
            gi = lo[:, i].take(tid) + c // sj_t
            gj = lo[:, j].take(tid) + c % sj_t
            yield _Columns(tid, k, gi, gj, origin, step)


def _interval(
    a: FloatArray, b: FloatArray, lo: IntArray, hi: IntArray, tau: FloatArray | float
) -> tuple[IntArray, IntArray]:
    """Return the integer range of g in [lo, hi] where a + g b >= tau (empty: lo > hi)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        x = (tau - a) / b
    x = np.clip(x, lo - 1.0, hi + 1.0)  # also maps +-inf; nan (b = 0) handled below
    glo = np.where(b > 0, np.maximum(np.ceil(x), lo), lo).astype(np.int64)
    ghi = np.where(b < 0, np.minimum(np.floor(x), hi), hi).astype(np.int64)
    flat_bad = (b == 0) & (a < tau)
    glo = np.where(flat_bad, hi + 1, glo)
    return glo, ghi


def _expand(
    cols: _Columns, klo: IntArray, khi: IntArray, budget: int
) -> Iterator[tuple[IntArray, IntArray, IntArray, IntArray, IntArray, IntArray]]:
    """Yield (column rows, g along the column, triangle ids, i0, i1, i2) of ranges [klo, khi]."""
    cnt = np.maximum(khi - klo + 1, 0)
    ccum = np.cumsum(cnt)
    if ccum.size == 0 or ccum[-1] == 0:
        return
    cuts = np.searchsorted(ccum, np.arange(1, int(ccum[-1]) // budget + 2) * budget)
    c0 = 0
    for c1 in np.unique(np.minimum(np.append(cuts + 1, len(cnt)), len(cnt))):
        rows = np.arange(c0, int(c1))
        c0 = int(c1)
        cc = cnt[rows]
        total = int(cc.sum())
        if not total:
            continue
        row = np.repeat(rows, cc)
        along = klo.take(row) + (np.arange(total) - np.repeat(np.cumsum(cc) - cc, cc))
        g = [along, along, along]
        g[cols.i], g[cols.j] = cols.gi.take(row), cols.gj.take(row)
        yield row, along, cols.tid.take(row), g[0], g[1], g[2]


def slab_points(
    lo: IntArray,
    hi: IntArray,
    normal: FloatArray,
    offset: FloatArray,
    half: FloatArray,
    origin: FloatArray,
    step: float,
    *,
    budget: int = 2_000_000,
) -> Iterator[tuple[IntArray, IntArray, IntArray, IntArray]]:
    """Yield (triangle ids, i0, i1, i2) of grid points near triangle planes, in chunks.

    The grid points are origin + (i0, i1, i2) * step [m]. For triangle t they are those with
    lo[t] <= index <= hi[t] (inclusive, (T,3)) and |normal[t]·p - offset[t]| <= half[t].
    Columns run along the axis of the largest normal component, so each holds at most
    2 * half / |n_k| / step + 1 points; a zero normal (degenerate triangle) keeps its
    whole box. Chunks hold about `budget` points.
    """
    weight = slab_point_counts(lo, hi, normal, half, step)
    for cols in _columns(lo, hi, normal, weight, origin, step, budget):
        a, b = cols.linear(normal, offset)
        lo_k, hi_k = cols.along(lo), cols.along(hi)
        h_t = half.take(cols.tid)
        # |a + g b| <= half: a + g b >= -half and -(a + g b) >= -half.
        klo, khi = _interval(a, b, lo_k, hi_k, -h_t)
        klo2, khi2 = _interval(-a, -b, lo_k, hi_k, -h_t)
        klo, khi = np.maximum(klo, klo2), np.minimum(khi, khi2)
        for _, _, tid, i0, i1, i2 in _expand(cols, klo, khi, budget):
            yield tid, i0, i1, i2


def band_points(
    tri: FloatArray,
    lo: IntArray,
    hi: IntArray,
    origin: FloatArray,
    step: float,
    reach: float,
    scale: float,
    *,
    budget: int = 1_000_000,
) -> Iterator[tuple[IntArray, IntArray, IntArray, IntArray, FloatArray]]:
    """Yield (triangle ids, i0, i1, i2, d2) for grid points that may lie within `reach` [m].

    Candidates of triangle t (T,3,3) are the grid points origin + index * step with
    lo[t] <= index <= hi[t] in its plane slab (`plane_slabs`); for a well-shaped triangle
    also at most `reach` (plus 1e-9 * scale) outside each of its three side planes (the
    planes through an edge along the normal: the triangle lies inside all three, so a point
    farther outside one is farther from the triangle). d2 is the squared distance [m^2] to
    the triangle, computed in the triangle's own frame (plane distance squared plus the
    squared 2-D distance to the triangle in its plane: 0 inside, else the nearest of its
    three edges); NaN for the other triangles, where the caller computes it. Every point
    within `reach` is yielded.
    """
    n, offset, half = plane_slabs(tri, reach, cube=False, scale=scale)
    a0 = tri[:, 0]
    e1, e2 = tri[:, 1] - a0, tri[:, 2] - a0
    l1 = np.linalg.norm(e1, axis=1)
    nn = np.linalg.norm(n, axis=1)
    good = (nn > 0) & (nn >= _WELL_SHAPED * l1 * np.linalg.norm(e2, axis=1))
    safe = np.where(good, 1.0, 0.0)[:, None]
    unit = safe * n / np.where(good, nn, 1.0)[:, None]
    # The frame: u along ab, v = unit x u; the triangle is (0,0), (bx,0), (cx,cy), cy > 0.
    fu = safe * e1 / np.where(good, l1, 1.0)[:, None]
    fv = np.cross(unit, fu)
    bx = np.where(good, l1, 1.0)
    cx, cy = np.einsum("ij,ij->i", e2, fu), np.where(good, np.einsum("ij,ij->i", e2, fv), 1.0)
    ex1, ey1, ex2, ey2 = cx - bx, cy, -cx, -cy  # edges b -> c and c -> a
    inv1 = 1.0 / (ex1 * ex1 + ey1 * ey1)
    inv2 = 1.0 / (ex2 * ex2 + ey2 * ey2)
    cu, cv, cn = (np.einsum("ij,ij->i", w, a0) for w in (fu, fv, unit))
    sides = []
    for m in range(3):
        p0, p1, opp = tri[:, m], tri[:, (m + 1) % 3], tri[:, (m + 2) % 3]
        s = np.cross(unit, p1 - p0)
        s /= np.maximum(np.linalg.norm(s, axis=1), 1e-300)[:, None]
        s *= np.where(np.einsum("ij,ij->i", s, opp - p0) < 0, -1.0, 1.0)[:, None]
        sides.append(
            (np.where(good[:, None], s, 0.0), np.where(good, np.einsum("ij,ij->i", s, p0), -1.0))
        )
    tau = -reach - 1e-9 * scale
    weight = slab_point_counts(lo, hi, n, half, step)
    for cols in _columns(lo, hi, n, weight, origin, step, budget):
        a, b = cols.linear(n, offset)
        lo_k, hi_k = cols.along(lo), cols.along(hi)
        h_t = half.take(cols.tid)
        klo, khi = _interval(a, b, lo_k, hi_k, -h_t)
        klo2, khi2 = _interval(-a, -b, lo_k, hi_k, -h_t)
        klo, khi = np.maximum(klo, klo2), np.minimum(khi, khi2)
        for s, c in sides:
            sa, sb = cols.linear(s, c)
            glo, ghi = _interval(sa, sb, lo_k, hi_k, tau)
            klo, khi = np.maximum(klo, glo), np.minimum(khi, ghi)
        lin = [cols.linear(w, c) for w, c in ((fu, cu), (fv, cv), (unit, cn))]
        for row, along, tid, i0, i1, i2 in _expand(cols, klo, khi, budget):
            gf = along.astype(float)
            x, y, z = (a_.take(row) + gf * b_.take(row) for a_, b_ in lin)
            bx_t, cx_t, cy_t = bx.take(tid), cx.take(tid), cy.take(tid)
            # Edge a -> b on the x axis.
            dx = x - np.clip(x, 0.0, bx_t)
            d_ab = dx * dx + y * y
            # Edge b -> c.
            qx = x - bx_t
            e_x, e_y = ex1.take(tid), ey1.take(tid)
            t = np.clip((qx * e_x + y * e_y) * inv1.take(tid), 0.0, 1.0)
            rx, ry = qx - t * e_x, y - t * e_y
            d_bc = rx * rx + ry * ry
            left_bc = e_x * y - e_y * qx >= 0.0
            # Edge c -> a.
            qx, qy = x - cx_t, y - cy_t
            e_x, e_y = ex2.take(tid), ey2.take(tid)
            t = np.clip((qx * e_x + qy * e_y) * inv2.take(tid), 0.0, 1.0)
            rx, ry = qx - t * e_x, qy - t * e_y
            d_ca = rx * rx + ry * ry
            left_ca = e_x * qy - e_y * qx >= 0.0
            inside = (y >= 0.0) & left_bc & left_ca
            d2 = z * z + np.where(inside, 0.0, np.minimum(np.minimum(d_ab, d_bc), d_ca))
            d2[~good.take(tid)] = np.nan
            yield tid, i0, i1, i2, d2
