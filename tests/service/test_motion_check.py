"""Motion plans check their trajectory with the fast engine: same sample verdicts as the dense check."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from workbench.motion.validation import acceleration_bound, interval_acceleration_bound
from workbench.service import Workbench

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "projects" / "mz07_cell.json"


@pytest.fixture(scope="module")
def cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A fresh cache: the first plan fits the spheres and builds the field itself."""
    return tmp_path_factory.mktemp("wbcache")


@pytest.mark.slow  # over 5 s here
def test_plan_uses_the_fast_mode_and_matches_the_dense_check(
    cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    wb = Workbench.open(EXAMPLE)
    plan = wb.plan_motion()
    rep = plan.collision_report
    assert rep.fallback is None and rep.mode == "spheres"
    assert list((cache / "sdf").glob("spheres-*.npz")) and list((cache / "sdf").glob("sdf-*.npz"))
    dense = wb.checker.check_path(plan.positions, distance=True)
    assert rep.colliding_indices == dense.colliding_indices
    assert rep.collision_free == dense.collision_free
    assert "collision-free, including between samples (" in rep.message
    # The one clearance figure: fcl's least distance over the samples, with its pair.
    near = rep.nearest
    assert near is not None and near.pair is not None
    assert near.distance == pytest.approx(dense.min_distance, abs=1e-9)
    assert f"clearance {near.distance * 1e3:.1f} mm ({near.pair[0]} – {near.pair[1]}" in rep.message
    assert rep.message in plan.summary()
    # The certified clearance is a lower bound of fcl's distance at every sample.
    assert 0.0 < rep.clearance <= dense.min_distance + 1e-9
    # A second session starts from the cache and gives the same report.
    again = Workbench.open(EXAMPLE).plan_motion()
    assert again.collision_report.clearance == pytest.approx(rep.clearance)


def test_a_colliding_plan_names_the_first_contact(
    cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The table raised into the program's path: the first failure is where the dense check says."""
    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    data = json.loads(EXAMPLE.read_text())
    table = next(o for o in data["cell"]["objects"] if o["name"] == "table")
    table["size"][2] += 400
    table["pose"]["xyz"][2] += 200
    wb = Workbench.from_dict(data)
    plan = wb.plan_motion()
    rep = plan.collision_report
    dense = [wb.checker.check(q, distance=False).in_collision for q in plan.positions]
    assert rep.colliding_indices == tuple(np.flatnonzero(dense))
    assert not plan.ok and rep.first_time is not None
    first = int(np.flatnonzero(dense)[0])
    assert rep.first_time <= plan.times[first] + 1e-9
    assert plan.colliding[first]
    assert "collision at t =" in rep.message and rep.link is not None


def test_open_mesh_obstacle_falls_back_to_the_dense_exact_check(tmp_path: Path) -> None:
    box = trimesh.creation.box((0.2, 0.2, 0.2))
    top = np.flatnonzero(box.face_normals[:, 2] > 0.5)
    trimesh.Trimesh(box.vertices * 1000, np.delete(box.faces, top, axis=0)).export(
        tmp_path / "tray.stl"
    )
    data = json.loads(EXAMPLE.read_text())
    data["cell"]["objects"].append(
        {"name": "tray", "shape": "mesh", "path": "tray.stl", "pose": {"xyz": [-900, 900, 100]}}
    )
    wb = Workbench.from_dict(data, base_dir=tmp_path)
    plan = wb.plan_motion()
    rep = plan.collision_report
    assert rep.fallback is not None and "tray" in rep.fallback
    assert "not certified between samples" in rep.message
    dense = wb.checker.check_path(plan.positions)
    assert rep.colliding_indices == dense.colliding_indices


def test_acceleration_bound_is_the_trajectory_peak(
    cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Twin: accelerations sampled every 0.1 ms stay below the bound and reach it."""
    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    wb = Workbench.open(EXAMPLE)
    traj = wb.plan_motion().trajectory
    bound = acceleration_bound(traj)
    _, _, _, acc = traj.sample(1e-4)
    peak = np.abs(acc).max(axis=0)
    assert np.all(peak <= bound + 1e-9)
    assert np.all(bound - peak <= np.abs(traj.piece_j).max(axis=1) * 1e-4 + 1e-9)


def test_interval_acceleration_bound_holds_on_every_interval(
    cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Twin: accelerations sampled every 0.1 ms within each interval stay below its bound."""
    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    wb = Workbench.open(EXAMPLE)
    traj = wb.plan_motion().trajectory
    ts, _, _, acc = traj.sample(1e-4)
    rng = np.random.default_rng(3)
    t0 = rng.uniform(0.0, traj.duration, 400)
    t1 = np.minimum(t0 + rng.uniform(0.0, 0.3, 400), traj.duration)
    t0[:5], t1[:5] = 0.0, traj.duration  # whole trajectory: the global bound
    bound = interval_acceleration_bound(traj)(t0, t1)
    for k in range(len(t0)):
        inside = (ts >= t0[k]) & (ts <= t1[k])
        if inside.any():
            assert np.all(np.abs(acc[inside]).max(axis=0) <= bound[k] + 1e-9), k
    assert np.allclose(bound[:5], acceleration_bound(traj))
    # Not vacuous: far below the whole trajectory's bound on most short intervals.
    short = (t1 - t0) < 0.05
    assert np.median(bound[short].sum(axis=1) / acceleration_bound(traj).sum()) < 0.9


def test_the_chord_slack_covers_the_jumps_where_pieces_meet(
    cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The a·h²/8 chord bound needs a C1 motion; the pieces' rounding jumps stay in PIECE_JUMP."""
    from workbench.collision.path_check import PIECE_JUMP

    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    traj = Workbench.open(EXAMPLE).plan_motion().trajectory
    starts = np.unique(
        traj.piece_start[(traj.piece_start > 0) & (traj.piece_start < traj.duration)]
    )
    before = traj.at(np.nextafter(starts, -np.inf))[0]
    after = traj.at(starts)[0]
    jump = np.abs(after - before).max()
    assert jump <= PIECE_JUMP
