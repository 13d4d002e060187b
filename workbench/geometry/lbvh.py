"""Linear BVH over a triangle mesh: Karras' (2012) radix tree, closest points, ray crossings.

Seed 001, step 1: the centres of the triangles' AABBs are quantised in the mesh AABB to
Morton codes and sorted; the binary radix tree on those (index-augmented) keys is built
bottom-up as in Apetrei (2014), all nodes whose children are done in one numpy round, with
the box refit fused into the same rounds. It is the tree of Karras' top-down binary-search
definition (the tests compare both), at O(n) work instead of O(n log n).

Node numbering: internal node i (0 .. n-2) splits leaves i | i+1 (the root is `root`),
leaf k (k-th triangle in Morton order) is node n-1+k. With one triangle the root is that
leaf.

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
from workbench.geometry.morton import morton_codes, radix_argsort

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]
_EMPTY = 1e30
_MORTON_BITS = 16  # per axis: 48-bit codes, three 16-bit radix passes


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
        used = np.zeros(len(v), dtype=bool)
        used[f.reshape(-1)] = True
        v_lo, v_hi = v.min(axis=0), v.max(axis=0)
        if used.all():
            self.bounds = np.stack([v_lo, v_hi])
        else:
            self.bounds = np.stack([v[used].min(axis=0), v[used].max(axis=0)])
        scale = float((v_hi - v_lo).max()) or 1.0
        self.scale = scale
        # Morton codes of the triangles' AABB centres (independent of vertex order, so
        # duplicate triangles get equal codes), sorted stably: ties keep index order, which
        # is Karras' index-augmented key without a 64-bit sort. The codes only order the
        # leaves (any order gives exact queries), so float32 is enough for them.
        per_axis = _MORTON_BITS
        ext = np.where(self.bounds[1] > self.bounds[0], self.bounds[1] - self.bounds[0], 1.0)
        v32 = ((v - self.bounds[0]) / ext).astype(np.float32)
        w0, w1, w2 = v32[f[:, 0]], v32[f[:, 1]], v32[f[:, 2]]
        centre = np.minimum(np.minimum(w0, w1), w2)
        centre += np.maximum(np.maximum(w0, w1), w2)
        centre *= np.float32(0.5)
        codes = morton_codes(centre, per_axis)
        order = radix_argsort(codes, 3 * per_axis)
        codes = codes[order]
        order = self._drop_duplicates(f, codes, order)
        self.duplicate_count = int(len(f) - len(order))
        if self.duplicate_count:
            codes = codes[self._kept_mask]
            # Leaf k is face row face_ids[self.order[k]]; face_ids ascending (the first
            # row of each duplicate group).
            self.face_ids: IntArray = np.sort(order)
            rank = np.empty(len(f), dtype=np.int64)
            rank[self.face_ids] = np.arange(len(self.face_ids))
            self.order: IntArray = rank[order]
        else:
            self.face_ids, self.order = np.arange(len(f)), order
        fo = f[order]
        # Triangles in Morton order (leaf k is a[k], b[k], c[k]), contiguous for queries.
        self.a, self.b, self.c = v[fo[:, 0]], v[fo[:, 1]], v[fo[:, 2]]
        a, b, c = self.a, self.b, self.c
        e1, e2 = b - a, c - a
        nx = e1[:, 1] * e2[:, 2] - e1[:, 2] * e2[:, 1]
        ny = e1[:, 2] * e2[:, 0] - e1[:, 0] * e2[:, 2]
        nz = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
        area2 = np.sqrt(nx * nx + ny * ny + nz * nz)
        self.degenerate_count = int(np.sum(area2 <= 1e-14 * scale * scale))
        n = len(order)
        self.n = n
        self.n_internal = n - 1
        self.codes: NDArray[np.uint64] = codes  # sorted Morton codes of the leaves
        box = np.empty((2 * n, 6))  # last row: the empty box, for empty wide slots (-1)
        box[-1] = _EMPTY
        leaf = box[n - 1 : 2 * n - 1]
        np.minimum(np.minimum(a, b, out=leaf[:, :3]), c, out=leaf[:, :3])
        np.maximum(np.maximum(a, b, out=leaf[:, 3:]), c, out=leaf[:, 3:])
        np.negative(leaf[:, 3:], out=leaf[:, 3:])
        self.left, self.right, self.first, self.last, self.root, self.depth = self._build(
            codes, box
        )
        self._box = box
        self.wide_child, self.wide_lo, self.wide_hi = self._collapse()

    @property
    def lo(self) -> FloatArray:
        """Return box minima (2n-1, 3) [m] of the binary nodes (internal, then leaves)."""
        return self._box[:-1, :3]

    @property
    def hi(self) -> FloatArray:
        """Return box maxima (2n-1, 3) [m] of the binary nodes (internal, then leaves)."""
        return -self._box[:-1, 3:]

    # ------------------------------------------------------------------ construction
    def _drop_duplicates(self, f: IntArray, codes: NDArray[np.uint64], order: IntArray) -> IntArray:
        """Return `order` without duplicate triangles (same vertex indices in any order).

        Duplicates have equal Morton codes, so only runs of equal codes are compared; the
        lowest face row of each group is kept (so ids returned are the caller's first row).
        """
        self._kept_mask = np.ones(len(order), dtype=bool)
        same_code = codes[1:] == codes[:-1]
        if not same_code.any():
            return order
        in_run = np.zeros(len(order), dtype=bool)
        in_run[1:] |= same_code
        in_run[:-1] |= same_code
        pos = np.nonzero(in_run)[0]
        fr = f[order[pos]]
        c0, c1, c2 = fr[:, 0], fr[:, 1], fr[:, 2]
        lo_i, hi_i = np.minimum(np.minimum(c0, c1), c2), np.maximum(np.maximum(c0, c1), c2)
        mid_i = c0 + c1 + c2 - lo_i - hi_i
        # Sort by (code, vertex triple, face row): equal triples end up adjacent.
        srt = np.lexsort((order[pos], hi_i, mid_i, lo_i, codes[pos]))
        ps, ls, ms, hs = pos[srt], lo_i[srt], mid_i[srt], hi_i[srt]
        dup = (
            (codes[ps[1:]] == codes[ps[:-1]])
            & (ls[1:] == ls[:-1])
            & (ms[1:] == ms[:-1])
            & (hs[1:] == hs[:-1])
        )
        self._kept_mask[ps[1:][dup]] = False
        return order[self._kept_mask]

    @staticmethod
    def _build(
        codes: NDArray[np.uint64], box: FloatArray
    ) -> tuple[IntArray, IntArray, IntArray, IntArray, int, int]:
        """Binary radix tree of sorted `codes` (index-augmented) and its boxes, bottom-up (Apetrei 2014).

        Internal node i splits leaves i | i+1; a node covering leaves [l, r] is the left
        child of internal node r when keys r, r+1 share a longer prefix than keys l-1, l
        (a smaller XOR), else the right child of internal node l-1. This is the tree of
        Karras' top-down definition. All nodes whose two children are done move up in one
        numpy round (so work is O(n) over about depth rounds), and each round unions the
        children's boxes: `box` (2n, 6) holds [lo, -hi] rows (leaves preset at n-1+k), so
        one minimum gives both. Returns (left, right, first, last, root, rounds).
        """
        n = len(codes)
        m = n - 1
        if m == 0:
            e = np.zeros(0, dtype=np.int64)
            return e, e, e, e, 0, 1
        # dx[i]: XOR of the index-augmented keys (code << index_bits | i) of leaves i, i+1,
        # as float64 (exact: codes have 48 bits; equal codes fall back to the index XOR,
        # below every code bit). Only comparisons of dx on the two sides of a node are
        # made, and those never share their highest set bit, so their order is that of
        # Karras' prefix lengths.
        cx = (codes[1:] ^ codes[:-1]).astype(np.float64)
        k = np.arange(m, dtype=np.int64)
        dx = np.where(cx != 0, cx * float(1 << max(1, m.bit_length())), k ^ (k + 1))
        left = np.empty(m, dtype=np.int64)
        right = np.empty(m, dtype=np.int64)
        first = np.empty(m, dtype=np.int64)
        last = np.empty(m, dtype=np.int64)
        arrived = np.zeros(m, dtype=np.int8)
        node = np.arange(m, m + n, dtype=np.int64)
        lo_r = np.arange(n, dtype=np.int64)
        hi_r = lo_r
        rounds, root = 1, -1
        while True:
            # Parent choice; a node with l == 0 goes left (parent r), with r == n-1 right.
            dl = dx[np.maximum(lo_r - 1, 0)]
            dr = dx[np.minimum(hi_r, m - 1)]
            as_left = (lo_r == 0) | ((hi_r != m) & (dr < dl))
            il = np.nonzero(as_left)[0]
            ir = np.nonzero(~as_left)[0]
            pl, pr = hi_r[il], lo_r[ir] - 1
            left[pl], first[pl] = node[il], lo_r[il]
            right[pr], last[pr] = node[ir], hi_r[ir]
            arrived[pl] += 1
            arrived[pr] += 1
            ready_l = pl[arrived[pl] == 2]
            arrived[ready_l] = 3  # taken: not again from the right-child side
            ready = np.concatenate([ready_l, pr[arrived[pr] == 2]])
            if ready.size == 0:
                break
            rounds += 1
            # np.take: a row gather several times faster than fancy indexing
            box[ready] = np.minimum(
                np.take(box, left[ready], axis=0), np.take(box, right[ready], axis=0)
            )
            node, lo_r, hi_r = ready, first[ready], last[ready]
            whole = (lo_r == 0) & (hi_r == m)
            if whole.any():  # the root: stop once it is the only node left
                root = int(ready[whole][0])
                keep = ~whole
                node, lo_r, hi_r = node[keep], lo_r[keep], hi_r[keep]
                if node.size == 0:
                    break
        return left, right, first, last, root, rounds

    def _collapse(self) -> tuple[IntArray, FloatArray, FloatArray]:
        """Return the 8-wide tree: children (W, 8), child box lo (3, W, 8) and hi (3, W, 8).

        Each wide node starts from a binary node's two children and repeatedly opens the
        internal child of largest box surface until it has 8 (the usual BVH8 collapse),
        small subtrees (<= 3 leaves) first.
        A child reference >= 0 is a wide node, <= -2 is leaf k = -ref - 2 (Morton order),
        -1 is empty (an inverted box 1e30 away, never entered).
        Fewer, wider nodes mean fewer numpy passes per query, each on contiguous boxes.
        """
        m, n = self.n_internal, self.n
        if m == 0:
            binary = np.full((1, 8), -1, dtype=np.int64)
            binary[0, 0] = 0
            child = np.where(binary == 0, -2, -1)
        else:
            ext = -self._box[:m, 3:] - self._box[:m, :3]
            # Opening score per binary node, one gather per step: surface for internal
            # nodes, -inf for leaves and for the empty slot (index -1 is the last entry).
            score_of = np.full(m + n + 1, -np.inf)
            score_of[:m] = ext[:, 0] * ext[:, 1] + ext[:, 1] * ext[:, 2] + ext[:, 2] * ext[:, 0]
            # Subtrees of <= 3 leaves open first: as wide nodes of their own they would
            # fill 2-3 of 8 slots (-28 % wide nodes, queries 5-20 % faster).
            score_of[:m][self.last - self.first < 3] = np.inf
            levels, parents = [], np.array([self.root], dtype=np.int64)
            while parents.size:
                sets = np.full((len(parents), 8), -1, dtype=np.int64)
                sets[:, 0], sets[:, 1] = self.left[parents], self.right[parents]
                rows = np.arange(len(parents))
                for count in range(2, 8):
                    score = score_of[sets[rows]]
                    j = np.argmax(score, axis=1)
                    go = score[np.arange(len(rows)), j] > -np.inf
                    rows, j = rows[go], j[go]  # rows with nothing left to open are done
                    if rows.size == 0:
                        break
                    node = sets[rows, j]
                    sets[rows, j], sets[rows, count] = self.left[node], self.right[node]
                levels.append(sets)
                parents = sets[(sets >= 0) & (sets < m)]
            binary = np.concatenate(levels)
            wide_id = np.full(m, -1, dtype=np.int64)
            is_inner = (binary >= 0) & (binary < m)
            wide_id[binary[is_inner]] = np.arange(1, is_inner.sum() + 1)
            leaf_ref = np.where(binary >= m, -(binary - m) - 2, -1)
            child = np.where(is_inner, wide_id[np.clip(binary, 0, m - 1)], leaf_ref)
        # Coordinate-major (3, W, 8): per-axis work on flat (pairs, 8) arrays is 2-3x faster
        # in numpy than broadcasting over a trailing axis of length 3. Slot -1 reads the
        # appended inverted box.
        out = np.empty((6,) + binary.shape)
        for k in range(6):  # one 1-D gather per coordinate, straight into place
            np.take(np.ascontiguousarray(self._box[:, k]), binary, out=out[k])
        np.negative(out[3:], out=out[3:])
        return child, out[:3], out[3:]

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
                d, e = np.take(wlo[k], w, axis=0), np.take(whi[k], w, axis=0)
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
        it lies within 1e-9 (barycentric) of a triangle edge, on either side of it, or the
        ray lies in a triangle's plane: parity counts through such hits are not trustworthy
        (and t of a ray lying in the plane is meaningless). A ray through an edge shared by
        two triangles is so either a regular hit of exactly one of them or flagged
        degenerate: rounding can put it just outside both (barycentrics ~ -1e-16).
        """
        q, t, degen, _ = self.ray_hit_leaves(origins, directions, full_line=full_line)
        return q, t, degen

    def ray_hit_leaves(
        self, origins: ArrayLike, directions: ArrayLike, *, full_line: bool = False
    ) -> tuple[IntArray, FloatArray, NDArray[np.bool_], IntArray]:
        """Return `ray_hits`' (query ids, t, degenerate flags) and the leaves hit (H,).

        A leaf k is the triangle (a[k], b[k], c[k]) in Morton order.
        """
        q, t, degen, leaf, _ = self._ray_query(origins, directions, full_line)
        return q, t, degen, leaf

    def _ray_query(
        self, origins: ArrayLike, directions: ArrayLike, full_line: bool
    ) -> tuple[IntArray, FloatArray, NDArray[np.bool_], IntArray, NDArray[np.bool_]]:
        """Return `ray_hit_leaves` and whether each hit touches the closed triangle (H,)."""
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
        out_q, out_t, out_g, out_l, out_c = [], [], [], [], []
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
                t, ok, degen, touch = self._moller_trumbore(o[ql], dv[ql], tl, full_line)
                keep = ok | degen
                out_q.append(ql[keep])
                out_t.append(t[keep])
                out_g.append(degen[keep])
                out_l.append(tl[keep])
                out_c.append(touch[keep])
            rows, cols = np.nonzero(hit & (refs >= 0))
            q, w = q[rows], refs[rows, cols]
        if not out_q:
            e = np.zeros(0, dtype=np.int64)
            return e, np.zeros(0), np.zeros(0, dtype=bool), e, np.zeros(0, dtype=bool)
        return (
            np.concatenate(out_q),
            np.concatenate(out_t),
            np.concatenate(out_g),
            np.concatenate(out_l),
            np.concatenate(out_c),
        )

    def _moller_trumbore(
        self, o: FloatArray, d: FloatArray, tri: IntArray, full_line: bool
    ) -> tuple[FloatArray, NDArray[np.bool_], NDArray[np.bool_], NDArray[np.bool_]]:
        """Return (t, regular hit, degenerate, touches the closed triangle) per ray-triangle."""
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
        ahead = full_line | (t > 0)
        inside = (u >= 0) & (v >= 0) & (w >= 0) & ahead
        # Within 1e-9 of an edge on either side: a ray through an edge shared by two
        # triangles may round to just outside both, so the band outside must be flagged too
        # (gated by `inside` it never applied, and such a ray crossed nothing, unflagged).
        near_edge = (
            (np.minimum(np.minimum(u, v), w) < 1e-9)
            & (u > -1e-9)
            & (v > -1e-9)
            & (w > -1e-9)
            & ahead
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
        solid = ~flat & area_ok
        hit = inside & solid
        degen = (near_edge & solid) | (in_plane & area_ok)
        # What `ray_crossings` counts: the closed triangle touched (or grazed in its plane).
        touch = hit | (in_plane & area_ok)
        return t, hit & ~degen, degen, touch

    def ray_crossings(self, origins: ArrayLike, direction: ArrayLike) -> IntArray:
        """Return the number of triangles (M,) each ray ``origins + t*direction``, t > 0, crosses.

        Hits exactly on an edge or grazing a face count once per triangle touched (so parity
        can be wrong there); `ray_hits` flags them.
        """
        o = np.asarray(origins, dtype=float)
        q, _, _, _, touch = self._ray_query(o, direction, False)
        return np.bincount(q[touch], minlength=len(o)).astype(np.int64)
