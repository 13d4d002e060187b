"""`Workbench.collision`: checks, path reports, spheres and SDF slices through the service."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from block_cell import block_cell

from workbench.errors import InputError, WorkbenchError
from workbench.service import Workbench
from workbench.service.collision_engine import CollisionService

PROJECT = block_cell()
Q_HIT = np.array([0.0, -0.68, 0.595, 0.0, -0.085, 0.0])  # the tool 50 mm deep in the block


@pytest.fixture(scope="module")
def svc(engine_cache: Path) -> CollisionService:
    wb = Workbench.from_dict(PROJECT)
    return CollisionService(wb, cache_dir=engine_cache)


def test_check_agrees_with_the_exact_checker(svc: CollisionService) -> None:
    free = svc.check()
    assert not free.colliding and free.clearance >= 0
    hit = svc.check(Q_HIT)
    assert hit.colliding and hit.obstacle == "block" and hit.link == "tool"
    assert svc.wb.checker.check(Q_HIT, distance=False).in_collision
    assert 0.0 < hit.penetration <= 0.2


def test_spheres_follow_the_links(svc: CollisionService) -> None:
    c, r, names = svc.spheres(Q_HIT)
    eng = svc.engine()
    poses = svc.wb.link_poses(Q_HIT)
    k = names.index("link3")
    local = eng.centres[k]
    assert np.allclose(c[k], poses[3][:3, :3] @ local + poses[3][:3, 3])
    assert len(c) == len(r) == len(names) and np.all(r > 0)


def test_sdf_slice_matches_the_box_distance(svc: CollisionService) -> None:
    """Twin: the closed-form signed distance of the block, within the field's error bound."""
    values, corners = svc.sdf_slice("z", 0.3, size=41)
    assert values.shape == (41, 41)
    x = np.linspace(corners[0, 0], corners[1, 0], 41)
    y = np.linspace(corners[0, 1], corners[1, 1], 41)
    X, Y = np.meshgrid(x, y, indexing="ij")
    q = np.abs(np.stack([X - 0.6, Y, np.zeros_like(X)], axis=-1)) - [0.15, 0.2, 0.15]
    exact = np.linalg.norm(np.maximum(q, 0), axis=-1) + np.minimum(q.max(axis=-1), 0)
    err = svc.engine().sdf.max_error  # type: ignore[union-attr]
    # Never farther from the block than it is (what the conservative test needs); outside,
    # never negative. (Inside, some corners near the faces read +max_error: see the report.)
    assert np.all(values <= np.abs(exact) + err + 1e-6)
    assert np.all(values[exact > err] >= 0)
    assert np.any(values < -0.001)


def test_cache_makes_the_second_build_instant(svc: CollisionService, tmp_path: Path) -> None:
    first = svc.engine()
    # The same checker: the engine that plans use is shared, not rebuilt.
    again = CollisionService(svc.wb, cache_dir=svc.cache_dir)
    assert again.engine() is first
    # A new session on the same project: the field and the sphere fits come from the disk cache.
    messages: list[str] = []
    fresh = CollisionService(Workbench.from_dict(PROJECT), cache_dir=svc.cache_dir)
    eng = fresh.engine(progress=lambda f, m: messages.append(m))
    assert any("cache" in m for m in messages), messages
    assert eng is not first
    np.testing.assert_array_equal(eng.radii, first.radii)
    np.testing.assert_array_equal(eng.centres, first.centres)


def test_bad_input_through_the_service(svc: CollisionService) -> None:
    with pytest.raises(InputError, match="q"):
        svc.check([0.0, 1.0])
    with pytest.raises(InputError, match="qs"):
        svc.check_path(np.zeros((0, 6)))
    with pytest.raises(InputError, match="finite"):
        svc.check_path(np.full((2, 6), np.nan))
    with pytest.raises(InputError, match="mode"):
        svc.check(mode="voxels")
    with pytest.raises(InputError, match="axis"):
        svc.sdf_slice("w", 0.0)
    with pytest.raises(InputError, match="spheres_per_link"):
        CollisionService(svc.wb, spheres_per_link=0, cache_dir=svc.cache_dir).engine()


@pytest.mark.slow  # over 5 s here
def test_open_mesh_obstacle_from_the_project_warns_and_stays_conservative(tmp_path: Path) -> None:
    """A non-watertight obstacle (a box without its top) gets an unsigned field and a warning."""
    import trimesh

    box = trimesh.creation.box((0.3, 0.4, 0.3))
    top = np.flatnonzero(box.face_normals[:, 2] > 0.5)
    open_box = trimesh.Trimesh(box.vertices * 1000, np.delete(box.faces, top, axis=0))
    open_box.export(tmp_path / "open.stl")
    data = json.loads(json.dumps(PROJECT))
    data["cell"]["objects"] = [
        {"name": "tray", "shape": "mesh", "path": "open.stl", "pose": {"xyz": [600, 0, 300]}}
    ]
    wb = Workbench.from_dict(data, base_dir=tmp_path)
    svc = CollisionService(wb, cache_dir=tmp_path / "sdf")
    with pytest.warns(UserWarning, match="not watertight"):
        eng = svc.engine()
    assert eng.sdf is not None and not eng.sdf.signed
    assert svc.check(Q_HIT).flagged


def test_empty_and_nan_meshes_in_the_project_are_refused(tmp_path: Path) -> None:
    (tmp_path / "empty.stl").write_text("solid empty\nendsolid empty\n")
    data = json.loads(json.dumps(PROJECT))
    data["cell"]["objects"] = [{"name": "jig", "shape": "mesh", "path": "empty.stl"}]
    with pytest.raises(WorkbenchError, match="cell.objects\\[0\\]"):
        Workbench.from_dict(data, base_dir=tmp_path)
