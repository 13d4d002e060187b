"""Pair tables: their bound never exceeds python-fcl's distance (twin), and they fill lazily."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from block_cell import block_cell

from workbench.collision.engine import TABLE_TOL, CollisionEngine
from workbench.collision.pair_table import PairTable, pair_joints
from workbench.errors import InputError
from workbench.service import Workbench

PROJECT = block_cell()


@pytest.fixture(scope="module")
def engine(engine_cache: Path) -> CollisionEngine:
    wb = Workbench.from_dict(PROJECT)
    cache = str(engine_cache)
    return CollisionEngine(
        wb.checker, "spheres", spheres_per_link=4, resolution=32, cache_dir=cache
    )


def _fcl_distance(engine: CollisionEngine, pair: tuple[str, str], q: np.ndarray) -> float:
    """Twin: python-fcl at the full configuration (0 when touching or held)."""
    scene = engine.exact.scene
    T = engine.body_poses(q[None])[0]
    for name in pair:
        if name in scene.moving:
            scene.moving[name].place(T[engine.body_names.index(name)])
    return 0.0 if scene.collides(*pair) else scene.distance(*pair)


def test_tables_cover_the_pairs_of_one_or_two_joints(engine: CollisionEngine) -> None:
    tables = engine.pair_tables
    for pair in [("link4", "link6"), ("link4", "tool"), ("link5", "tool"), ("link2", "link4")]:
        assert pair in tables
    assert list(tables[("link5", "tool")].joints) == [5]
    assert list(tables[("link4", "link6")].joints) == [4, 5]
    assert list(tables[("link1", "block")].joints) == [0]
    assert ("tool", "block") not in tables  # six joints: no table
    assert ("link3", "block") not in tables
    assert list(pair_joints(2, 4)) == [2, 3]
    assert list(pair_joints(2, None)) == [0, 1]


@pytest.mark.parametrize(
    "pair", [("link4", "link6"), ("link4", "tool"), ("link5", "tool"), ("link2", "link4")]
)
def test_table_bound_is_never_above_fcl_distance(
    engine: CollisionEngine, pair: tuple[str, str]
) -> None:
    """Twin: on random joint values within and just outside the limits, bound <= fcl."""
    rng = np.random.default_rng(7)
    lim = engine.exact.robot.limits
    table = engine.pair_tables[pair]
    # Random full configurations (every joint random: the distance does not depend on the
    # others), most within the limits, some beyond them (certified intervals may leave them).
    q = rng.uniform(lim[:, 0] - 0.05, lim[:, 1] + 0.05, (300, 6))
    # Half of them concentrated on a small patch, so that neighbouring cells share nodes.
    q[150:, table.joints] = q[150, table.joints] + rng.uniform(
        -0.05, 0.05, (150, len(table.joints))
    )
    bound = table.bound(q)
    exact = np.array([_fcl_distance(engine, pair, qi) for qi in q])
    assert np.all(bound <= exact + 1e-9), float(np.max(bound - exact))
    # Not vacuous: the bound is within the table's tolerance of fcl where the pair is apart.
    inside = np.all(
        (q[:, table.joints] >= lim[table.joints, 0]) & (q[:, table.joints] <= lim[table.joints, 1]),
        axis=1,
    )
    apart = inside & (exact > 0)
    assert apart.sum() > 100
    assert np.all(exact[apart] - bound[apart] <= TABLE_TOL + 1e-9)


def test_table_fills_lazily_and_reuses_nodes() -> None:
    calls: list[int] = []

    def distance(qn: np.ndarray) -> np.ndarray:
        calls.append(len(qn))
        return 1.0 + 0.1 * np.sin(qn[:, 1])  # Lipschitz 0.1 in q1: the lever bounds it

    table = PairTable(
        np.array([1]), np.array([-1.0]), np.array([1.0]), np.array([0.1]), 3, distance, tol=0.01
    )
    q = np.zeros((5, 3))
    q[:, 1] = np.linspace(-0.2, 0.2, 5)
    b = table.bound(q)
    assert np.all(b <= 1.0 + 0.1 * np.sin(q[:, 1]) + 1e-12)
    first = table.filled
    assert 0 < first < table.count[0]
    table.bound(q)
    assert table.filled == first and len(calls) == 1  # nothing recomputed
    # More new nodes than allowed: no information and nothing filled.
    far = np.zeros((2, 3))
    far[:, 1] = [0.9, -0.9]
    assert np.all(table.bound(far, max_new=1) == -np.inf)
    assert table.filled == first and len(calls) == 1
    assert np.all(np.isfinite(table.bound(far, max_new=4)))


def test_bad_table_input() -> None:
    with pytest.raises(InputError, match="joints"):
        PairTable(np.array([0, 1, 2]), np.zeros(3), np.ones(3), np.ones(3), 6, lambda q: q[:, 0])
    with pytest.raises(InputError, match="lever"):
        PairTable(np.array([0]), np.zeros(1), np.ones(1), np.zeros(1), 6, lambda q: q[:, 0])
    with pytest.raises(InputError, match="tol"):
        PairTable(np.array([0]), np.zeros(1), np.ones(1), np.ones(1), 6, lambda q: q[:, 0], tol=0.0)


@pytest.mark.slow  # over 5 s here
def test_tables_are_cached_on_disk(tmp_path_factory: pytest.TempPathFactory) -> None:
    """A new engine on the same cell loads the nodes a path check computed; bounds agree."""
    wb = Workbench.from_dict(PROJECT)
    cache = str(tmp_path_factory.mktemp("tables"))
    first = CollisionEngine(
        wb.checker, "spheres", spheres_per_link=4, resolution=32, cache_dir=cache
    )
    rng = np.random.default_rng(11)
    lim = wb.robot.limits
    q = np.clip(
        rng.uniform(-0.3, 0.3, 6) + np.linspace(0, 1, 40)[:, None] * rng.normal(0, 0.4, 6),
        lim[:, 0],
        lim[:, 1],
    )
    table = first.pair_tables[("link4", "tool")]
    b1 = table.bound(q)
    assert table.filled > 0
    first.save_tables()
    files = list(Path(cache).glob("table-*.npz"))
    assert files
    again = CollisionEngine(
        wb.checker, "spheres", spheres_per_link=4, resolution=32, cache_dir=cache
    )
    t2 = again.pair_tables[("link4", "tool")]
    b2 = t2.bound(q)
    assert t2.filled == 0  # every node came from the file
    assert np.array_equal(b1, b2)
    # Another tool is another table (the digest covers the meshes and poses).
    other = dict(PROJECT, tool={"tcp": {"xyz": [0, 0, 200]}, "size": [60, 80, 170]})
    wb2 = Workbench.from_dict(other)
    e3 = CollisionEngine(wb2.checker, "spheres", spheres_per_link=4, resolution=32, cache_dir=cache)
    e3.pair_tables[("link4", "tool")].bound(q)
    assert e3.pair_tables[("link4", "tool")].filled > 0


def _small_table() -> tuple[PairTable, list[int]]:
    calls: list[int] = []

    def distance(qn: np.ndarray) -> np.ndarray:
        calls.append(len(qn))
        return 1.0 + 0.1 * np.sin(qn[:, 1])

    table = PairTable(
        np.array([1]), np.array([-1.0]), np.array([1.0]), np.array([0.1]), 3, distance, tol=0.01
    )
    return table, calls


def test_truncated_or_old_table_entry_is_recomputed_and_overwritten(tmp_path: Path) -> None:
    """A damaged entry (a crash of another writer, a full disk) is a miss, never an error."""
    q = np.zeros((5, 3))
    q[:, 1] = np.linspace(-0.2, 0.2, 5)
    entry = tmp_path / "table-x.npz"
    first, _ = _small_table()
    first.attach(entry)
    b = first.bound(q)
    first.save()
    assert sorted(p.name for p in tmp_path.iterdir()) == [entry.name]  # no temp files left
    entry.write_bytes(entry.read_bytes()[:200])
    again, calls = _small_table()
    again.attach(entry)  # old code: zipfile.BadZipFile here
    assert again.filled == 0
    np.testing.assert_array_equal(again.bound(q), b)
    assert again.filled == first.filled and len(calls) == 1  # computed again
    again.save()
    third, calls = _small_table()
    third.attach(entry)
    np.testing.assert_array_equal(third.bound(q), b)
    assert third.filled == 0 and not calls  # the overwritten entry is read
    assert sorted(p.name for p in tmp_path.iterdir()) == [entry.name]
    # An entry of the previous version (no format field) is ignored, not misread.
    np.savez(entry, values=np.zeros(third.values.shape))
    old, calls = _small_table()
    old.attach(entry)
    np.testing.assert_array_equal(old.bound(q), b)
    assert old.filled > 0 and calls
