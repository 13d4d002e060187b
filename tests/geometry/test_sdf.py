"""Sparse SDF against exact signed distances (LBVH distance, trimesh containment for the sign)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError, MeshError
from workbench.geometry.lbvh import LBVH
from workbench.geometry.sdf import SparseSDF, triangle_box_overlap


def _scene() -> trimesh.Trimesh:
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=0.5)
    box = trimesh.creation.box((0.4, 0.8, 0.3))  # faces on round coordinates: grazing rays
    box.apply_translation((1.0, 0.1, 0.05))
    return trimesh.util.concatenate([sphere, box])


def _exact(m: trimesh.Trimesh, p: np.ndarray) -> np.ndarray:
    d = LBVH(m.vertices, m.faces).closest_points(p)[1]
    return np.where(m.contains(p), -d, d)


def _in_band(sdf: SparseSDF, p: np.ndarray) -> np.ndarray:
    ci = np.floor((p - sdf.origin) / sdf.cell_size).astype(int)
    ok = np.all((ci >= 0) & (ci < sdf.dims), axis=1)
    band = np.zeros(len(p), dtype=bool)
    band[ok] = sdf.block_index[tuple(ci[ok].T)] >= 0
    return band


@pytest.fixture(scope="module")
def scene_sdf() -> tuple[trimesh.Trimesh, SparseSDF]:
    m = _scene()
    return m, SparseSDF.from_mesh(m, resolution=16, subdivisions=4)


def test_band_error_within_stated_bound(scene_sdf) -> None:
    m, sdf = scene_sdf
    rng = np.random.default_rng(0)
    p = rng.uniform(m.bounds[0] - 0.2, m.bounds[1] + 0.2, (4000, 3))
    band = _in_band(sdf, p)
    q, ex = sdf.query(p[band]), _exact(m, p[band])
    near = np.abs(ex) <= sdf.band
    assert sdf.signed and near.sum() > 800
    assert np.abs(q[near] - ex[near]).max() <= sdf.max_error
    # Beyond the band, inside marked cells: truncated, never more than max_error too far.
    assert np.all(np.abs(q[~near]) <= np.abs(ex[~near]) + sdf.max_error)
    assert np.all(np.sign(q[~near]) == np.sign(ex[~near]))
    assert sdf.max_error == pytest.approx(np.sqrt(3) / 2 * sdf.cell_size / 4, rel=1e-4)
    # Exactly at fine corners the value is the exact distance (up to float32).
    corner = (
        sdf.origin
        + (np.floor((p[band][:200] - sdf.origin) / sdf.fine_cell_size)) * sdf.fine_cell_size
    )
    corner += 1e-9  # stay in the same coarse cell despite rounding (the field is 1-Lipschitz)
    ex = _exact(m, corner)
    trunc = sdf.band + sdf.max_error
    np.testing.assert_allclose(sdf.query(corner), np.clip(ex, -trunc, trunc), atol=1e-6)


def test_outside_band_is_a_lower_bound_with_the_right_sign(scene_sdf) -> None:
    m, sdf = scene_sdf
    rng = np.random.default_rng(1)
    p = rng.uniform(m.bounds[0] - 1.0, m.bounds[1] + 1.0, (4000, 3))
    p = np.concatenate([p, rng.uniform(-0.2, 0.2, (300, 3))])  # deep inside the sphere
    far = ~_in_band(sdf, p)
    q, ex = sdf.query(p[far]), _exact(m, p[far])
    assert far.sum() > 2000 and np.sum(ex < 0) > 100
    assert np.all(np.sign(q) == np.sign(ex))
    assert np.all(np.abs(q) <= np.abs(ex) + 1e-12)
    assert np.all(np.abs(q) >= sdf.band * (1 - 1e-6))  # at least the band width


def test_against_trimesh_signed_distance(scene_sdf) -> None:
    m, sdf = scene_sdf
    rng = np.random.default_rng(2)
    p = rng.uniform(m.bounds[0], m.bounds[1], (300, 3))
    band = _in_band(sdf, p)
    ref = -trimesh.proximity.signed_distance(m, p[band])  # trimesh: positive inside
    near = np.abs(ref) <= sdf.band
    assert near.sum() > 50
    assert np.abs(sdf.query(p[band])[near] - ref[near]).max() <= sdf.max_error


def test_memory_is_sparse_and_progress_reported(tmp_path) -> None:
    m = _scene()
    calls: list[tuple[float, str]] = []
    sdf = SparseSDF.from_mesh(
        m,
        resolution=24,
        subdivisions=4,
        band=0.0,
        cache_dir=tmp_path,
        progress=lambda f, s: calls.append((f, s)),
    )
    dense = (sdf.dims * sdf.subdivisions + 1).prod() * 4
    assert sdf.memory_bytes < dense / 2
    fr = [c[0] for c in calls]
    assert fr[0] == 0.0 and fr[-1] == 1.0 and fr == sorted(fr)
    # Second build comes from the cache file, with identical values.
    calls.clear()
    again = SparseSDF.from_mesh(
        m,
        resolution=24,
        subdivisions=4,
        band=0.0,
        cache_dir=tmp_path,
        progress=lambda f, s: calls.append((f, s)),
    )
    assert len(calls) == 1 and "cache" in calls[0][1]
    np.testing.assert_array_equal(again.values, sdf.values)
    # Other parameters: another cache entry.
    SparseSDF.from_mesh(m, resolution=22, subdivisions=4, band=0.0, cache_dir=tmp_path)
    entries = sorted(tmp_path.glob("sdf-*.npz"))
    assert len(entries) == 2
    # A truncated entry (a crash of another writer, a full disk) is rebuilt, not an error.
    for e in entries:
        e.write_bytes(e.read_bytes()[:200])
    calls.clear()
    rebuilt = SparseSDF.from_mesh(
        m,
        resolution=24,
        subdivisions=4,
        band=0.0,
        cache_dir=tmp_path,
        progress=lambda f, s: calls.append((f, s)),
    )
    assert len(calls) > 1 and not any("cache" in c[1] for c in calls)
    np.testing.assert_array_equal(rebuilt.values, sdf.values)
    assert len(list(tmp_path.glob("sdf-*.npz"))) == 2  # overwritten in place, no leftovers
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(e.name for e in entries)


def test_open_mesh_warns_and_is_unsigned() -> None:
    m = trimesh.creation.icosphere(subdivisions=3, radius=0.5)
    m.update_faces(m.face_normals[:, 2] < 0.9)  # cut a hole at the top
    with pytest.warns(UserWarning, match="not watertight"):
        sdf = SparseSDF.from_mesh(m, resolution=12)
    assert not sdf.signed
    rng = np.random.default_rng(0)
    p = rng.uniform(-0.6, 0.6, (2000, 3))
    q = sdf.query(p)
    assert np.all(q >= 0)
    d = LBVH(m.vertices, m.faces).closest_points(p)[1]
    band = _in_band(sdf, p) & (d <= sdf.band)
    assert band.sum() > 200
    assert np.abs(q[band] - d[band]).max() <= sdf.max_error
    assert np.all(q[~band] <= d[~band] + sdf.max_error)


def test_grid_aligned_box_signs() -> None:
    """Box faces lie on fine-grid lines, so axis rays graze edges: signs must still be right."""
    m = trimesh.creation.box((1.0, 1.0, 1.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sdf = SparseSDF.from_mesh(m, cell_size=0.125, subdivisions=2, band=0.125)
    rng = np.random.default_rng(0)
    p = rng.uniform(-0.8, 0.8, (3000, 3))
    q, ex = sdf.query(p), _exact(m, p)
    near = _in_band(sdf, p) & (np.abs(ex) <= sdf.band)
    assert near.sum() > 300
    assert np.abs(q[near] - ex[near]).max() <= sdf.max_error
    assert np.all(np.sign(q[np.abs(ex) > sdf.max_error]) == np.sign(ex[np.abs(ex) > sdf.max_error]))


@pytest.mark.parametrize("delta", [1e-13, -1e-13, 1e-11])
def test_sign_of_corners_a_hair_inside_an_oblique_face(delta: float) -> None:
    """Grid corners 7e-14 inside (or outside) a face at 45 degrees to both ray axes.

    Both axis rays then hit the face a hair from the corner, so a parity that orders hits
    and corners with too little resolution gets both wrong at once (the old single float
    key per row did, for ~90 % of these corners) and no fallback is asked. Twin: the
    prism's exact inside test (0 < x, y, z < 1 and x + y < c).
    """
    c = 1.5 + delta
    poly = np.array([[0, 0], [1, 0], [1, c - 1], [c - 1, 1], [0, 1]])
    m = trimesh.convex.convex_hull(
        np.concatenate([np.c_[poly, np.zeros(5)], np.c_[poly, np.ones(5)]])
    )
    sdf = SparseSDF.from_mesh(m, cell_size=1 / 16, subdivisions=4, band=1 / 16)
    assert sdf.signed and np.all(sdf.origin == -0.125) and sdf.fine_cell_size == 1 / 64
    i = np.arange(42, 71)  # x = (i - 8) / 64 in (0.5, 1), y = 1.5 - x: on x + y = 1.5
    k = np.arange(9, 72)  # z in (0, 1)
    ii, kk = np.meshgrid(i, k, indexing="ij")
    p = np.stack([(ii - 8) / 64, (112 - ii - 8) / 64, (kk - 8) / 64], axis=-1).reshape(-1, 3)
    assert np.all(p[:, 0] + p[:, 1] == 1.5)
    inside = np.all((p > 0) & (p < 1), axis=1) & (p[:, 0] + p[:, 1] < c)
    assert inside.all() == (delta > 0) and inside.any() == (delta > 0)
    q = sdf.query(p)
    assert np.all((q < 0) == inside)
    assert np.abs(q).max() <= abs(delta)  # and the value is the (tiny) exact distance


def test_triangle_box_overlap_against_sampled_distance() -> None:
    rng = np.random.default_rng(0)
    n = 3000
    v = rng.uniform(-1, 1, (n, 3, 3))
    centre, half = rng.uniform(-1, 1, (n, 3)), 0.2
    ok = triangle_box_overlap(v[:, 0], v[:, 1], v[:, 2], centre, half)
    # Twin: dense samples of the triangle inside the cube means overlap.
    u, w = np.meshgrid(np.linspace(0, 1, 40), np.linspace(0, 1, 40))
    keep = u + w <= 1
    u, w = u[keep], w[keep]
    pts = (
        v[:, None, 0]
        + u[None, :, None] * (v[:, None, 1] - v[:, None, 0])
        + w[None, :, None] * (v[:, None, 2] - v[:, None, 0])
    )
    sampled = np.any(np.all(np.abs(pts - centre[:, None]) <= half, axis=2), axis=1)
    assert np.all(ok[sampled])  # never misses an overlap
    assert np.mean(ok & ~sampled) < 0.02  # and rarely claims one the samples did not find


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"resolution": 1}, InputError, "resolution"),
        ({"cell_size": -1.0}, InputError, "cell_size"),
        ({"band": -0.1}, InputError, "band"),
        ({"subdivisions": 0}, InputError, "subdivisions"),
    ],
)
def test_bad_parameters(kwargs, error, match) -> None:
    with pytest.raises(error, match=match):
        SparseSDF.from_mesh(trimesh.creation.box(), **kwargs)


def test_bad_meshes() -> None:
    with pytest.raises(MeshError, match="empty"):
        SparseSDF.from_mesh((np.zeros((0, 3)), np.zeros((0, 3), dtype=int)))
    with pytest.raises(InputError, match="NaN"):
        SparseSDF.from_mesh(([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]))
    with pytest.raises(InputError, match="trimesh"):
        SparseSDF.from_mesh("box.stl")


def _work_cell() -> trimesh.Trimesh:
    """A cell like projects/mz07_cell.json: a large floor, a table, boxes and a cylinder."""
    parts = []
    for size, centre in (
        ((2.4, 2.4, 0.02), (0.0, 0.0, -0.01)),
        ((0.5, 0.8, 0.4), (0.6, 0.0, 0.2)),
        ((0.2, 0.3, 0.25), (0.55, 0.1, 0.525)),
    ):
        b = trimesh.creation.box(size)
        b.apply_translation(centre)
        parts.append(b)
    pillar = trimesh.creation.cylinder(radius=0.08, height=1.6, sections=32)
    pillar.apply_translation((-0.7, 0.6, 0.8))
    tilted = trimesh.creation.box((0.9, 0.05, 0.6))  # a large oblique face
    tilted.apply_transform(trimesh.transformations.euler_matrix(0.3, 0.5, 0.7))
    tilted.apply_translation((-0.3, -0.6, 0.6))
    return trimesh.util.concatenate([*parts, pillar, tilted])


def _marked_brute(tri: np.ndarray, sdf: SparseSDF) -> np.ndarray:
    """Slow twin of the coarse marking: every cell of each triangle's grown box, SAT-tested."""
    h, r, origin, dims = sdf.cell_size, sdf.band, sdf.origin, sdf.dims
    marked = np.zeros(dims, dtype=bool)
    for t in tri:
        lo = np.clip(np.floor((t.min(axis=0) - r - origin) / h).astype(int), 0, dims - 1)
        hi = np.clip(np.floor((t.max(axis=0) + r - origin) / h).astype(int), 0, dims - 1)
        axes = [np.arange(lo[k], hi[k] + 1) for k in range(3)]
        cells = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
        if len(cells) > 8:  # small boxes are marked whole (the field's documented rule)
            v = np.broadcast_to(t, (len(cells), 3, 3))
            ok = triangle_box_overlap(
                v[:, 0], v[:, 1], v[:, 2], origin + (cells + 0.5) * h, h / 2 + r
            )
            cells = cells[ok]
        marked[tuple(cells.T)] = True
    return marked


def _random_mesh(seed: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    big = rng.uniform(-1, 1, (20, 3, 3))  # large triangles in all orientations
    small = rng.uniform(-1, 1, (300, 1, 3)) + rng.normal(0, 0.05, (300, 3, 3))
    tri = np.concatenate([big, small])
    tri[:3, :, 2] = 0.25  # axis-aligned planes, on grid-ish coordinates
    return tri.reshape(-1, 3), np.arange(len(tri) * 3).reshape(-1, 3)


@pytest.mark.parametrize("case", ["cell", "random0", "random1"])
def test_marked_cells_equal_brute_force_separating_axis_test(case: str) -> None:
    if case == "cell":
        m = _work_cell()
        v, f = np.asarray(m.vertices), np.asarray(m.faces)
        sdf = SparseSDF.from_mesh((v, f), resolution=24, subdivisions=2, band=0.14)
    else:
        v, f = _random_mesh(int(case[-1]))
        with pytest.warns(UserWarning, match="not watertight"):
            sdf = SparseSDF.from_mesh((v, f), resolution=20, subdivisions=2, band=0.09)
    brute = _marked_brute(v[f], sdf)
    assert brute.sum() > 500
    np.testing.assert_array_equal(sdf.block_index >= 0, brute)


@pytest.mark.parametrize("band", [0.0, 0.14])
def test_every_corner_value_is_the_truncated_exact_distance(band: float) -> None:
    """Twin: the LBVH's exact distance at every stored corner, truncated at W (float32).

    Magnitudes only: the sign is the ray-parity pass's (tested above), untouched here.
    """
    m = _work_cell()
    sdf = SparseSDF.from_mesh(m, resolution=24, subdivisions=3, band=band)
    s = sdf.subdivisions
    blocks = np.argwhere(sdf.block_index >= 0)
    order = sdf.block_index[tuple(blocks.T)]
    e = np.arange(s + 1)
    offs = np.stack(np.meshgrid(e, e, e, indexing="ij"), axis=-1).reshape(-1, 3)
    corners = sdf.origin + (blocks[:, None] * s + offs[None]).reshape(-1, 3) * sdf.fine_cell_size
    values = sdf.values[order].reshape(-1).astype(float)
    exact = LBVH(m.vertices, m.faces).closest_points(corners)[1]
    trunc = sdf.band + np.sqrt(3) / 2 * sdf.fine_cell_size
    assert len(corners) > 50_000 and np.sum(exact < trunc) > 20_000
    np.testing.assert_allclose(np.abs(values), np.minimum(exact, trunc), rtol=0, atol=1e-7)


def _query_twin(sdf: SparseSDF, p: np.ndarray) -> np.ndarray:
    """Slow twin of `query`: per-point cell lookups by 3-D indexing, the same arithmetic."""
    g = (p - sdf.origin) / sdf.cell_size
    ci = np.floor(g).astype(np.int64)
    lo, hi = sdf.mesh_bounds
    out = np.linalg.norm(np.maximum(np.maximum(lo - p, p - hi), 0.0), axis=1)
    s = sdf.subdivisions
    for n in range(len(p)):
        c = ci[n]
        if np.any(c < 0) or np.any(c >= sdf.dims):
            continue
        b = sdf.block_index[c[0], c[1], c[2]]
        if b < 0:
            out[n] = sdf.far[c[0], c[1], c[2]]
            continue
        local = (g[n] - c) * s
        fi = np.clip(np.floor(local).astype(np.int64), 0, s - 1)
        t = local - fi
        acc = 0.0
        for dx in (0, 1):
            for dy in (0, 1):
                for dz in (0, 1):
                    w = (t[0] if dx else 1.0 - t[0]) * (t[1] if dy else 1.0 - t[1])
                    w *= t[2] if dz else 1.0 - t[2]
                    acc += w * float(sdf.values[b, fi[0] + dx, fi[1] + dy, fi[2] + dz])
        out[n] = acc
    return out


def test_query_equals_its_per_point_twin(scene_sdf) -> None:
    m, sdf = scene_sdf
    rng = np.random.default_rng(5)
    lo, hi = m.bounds
    fine = sdf.fine_cell_size
    p = np.concatenate(
        [
            rng.uniform(lo, hi, (1500, 3)),  # inside the mesh box: band and far cells
            m.sample(1000) + rng.normal(0, 0.02, (1000, 3)),  # in the band
            rng.uniform(lo - 0.3, hi + 0.3, (1000, 3)),  # around, some outside the grid
            rng.uniform(lo - 5.0, hi + 5.0, (500, 3)),  # mostly outside the grid
            np.round(rng.uniform(lo, hi, (500, 3)) / fine) * fine,  # on fine corners
            sdf.origin + rng.integers(-1, sdf.dims.max() + 1, (500, 3)) * sdf.cell_size,  # on faces
        ]
    )
    band = _in_band(sdf, p)
    assert band.sum() > 1000 and (~band).sum() > 1000
    np.testing.assert_allclose(sdf.query(p), _query_twin(sdf, p), rtol=0, atol=1e-12)
