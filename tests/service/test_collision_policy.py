"""The plan collision policy is one project field, used by all four workflows' plans.

Twin: the exact mode checks every sample densely with python-fcl, so its colliding samples
are the ground truth that the default (spheres + SDF, confirmed by fcl) must equal.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from workbench.collision import CollisionPolicy
from workbench.errors import InputError, WorkbenchError
from workbench.service import Workbench

ROOT = Path(__file__).resolve().parents[2]
PROJECTS = ROOT / "projects"


def _mz07(wb: Workbench) -> list[Any]:
    return [wb.plan_motion().collision_report]


def _bending(wb: Workbench) -> list[Any]:
    return [wb.bending.plan().robot_report]


def _assembly(wb: Workbench) -> list[Any]:
    return list(wb.assembly.plan_sequence().robot_reports.values())


def _polishing(wb: Workbench) -> list[Any]:
    wb.polishing.plan_path()
    return [wb.polishing.plan_motion().collision_report]


WORKFLOWS: dict[str, tuple[str, Callable[[Workbench], list[Any]]]] = {
    "mz07": ("mz07_cell.json", _mz07),
    "bending": ("bending_cell.json", _bending),
    "assembly": ("assembly_cell.json", _assembly),
    "polishing": ("polishing_cell.json", _polishing),
}


@pytest.fixture(scope="module")
def cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("wbcache")


@pytest.mark.slow
@pytest.mark.parametrize("workflow", list(WORKFLOWS))
def test_the_mode_is_one_project_field_for_every_workflow(
    workflow: str, cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    name, plan = WORKFLOWS[workflow]
    data = json.loads((PROJECTS / name).read_text())
    assert "collision" not in data  # the examples use the default
    default = Workbench.from_dict(data, base_dir=PROJECTS)
    assert default.collision_policy == CollisionPolicy(margin=0.0005)  # the default 0.5 mm
    fast = plan(default)
    assert fast and all(r.mode == "spheres" and r.fallback is None for r in fast)

    data["collision"] = {"mode": "exact"}
    wb = Workbench.from_dict(data, base_dir=PROJECTS)
    assert wb.collision_policy.mode == "exact"
    exact = plan(wb)
    assert all(r.mode == "exact" and not r.certified for r in exact)
    assert all("exact check" in r.message and "collision mode is exact" in r.message for r in exact)
    # The same samples collide in both modes (the fast mode's verdicts are the exact ones).
    assert [r.colliding_indices for r in exact] == [r.colliding_indices for r in fast]


def test_set_mode_changes_the_next_plan_and_is_saved(
    cache: Path, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    assert wb.collision.mode == "spheres"
    wb.collision.set_mode("exact")
    assert wb.collision_policy.mode == "exact"
    assert wb.plan_motion().collision_report.mode == "exact"
    saved = json.loads(wb.save(tmp_path / "p.json").read_text())
    assert saved["collision"]["mode"] == "exact"
    assert Workbench.open(tmp_path / "p.json").collision_policy.mode == "exact"
    with pytest.raises(InputError, match="collision.mode"):
        wb.collision.set_mode("voxels")
    assert wb.collision_policy.mode == "exact"  # refused: unchanged
    wb.collision.set_mode("spheres")
    rep = wb.plan_motion().collision_report
    assert rep.mode == "spheres" and rep.fallback is None


def test_capsules_mode_serves_a_whole_plan(cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The capsules engine certifies the plan too, with the exact sample verdicts."""
    monkeypatch.setenv("WORKBENCH_CACHE", str(cache))
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    wb.collision.set_mode("capsules")
    rep = wb.plan_motion().collision_report
    assert rep.mode == "capsules" and rep.fallback is None, rep.message
    dense = wb.checker.check_path(wb.last_plan.positions)  # type: ignore[union-attr]
    assert rep.colliding_indices == dense.colliding_indices
    assert rep.collision_free == dense.collision_free


def test_a_bad_policy_in_the_project_names_the_field() -> None:
    data = json.loads((PROJECTS / "mz07_cell.json").read_text())
    data["collision"] = {"mode": "voxels"}
    with pytest.raises(WorkbenchError, match="collision.mode"):
        Workbench.from_dict(data, base_dir=PROJECTS)
    with pytest.raises(InputError, match="mode"):
        CollisionPolicy(mode="voxels")  # type: ignore[arg-type]


def test_an_open_mesh_falls_back_even_when_the_panel_built_the_spheres_engine(
    tmp_path: Path,
) -> None:
    """The plan's fallback does not depend on whether the Robot tab built an engine first."""
    import numpy as np
    import trimesh

    from workbench.collision import shared_engine

    box = trimesh.creation.box((0.2, 0.2, 0.2))
    top = np.flatnonzero(box.face_normals[:, 2] > 0.5)
    trimesh.Trimesh(box.vertices * 1000, np.delete(box.faces, top, axis=0)).export(
        tmp_path / "tray.stl"
    )
    data = json.loads((PROJECTS / "mz07_cell.json").read_text())
    data["cell"]["objects"].append(
        {"name": "tray", "shape": "mesh", "path": "tray.stl", "pose": {"xyz": [-900, 900, 100]}}
    )
    wb = Workbench.from_dict(data, base_dir=tmp_path)
    policy = wb.collision_policy
    eng, why = shared_engine(wb.checker, policy)
    assert eng is None and why is not None and "'tray' is not watertight" in why
    # What the collision panel's build leaves in the checker's cache (a stand-in: the check
    # must not reach it).
    wb.checker.engines[policy.key()] = object()
    assert shared_engine(wb.checker, policy) == (None, why)
