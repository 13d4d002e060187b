"""Linear BVH over a triangle mesh: Karras (2012) construction, closest points, ray crossings.

Seed 001, step 1: triangle centroids are quantised in the mesh AABB to Morton codes, sorted,
and the binary radix tree is built by Karras' binary search, every internal node at once
(numpy over nodes, O(log n) passes). Boxes are refit bottom-up one tree level at a time.

Node numbering: internal nodes 0 .. n-2 (root 0), leaf k (k-th triangle in Morton order)
is node n-1+k. With one triangle the root is that leaf.

Input handling: NaN/inf vertices, bad shapes and out-of-range indices raise InputError; a
mesh without faces raises MeshError. Degenerate (zero-area) triangles are kept: distances to
them are exact (as segments/points) and they never count as ray crossings. Duplicate
triangles (same three vertex indices in any order) are dropped from the tree so they cannot
double-count ray crossings; ids returned always refer to the caller's face rows (the first
of a duplicate group). Counts are in `degenerate_count` and `duplicate_count`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, MeshError
from workbench.geometry.distance import closest_points_on_triangles
from workbench.geometry.morton import bits_for, highest_bit, morton_codes

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
_EMPTY = 1e30


def check_mesh(vertices: ArrayLike, faces: ArrayLike) -> tuple[FloatArray, IntArray]:
    """Return (vertices (V,3) float64 [m], faces (F,3) int64) after validating them."""
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces)
    if v.ndim != 2 or v.shape[1] != 3:
        raise InputError(f"vertices must have shape (V, 3), got {v.shape}")
    if f.size == 0 or v.size == 0:
        raise MeshError(
            f"mesh is empty ({len(v)} vertices, {f.size // 3} faces); give at least one triangle"
        )
    if f.ndim != 2 or f.shape[1] != 3:
        raise InputError(f"faces must have shape (F, 3) of vertex indices, got {f.shape}")
    if not np.issubdtype(f.dtype, np.integer):
        raise InputError(f"faces must hold integer vertex indices, got dtype {f.dtype}")
    if not np.all(np.isfinite(v)):
        bad = np.unique(np.nonzero(~np.isfinite(v))[0])
        raise InputError(
            f"vertices contain NaN or inf at rows {bad[:5].tolist()}; remove or fix them"
        )
    f = f.astype(np.int64)
    if f.min() < 0 or f.max() >= len(v):
        raise InputError(
            f"faces index vertices out of range [0, {len(v) - 1}]: min {f.min()}, max {f.max()}"
        )
    return v, f


class LBVH:
    """Bounding volume hierarchy of a triangle mesh for exact closest-point and ray queries."""

    def __init__(self, vertices: ArrayLike, faces: ArrayLike) -> None:
        v, f = check_mesh(vertices, faces)
        self.vertices, self.faces = v, f
        # Drop duplicate triangles (any vertex order); keep the first row of each group.
        c0, c1, c2 = f[:, 0], f[:, 1], f[:, 2]
        lo_i, hi_i = np.minimum(np.minimum(c0, c1), c2), np.maximum(np.maximum(c0, c1), c2)
        mid_i = c0 + c1 + c2 - lo_i - hi_i
        if len(v) < (1 << 21):  # one int64 key per sorted index triple
            order = np.argsort((lo_i << 42) | (mid_i << 21) | hi_i, kind="stable")
        else:
            order = np.lexsort((hi_i, mid_i, lo_i))
        lo_s, mid_s, hi_s = lo_i[order], mid_i[order], hi_i[order]
        same = (lo_s[1:] == lo_s[:-1]) & (mid_s[1:] == mid_s[:-1]) & (hi_s[1:] == hi_s[:-1])
        keep = np.ones(len(f), dtype=bool)
        keep[order[1:][same]] = False
        self.duplicate_count = int(len(f) - keep.sum())
        self.face_ids: IntArray = np.nonzero(keep)[0]
        tri = v[f[self.face_ids]]
        area2 = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
        scale = float(np.ptp(v, axis=0).max()) or 1.0
        self.degenerate_count = int(np.sum(area2 <= 1e-14 * scale * scale))
        self.scale = scale
        n = len(tri)
        self.n = n
        self.n_internal = n - 1
        t0, t1, t2 = tri[:, 0], tri[:, 1], tri[:, 2]
        tri_lo = np.minimum(np.minimum(t0, t1), t2)
        tri_hi = np.maximum(np.maximum(t0, t1), t2)
        self.bounds = np.stack([tri_lo.min(axis=0), tri_hi.max(axis=0)])
        # Morton keys of centroids, augmented by index.
        per_axis, index_bits = bits_for(n)
        self._per_axis = per_axis
        ext = np.where(self.bounds[1] > self.bounds[0], self.bounds[1] - self.bounds[0], 1.0)
        unit = ((t0 + t1 + t2) / 3.0 - self.bounds[0]) / ext
        keys = (morton_codes(unit, per_axis) << np.uint64(index_bits)) | np.arange(
            n, dtype=np.uint64
        )
        keys.sort()
        self.order: IntArray = (keys & np.uint64((1 << index_bits) - 1)).astype(np.int64)
        self.left, self.right, self.first, self.last = self._build(keys)
        self.lo, self.hi, self.depth = self._refit(tri_lo[self.order], tri_hi[self.order])
        # Triangles in Morton order (leaf k is a[k], b[k], c[k]); node k covers leaves
        # first[k] .. last[k] (internal k).
        sorted_tri = tri[self.order]
        self.a, self.b, self.c = sorted_tri[:, 0], sorted_tri[:, 1], sorted_tri[:, 2]
        self.wide_child, self.wide_lo, self.wide_hi = self._collapse()

    # ------------------------------------------------------------------ construction
    def _build(self, keys: NDArray[np.uint64]) -> tuple[IntArray, IntArray, IntArray, IntArray]:
        n, m = self.n, self.n - 1
        if m == 0:
            e = np.zeros(0, dtype=np.int64)
            return e, e, e, e
        i = np.arange(m, dtype=np.int64)

        def delta(a: IntArray, b: IntArray) -> IntArray:
            ok = (b >= 0) & (b < n)
            x = keys[a] ^ keys[np.clip(b, 0, n - 1)]
            return np.where(ok, 63 - highest_bit(np.where(ok, x, np.uint64(1))), -1)

        d = np.where(delta(i, i + 1) > delta(i, i - 1), 1, -1)
        dmin = delta(i, i - d)
        lmax = np.full(m, 2, dtype=np.int64)
        act = np.arange(m)
        while act.size:
            grow = delta(act, act + lmax[act] * d[act]) > dmin[act]
            act = act[grow]
            lmax[act] *= 2
        length = np.zeros(m, dtype=np.int64)
        t = lmax // 2
        while np.any(t >= 1):
            ok = (t >= 1) & (delta(i, i + (length + t) * d) > dmin)
            length += np.where(ok, t, 0)
            t //= 2
        j = i + length * d
        dnode = delta(i, j)
        s = np.zeros(m, dtype=np.int64)
        t = length.copy()
        act = np.arange(m)
        while act.size:
            t[act] = (t[act] + 1) >> 1
            ok = delta(act, act + (s[act] + t[act]) * d[act]) > dnode[act]
            s[act] += np.where(ok, t[act], 0)
            act = act[t[act] > 1]
        gamma = i + s * d + np.minimum(d, 0)
        first, last = np.minimum(i, j), np.maximum(i, j)
        left = np.where(first == gamma, m + gamma, gamma)
        right = np.where(last == gamma + 1, m + gamma + 1, gamma + 1)
        return left, right, first, last

    def _refit(
        self, leaf_lo: FloatArray, leaf_hi: FloatArray
    ) -> tuple[FloatArray, FloatArray, int]:
        m = self.n_internal
        lo = np.concatenate([np.zeros((m, 3)), leaf_lo])
        hi = np.concatenate([np.zeros((m, 3)), leaf_hi])
        levels = []
        frontier = np.zeros(1 if m else 0, dtype=np.int64)
        while frontier.size:  # top-down BFS over internal nodes, one level per pass
            levels.append(frontier)
            ch = np.concatenate([self.left[frontier], self.right[frontier]])
            frontier = ch[ch < m]
        for nodes in reversed(levels):  # bottom-up union of the two children
            lo[nodes] = np.minimum(lo[self.left[nodes]], lo[self.right[nodes]])
            hi[nodes] = np.maximum(hi[self.left[nodes]], hi[self.right[nodes]])
        return lo, hi, len(levels) + 1

    def _collapse(self) -> tuple[IntArray, FloatArray, FloatArray]:
        """Return the 8-wide tree: children (W, 8), child box lo (3, W, 8) and hi (3, W, 8).

        Each wide node starts from a binary node's two children and repeatedly opens the
        internal child of largest box surface until it has 8 (the usual BVH8 collapse).
        A child reference >= 0 is a wide node, <= -2 is leaf k = -ref - 2 (Morton order),
        -1 is empty (an inverted box 1e30 away, never entered).
        Fewer, wider nodes mean fewer numpy passes per query, each on contiguous boxes.
        """
        m = self.n_internal
        if m == 0:
            binary = np.full((1, 8), -1, dtype=np.int64)
            binary[0, 0] = 0
            child = np.where(binary == 0, -2, -1)
        else:
            ext = self.hi - self.lo
            area = ext[:, 0] * ext[:, 1] + ext[:, 1] * ext[:, 2] + ext[:, 2] * ext[:, 0]
            levels, parents = [], np.zeros(1, dtype=np.int64)
            while parents.size:
                sets = np.full((len(parents), 8), -1, dtype=np.int64)
                sets[:, 0], sets[:, 1] = self.left[parents], self.right[parents]
                rows = np.arange(len(parents))
                for count in range(2, 8):
                    inner = (sets >= 0) & (sets < m)
                    score = np.where(inner, area[np.clip(sets, 0, m - 1)], -np.inf)
                    j = np.argmax(score, axis=1)
                    go = inner[rows, j]
                    r, jj = rows[go], j[go]
                    node = sets[r, jj]
                    sets[r, jj], sets[r, count] = self.left[node], self.right[node]
                levels.append(sets)
                parents = sets[(sets >= 0) & (sets < m)]
            binary = np.concatenate(levels)
            wide_id = np.full(m, -1, dtype=np.int64)
            is_inner = (binary >= 0) & (binary < m)
            wide_id[binary[is_inner]] = np.arange(1, is_inner.sum() + 1)
            leaf_ref = np.where(binary >= m, -(binary - m) - 2, -1)
            child = np.where(is_inner, wide_id[np.clip(binary, 0, m - 1)], leaf_ref)
        # Coordinate-major (3, W, 8): per-axis work on flat (pairs, 8) arrays is 2-3x faster
        # in numpy than broadcasting over a trailing axis of length 3.
        lo = np.full((3,) + child.shape, _EMPTY)
        hi = np.full((3,) + child.shape, -_EMPTY)
        used = binary >= 0
        for k in range(3):
            lo[k][used], hi[k][used] = self.lo[binary[used], k], self.hi[binary[used], k]
        return child, lo, hi

    # ------------------------------------------------------------------ queries
    def closest_points(self, points: ArrayLike) -> tuple[FloatArray, FloatArray, IntArray]:
        """Return (closest points (M,3) [m], distances (M,) [m], triangle ids (M,)) for points (M,3).

        Same order as ``trimesh.proximity.closest_point``; ids index the caller's faces. Where
        several triangles are equally close, any one of them may be returned.
        """
        p_in = np.asarray(points, dtype=float)
        if p_in.ndim != 2 or p_in.shape[1] != 3:
            raise InputError(f"points must have shape (M, 3), got {p_in.shape}")
        if not np.all(np.isfinite(p_in)):
            raise InputError("points contain NaN or inf; give finite coordinates in metres")
        mq = len(p_in)
        # Queries in Morton order: neighbouring queries visit the same nodes (cache locality).
        ext = np.where(self.bounds[1] > self.bounds[0], self.bounds[1] - self.bounds[0], 1.0)
        qorder = np.argsort(morton_codes((p_in - self.bounds[0]) / ext, 10), kind="stable")
        p = p_in[qorder]
        child, wlo, whi = self.wide_child, self.wide_lo, self.wide_hi

        def box_d2(pq: FloatArray, w: IntArray) -> FloatArray:
            acc = np.zeros((len(w), 8))
            for k in range(3):
                pk = np.repeat(pq[:, k], 8).reshape(-1, 8)
                d, e = wlo[k][w], whi[k][w]
                d -= pk
                np.subtract(pk, e, out=e)
                np.maximum(d, e, out=d)
                np.maximum(d, 0.0, out=d)
                d *= d
                acc += d
            return acc

        # Greedy descent to one leaf per query: a tight first upper bound for pruning.
        ref = np.zeros(mq, dtype=np.int64)
        act = np.arange(mq)
        while act.size:
            w = ref[act]
            j = np.argmin(box_d2(p[act], w), axis=1)
            ref[act] = child[w, j]
            act = act[ref[act] >= 0]
        best_k = -ref - 2
        best_pt = closest_points_on_triangles(p, self.a[best_k], self.b[best_k], self.c[best_k])
        best2 = np.sum((best_pt - p) ** 2, axis=1)
        q, w = np.arange(mq), np.zeros(mq, dtype=np.int64)
        while q.size:
            d2 = box_d2(p[q], w)
            refs = child[w]
            keep = d2 < best2[q][:, None]
            rows, cols = np.nonzero(keep & (refs <= -2))
            if rows.size:
                qk, k = q[rows], -refs[rows, cols] - 2
                cp = closest_points_on_triangles(p[qk], self.a[k], self.b[k], self.c[k])
                dk = np.sum((cp - p[qk]) ** 2, axis=1)
                new = best2.copy()
                np.minimum.at(new, qk, dk)
                win = (dk == new[qk]) & (dk < best2[qk])
                best2 = new
                best_pt[qk[win]] = cp[win]
                best_k[qk[win]] = k[win]
                keep &= d2 < best2[q][:, None]
            rows, cols = np.nonzero(keep & (refs >= 0))
            q, w = q[rows], refs[rows, cols]
        out_pt, out_d, out_id = np.empty_like(best_pt), np.empty(mq), np.empty(mq, dtype=np.int64)
        out_pt[qorder], out_d[qorder] = best_pt, np.sqrt(best2)
        out_id[qorder] = self.face_ids[self.order[best_k]]
        return out_pt, out_d, out_id

    def ray_hits(
        self, origins: ArrayLike, directions: ArrayLike, *, full_line: bool = False
    ) -> tuple[IntArray, FloatArray, NDArray[np.bool_]]:
        """Return (query ids (H,), ray parameters t (H,), degenerate flags (H,)) of all hits.

        Rays are ``origins[k] + t * directions[k]`` with t > 0 (any t if `full_line`);
        `directions` is (3,) or (M,3), not necessarily unit. A hit is flagged degenerate when
        it lies within 1e-9 (barycentric) of a triangle edge or the ray lies in a triangle's
        plane: parity counts through such hits are not trustworthy.
        """
        o = np.asarray(origins, dtype=float)
        if o.ndim != 2 or o.shape[1] != 3 or not np.all(np.isfinite(o)):
            raise InputError(f"origins must be finite with shape (M, 3), got {o.shape}")
        dv = np.broadcast_to(np.asarray(directions, dtype=float), o.shape)
        if not np.all(np.isfinite(dv)) or np.any(np.linalg.norm(dv, axis=1) == 0):
            raise InputError("directions must be finite and non-zero, shape (3,) or (M, 3)")
        eps_box = 1e-9 * self.scale
        inv = 1.0 / np.where(np.abs(dv) < 1e-300, 1e-300, dv)
        t_lo = -np.inf if full_line else 0.0
        child, wlo, whi = self.wide_child, self.wide_lo, self.wide_hi
        q, w = np.arange(len(o)), np.zeros(len(o), dtype=np.int64)
        out_q, out_t, out_g = [], [], []
        while q.size:
            tmin = np.full((len(q), 8), t_lo)
            tmax = np.full((len(q), 8), np.inf)
            for k in range(3):
                ok = np.repeat(o[q, k], 8).reshape(-1, 8)
                ik = np.repeat(inv[q, k], 8).reshape(-1, 8)
                with np.errstate(over="ignore", invalid="ignore"):
                    t1 = (wlo[k][w] - eps_box - ok) * ik
                    t2 = (whi[k][w] + eps_box - ok) * ik
                np.maximum(tmin, np.minimum(t1, t2), out=tmin)
                np.minimum(tmax, np.maximum(t1, t2), out=tmax)
            hit = tmax >= tmin  # empty slots (ref -1) are dropped below
            refs = child[w]
            rows, cols = np.nonzero(hit & (refs <= -2))
            if rows.size:
                ql, tl = q[rows], -refs[rows, cols] - 2
                t, ok, degen = self._moller_trumbore(o[ql], dv[ql], tl, full_line)
                keep = ok | degen
                out_q.append(ql[keep])
                out_t.append(t[keep])
                out_g.append(degen[keep])
            rows, cols = np.nonzero(hit & (refs >= 0))
            q, w = q[rows], refs[rows, cols]
        if not out_q:
            return np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0, dtype=bool)
        return np.concatenate(out_q), np.concatenate(out_t), np.concatenate(out_g)

    def _moller_trumbore(
        self, o: FloatArray, d: FloatArray, tri: IntArray, full_line: bool
    ) -> tuple[FloatArray, NDArray[np.bool_], NDArray[np.bool_]]:
        a = self.a[tri]
        e1, e2 = self.b[tri] - a, self.c[tri] - a
        pv = np.cross(d, e2)
        det = np.einsum("ij,ij->i", e1, pv)
        scale = np.linalg.norm(e1, axis=1) * np.linalg.norm(e2, axis=1) * np.linalg.norm(d, axis=1)
        flat = np.abs(det) <= 1e-12 * scale
        inv = 1.0 / np.where(flat, 1.0, det)
        tv = o - a
        u = np.einsum("ij,ij->i", tv, pv) * inv
        qv = np.cross(tv, e1)
        v = np.einsum("ij,ij->i", d, qv) * inv
        t = np.einsum("ij,ij->i", e2, qv) * inv
        w = 1.0 - u - v
        inside = (u >= 0) & (v >= 0) & (w >= 0) & (full_line | (t > 0))
        near_edge = (
            (np.minimum(np.minimum(u, v), w) < 1e-9) & (u > -1e-9) & (v > -1e-9) & (w > -1e-9)
        )
        nonzero_area = scale > 0
        # A ray parallel to a non-degenerate triangle's plane and lying in it grazes it.
        n = np.cross(e1, e2)
        nn = np.linalg.norm(n, axis=1)
        in_plane = (
            flat
            & nonzero_area
            & (np.abs(np.einsum("ij,ij->i", tv, n)) <= 1e-9 * self.scale * np.maximum(nn, 1e-300))
        )
        area_ok = nn > 1e-14 * self.scale * self.scale
        hit = inside & ~flat & area_ok
        degen = (hit & near_edge) | (in_plane & area_ok)
        return t, hit & ~degen, degen

    def ray_crossings(self, origins: ArrayLike, direction: ArrayLike) -> IntArray:
        """Return the number of triangles (M,) each ray ``origins + t*direction``, t > 0, crosses.

        Hits exactly on an edge or grazing a face count once per triangle touched (so parity
        can be wrong there); `ray_hits` flags them.
        """
        o = np.asarray(origins, dtype=float)
        q, _, _ = self.ray_hits(o, direction)
        return np.bincount(q, minlength=len(o)).astype(np.int64)
