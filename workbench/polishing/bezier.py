"""Quadratic Bézier triangles fitted to a triangle mesh (seed 004, eqs. 1-4), batched.

Each face (A, B, C) becomes the patch

    P(u, v, w) = u² A + v² B + w² C + 2uv P110 + 2vw P011 + 2uw P101,   u + v + w = 1,

(eq. 2, derived again). The edge control point of edge A-B is chosen so that the patch edge
passes through the midpoint M of the cubic Hermite curve from A to B (eq. 3) whose end
tangents are the edge direction projected onto each end's tangent plane (eq. 4),
normalised and scaled by the chord length L = |B - A|:

    M = (A + B)/2 + (T_A - T_B)/8,      P110 = 2M - (A + B)/2 = (A + B)/2 + (T_A - T_B)/4.

(The seed takes the curve midpoint itself as the control point; a quadratic edge through
M needs the control point above, or the surface only gets half of the bulge.) For a circle
of radius R and chord angle θ the bulge is R sin²(θ/2)/2 against the true R(1 - cos(θ/2)):
equal to second order. The control point depends only on the edge's two vertices and
their normals, and is computed once per unique edge, so neighbouring patches share their
edge curve exactly (C0).
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import trimesh
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, MeshError

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class BezierSurface:
    """Quadratic Bézier triangles over `faces` (F, 3) of `vertices` (V, 3) [m], fitted with unit
    `vertex_normals` (V, 3). Control points are computed on demand for the patches asked
    for (`control_points_of`); `control_points` (F, 6, 3) gives all of them, ordered
    [P200 = A, P020 = B, P002 = C, P110, P011, P101]."""

    vertices: F64
    faces: NDArray[np.int64]
    vertex_normals: F64
    _cache: dict[str, Any] = field(init=False, repr=False, compare=False)

    @property
    def n_faces(self) -> int:
        """Return the number of patches."""
        return int(self.faces.shape[0])

    @cached_property
    def control_points(self) -> F64:
        """Return the control points (F, 6, 3) [m] of every patch."""
        return self.control_points_of(np.arange(self.n_faces))

    def __post_init__(self) -> None:
        # Filled as patches are asked for: planning evaluates the same faces several times
        # (Newton iterations). Rows are stored compactly in the order computed (row[f], -1
        # for none), so a path over a large mesh touches memory for its own faces only.
        # Made here, not lazily, so concurrent first callers (viser callback threads) cannot
        # each make their own; the lock makes growing and filling one step (below).
        cache = {
            "row": np.full(self.n_faces, -1, dtype=np.int64),
            "cp": np.empty((0, 6, 3)),
            "used": 0,
            "lock": threading.Lock(),
        }
        object.__setattr__(self, "_cache", cache)

    def control_points_of(self, face: ArrayLike) -> F64:
        """Return the control points (..., 6, 3) [m] of patches `face` (...). Thread-safe."""
        f = np.asarray(face, dtype=np.int64)
        flat = f.ravel()
        cache = self._cache
        row = cache["row"]
        idx = row[flat]
        if len(flat[idx < 0]):  # (faster than .any() on the short arrays of single points)
            # Two fills at once would take the same free rows (or grow from a stale store) and
            # overwrite each other's control points; under the lock, faces filled meanwhile by
            # another thread are looked up again and not recomputed.
            with cache["lock"]:
                idx = row[flat]
                need = flat[idx < 0]
                if len(need):
                    need = np.unique(need)
                    start = int(cache["used"])
                    store = cache["cp"]
                    if start + len(need) > len(store):  # grow by doubling: amortised O(1)
                        grown = np.empty((max(2 * len(store), start + len(need), 64), 6, 3))
                        grown[:start] = store[:start]
                        cache["cp"] = store = grown
                    store[start : start + len(need)] = self._compute_control_points(need)
                    # Rows are published only after they are written, so a lock-free reader
                    # that sees row[f] >= 0 finds its control points in any later store.
                    row[need] = np.arange(start, start + len(need))
                    cache["used"] = start + len(need)
                    idx = row[flat]
        # Stores only grow by copying every written row, so rows idx < used are in any store.
        return cache["cp"][idx].reshape(f.shape + (6, 3))

    def _compute_control_points(self, face: NDArray[np.int64]) -> F64:
        tri = self.faces[face]
        # Each face edge is computed from its endpoints in sorted order, so the two faces of
        # an edge get bit-identical control points (C0) without a sort over all edges.
        nxt = tri[:, [1, 2, 0]]
        edges = np.stack([np.minimum(tri, nxt).ravel(), np.maximum(tri, nxt).ravel()], axis=1)
        edge_cp = _edge_control_points(self.vertices, self.vertex_normals, edges).reshape(-1, 3, 3)
        # face edges are (A,B) -> P110, (B,C) -> P011, (C,A) -> P101.
        return np.concatenate([self.vertices[tri], edge_cp], axis=1)

    def _check(self, face: ArrayLike, bary: ArrayLike) -> tuple[NDArray[np.int64], F64]:
        f = np.asarray(face, dtype=np.int64)
        b = np.asarray(bary, dtype=float)
        if b.shape[-1:] != (3,):
            raise InputError(f"bary must have shape (..., 3) = (u, v, w), got {b.shape}")
        if f.shape != b.shape[:-1]:
            raise InputError(f"face shape {f.shape} must equal bary's leading shape {b.shape[:-1]}")
        if f.size and (f.min() < 0 or f.max() >= self.n_faces):
            raise InputError(
                f"face indices must lie in [0, {self.n_faces}), got [{f.min()}, {f.max()}]"
            )
        return f, b

    def evaluate(self, face: ArrayLike, bary: ArrayLike) -> F64:
        """Return points (..., 3) [m] at barycentric `bary` (..., 3) = (u, v, w) of patches `face` (...)."""
        f, b = self._check(face, bary)
        return _point(self.control_points_of(f), b)

    def derivatives(self, face: ArrayLike, bary: ArrayLike) -> tuple[F64, F64]:
        """Return (dP/du, dP/dv) (..., 3) [m] with w = 1 - u - v eliminated."""
        f, b = self._check(face, bary)
        return _derivatives(self.control_points_of(f), b)

    def normal(self, face: ArrayLike, bary: ArrayLike) -> F64:
        """Return unit surface normals (..., 3), oriented like the face winding (A, B, C)."""
        return _unit_normal(*self.derivatives(face, bary))

    def evaluate_with_derivatives(
        self, face: ArrayLike, bary: ArrayLike
    ) -> tuple[F64, F64, F64, F64]:
        """Return (points, dP/du, dP/dv, unit normals) (..., 3) at `bary` of patches `face`,
        sharing one lookup (derivatives with w = 1 - u - v eliminated, as `derivatives`)."""
        f, b = self._check(face, bary)
        cp = self.control_points_of(f)
        d_du, d_dv = _derivatives(cp, b)
        return _point(cp, b), d_du, d_dv, _unit_normal(d_du, d_dv)

    def evaluate_with_normal(self, face: ArrayLike, bary: ArrayLike) -> tuple[F64, F64]:
        """Return (points, unit normals) (..., 3) at `bary` of patches `face`, sharing one lookup."""
        f, b = self._check(face, bary)
        cp = self.control_points_of(f)
        return _point(cp, b), _unit_normal(*_derivatives(cp, b))


def _point(cp: F64, b: F64) -> F64:
    u, v, w = b[..., 0:1], b[..., 1:2], b[..., 2:3]
    return (
        u * u * cp[..., 0, :]
        + v * v * cp[..., 1, :]
        + w * w * cp[..., 2, :]
        + 2 * u * v * cp[..., 3, :]
        + 2 * v * w * cp[..., 4, :]
        + 2 * u * w * cp[..., 5, :]
    )


def _derivatives(cp: F64, b: F64) -> tuple[F64, F64]:
    u, v, w = b[..., 0:1], b[..., 1:2], b[..., 2:3]
    a_, b_, c_, p110, p011, p101 = (cp[..., i, :] for i in range(6))
    d_du = 2 * (u * a_ - w * c_ + v * p110 - v * p011 + (w - u) * p101)
    d_dv = 2 * (v * b_ - w * c_ + u * p110 + (w - v) * p011 - u * p101)
    return d_du, d_dv


def _unit_normal(d_du: F64, d_dv: F64) -> F64:
    n = np.cross(d_du, d_dv)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def _edge_control_points(vertices: F64, normals: F64, edges: NDArray[np.int64]) -> F64:
    """Return the quadratic control point (E, 3) of each edge (E, 2) (module docstring)."""
    # Component rows (3, E): products and sums written out on contiguous rows are faster
    # than row-wise einsum dot products on (E, 3) arrays.
    p0, p1 = (np.ascontiguousarray(vertices[edges[:, i]].T) for i in range(2))
    n0, n1 = (np.ascontiguousarray(normals[edges[:, i]].T) for i in range(2))
    chord = p1 - p0
    length = np.sqrt(chord[0] * chord[0] + chord[1] * chord[1] + chord[2] * chord[2])
    v12 = chord / np.where(length > 0, length, 1.0)
    # eq. 4: t = n x (v12 x n) = v12 - (v12.n) n, the chord projected onto the tangent plane.
    t0 = v12 - (v12[0] * n0[0] + v12[1] * n0[1] + v12[2] * n0[2]) * n0
    t1 = v12 - (v12[0] * n1[0] + v12[1] * n1[1] + v12[2] * n1[2]) * n1
    l0 = np.sqrt(t0[0] * t0[0] + t0[1] * t0[1] + t0[2] * t0[2])
    l1 = np.sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2])
    # A normal parallel to the chord gives no tangent: fall back to the chord (a straight edge).
    t0 = np.where(l0 > 1e-9, t0 / np.where(l0 > 1e-9, l0, 1.0), v12)
    t1 = np.where(l1 > 1e-9, t1 / np.where(l1 > 1e-9, l1, 1.0), v12)
    return (0.5 * (p0 + p1) + 0.25 * length * (t0 - t1)).T


def _row_norms(v: F64) -> F64:
    """Return |v_i| (N,) of rows v (N, 3), from the columns: numpy reduces a short last axis
    row by row, several times slower on large arrays."""
    x, y, z = v[:, 0], v[:, 1], v[:, 2]
    return np.sqrt(x * x + y * y + z * z)


def area_weighted_normals(vertices: F64, faces: NDArray[np.int64]) -> F64:
    """Return unit vertex normals (V, 3): the sum of the adjacent faces' area vectors, normalised.

    Unreferenced vertices get (0, 0, 0)."""
    tri = vertices[faces]
    a, b = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    fn = np.stack(
        [
            a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1],
            a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0],
        ],
        axis=1,
    )
    idx = faces.ravel()
    n = np.stack(
        [np.bincount(idx, np.repeat(fn[:, k], 3), minlength=len(vertices)) for k in range(3)],
        axis=1,
    )
    norm = np.linalg.norm(n, axis=1, keepdims=True)
    return n / np.where(norm > 0, norm, 1.0)


def fit_bezier_triangles(
    mesh: trimesh.Trimesh, *, vertex_normals: ArrayLike | None = None
) -> BezierSurface:
    """Return the `BezierSurface` fitted to `mesh` (lengths in m), one quadratic patch per face.

    The patches' control points are computed when first asked for (`control_points`,
    `evaluate`): planning touches only the faces under the path.

    vertex_normals: (V, 3) normals to fit with; default the area-weighted face normals
    (`area_weighted_normals`, following the winding). Raises `MeshError` for a mesh with
    no faces and `InputError` for normals of the wrong shape or zero length.
    """
    vertices = np.asarray(mesh.vertices, dtype=float)
    faces = np.asarray(mesh.faces, dtype=np.int64)
    if len(faces) == 0:
        raise MeshError("mesh has no faces; fit_bezier_triangles needs a triangle mesh")
    if vertex_normals is None:
        normals = area_weighted_normals(vertices, faces)
    else:
        normals = np.asarray(vertex_normals, dtype=float)
        if normals.shape != vertices.shape:
            raise InputError(
                f"vertex_normals must have shape {vertices.shape}, got {normals.shape}"
            )
        length = _row_norms(normals)
        normals = normals / np.where(length > 0, length, 1.0)[:, None]
    zero = _row_norms(normals) == 0
    if zero.any() and zero[faces].any():
        raise InputError("vertex_normals contains zero-length normals at vertices used by faces")
    return BezierSurface(vertices=vertices, faces=faces, vertex_normals=normals)
