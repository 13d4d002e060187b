"""`bending.grasp_grid`: the sequence search's candidate grasps are a named project setting.

Its defaults are the domain's `GridSettings()`; through the service the setting is the grid
the search takes (twin: `grasp_grid` called with the same values); bad values name the field.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import shapely

from workbench import Workbench
from workbench.errors import WorkbenchError
from workbench.pressbrake.grasp_grid import GridSettings, grasp_grid
from workbench.project.grasp_grid import GraspGridSpec
from workbench.service.bending_process import sweep_context

ROOT = Path(__file__).resolve().parents[2]
CELL = ROOT / "projects" / "u_channel_cell.json"


def _open(**grid: Any) -> Workbench:
    data = json.loads(CELL.read_text())
    data["bending"]["grasp_grid"] = grid
    return Workbench.from_dict(data, base_dir=ROOT / "projects")


def test_the_defaults_are_the_domains() -> None:
    got, want = GraspGridSpec().to_si(), GridSettings()
    assert got.spacing == pytest.approx(want.spacing, rel=1e-15)
    assert got.inset == pytest.approx(want.inset, rel=1e-15)
    np.testing.assert_allclose(got.yaws, want.yaws, rtol=0, atol=1e-15)
    assert got.faces == want.faces


def test_the_search_takes_the_projects_grid() -> None:
    wb = _open(spacing=40, inset=5, yaws=[0, 180], faces=["top", "bottom"])
    ctx = sweep_context(wb.bending)
    want = grasp_grid(wb.bending.part, spacing=0.04, inset=0.005, yaws=(0.0, np.pi), faces=(1, -1))
    assert len(ctx.grasps) == len(want) > 0
    for a, b in zip(ctx.grasps, want, strict=True):
        assert (a.flange, a.face) == (b.flange, b.face)
        np.testing.assert_allclose(a.offset, b.offset, atol=1e-12)
        assert a.yaw == pytest.approx(b.yaw, abs=1e-12)
    assert {g.face for g in ctx.grasps} == {1, -1}
    default = sweep_context(Workbench.open(CELL).bending)
    assert {g.face for g in default.grasps} == {1} and len(default.grasps) != len(want)


@pytest.mark.parametrize(
    ("grid", "field"),
    [
        ({"spacing": 0}, "bending.grasp_grid.spacing"),
        ({"spacing": float("nan")}, "bending.grasp_grid.spacing"),
        ({"inset": -1}, "bending.grasp_grid.inset"),
        ({"yaws": []}, "bending.grasp_grid.yaws"),
        ({"yaws": [0, 90, 0]}, "bending.grasp_grid.yaws"),
        ({"faces": ["top", "top"]}, "bending.grasp_grid.faces"),
        ({"faces": ["side"]}, "bending.grasp_grid.faces"),
        ({"rows": 3}, "bending.grasp_grid.rows"),
    ],
)
def test_bad_grids_name_the_field(grid: dict[str, Any], field: str) -> None:
    with pytest.raises(WorkbenchError, match=field.replace(".", r"\.")):
        _open(**grid)


def test_a_grid_with_too_many_candidates_says_how_to_fix_it() -> None:
    wb = _open(spacing=2, inset=0)
    with pytest.raises(WorkbenchError, match=r"bending\.grasp_grid: .*widen the spacing"):
        wb.bending.find_sequences()


def test_a_cup_footprint_sets_apart_the_grasps_over_an_edge_and_says_why() -> None:
    wide = dict(spacing=40, inset=0, yaws=[0])
    free = sweep_context(_open(**wide).bending)
    ctx = sweep_context(_open(**wide, cup_diameter=30).bending)
    assert not free.refused and ctx.refused
    assert len(ctx.grasps) + len(ctx.refused) == len(free.grasps)
    part = _open(**wide).bending.part
    for g, why in ctx.refused:  # inset 0: every refused cup centre is within 15 mm of an edge
        poly = shapely.Polygon(part.flanges[part.flange_index(g.flange)].polygon)
        assert "hangs" in why and poly.exterior.distance(shapely.Point(*g.offset)) < 0.015
    for g in ctx.grasps:
        poly = shapely.Polygon(part.flanges[part.flange_index(g.flange)].polygon)
        assert poly.exterior.distance(shapely.Point(*g.offset)) >= 0.015 - 1e-4  # chorded cup
    half = sweep_context(_open(**wide, cup_diameter=30, max_overhang=0.5).bending)
    assert len(half.refused) < len(ctx.refused)
    with pytest.raises(WorkbenchError, match="cup_diameter or pad"):
        _open(**wide, cup_diameter=30, pad=[20, 10])
