"""PSO enveloping spheres: exact containment checked by brute force and dense sampling."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError, MeshError
from workbench.geometry.spheres import (
    SphereSet,
    _contain_triangles,
    _holds,
    _tighten,
    fit_spheres,
)
from workbench.geometry.subdivide import split_long_triangles


def _link() -> trimesh.Trimesh:
    """A UR-like link: a long cylinder with a fatter cylinder (the joint housing) at one end."""
    arm = trimesh.creation.cylinder(radius=0.04, height=0.4, sections=20)
    joint = trimesh.creation.cylinder(radius=0.06, height=0.12, sections=20)
    joint.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0]))
    joint.apply_translation((0, 0, 0.2))
    return trimesh.util.concatenate([arm, joint])


@pytest.fixture(scope="module")
def fitted() -> tuple[trimesh.Trimesh, SphereSet]:
    m = _link()
    return m, fit_spheres(m, 6, seed=0)


def test_every_vertex_and_dense_surface_sample_is_inside(fitted) -> None:
    m, s = fitted
    assert s.centres.shape[1] == 3 and s.radii.shape == (len(s.centres),) and len(s.centres) <= 6
    assert s.contains(m.vertices).all()
    pts, _ = trimesh.sample.sample_surface(m, 50_000, seed=1)
    assert s.contains(pts).all()
    assert s.coverage == 1.0


def test_every_triangle_is_inside_one_sphere(fitted) -> None:
    """A ball is convex: a triangle is inside if its three vertices are (brute force here)."""
    m, s = fitted
    tri = m.vertices[m.faces]
    pieces = split_long_triangles(tri, 0.03)

    # Splitting keeps the surface: same total area, every piece inside its parent's plane.
    def area(t: np.ndarray) -> float:
        return float(
            0.5 * np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1).sum()
        )

    assert area(pieces) == pytest.approx(area(tri), rel=1e-12)
    assert np.linalg.norm(pieces - np.roll(pieces, 1, axis=1), axis=2).max() <= 0.03
    radii = _contain_triangles(pieces, s.centres, 0.4)
    far = np.linalg.norm(pieces[:, :, None, :] - s.centres[None, None], axis=3).max(
        axis=1
    )  # (T, k)
    assert np.all(np.any(far <= radii[None], axis=1))
    # And the fitted set itself: dense barycentric samples of every original triangle.
    u, w = np.meshgrid(np.linspace(0, 1, 12), np.linspace(0, 1, 12))
    keep = u + w <= 1
    bary = np.stack([1 - u[keep] - w[keep], u[keep], w[keep]], axis=1)
    assert s.contains(np.einsum("sb,tbd->tsd", bary, tri).reshape(-1, 3)).all()


def test_more_spheres_fit_tighter_than_one() -> None:
    m = _link()
    one, six = fit_spheres(m, 1), fit_spheres(m, 6)
    assert np.isfinite(one.volume_overshoot) and six.volume_overshoot < 0.5 * one.volume_overshoot
    # Single-sphere twin: every vertex inside, radius at least half the largest vertex spread.
    spread = np.max(np.linalg.norm(m.vertices[:, None] - m.vertices[None], axis=2))
    assert one.radii[0] >= spread / 2 - 1e-12
    # Monte Carlo union volume against the closed form of disjoint spheres' upper bound.
    assert six.union_volume <= np.sum(4 / 3 * np.pi * six.radii**3) + 1e-12


def test_seeded_fit_is_reproducible() -> None:
    m = _link()
    a, b = fit_spheres(m, 4, seed=3), fit_spheres(m, 4, seed=3)
    np.testing.assert_array_equal(a.centres, b.centres)
    np.testing.assert_array_equal(a.radii, b.radii)


def test_open_mesh_reports_nan_overshoot_but_still_contains() -> None:
    m = trimesh.creation.icosphere(subdivisions=2, radius=0.1)
    m.update_faces(m.face_normals[:, 2] < 0.9)
    s = fit_spheres(m, 3)
    assert np.isnan(s.volume_overshoot)
    assert s.contains(trimesh.sample.sample_surface(m, 5000, seed=0)[0]).all()


@pytest.mark.parametrize("count", [0, -2, 1.5])
def test_bad_sphere_count(count) -> None:
    with pytest.raises(InputError, match="count"):
        fit_spheres(_link(), count)


def test_bad_meshes() -> None:
    with pytest.raises(MeshError, match="empty"):
        fit_spheres((np.zeros((0, 3)), np.zeros((0, 3), dtype=int)), 2)
    with pytest.raises(InputError, match="NaN"):
        fit_spheres(([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]), 2)


def test_tightening_keeps_every_piece_in_one_sphere_and_ends_below_a_plain_assignment() -> None:
    """Twins by brute force over pieces x spheres (direct differences).

    Volume: against the plain cover at the start centres computed here independently (each
    piece to the sphere nearest by its farthest vertex, each radius its farthest assigned
    vertex); tightening must end strictly below it. Tightness: every radius is attained by
    a piece (no slack beyond the farthest vertex).
    """
    m = _link()
    pieces = split_long_triangles(m.vertices[m.faces], 0.03)
    rng = np.random.default_rng(4)
    start = pieces.reshape(-1, 3)[rng.choice(len(pieces) * 3, 6, replace=False)]
    far0 = np.linalg.norm(pieces[:, :, None, :] - start[None, None], axis=3).max(axis=1)
    owner = np.argmin(far0, axis=1)
    plain = np.array(
        [far0[owner == j, j].max() if np.any(owner == j) else 0.0 for j in range(len(start))]
    )
    centres, radii = _tighten(pieces, start)
    assert np.sum(radii**3) < 0.9 * np.sum(plain**3)
    far = np.linalg.norm(pieces[:, :, None, :] - centres[None, None], axis=3).max(axis=1)
    assert np.all(np.any(far <= radii[None] * (1 + 1e-12), axis=1))
    used = radii > 0
    assert np.all(np.min(np.abs(far[:, used] - radii[None, used]), axis=0) <= 1e-12)


def _contains_exactly(s: SphereSet, pts: np.ndarray) -> bool:
    """Twin of `SphereSet.contains`: direct differences and norms, point by point."""
    d = np.linalg.norm(pts[:, None, :] - s.centres[None], axis=2)
    return bool(np.all(np.any(d <= s.radii[None], axis=1)))


def _dense_samples(tri: np.ndarray, n: int = 12) -> np.ndarray:
    u, w = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    keep = u + w <= 1
    bary = np.stack([1 - u[keep] - w[keep], u[keep], w[keep]], axis=1)
    return np.einsum("sb,tbd->tsd", bary, tri).reshape(-1, 3)


def _pieces_held(pieces: np.ndarray, centres: np.ndarray, radii: np.ndarray) -> bool:
    """Twin of the fit's guarantee: each piece's three vertices in one sphere, direct norms."""
    far = np.linalg.norm(pieces[:, :, None, :] - centres[None, None], axis=3).max(axis=1)
    return bool(np.all(np.any(far <= radii[None], axis=1)))


@pytest.mark.parametrize("offset", [0.0, 1.0, 10.0, 100.0, 1000.0])
def test_containment_is_exact_far_from_the_origin(offset: float, tmp_path) -> None:
    """A 0.1 m part moved out to 1000 m: every triangle piece in one sphere, every sample in.

    The expanded |p|^2 - 2 p.c + |c|^2 underestimated the needed radius by ~1e-10 m at
    100 m against a ~1e-13 m margin; the twins take direct differences.
    """
    m = _link()
    m.apply_scale(0.25)
    m.apply_translation(offset * np.array([1.0, -0.6, 0.8]))
    tri = np.asarray(m.vertices)[m.faces]
    # The containment step itself, at given centres (the mesh's own vertices).
    pieces = split_long_triangles(tri, 0.0075)
    rng = np.random.default_rng(2)
    centres = pieces.reshape(-1, 3)[rng.choice(len(pieces) * 3, 8, replace=False)]
    assert _pieces_held(pieces, centres, _contain_triangles(pieces, centres, 0.1))
    # The whole fit: its own pieces (split length from its cache entry), vertices, samples.
    s = fit_spheres(m, 4, seed=0, iterations=20, cache_dir=tmp_path)
    (entry,) = list(tmp_path.glob("spheres-*.npz"))
    with np.load(entry) as d:
        split = float(d["split"])
    assert _pieces_held(split_long_triangles(tri, split, limit=200_000), s.centres, s.radii)
    assert _contains_exactly(s, np.asarray(m.vertices))
    assert _contains_exactly(s, _dense_samples(tri))
    # The margin stays negligible against the part (0.1 m): far parts fit as tightly.
    assert s.radii.max() < 0.1


def test_coarse_to_fine_check_agrees_with_every_piece_brute_force() -> None:
    """`_holds` (the check on load) against the fit's pieces, all checked by direct norms."""
    m = _link()
    tri = np.asarray(m.vertices)[m.faces]
    s = fit_spheres(m, 5, seed=2, iterations=10)
    split = 0.02
    pieces = split_long_triangles(tri, split)
    radii = _contain_triangles(pieces, s.centres, 0.4)
    assert _holds(tri, s.centres, radii, split) and _pieces_held(pieces, s.centres, radii)
    rng = np.random.default_rng(5)
    seen = set()
    for _ in range(40):
        r = radii * rng.uniform(0.97, 1.0, len(radii)) ** rng.integers(0, 2, len(radii))
        want = _pieces_held(pieces, s.centres, r)
        assert _holds(tri, s.centres, r, split) == want
        seen.add(want)
    assert seen == {True, False}  # both outcomes exercised


def _entry_data(entry) -> dict[str, np.ndarray]:
    with np.load(entry) as d:
        return {k: d[k] for k in d.files}


def test_cache_returns_the_same_fit_and_is_keyed_by_parameters(tmp_path) -> None:
    m = _link()
    fresh = fit_spheres(m, 4, seed=1, iterations=10)
    first = fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path)
    (entry,) = list(tmp_path.glob("spheres-*.npz"))
    again = fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path)
    for s in (first, again):
        np.testing.assert_array_equal(s.centres, fresh.centres)
        np.testing.assert_array_equal(s.radii, fresh.radii)
        assert s.volume_overshoot == fresh.volume_overshoot
    # The second call read the file: a marked entry that still holds the mesh (doubled
    # radii) comes back as stored.
    data = _entry_data(entry)
    data["radii"] = data["radii"] * 2
    np.savez(entry, **data)
    np.testing.assert_array_equal(
        fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path).radii, fresh.radii * 2
    )
    fit_spheres(m, 3, seed=1, iterations=10, cache_dir=tmp_path)  # other parameters: own entry
    assert len(list(tmp_path.glob("spheres-*.npz"))) == 2


def test_cached_spheres_that_do_not_hold_the_mesh_are_refitted(tmp_path) -> None:
    """Halved radii on disk: detected by the containment check, refitted and overwritten."""
    m = _link()
    fresh = fit_spheres(m, 4, seed=1, iterations=10)
    fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path)
    (entry,) = list(tmp_path.glob("spheres-*.npz"))
    data = _entry_data(entry)
    data["radii"] = data["radii"] / 2
    np.savez(entry, **data)
    got = fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path)
    np.testing.assert_array_equal(got.radii, fresh.radii)
    np.testing.assert_array_equal(got.centres, fresh.centres)
    assert _contains_exactly(got, np.asarray(m.vertices))
    assert _contains_exactly(got, _dense_samples(np.asarray(m.vertices)[m.faces]))
    np.testing.assert_array_equal(_entry_data(entry)["radii"], fresh.radii)  # overwritten
    # A single sphere shrunk by 1e-9 m is caught too (the check is exact, not sampled).
    data = _entry_data(entry)
    data["radii"][int(np.argmax(data["radii"]))] -= 1e-9
    np.savez(entry, **data)
    np.testing.assert_array_equal(
        fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path).radii, fresh.radii
    )


def test_truncated_cache_entry_is_refitted_not_an_error(tmp_path) -> None:
    """A truncated entry (a crash of another writer, a full disk) is rebuilt in place."""
    m = _link()
    fresh = fit_spheres(m, 4, seed=1, iterations=10)
    fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path)
    (entry,) = list(tmp_path.glob("spheres-*.npz"))
    entry.write_bytes(entry.read_bytes()[:200])
    got = fit_spheres(m, 4, seed=1, iterations=10, cache_dir=tmp_path)  # old: BadZipFile
    np.testing.assert_array_equal(got.radii, fresh.radii)
    np.testing.assert_array_equal(_entry_data(entry)["radii"], fresh.radii)
    assert [p.name for p in tmp_path.iterdir()] == [entry.name]  # no temporary files left
