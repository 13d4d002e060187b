"""The checker interface: motion bound, path guarantee and modes against dense exact checks."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from block_cell import block_cell

from workbench.collision.engine import CollisionEngine
from workbench.errors import InputError
from workbench.service import Workbench

PROJECT = block_cell()
Q_FREE = np.zeros(6)
Q_HIT = np.array([0.0, -0.68, 0.595, 0.0, -0.085, 0.0])  # the tool 50 mm deep in the block


@pytest.fixture(scope="module")
def wb(tmp_path_factory: pytest.TempPathFactory) -> Workbench:
    return Workbench.from_dict(PROJECT)


@pytest.fixture(scope="module")
def engines(wb: Workbench, engine_cache: Path) -> dict[str, CollisionEngine]:
    cache = str(engine_cache)
    return {
        m: CollisionEngine(wb.checker, m, spheres_per_link=4, resolution=32, cache_dir=cache)
        for m in ("spheres", "capsules", "exact")
    }


def test_no_misses_on_random_configurations(
    wb: Workbench, engines: dict[str, CollisionEngine]
) -> None:
    """Twin: the exact fcl checker (cell and self-collision pairs, containment included)."""
    rng = np.random.default_rng(1)
    lim = wb.robot.limits
    q = rng.uniform(lim[:, 0], lim[:, 1], (400, 6))
    q[:, 1:3] = rng.uniform(-1.2, 1.2, (400, 2))
    exact = np.array([wb.checker.check(x, distance=False).in_collision for x in q])
    assert exact.sum() > 20
    for mode in ("spheres", "capsules"):
        clr, _ = engines[mode].items(q)
        flagged = clr.min(axis=1) <= 0
        assert not np.any(exact & ~flagged), mode


@pytest.mark.parametrize("mode", ["spheres", "capsules", "exact"])
def test_free_path_guarantee_holds_between_samples(
    wb: Workbench, engines: dict[str, CollisionEngine], mode: str
) -> None:
    """Twin: fcl distance on a 8x denser sampling stays >= the reported clearance."""
    qs = np.linspace(Q_FREE, [1.0, 0.3, 0.0, 0.5, 0.0, 0.0], 12)
    rep = engines[mode].check_path(qs, np.linspace(0, 1.1, 12))
    assert rep.collision_free and rep.clearance > 0, rep.message
    assert "collision-free, including between samples, with clearance of at least" in rep.message
    dense = np.linspace(qs[0], qs[-1], 90)
    d = [wb.checker.check(x).min_distance for x in dense]
    assert min(d) >= rep.clearance - 1e-9


@pytest.mark.parametrize("mode", ["spheres", "capsules", "exact"])
def test_colliding_path_names_time_link_obstacle_and_penetration(
    wb: Workbench, engines: dict[str, CollisionEngine], mode: str
) -> None:
    """Coarse samples (3) that jump over the contact: the collision is found between them."""
    qs = np.array([Q_FREE, Q_HIT, Q_FREE])
    times = np.array([0.0, 1.0, 2.0])
    # The first exact contact along the straight segment, by dense sampling (the twin).
    dense = np.linspace(Q_FREE, Q_HIT, 101)
    hit = [wb.checker.check(x, distance=False).in_collision for x in dense]
    assert any(hit)
    rep = engines[mode].check_path(qs, times)
    assert not rep.collision_free
    assert rep.first_time is not None and rep.first_time <= 1.0 + 1e-9
    assert rep.obstacle == "block" and rep.link is not None
    assert rep.penetration >= 0.0
    assert rep.first_report is not None and rep.first_report.in_collision
    assert "hits block" in rep.message


def test_bad_input(wb: Workbench) -> None:
    with pytest.raises(InputError, match="mode"):
        CollisionEngine(wb.checker, "voxels")
    with pytest.raises(InputError, match="spheres_per_link"):
        CollisionEngine(wb.checker, "spheres", spheres_per_link=0)
    with pytest.raises(InputError, match="margin"):
        CollisionEngine(wb.checker, "exact", margin=float("nan"))
    eng = CollisionEngine(wb.checker, "exact")
    with pytest.raises(InputError, match="shape"):
        eng.check_path(np.zeros((3, 5)))
    with pytest.raises(InputError, match="times"):
        eng.check_path(np.zeros((3, 6)), [0.0, 1.0])
