"""The cell subdivision's disk cache: the same grid as `subdivide`, stale or damaged entries rebuilt."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from workbench.assembly import cell_cache, cells
from workbench.assembly.cells import subdivide, subdivide_cached


@pytest.fixture()
def folder(tmp_path, monkeypatch):
    monkeypatch.setenv("WORKBENCH_CACHE", str(tmp_path))
    monkeypatch.delenv(cell_cache.CELL_CACHE_ENV, raising=False)
    cells._CACHE.clear()
    yield tmp_path / "cells"
    cells._CACHE.clear()


def _part() -> trimesh.Trimesh:
    m = trimesh.creation.annulus(r_min=0.02, r_max=0.05, height=0.03, sections=24)
    m.apply_translation([0.3, -0.1, 0.05])
    return m


def _same(a, b):
    assert np.array_equal(a.origin, b.origin) and a.cell_size == b.cell_size
    assert np.array_equal(a.occupied, b.occupied) and np.array_equal(a.boundary, b.boundary)
    assert a.closed == b.closed


def _count_subdivisions(monkeypatch):
    calls = []
    real = cells.subdivide
    monkeypatch.setattr(cells, "subdivide", lambda m, c: calls.append(c) or real(m, c))
    return calls


def test_a_new_process_reads_the_grid_from_disk(folder, monkeypatch):
    mesh = _part()
    twin = subdivide(mesh, 0.004)  # the uncached subdivision
    calls = _count_subdivisions(monkeypatch)
    _same(subdivide_cached(mesh, 0.004), twin)
    assert calls == [0.004] and len(list(folder.glob("cells-*.npz"))) == 1
    cells._CACHE.clear()  # as in a fresh process: memory empty, disk filled
    _same(subdivide_cached(mesh, 0.004), twin)
    assert calls == [0.004]


def test_the_key_is_the_geometry_and_the_cell_size(folder, monkeypatch):
    mesh = _part()
    subdivide_cached(mesh, 0.004)
    calls = _count_subdivisions(monkeypatch)
    cells._CACHE.clear()
    _same(subdivide_cached(mesh, 0.005), subdivide(mesh, 0.005))
    moved = mesh.copy()
    moved.apply_translation([1e-6, 0, 0])
    cells._CACHE.clear()
    _same(subdivide_cached(moved, 0.004), subdivide(moved, 0.004))
    assert calls[:1] == [0.005] and calls.count(0.004) >= 1
    assert len(list(folder.glob("cells-*.npz"))) == 3


@pytest.mark.parametrize("damage", ["truncated", "garbage", "flipped_boundary", "wrong_shape"])
def test_a_damaged_or_forged_entry_is_rebuilt(folder, monkeypatch, damage):
    mesh = _part()
    twin = subdivide(mesh, 0.004)
    subdivide_cached(mesh, 0.004)
    (path,) = folder.glob("cells-*.npz")
    if damage == "truncated":
        path.write_bytes(path.read_bytes()[:300])
    elif damage == "garbage":
        path.write_bytes(b"\0" * 1000)
    else:
        with np.load(path) as z:
            arrays = {k: z[k] for k in z.files}
        if damage == "flipped_boundary":  # a forged entry (valid zip): no boundary cells at all
            arrays["boundary"] = np.zeros_like(arrays["boundary"])
            arrays["occupied"] = np.zeros_like(arrays["occupied"])
        else:
            arrays["shape"] = arrays["shape"] + 1
        np.savez(path, **arrays)
        path = path.with_suffix(".npz")
    cells._CACHE.clear()
    calls = _count_subdivisions(monkeypatch)
    _same(subdivide_cached(mesh, 0.004), twin)
    assert calls == [0.004]
    cells._CACHE.clear()
    _same(subdivide_cached(mesh, 0.004), twin)  # rewritten: read back good
    assert calls == [0.004]


def test_the_cache_can_be_switched_off(folder, monkeypatch):
    monkeypatch.setenv(cell_cache.CELL_CACHE_ENV, "0")
    subdivide_cached(_part(), 0.004)
    assert not folder.exists()


def test_a_read_only_cache_does_not_fail_the_subdivision(folder, monkeypatch):
    def refuse(*a, **k):
        raise PermissionError("read-only")

    monkeypatch.setattr(cell_cache, "store_entry", refuse)
    _same(subdivide_cached(_part(), 0.004), subdivide(_part(), 0.004))
