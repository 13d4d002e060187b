"""Sphere fits shipped with the package (geometry/fits/): current, checked on load, refitted if bad.

`WORKBENCH_UPDATE_FITS=1 python -m pytest tests/geometry/test_shipped_fits.py` rewrites the
shipped set from the presets' link meshes (after a change to the fit or to link_shapes.py).
"""

from __future__ import annotations

import os
import shutil
import tomllib
from pathlib import Path

import numpy as np
import pytest

from workbench.collision.plan_check import SPHERES_PER_LINK
from workbench.geometry import spheres as sp
from workbench.geometry.npz_cache import cache_path
from workbench.kinematics.robot_library import preset_robot

ROOT = Path(__file__).resolve().parents[2]


def _preset_meshes() -> list:
    return list(preset_robot("mz07").link_meshes())


def _key(mesh) -> str:
    v, f = sp._mesh_arrays(mesh)
    return cache_path(
        ".", "spheres", list(sp.mesh_key_arrays(v, f)), sp._params(SPHERES_PER_LINK)
    ).name


@pytest.fixture(scope="module", autouse=True)
def _maybe_update():
    if os.environ.get("WORKBENCH_UPDATE_FITS") == "1":
        sp.write_shipped_fits(_preset_meshes(), SPHERES_PER_LINK)


def test_every_preset_link_has_a_shipped_fit_and_nothing_else_is_shipped():
    want = {_key(m) for m in _preset_meshes()}
    have = {p.name for p in sp.SHIPPED_FITS.glob("spheres-*.npz")}
    assert want <= have, (
        f"missing shipped fits {sorted(want - have)}: run "
        "WORKBENCH_UPDATE_FITS=1 python -m pytest tests/geometry/test_shipped_fits.py"
    )
    assert have <= want, f"stale shipped fits {sorted(have - want)} (no preset link has that mesh)"


def test_shipped_fit_is_the_fit_and_is_used_without_fitting(tmp_path, monkeypatch):
    """The twin: a fresh fit of the same mesh (no cache) equals the shipped entry exactly;
    with a cache folder the shipped entry is returned, nothing is fitted or written."""
    meshes = _preset_meshes()
    mesh = meshes[2]
    fresh = sp.fit_spheres(mesh, SPHERES_PER_LINK, seed=0)
    calls = []
    real_fit = sp._fit
    monkeypatch.setattr(sp, "_fit", lambda *a: calls.append(1) or real_fit(*a))
    got = sp.fit_spheres(mesh, SPHERES_PER_LINK, seed=0, cache_dir=tmp_path)
    assert calls == [] and list(tmp_path.iterdir()) == []
    np.testing.assert_array_equal(got.centres, fresh.centres)
    np.testing.assert_array_equal(got.radii, fresh.radii)
    assert got.union_volume == fresh.union_volume and got.coverage == fresh.coverage


def test_shipped_fits_hold_their_meshes():
    """Independent check: every vertex and dense surface samples lie in the union of spheres."""
    rng = np.random.default_rng(3)
    for mesh in _preset_meshes():
        d = sp._shipped_entry(_key(mesh), ("centres", "radii"))
        assert d is not None
        c, r = d["centres"], d["radii"]
        pts = np.concatenate([mesh.vertices, mesh.sample(3000, seed=rng.integers(1 << 30))])
        d2 = ((pts[:, None] - c[None]) ** 2).sum(axis=2)
        assert np.all(np.any(d2 <= r[None] ** 2 * (1 + 1e-9), axis=1))


@pytest.mark.parametrize("damage", ["shrunk", "truncated", "not_a_zip"])
def test_a_bad_shipped_fit_is_refitted(tmp_path, monkeypatch, damage):
    """A shipped entry whose spheres no longer hold the mesh, or that cannot be read, is not
    used: the mesh is fitted and the fit goes to the disk cache."""
    mesh = _preset_meshes()[1]
    name = _key(mesh)
    with np.load(sp.SHIPPED_FITS / name) as z:
        good = z["radii"].copy()
    shipped = tmp_path / "fits"
    shipped.mkdir()
    shutil.copy(sp.SHIPPED_FITS / name, shipped / name)
    target = shipped / name
    if damage == "shrunk":
        with np.load(target) as z:
            arrays = {k: z[k] for k in z.files}
        arrays["radii"] = arrays["radii"] * 0.9
        np.savez(target, **arrays)
    elif damage == "truncated":
        target.write_bytes(target.read_bytes()[:200])
    else:
        target.write_bytes(b"not a zip file at all")
    monkeypatch.setattr(sp, "SHIPPED_FITS", shipped)
    calls = []
    real_fit = sp._fit
    monkeypatch.setattr(sp, "_fit", lambda *a: calls.append(1) or real_fit(*a))
    cache = tmp_path / "cache"
    got = sp.fit_spheres(mesh, SPHERES_PER_LINK, seed=0, cache_dir=cache)
    assert calls == [1]
    assert (cache / name).is_file()
    np.testing.assert_array_equal(got.radii, good)  # the fit itself, not the damaged entry


def test_pyproject_ships_the_fits():
    conf = tomllib.loads((ROOT / "pyproject.toml").read_text())
    patterns = conf["tool"]["setuptools"]["package-data"]["workbench"]
    assert "geometry/fits/*.npz" in patterns
    assert any(sp.SHIPPED_FITS.glob("spheres-*.npz"))
