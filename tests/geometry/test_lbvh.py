"""LBVH against brute force (every triangle) and trimesh.proximity."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError, MeshError
from workbench.geometry.distance import closest_points_on_triangles
from workbench.geometry.lbvh import LBVH


def _scene() -> trimesh.Trimesh:
    """A sphere and a disjoint box: closed, with small and large triangles."""
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=0.5)
    box = trimesh.creation.box((0.4, 0.8, 0.3))
    box.apply_translation((1.0, 0.1, 0.05))
    return trimesh.util.concatenate([sphere, box])


def _brute_closest(v: np.ndarray, f: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    tri = v[f]
    d = np.empty((len(p), len(f)))
    for i in range(0, len(p), 64):  # chunks of queries against every triangle
        cp = closest_points_on_triangles(
            p[i : i + 64, None, :], tri[None, :, 0], tri[None, :, 1], tri[None, :, 2]
        )
        d[i : i + 64] = np.linalg.norm(cp - p[i : i + 64, None, :], axis=2)
    return d.min(axis=1), d


def _brute_crossings(
    v: np.ndarray, f: np.ndarray, o: np.ndarray, direction: np.ndarray
) -> np.ndarray:
    a, b, c = (v[f][:, k][None] for k in range(3))
    e1, e2 = b - a, c - a
    dv = np.broadcast_to(direction, (len(o), f.shape[0], 3))
    pv = np.cross(dv, e2)
    det = np.sum(e1 * pv, axis=2)
    tv = o[:, None, :] - a
    u = np.sum(tv * pv, axis=2) / det
    qv = np.cross(tv, e1)
    w = np.sum(dv * qv, axis=2) / det
    t = np.sum(e2 * qv, axis=2) / det
    return np.sum((u >= 0) & (w >= 0) & (u + w <= 1) & (t > 0), axis=1)


def test_tree_structure_is_a_valid_bvh() -> None:
    m = _scene()
    bvh = LBVH(m.vertices, m.faces)
    n, k = bvh.n, bvh.n_internal
    children = np.concatenate([bvh.left, bvh.right])
    # Every node except the root is the child of exactly one internal node.
    assert np.array_equal(np.sort(children), np.delete(np.arange(n + k), bvh.root))
    assert bvh.first[bvh.root] == 0 and bvh.last[bvh.root] == n - 1
    # Each internal node's box is the union of its children's boxes; leaves bound triangles.
    np.testing.assert_array_equal(bvh.lo[:k], np.minimum(bvh.lo[bvh.left], bvh.lo[bvh.right]))
    np.testing.assert_array_equal(bvh.hi[:k], np.maximum(bvh.hi[bvh.left], bvh.hi[bvh.right]))
    tri = np.stack([bvh.a, bvh.b, bvh.c], axis=1)
    np.testing.assert_array_equal(bvh.lo[k:], tri.min(axis=1))
    # Node ranges split at the Karras split position: left covers [first, g], right [g+1, last].
    size = np.concatenate([bvh.last - bvh.first + 1, np.ones(n, dtype=int)])
    np.testing.assert_array_equal(size[:k], size[bvh.left] + size[bvh.right])
    # The 8-wide collapse references every leaf exactly once.
    leaves = -bvh.wide_child[bvh.wide_child <= -2] - 2
    assert np.array_equal(np.sort(leaves), np.arange(n))


def _karras_splits(keys: list[int]) -> dict[tuple[int, int], int]:
    """Top-down binary radix tree (Karras 2012): {(first, last): split} for internal nodes."""
    out: dict[tuple[int, int], int] = {}
    stack = [(0, len(keys) - 1)]
    while stack:
        lo, hi = stack.pop()
        if lo == hi:
            continue
        bit = (keys[lo] ^ keys[hi]).bit_length() - 1  # highest differing bit
        split = max(i for i in range(lo, hi + 1) if not (keys[i] >> bit) & 1)
        out[(lo, hi)] = split
        stack += [(lo, split), (split + 1, hi)]
    return out


@pytest.mark.parametrize("clustered", [False, True])
def test_bottom_up_build_is_the_karras_radix_tree(clustered: bool) -> None:
    """Internal node i splits leaves i | i+1 and covers exactly Karras' ranges."""
    m = _scene()
    v, f = np.asarray(m.vertices), np.asarray(m.faces)
    if clustered:  # many equal Morton codes: ties are split by the leaf index
        v = np.round(v * 4) / 4
    bvh = LBVH(v, f)
    bits = bvh.n.bit_length()
    keys = [(int(c) << bits) | i for i, c in enumerate(bvh.codes)]  # index-augmented
    assert keys == sorted(keys)
    twin = _karras_splits(keys)
    ours = {(int(a), int(b)): i for i, (a, b) in enumerate(zip(bvh.first, bvh.last, strict=True))}
    assert ours == twin


def test_closest_points_match_brute_force_and_trimesh() -> None:
    rng = np.random.default_rng(0)
    m = _scene()
    bvh = LBVH(m.vertices, m.faces)
    p = rng.uniform(m.bounds[0] - 0.3, m.bounds[1] + 0.3, (600, 3))
    cp, d, tid = bvh.closest_points(p)
    brute, all_d = _brute_closest(m.vertices, m.faces, p)
    np.testing.assert_allclose(d, brute, rtol=0, atol=1e-12)
    # The returned triangle is one of the closest, and the point lies on it.
    np.testing.assert_allclose(all_d[np.arange(len(p)), tid], brute, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(cp - p, axis=1), d, atol=1e-12)
    cp2, d2, _ = trimesh.proximity.closest_point(m, p[:300])
    np.testing.assert_allclose(d[:300], d2, atol=1e-9)
    np.testing.assert_allclose(cp[:300], cp2, atol=1e-7)


def test_ray_crossings_match_brute_force_and_containment() -> None:
    rng = np.random.default_rng(0)
    m = _scene()
    bvh = LBVH(m.vertices, m.faces)
    p = rng.uniform(m.bounds[0] - 0.1, m.bounds[1] + 0.1, (800, 3))
    direction = np.array([1.0, 0.0123, 0.0071])
    ours = bvh.ray_crossings(p, direction)
    np.testing.assert_array_equal(ours, _brute_crossings(m.vertices, m.faces, p, direction))
    np.testing.assert_array_equal(ours % 2 == 1, m.contains(p))


def test_equal_centroids_use_the_index_augmented_key() -> None:
    """Many triangles share one centroid (one Morton code): the tree must still be exact."""
    rng = np.random.default_rng(0)
    base = np.array([[0.1, 0, 0], [-0.05, 0.08, 0], [-0.05, -0.08, 0]])
    rots = trimesh.transformations.random_rotation_matrix
    tris = np.stack([base @ rots(rng.random(3))[:3, :3].T for _ in range(300)])
    tris = np.concatenate([tris, tris[:50] + 1.0])  # a second cluster, so the AABB is not tiny
    v, f = tris.reshape(-1, 3), np.arange(len(tris) * 3).reshape(-1, 3)
    bvh = LBVH(v, f)
    p = rng.uniform(-0.3, 1.3, (300, 3))
    _, d, _ = bvh.closest_points(p)
    np.testing.assert_allclose(d, _brute_closest(v, f, p)[0], atol=1e-12)


def test_duplicate_and_degenerate_triangles() -> None:
    rng = np.random.default_rng(0)
    m = _scene()
    v = np.concatenate([m.vertices, [[2.0, 2.0, 2.0], [2.5, 2.0, 2.0], [3.0, 2.0, 2.0]]])
    nv = len(m.vertices)
    dup = m.faces[:5][:, [1, 2, 0]]  # same triangles, rotated vertex order
    sliver = [[nv, nv + 1, nv + 2], [nv, nv, nv]]  # collinear, and a single point
    f = np.concatenate([m.faces, dup, sliver])
    bvh = LBVH(v, f)
    assert bvh.duplicate_count == 5 and bvh.degenerate_count == 2
    p = rng.uniform(-1, 3.5, (300, 3))
    _, d, tid = bvh.closest_points(p)
    np.testing.assert_allclose(d, _brute_closest(v, f, p)[0], atol=1e-12)
    assert tid.max() < len(f) and not np.any(
        np.isin(tid, np.arange(len(m.faces), len(m.faces) + 5))
    )
    # Duplicates would double-count crossings and flip parity: they are dropped.
    q = rng.uniform(m.bounds[0], m.bounds[1], (400, 3))
    np.testing.assert_array_equal(
        bvh.ray_crossings(q, [1.0, 0.0123, 0.0071]) % 2 == 1, m.contains(q)
    )


def test_single_triangle_and_hits_flagged_on_edges() -> None:
    bvh = LBVH([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    cp, d, tid = bvh.closest_points([[0.2, 0.2, 1.0], [2.0, 0.0, 0.0]])
    np.testing.assert_allclose(d, [1.0, 1.0])
    np.testing.assert_allclose(cp, [[0.2, 0.2, 0.0], [1.0, 0.0, 0.0]])
    assert tid.tolist() == [0, 0]
    q, t, degenerate = bvh.ray_hits([[0.5, 0.5, -1.0], [0.2, 0.2, -1.0]], [0.0, 0.0, 1.0])
    assert q.tolist() == [0, 1] and degenerate.tolist() == [True, False]
    np.testing.assert_allclose(t, [1.0, 1.0])


@pytest.mark.parametrize(
    ("vertices", "faces", "error", "match"),
    [
        (np.zeros((0, 3)), np.zeros((0, 3), dtype=int), MeshError, "empty"),
        ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.zeros((0, 3), dtype=int), MeshError, "empty"),
        ([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], InputError, "NaN"),
        ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]], InputError, "out of range"),
        ([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], InputError, "vertices must have shape"),
        ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0.0, 1.0, 2.0]], InputError, "integer"),
    ],
)
def test_bad_meshes_are_rejected(vertices, faces, error, match) -> None:
    with pytest.raises(error, match=match):
        LBVH(vertices, faces)


def test_bad_query_points() -> None:
    bvh = LBVH([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(InputError, match="points"):
        bvh.closest_points([[0, 0, np.inf]])
    with pytest.raises(InputError, match="points"):
        bvh.closest_points([0, 0, 0])
    with pytest.raises(InputError, match="directions"):
        bvh.ray_crossings([[0, 0, 0]], [0, 0, 0])


def _edge_and_vertex_rays(
    rng: np.random.Generator, v: np.ndarray, edges: np.ndarray, n: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Return (origins, directions, points): rays with origin + 1 * direction = point, the
    points on the given edges (a random fraction of them at the edges' end vertices)."""
    e = edges[rng.integers(0, len(edges), n)]
    s = rng.uniform(0, 1, n)
    s[: n // 5] = rng.integers(0, 2, n // 5)  # a fifth through a vertex
    p = v[e[:, 0]] + s[:, None] * (v[e[:, 1]] - v[e[:, 0]])
    d = rng.normal(size=(n, 3))
    return p - d, d, p


def test_rays_through_shared_edges_and_vertices_count_once_or_are_flagged() -> None:
    # A ray through an edge shared by two triangles may round to just outside both
    # (barycentrics ~ -1e-16): it must then still be flagged degenerate, never lost.
    rng = np.random.default_rng(3)
    lost = 0
    for _ in range(200):  # random (generally non-planar) quads split along 0-2
        v = rng.normal(size=(4, 3))
        bvh = LBVH(v, [[0, 1, 2], [0, 2, 3]])
        o, d, _ = _edge_and_vertex_rays(rng, v, np.array([[0, 2]]), 100)
        for full_line in (False, True):
            q, t, degen = bvh.ray_hits(o, d, full_line=full_line)
            at_p = np.abs(t - 1.0) < 1e-6  # the hits at the shared edge
            regular = np.bincount(q[at_p & ~degen], minlength=len(o))
            flagged = np.bincount(q[at_p & degen], minlength=len(o)) > 0
            assert np.all((regular == 1) | flagged) and not np.any(flagged & (regular > 0))
            lost += int(np.sum((regular == 0) & ~flagged))
    assert lost == 0
    # A closed mesh: rays from outside through edges and vertices. Wherever nothing on the
    # whole line is flagged, the regular crossings are even (in and out), and at the point
    # itself exactly one is counted.
    m = trimesh.creation.icosphere(subdivisions=2, radius=0.5)
    v, f = np.asarray(m.vertices), np.asarray(m.faces)
    bvh = LBVH(v, f)
    o, d, p = _edge_and_vertex_rays(rng, v, np.asarray(m.edges_unique), 3000)
    far = p - 2.0 * d / np.linalg.norm(d, axis=1, keepdims=True)  # outside the sphere
    q, t, degen = bvh.ray_hits(far, d, full_line=True)
    at_p = np.abs(t - 2.0 / np.linalg.norm(d[q], axis=1)) < 1e-6
    regular = np.bincount(q[~degen], minlength=len(o))
    any_flag = np.bincount(q[degen], minlength=len(o)) > 0
    at_regular = np.bincount(q[at_p & ~degen], minlength=len(o))
    at_flag = np.bincount(q[at_p & degen], minlength=len(o)) > 0
    assert np.all((at_regular == 1) | at_flag) and not np.any(at_flag & (at_regular > 0))
    assert np.all(regular[~any_flag] % 2 == 0)
    assert at_flag.sum() > 500  # the rays through vertices and edges are flagged, mostly
    # ray_crossings still counts each closed triangle the ray touches once.
    mq = rng.uniform(-0.6, 0.6, (500, 3))
    direction = np.array([1.0, 0.0123, 0.0071])
    np.testing.assert_array_equal(
        bvh.ray_crossings(mq, direction), _brute_crossings(v, f, mq, direction)
    )
