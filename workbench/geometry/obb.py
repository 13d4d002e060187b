"""Oriented bounding boxes (OBB) and the exact 15-axis separating-axis overlap test, batched.

An `OBB` is a box with centre `center` (..., 3) [m], axes given by the columns of
`rotation` (..., 3, 3) (box frame -> parent frame) and half side lengths
`half_extents` (..., 3) [m]. All arrays share (broadcast to) one batch shape.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError

# Added to |R| so that near-parallel edge pairs (cross-product axis ~ 0) never report a
# false separation from rounding noise (Gottschalk 1996; Ericson, RTCD §4.4.1).
SAT_EPS = 1e-12

# Axis order x, y, z, x, y (see `sat_overlap_rt`).
_CYC = np.array([0, 1, 2, 0, 1])


def _as_float(name: str, value: ArrayLike, tail: tuple[int, ...]) -> NDArray[np.float64]:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(f"OBB {name}: expected numbers, got {value!r}") from exc
    if arr.ndim < len(tail) or arr.shape[arr.ndim - len(tail) :] != tail:
        raise InputError(
            f"OBB {name}: expected shape (..., {', '.join(map(str, tail))}), got {arr.shape}"
        )
    if not np.all(np.isfinite(arr)):
        raise InputError(f"OBB {name}: contains NaN or inf")
    return arr


@dataclass(frozen=True, eq=False)
class OBB:
    """Oriented boxes: centre [m], rotation (columns = box axes), half extents [m]; batched."""

    center: NDArray[np.float64]
    rotation: NDArray[np.float64]
    half_extents: NDArray[np.float64]

    def __post_init__(self) -> None:
        c = _as_float("center", self.center, (3,))
        r = _as_float("rotation", self.rotation, (3, 3))
        e = _as_float("half_extents", self.half_extents, (3,))
        if np.any(e < 0):
            raise InputError(f"OBB half_extents: must be >= 0 m, got min {e.min():.6g}")
        ortho = np.swapaxes(r, -1, -2) @ r - np.eye(3)
        if r.size and (np.max(np.abs(ortho)) > 1e-6 or np.min(np.linalg.det(r)) < 0):
            raise InputError("OBB rotation: must be proper orthonormal (R^T R = I, det R = +1)")
        try:
            shape = np.broadcast_shapes(c.shape[:-1], r.shape[:-2], e.shape[:-1])
        except ValueError as exc:
            raise InputError(
                f"OBB batch shapes differ: center {c.shape}, rotation {r.shape}, "
                f"half_extents {e.shape}"
            ) from exc
        object.__setattr__(self, "center", np.broadcast_to(c, shape + (3,)))
        object.__setattr__(self, "rotation", np.broadcast_to(r, shape + (3, 3)))
        object.__setattr__(self, "half_extents", np.broadcast_to(e, shape + (3,)))

    @property
    def shape(self) -> tuple[int, ...]:
        """Return the batch shape."""
        return self.center.shape[:-1]

    def __len__(self) -> int:
        return self.shape[0] if self.shape else 1

    def __getitem__(self, index: Any) -> OBB:
        """Return the boxes selected by `index` over the batch dimensions."""
        if not self.shape:
            raise InputError("OBB: cannot index a single (unbatched) box")
        return OBB._of_checked(self.center[index], self.rotation[index], self.half_extents[index])

    def reshape(self, *shape: int) -> OBB:
        """Return the same boxes with batch shape `shape`."""
        return OBB._of_checked(
            self.center.reshape(shape + (3,)),
            self.rotation.reshape(shape + (3, 3)),
            self.half_extents.reshape(shape + (3,)),
        )

    @classmethod
    def _of_checked(
        cls, center: NDArray[np.float64], rotation: NDArray[np.float64], half: NDArray[np.float64]
    ) -> OBB:
        """Return boxes made of checked boxes' arrays (selected or reshaped over the batch).

        Their values were checked when those boxes were made (finite, proper orthonormal,
        non-negative), so only the shapes are: an index that reached into a box's own
        coordinates goes through the full check and is refused there. The trees' traversals
        index boxes tens of thousands of times per plan (the seed part cell's cycle plan: 21.3 s
        with this, 21.9-23.8 s checking each again, measured here).
        """
        batch = center.shape[:-1]
        if (
            center.shape[-1:] == (3,)
            and rotation.shape == batch + (3, 3)
            and half.shape == batch + (3,)
        ):
            box = object.__new__(cls)
            object.__setattr__(box, "center", center)
            object.__setattr__(box, "rotation", rotation)
            object.__setattr__(box, "half_extents", half)
            return box
        return cls(center, rotation, half)

    def transformed(self, T: ArrayLike) -> OBB:
        """Return the boxes moved by rigid transforms T (..., 4, 4) (T maps parent -> new parent)."""
        T = _as_float("transform", T, (4, 4))
        R, p = T[..., :3, :3], T[..., :3, 3]
        return OBB((R @ self.center[..., None])[..., 0] + p, R @ self.rotation, self.half_extents)

    def corners(self) -> NDArray[np.float64]:
        """Return the 8 corners (..., 8, 3) [m], index bits (x, y, z) = (1, 2, 4)."""
        signs = np.array([[(i >> k) & 1 for k in range(3)] for i in range(8)], float) * 2 - 1
        local = signs * self.half_extents[..., None, :]  # (..., 8, 3)
        return self.center[..., None, :] + local @ np.swapaxes(self.rotation, -1, -2)

    def volume(self) -> NDArray[np.float64]:
        """Return box volumes (...) [m³]."""
        return 8.0 * np.prod(self.half_extents, axis=-1)

    def contains(self, points: ArrayLike, tol: float = 1e-9) -> NDArray[np.bool_]:
        """Return whether points (..., 3) lie inside the boxes (broadcast), within `tol` [m]."""
        points = np.asarray(points, dtype=float)
        local = (np.swapaxes(self.rotation, -1, -2) @ (points - self.center)[..., None])[..., 0]
        return np.all(np.abs(local) <= self.half_extents + tol, axis=-1)

    @classmethod
    def from_points(cls, points: ArrayLike, rotations: ArrayLike | None = None) -> OBB:
        """Return one box containing all `points` (N, 3) [m].

        Candidate orientations are the points' principal axes, the identity and any extra
        `rotations` (K, 3, 3); the candidate with the least volume wins.
        """
        pts = _as_float("points", points, (3,))
        if pts.ndim != 2 or len(pts) == 0:
            raise InputError(
                f"OBB.from_points points: expected shape (N, 3) with N >= 1, got {pts.shape}"
            )
        cands = [np.eye(3)]
        if len(pts) >= 2:
            _, vecs = np.linalg.eigh(np.cov((pts - pts.mean(0)).T) + 0 * np.eye(3))
            vecs = vecs[:, ::-1].copy()
            if np.linalg.det(vecs) < 0:
                vecs[:, 2] *= -1
            cands.append(vecs)
        if rotations is not None:
            extra = _as_float("rotations", rotations, (3, 3)).reshape(-1, 3, 3)
            cands.extend(extra)
        Rs = np.stack(cands)  # (K, 3, 3)
        local = pts[None] @ Rs  # (K, N, 3): coordinates along each candidate's axes
        lo, hi = local.min(axis=1), local.max(axis=1)
        best = int(np.argmin(np.prod(hi - lo + 1e-12, axis=1)))
        R = Rs[best]
        center = R @ ((lo[best] + hi[best]) / 2)
        return cls(center, R, (hi[best] - lo[best]) / 2)

    def record(self, origin: ArrayLike | None = None) -> NDArray[np.float64]:
        """Return seed 000's 18-float record (..., 18) [m]: origin, x/y/z axes, six offsets.

        The offsets are the distances from `origin` (default: the centre) to the box faces
        along -x, +x, -y, +y, -z, +z of the box axes (all >= 0 when origin is inside).
        """
        o = (
            self.center
            if origin is None
            else np.broadcast_to(np.asarray(origin, float), self.center.shape)
        )
        local = (np.swapaxes(self.rotation, -1, -2) @ (o - self.center)[..., None])[..., 0]
        neg = self.half_extents + local
        pos = self.half_extents - local
        offsets = np.stack([neg, pos], axis=-1).reshape(self.shape + (6,))
        axes = np.swapaxes(self.rotation, -1, -2).reshape(self.shape + (9,))
        return np.concatenate([o, axes, offsets], axis=-1)

    @classmethod
    def from_record(cls, record: ArrayLike) -> OBB:
        """Return boxes from 18-float records (..., 18) written by `record`."""
        rec = _as_float("record", record, (18,))
        o = rec[..., :3]
        R = np.swapaxes(rec[..., 3:12].reshape(rec.shape[:-1] + (3, 3)), -1, -2)
        off = rec[..., 12:].reshape(rec.shape[:-1] + (3, 2))
        half = (off[..., 0] + off[..., 1]) / 2
        shift = (off[..., 1] - off[..., 0]) / 2
        return cls(o + (R @ shift[..., None])[..., 0], R, half)


def sat_overlap(
    ca: NDArray[np.float64],
    Ra: NDArray[np.float64],
    ea: NDArray[np.float64],
    cb: NDArray[np.float64],
    Rb: NDArray[np.float64],
    eb: NDArray[np.float64],
    eps: float = SAT_EPS,
) -> NDArray[np.bool_]:
    """Return overlap verdicts (broadcast batch) of raw box arrays; no validation (hot path)."""
    nb = max(ca.ndim - 1, Ra.ndim - 2, ea.ndim - 1, cb.ndim - 1, Rb.ndim - 2, eb.ndim - 1)
    ca, cb, ea, eb = (x.reshape((1,) * (nb + 1 - x.ndim) + x.shape) for x in (ca, cb, ea, eb))
    Ra, Rb = (x.reshape((1,) * (nb + 2 - x.ndim) + x.shape) for x in (Ra, Rb))
    # Components first, batch last, contiguous: every step below is then an elementwise op
    # over contiguous batch rows (strided or stacked-3x3 matmul versions are 10-40x slower).
    first = np.ascontiguousarray
    return sat_overlap_t(
        first(np.moveaxis(cb - ca, -1, 0)),
        first(np.moveaxis(Ra, (-2, -1), (0, 1))),
        first(np.moveaxis(ea, -1, 0)),
        first(np.moveaxis(Rb, (-2, -1), (0, 1))),
        first(np.moveaxis(eb, -1, 0)),
        eps,
    )


def sat_overlap_t(
    d: NDArray[np.float64],
    A: NDArray[np.float64],
    a: NDArray[np.float64],
    B: NDArray[np.float64],
    b: NDArray[np.float64],
    eps: float = SAT_EPS,
) -> NDArray[np.bool_]:
    """Return overlap verdicts from component-first arrays: d = cb - ca (3, ...), A[k, i] (3, 3, ...), a (3, ...), B, b.

    Builds `sat_overlap_rt`'s inputs (B and d in A's frame, axes in cyclic order) and runs
    that test: one 15-axis implementation for the public and the tree's entry points.
    """
    shape = np.broadcast_shapes(d.shape[1:], A.shape[2:], a.shape[1:], B.shape[2:], b.shape[1:])
    Rt = np.empty((5, 6) + shape)
    R = np.einsum("ki...,kj...->ij...", A, B)  # R[i, j] = a_i . b_j
    Rt[:, :5] = R[_CYC][:, _CYC]
    Rt[:, 5] = np.einsum("ki...,k...->i...", A, d)[_CYC]  # centre offset in A's frame
    n = int(np.prod(shape))
    flat = (5, n)
    ac = np.broadcast_to(a[_CYC], (5,) + shape).reshape(flat)
    bc = np.broadcast_to(b[_CYC], (5,) + shape).reshape(flat)
    return sat_overlap_rt(Rt.reshape(5, 6, n), ac, bc, eps).reshape(shape)


def sat_overlap_rt(
    Rt: NDArray[np.float64],
    a: NDArray[np.float64],
    b: NDArray[np.float64],
    eps: float = SAT_EPS,
) -> NDArray[np.bool_]:
    """Return overlap verdicts (P,) of box pairs given in box A's frame; no validation (hot path).

    Axis indices are extended cyclically (x, y, z, x, y), so that the rolled indices i + 1,
    i + 2 (mod 3) of the edge axes are slices rather than gathers: `Rt` (5, 6, P) holds
    Rt[r, c] = a_(r%3) . b_(c%3) for c < 5 and Rt[r, 5] = a_(r%3) . (cb - ca) [m]; `a` and
    `b` (5, P) (or (5, 1)) are the half extents [m] in the same order. The same 15 axes, eps
    and arithmetic as `sat_overlap_t`, in about 30 numpy calls whatever P is; up to
    `FEW_PAIRS` pairs take a plain Python loop with the same operations in the same order.
    """
    n = Rt.shape[-1]
    if n <= FEW_PAIRS:
        return _sat_rt_few(Rt, a, b, eps)
    t = Rt[:, 5]
    aR = np.abs(Rt[:, :5])
    aR += eps  # |R| + eps as in Gottschalk's test: parallel edges never separate falsely
    R3, aR3, t3, a3, b3 = Rt[:3, :3], aR[:3, :3], t[:3], a[:3], b[:3]
    sep = np.empty((15, n), dtype=bool)
    # Axes of A: |t_i| > a_i + sum_j |R_ij| b_j.
    r = (aR3 * b3[None]).sum(axis=1)
    r += a3
    np.greater(np.abs(t3), r, out=sep[0:3])
    # Axes of B: |sum_i t_i R_ij| > sum_i a_i |R_ij| + b_j.
    lhs = (t3[:, None] * R3).sum(axis=0)
    r = (a3[:, None] * aR3).sum(axis=0)
    r += b3
    np.greater(np.abs(lhs), r, out=sep[3:6])
    # Edge axes a_i x b_j: |t_(i+2) R_(i+1)j - t_(i+1) R_(i+2)j| against
    # a_(i+1) |R_(i+2)j| + a_(i+2) |R_(i+1)j| + b_(j+1) |R_i(j+2)| + b_(j+2) |R_i(j+1)|.
    lhs = t[2:5, None] * Rt[1:4, :3]
    lhs -= t[1:4, None] * Rt[2:5, :3]
    np.abs(lhs, out=lhs)
    ra = a[1:4, None] * aR[2:5, :3]
    ra += a[2:5, None] * aR[1:4, :3]
    rb = b[None, 1:4] * aR[:3, 2:5]
    rb += b[None, 2:5] * aR[:3, 1:4]
    ra += rb
    np.greater(lhs, ra, out=sep[6:15].reshape(3, 3, n))
    return np.logical_not(np.logical_or.reduce(sep, axis=0))


# At most this many pairs, `sat_overlap_rt` loops in Python floats: the ~30 numpy calls of
# the vectorised test cost more than a few pairs' arithmetic (a tree's deeper levels and a
# single frame's root test test a handful of pairs). 12: measured crossover ~12-16 pairs
# (the loop exits at the first separating axis; the vectorised test is ~30 calls).
FEW_PAIRS = 12


def _sat_rt_few(
    Rt: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64], eps: float
) -> NDArray[np.bool_]:
    """Return `sat_overlap_rt` for a few pairs, one at a time: the same operations in the same
    order (so the same verdicts), written out axis by axis (edge (i, j) uses i + 1, i + 2)."""
    n = Rt.shape[-1]
    rows = Rt[:3].transpose(2, 0, 1).tolist()  # (P, 3, 6): R_ij for j < 3, t_i at j = 5
    al, bl = a[:3].T.tolist(), b[:3].T.tolist()
    al, bl = (al * n if len(al) == 1 else al), (bl * n if len(bl) == 1 else bl)
    out = np.zeros(n, dtype=bool)
    for p in range(n):
        (R00, R01, R02, _, _, t0), (R10, R11, R12, _, _, t1), (R20, R21, R22, _, _, t2) = rows[p]
        a0, a1, a2 = al[p]
        b0, b1, b2 = bl[p]
        Q00, Q01, Q02 = abs(R00) + eps, abs(R01) + eps, abs(R02) + eps
        Q10, Q11, Q12 = abs(R10) + eps, abs(R11) + eps, abs(R12) + eps
        Q20, Q21, Q22 = abs(R20) + eps, abs(R21) + eps, abs(R22) + eps
        if (  # axes of A
            abs(t0) > Q00 * b0 + Q01 * b1 + Q02 * b2 + a0
            or abs(t1) > Q10 * b0 + Q11 * b1 + Q12 * b2 + a1
            or abs(t2) > Q20 * b0 + Q21 * b1 + Q22 * b2 + a2
        ):
            continue
        if (  # axes of B
            abs(t0 * R00 + t1 * R10 + t2 * R20) > a0 * Q00 + a1 * Q10 + a2 * Q20 + b0
            or abs(t0 * R01 + t1 * R11 + t2 * R21) > a0 * Q01 + a1 * Q11 + a2 * Q21 + b1
            or abs(t0 * R02 + t1 * R12 + t2 * R22) > a0 * Q02 + a1 * Q12 + a2 * Q22 + b2
        ):
            continue
        out[p] = not (  # edge axes a_i x b_j
            abs(t2 * R10 - t1 * R20) > a1 * Q20 + a2 * Q10 + (b1 * Q02 + b2 * Q01)
            or abs(t2 * R11 - t1 * R21) > a1 * Q21 + a2 * Q11 + (b2 * Q00 + b0 * Q02)
            or abs(t2 * R12 - t1 * R22) > a1 * Q22 + a2 * Q12 + (b0 * Q01 + b1 * Q00)
            or abs(t0 * R20 - t2 * R00) > a2 * Q00 + a0 * Q20 + (b1 * Q12 + b2 * Q11)
            or abs(t0 * R21 - t2 * R01) > a2 * Q01 + a0 * Q21 + (b2 * Q10 + b0 * Q12)
            or abs(t0 * R22 - t2 * R02) > a2 * Q02 + a0 * Q22 + (b0 * Q11 + b1 * Q10)
            or abs(t1 * R00 - t0 * R10) > a0 * Q10 + a1 * Q00 + (b1 * Q22 + b2 * Q21)
            or abs(t1 * R01 - t0 * R11) > a0 * Q11 + a1 * Q01 + (b2 * Q20 + b0 * Q22)
            or abs(t1 * R02 - t0 * R12) > a0 * Q12 + a1 * Q02 + (b0 * Q21 + b1 * Q20)
        )
    return out


def obb_overlap(a: OBB, b: OBB) -> NDArray[np.bool_]:
    """Return whether boxes `a` and `b` overlap (touching counts), broadcast over batch dims.

    Exact separating-axis test over the 15 candidate axes (3 + 3 face normals, 9 edge
    cross products), robust for parallel edges.
    """
    if not isinstance(a, OBB) or not isinstance(b, OBB):
        raise InputError(
            f"obb_overlap: expected two OBB, got {type(a).__name__}, {type(b).__name__}"
        )
    try:
        np.broadcast_shapes(a.shape, b.shape)
    except ValueError as exc:
        raise InputError(
            f"obb_overlap: batch shapes {a.shape} and {b.shape} do not broadcast"
        ) from exc
    return sat_overlap(a.center, a.rotation, a.half_extents, b.center, b.rotation, b.half_extents)
