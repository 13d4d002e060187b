"""Enveloping spheres of a link mesh, fitted by particle swarm optimisation (seed 001, step 3).

A particle is a set of k sphere centres. It is decoded to radii by assigning every cover
point (vertices and area-weighted surface samples) to its nearest centre; each radius is the
farthest assigned point, so every particle covers every point (the constraint holds by
construction) and the objective is the total sphere volume (small overshoot).

After the swarm, containment is made exact, not sampled: every triangle is assigned to a
sphere that contains its three vertices (a ball is convex, so it then contains the whole
triangle) and radii are inflated to the farthest assigned vertex, distances taken as direct
differences (exact far from the origin too) and rounded outwards. The union of spheres thus
contains the whole surface. It need not contain a closed mesh's interior far from the
surface (an obstacle entirely inside a link, never touching its surface, is not caught).
"""

from __future__ import annotations

import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError, MeshError
from workbench.geometry.lbvh import check_mesh
from workbench.geometry.npz_cache import cache_path, load_entry, store_entry
from workbench.geometry.sdf import is_watertight
from workbench.geometry.subdivide import split_long_triangles

FloatArray = NDArray[np.float64]
# Bump when the fit or the entry changes: entries of older versions are not reused.
# 3: npz_cache key (shapes and dtypes), split length stored for the check on load.
_FORMAT = 3


@dataclass(frozen=True)
class SphereSet:
    """Spheres enveloping a mesh: centres (k,3) [m], radii (k,) [m] and fit figures.

    coverage: fraction of the check points (vertices and dense surface samples) inside the
    union (1.0 by construction). volume_overshoot: (union volume - mesh volume) / mesh
    volume, Monte Carlo estimate; NaN for an open mesh.
    """

    centres: FloatArray
    radii: FloatArray
    coverage: float
    union_volume: float
    mesh_volume: float
    volume_overshoot: float

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Return whether each point (M,3) [m] lies in at least one sphere."""
        p = np.asarray(points, dtype=float)
        d2 = np.sum((p[:, None, :] - self.centres[None]) ** 2, axis=2)
        return np.any(d2 <= self.radii[None] ** 2, axis=1)


def _surface_samples(tri: FloatArray, n: int, rng: np.random.Generator) -> FloatArray:
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    prob = area / area.sum() if area.sum() > 0 else np.full(len(tri), 1.0 / len(tri))
    t = rng.choice(len(tri), size=n, p=prob)
    u, v = rng.random(n), rng.random(n)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    a = tri[t, 0]
    return a + u[:, None] * (tri[t, 1] - a) + v[:, None] * (tri[t, 2] - a)


def _decode(centres: FloatArray, pts: FloatArray) -> FloatArray:
    """Return radii (P, k) covering `pts` (S,3) by nearest-centre assignment, centres (P,k,3)."""
    n_p, k = centres.shape[:2]
    d2 = (
        np.einsum("pkd,pkd->pk", centres, centres)[:, :, None]
        - 2 * centres @ pts.T
        + np.sum(pts**2, axis=1)[None, None]
    )
    nearest = np.argmin(d2, axis=1)  # (P, S)
    dmin = np.take_along_axis(d2, nearest[:, None, :], axis=1)[:, 0]
    r2 = np.zeros(n_p * k)
    np.maximum.at(
        r2, (np.arange(n_p)[:, None] * k + nearest).ravel(), np.maximum(dmin, 0.0).ravel()
    )
    return np.sqrt(r2.reshape(n_p, k))


def _contain_triangles(tri: FloatArray, centres: FloatArray, scale: float) -> FloatArray:
    """Return radii (k,) such that each triangle lies in one sphere (all three vertices in it)."""
    need = _need(tri, centres)
    radii, _ = _assign(need)
    return _outward(radii, scale, tri)


def _outward(radii: FloatArray, scale: float, pts: FloatArray) -> FloatArray:
    """Return radii rounded outwards: relative, mesh-size and coordinate-magnitude margins.

    The last term covers the rounding of coordinates themselves far from the origin (a
    split midpoint or a surface point of a part 1000 m out is only known to ~1e-13 m).
    """
    mag = float(np.max(np.abs(pts))) if pts.size else 0.0
    return radii * (1.0 + 1e-12) + 1e-12 * scale + 8 * np.finfo(float).eps * mag


def _need(tri: FloatArray, centres: FloatArray) -> FloatArray:
    """Return (T, k): the farthest vertex of each triangle from each centre [m].

    Direct differences, one centre at a time (k is small): the expanded quadratic form
    |p|^2 - 2 p.c + |c|^2 loses ~|p|^2 * eps, which far from the origin (1.6e-10 m at
    100 m for a 0.1 m part) exceeds the outward margin.
    """
    need2 = np.empty((len(tri), len(centres)))
    for j in range(len(centres)):
        d = tri - centres[j]
        np.max(np.einsum("tvd,tvd->tv", d, d), axis=1, out=need2[:, j])
    return np.sqrt(need2)


def _holds(tri: FloatArray, centres: FloatArray, radii: FloatArray, split: float) -> bool:
    """Return whether every piece of the fit's split of `tri` (T,3,3) lies in one sphere.

    The fit splits every triangle with an edge over `split` [m] 1 -> 4 (`split_long_triangles`)
    and puts each piece in one sphere. Checked here coarse to fine: a triangle held by one
    sphere holds all its pieces, so only the others are split (the same midpoints), one
    round at a time. Whatever the fit guarantees passes; a piece no sphere holds at the
    fit's length, or more than _PIECE_LIMIT open pieces, fails. Exact: direct differences.
    """
    for _ in range(_SPLIT_ROUNDS + 1):
        if len(tri) and len(centres):
            tri = tri[~np.any(_need(tri, centres) <= radii[None], axis=1)]
        if len(tri) == 0:
            return True
        edge = np.linalg.norm(tri - np.roll(tri, 1, axis=1), axis=2).max(axis=1)
        if np.any(edge <= split) or 4 * len(tri) > _PIECE_LIMIT:
            return False  # not split further by the fit, or a damaged entry's split
        tri = split_long_triangles(tri, split, rounds=1)
    return False


def _assign(need: FloatArray) -> tuple[FloatArray, NDArray[np.int64]]:
    """Return radii (k,) and each triangle's sphere (T,) so that every triangle is in its sphere.

    Triangles go to a sphere that already holds them (least inflation first, then the
    tightest), then each radius shrinks to its farthest assigned vertex; best of 4 rounds.
    """
    k = need.shape[1]
    radii = np.zeros(k)
    best: tuple[FloatArray, NDArray[np.int64]] | None = None
    rows = np.arange(len(need))
    for _ in range(4):
        extra = np.maximum(need - radii[None], 0.0)
        j = np.argmin(extra * 1e6 + need, axis=1)
        radii = np.zeros(k)
        np.maximum.at(radii, j, need[rows, j])
        if best is None or np.sum(radii**3) < np.sum(best[0] ** 3):
            best = (radii.copy(), j)
    assert best is not None
    return best


def _enclosing_centres(
    pts: FloatArray,
    owner: NDArray[np.int64],
    centres: FloatArray,
    rounds: int = 60,
    *,
    unique: tuple[FloatArray, NDArray[np.int64]] | None = None,
) -> FloatArray:
    """Return centres (k, 3) moved towards each sphere's smallest ball around its points.

    Badoiu-Clarkson steps (move a fraction 1/(t+2) towards the farthest point); the centre
    kept is the one with the smallest farthest distance seen. `owner` (P,) gives each point's
    sphere; spheres without points keep their centre. unique: `np.unique(pts, axis=0,
    return_inverse=True)` when the caller has it (the same points every round). All spheres
    step together (padded to the largest point set), each exactly as on its own.
    """
    upts, inv = unique if unique is not None else np.unique(pts, axis=0, return_inverse=True)
    inv = np.asarray(inv).reshape(-1)
    k = len(centres)
    sets = [np.unique(inv[owner == j]) for j in range(k)]  # sorted: np.unique's row order
    live = np.array([len(s) > 0 for s in sets])
    out = centres.copy()
    if not np.any(live):
        return out
    m = max(len(s) for s in sets)
    idx = np.zeros((k, m), dtype=np.int64)
    valid = np.zeros((k, m), dtype=bool)
    for j, s in enumerate(sets):
        idx[j, : len(s)] = s
        valid[j, : len(s)] = True
    p = upts[idx]  # (k, m, 3)
    rows = np.arange(k)
    c = centres.copy()
    d2 = np.where(valid, np.sum((p - c[:, None]) ** 2, axis=2), -np.inf)
    i = np.argmax(d2, axis=1)
    best, best_r2 = c.copy(), d2[rows, i]
    for t in range(rounds):
        c += (p[rows, i] - c) / (t + 2.0)
        d2 = np.where(valid, np.sum((p - c[:, None]) ** 2, axis=2), -np.inf)
        i = np.argmax(d2, axis=1)
        r2 = d2[rows, i]
        better = r2 < best_r2
        best[better], best_r2[better] = c[better], r2[better]
    out[live] = best[live]
    return out


def _tighten(
    pieces: FloatArray, centres: FloatArray, rounds: int = 8
) -> tuple[FloatArray, FloatArray]:
    """Return centres (k,3) and radii (k,) holding every piece in one sphere, smaller in total.

    Alternates assignment (`_assign`) and re-centring each sphere on the smallest ball around
    the vertices of its pieces (a Lloyd iteration for the k-centre cover). Every candidate is
    valid (each piece in its sphere); the smallest total volume wins.
    """
    need = _need(pieces, centres)
    radii, j = _assign(need)
    best = (centres.copy(), radii)
    pts = pieces.reshape(-1, 3)
    unique = np.unique(pts, axis=0, return_inverse=True)
    for _ in range(rounds):
        centres = _enclosing_centres(pts, np.repeat(j, 3), centres, unique=unique)
        need = _need(pieces, centres)
        radii, j = _assign(need)
        if np.sum(radii**3) < np.sum(best[1] ** 3):
            best = (centres.copy(), radii)
        else:
            break
    return best


def _axis_seeds(cover: FloatArray, count: int) -> FloatArray:
    """Return `count` centres: the mean cover point of equal-count slabs along the principal axis."""
    mean = cover.mean(axis=0)
    _, _, vt = np.linalg.svd(cover - mean, full_matrices=False)
    order = np.argsort((cover - mean) @ vt[0])
    return np.stack([cover[part].mean(axis=0) for part in np.array_split(order, count)])


def _mesh_arrays(mesh: Any) -> tuple[FloatArray, NDArray[np.int64]]:
    """Return the checked (vertices, faces) of a trimesh.Trimesh or a (vertices, faces) tuple."""
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        return check_mesh(mesh.vertices, mesh.faces)
    if isinstance(mesh, tuple) and len(mesh) == 2:
        return check_mesh(*mesh)
    raise InputError(
        f"mesh must be a trimesh.Trimesh or a (vertices, faces) tuple, got {type(mesh).__name__}"
    )


def fit_spheres(
    mesh: Any,
    count: int,
    *,
    seed: int = 0,
    iterations: int = 60,
    particles: int = 24,
    samples: int = 2000,
    cache_dir: str | Path | None = None,
) -> SphereSet:
    """Return `count` spheres enveloping `mesh` (trimesh.Trimesh or (vertices, faces)) [m].

    iterations/particles: PSO budget. samples: surface points the swarm must cover (besides
    vertices). Every triangle is contained exactly afterwards. cache_dir: reuse/store the fit
    there as ``spheres-<sha256 of mesh and parameters>.npz`` (`npz_cache`); a stored fit is
    used only after the same exact containment check the fit makes, else (and for an
    unreadable entry) it is fitted again and overwritten. A fit shipped with the package
    (`SHIPPED_FITS`, the presets' links) under the same key is used first, after the same
    check. Raises InputError for
    count <= 0, MeshError for an empty mesh.
    """
    v, f = _mesh_arrays(mesh)
    tri = v[f]
    area = float(
        np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1).sum()
    )
    if not area > 0.0:  # a box of zero size: every vertex on one point or one line
        extent = np.ptp(v[np.unique(f)], axis=0)
        raise MeshError(
            f"the mesh has no area (extent {extent.tolist()} m): spheres cannot envelop it; "
            "give the solid a positive size in every direction"
        )
    if not isinstance(count, int | np.integer) or count <= 0:
        raise InputError(f"count (spheres per link) must be a positive integer, got {count!r}")
    if iterations < 0 or particles < 1 or samples < 0:
        raise InputError(
            f"iterations >= 0, particles >= 1, samples >= 0 required; got {iterations}, {particles}, {samples}"
        )
    if cache_dir is None:
        return _fit(v, f, count, seed, iterations, particles, samples)[0]
    params = _params(count, seed, iterations, particles, samples)
    path = cache_path(cache_dir, "spheres", list(mesh_key_arrays(v, f)), params)
    required = ("centres", "radii", "split", *_SCALARS)
    for read in (lambda: _shipped_entry(path.name, required), lambda: load_entry(path, required)):
        d = read()  # a fit shipped with the package first, then the disk cache
        if d is not None:
            loaded = _checked_entry(v, f, d)
            if loaded is not None:
                return loaded
    # No entry, an unreadable one, or one whose spheres do not hold the mesh: fit again.
    s, split = _fit(v, f, count, seed, iterations, particles, samples)
    store_entry(path, _entry_arrays(s, split))
    return s


SHIPPED_FITS = Path(__file__).with_name("fits")
"""Fits shipped with the package (the presets' link meshes at the engine's default count):
entries named as in the disk cache (`cache_path`), read-only, checked on load like a cached
entry. Written by `write_shipped_fits` (`WORKBENCH_UPDATE_FITS=1 pytest
tests/geometry/test_shipped_fits.py` rewrites them for the MZ07 preset)."""


def _shipped_entry(name: str, required: tuple[str, ...]) -> dict[str, NDArray[Any]] | None:
    """Return the arrays of the shipped fit `name`, or None (none shipped, or unreadable)."""
    path = SHIPPED_FITS / name
    if not path.is_file():
        return None
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {k: np.asarray(data[k]) for k in data.files}
    except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile):
        return None
    return arrays if all(k in arrays for k in required) else None


KEY_ROUND = 1e-7
"""Vertices are rounded to this [m] for a fit's key: the same link mesh generated on another
machine (its convex hull's vertex order, the last bits of its floats) keys the same fit."""


def mesh_key_arrays(v: FloatArray, f: NDArray[np.int64]) -> tuple[FloatArray, NDArray[np.int64]]:
    """Return the mesh in a canonical form for keys: vertices rounded to `KEY_ROUND` and
    sorted, faces renumbered, each rotated to start at its least vertex (winding kept), sorted."""
    r = np.round(np.asarray(v, float) / KEY_ROUND) * KEY_ROUND + 0.0  # +0.0: no -0.0
    order = np.lexsort((r[:, 2], r[:, 1], r[:, 0]))
    rank = np.empty(len(r), dtype=np.int64)
    rank[order] = np.arange(len(r))
    g = rank[np.asarray(f, np.int64)]
    k = np.argmin(g, axis=1)
    rows = np.arange(len(g))[:, None]
    g = g[rows, (k[:, None] + np.arange(3)) % 3]
    g = g[np.lexsort((g[:, 2], g[:, 1], g[:, 0]))]
    return r[order], g


def write_shipped_fits(
    meshes: list[Any], count: int, folder: str | Path = SHIPPED_FITS
) -> list[Path]:
    """Replace the fits in `folder` by fresh fits of `count` spheres to each of `meshes`.

    The entries are the disk cache's own (default fit parameters, the same key), so
    `fit_spheres` finds them; every older entry in `folder` is removed. Returns the paths.
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.glob("spheres-*.npz"):
        old.unlink()
    out = []
    for mesh in meshes:
        v, f = _mesh_arrays(mesh)
        path = cache_path(folder, "spheres", list(mesh_key_arrays(v, f)), _params(int(count)))
        s, split = _fit(v, f, int(count), 0, 60, 24, 2000)
        store_entry(path, _entry_arrays(s, split))
        out.append(path)
    return out


def _params(
    count: int, seed: int = 0, iterations: int = 60, particles: int = 24, samples: int = 2000
) -> dict[str, int]:
    """Return what a fit depends on besides the mesh (the cache key's parameters)."""
    return {
        "count": int(count),
        "seed": int(seed),
        "iterations": int(iterations),
        "particles": int(particles),
        "samples": int(samples),
        "format": _FORMAT,
    }


def _entry_arrays(s: SphereSet, split: float) -> dict[str, NDArray[Any]]:
    return {
        "centres": s.centres,
        "radii": s.radii,
        "split": np.asarray(split, float),
        **{k: np.asarray(getattr(s, k), float) for k in _SCALARS},
    }


def _checked_entry(
    v: FloatArray, f: NDArray[np.int64], d: dict[str, NDArray[Any]]
) -> SphereSet | None:
    """Return the cached spheres if they hold every triangle piece as the fit made sure, else None.

    The conservative collision bounds rest on these spheres: an entry edited, damaged or
    written by another fit is checked exactly as `_fit` guarantees containment (each piece
    of the same split in one sphere, direct differences), at the cost of one `_need`.
    """
    centres, radii = np.asarray(d["centres"], float), np.asarray(d["radii"], float)
    split = float(d["split"])
    if (
        centres.ndim != 2
        or centres.shape[1:] != (3,)
        or radii.shape != (len(centres),)
        or not np.all(np.isfinite(centres))
        or not np.all(np.isfinite(radii))
        or not split > 0
    ):
        return None
    if not _holds(v[f], centres, radii, split):
        return None
    return SphereSet(centres, radii, *(float(d[k]) for k in _SCALARS))


# Most triangle pieces the fit splits the mesh into (and the check on load), most rounds.
_PIECE_LIMIT = 200_000
_SPLIT_ROUNDS = 30  # split_long_triangles' default
_SCALARS = ("coverage", "union_volume", "mesh_volume", "volume_overshoot")


def _fit(
    v: FloatArray,
    f: NDArray[np.int64],
    count: int,
    seed: int,
    iterations: int,
    particles: int,
    samples: int,
) -> tuple[SphereSet, float]:
    """Return the fit and the edge length its triangles were split to [m]."""
    rng = np.random.default_rng(seed)
    tri = v[f]
    scale = float(np.ptp(v, axis=0).max()) or 1.0
    used_v = v[np.unique(f)]
    cover = np.concatenate(
        [used_v[rng.permutation(len(used_v))[:samples]], _surface_samples(tri, samples, rng)]
    )
    lo, hi = cover.min(axis=0), cover.max(axis=0)
    # Initial swarm: particle 0 from a few Lloyd iterations, the others random cover points.
    x = cover[rng.integers(0, len(cover), size=(particles, count))] + rng.normal(
        0, 0.02 * scale, (particles, count, 3)
    )
    seeds = cover[rng.choice(len(cover), size=count, replace=len(cover) < count)]
    for _ in range(10):
        lab = np.argmin(np.sum((cover[:, None] - seeds[None]) ** 2, axis=2), axis=1)
        for j in range(count):  # count is small (spheres per link)
            if np.any(lab == j):
                seeds[j] = cover[lab == j].mean(axis=0)
    x[0] = seeds
    if particles > 1:  # particle 1: slab centroids along the principal axis (medial-axis-ish)
        x[1] = _axis_seeds(cover, count)
        half = particles // 2  # half the rest start near one of these two, half at random
        x[2 : 2 + half] = x[rng.integers(0, 2, size=max(0, min(half, particles - 2)))] + rng.normal(
            0, 0.01 * scale, (max(0, min(half, particles - 2)), count, 3)
        )
    vel = np.zeros_like(x)
    cost = np.sum(_decode(x, cover) ** 3, axis=1)
    pbest, pcost = x.copy(), cost.copy()
    g = int(np.argmin(pcost))
    for _ in range(iterations):
        r1, r2 = rng.random(x.shape), rng.random(x.shape)
        vel = 0.72 * vel + 1.49 * r1 * (pbest - x) + 1.49 * r2 * (pbest[g] - x)
        x = np.clip(x + vel, lo, hi)
        cost = np.sum(_decode(x, cover) ** 3, axis=1)
        better = cost < pcost
        pbest[better], pcost[better] = x[better], cost[better]
        g = int(np.argmin(pcost))
    centres = pbest[g]
    r_swarm = _decode(centres[None], cover)[0]
    # Long thin triangles (a cylinder's sides) would force huge spheres: split them first.
    split = 0.35 * float(np.median(r_swarm[r_swarm > 0])) if np.any(r_swarm > 0) else scale
    pieces = split_long_triangles(tri, split, limit=_PIECE_LIMIT, rounds=_SPLIT_ROUNDS)
    centres, radii = _tighten(pieces, centres)
    radii = _outward(radii, scale, pieces)
    keep = radii > 2 * _outward(np.zeros(1), scale, pieces)[0]  # more than the margin alone
    if not np.all(keep):  # spheres left with no triangle: drop them
        centres, radii = centres[keep], radii[keep]
    checks = np.concatenate([v[np.unique(f)], _surface_samples(tri, 10 * max(samples, 100), rng)])
    inside = np.any(
        np.sum((checks[:, None] - centres[None]) ** 2, axis=2) <= radii[None] ** 2, axis=1
    )
    mesh_volume = float(
        abs(np.sum(np.einsum("ij,ij->i", tri[:, 0], np.cross(tri[:, 1], tri[:, 2])))) / 6.0
    )
    blo, bhi = (centres - radii[:, None]).min(axis=0), (centres + radii[:, None]).max(axis=0)
    mc = rng.uniform(blo, bhi, size=(20000, 3))
    in_union = np.any(
        np.sum((mc[:, None] - centres[None]) ** 2, axis=2) <= radii[None] ** 2, axis=1
    )
    union_volume = float(np.prod(bhi - blo) * in_union.mean())
    closed = is_watertight(v, f) and mesh_volume > 1e-12 * scale**3
    overshoot = (union_volume - mesh_volume) / mesh_volume if closed else float("nan")
    sphere_set = SphereSet(
        centres, radii, float(inside.mean()), union_volume, mesh_volume, float(overshoot)
    )
    return sphere_set, split
