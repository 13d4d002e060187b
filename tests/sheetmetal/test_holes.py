"""Flange holes: validation, chording, the solid cut through (volume, watertight, brute force)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
import trimesh

from workbench.errors import InputError
from workbench.sheetmetal import SheetMetalPart, bend_allowance
from workbench.sheetmetal.holes import CHORD_TOLERANCE, MIN_HOLE_GAP, circle

T, R, W = 0.002, 0.004, 0.08


def rect(x0: float, y0: float, x1: float, y1: float) -> list[list[float]]:
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def slot(cx: float, cy: float, length: float, r: float) -> np.ndarray:
    """Stadium: a long hole of straight length `length` and end radius `r` (chorded)."""
    return np.asarray(
        shapely.LineString([[cx - length / 2, cy], [cx + length / 2, cy]])
        .buffer(r, 16)
        .exterior.coords
    )[:-1]


def spec(base_holes: list, wall_holes: list | None = None) -> dict:
    return {
        "thickness": T,
        "flanges": [
            {"name": "base", "polygon": rect(0, 0, W, 0.06), "holes": base_holes},
            {"name": "wall", "polygon": rect(0, 0, W, 0.04), "holes": wall_holes or []},
        ],
        "bends": [
            {
                "name": "b1",
                "parent": 0,
                "parent_edge": 2,
                "child": 1,
                "child_edge": 0,
                "included_angle": np.pi / 2,
                "inner_radius": R,
            }
        ],
    }


def area(ring) -> float:
    return float(shapely.Polygon(ring).area)


def test_solid_has_the_holes_cut_through() -> None:
    holes = [
        circle((0.02, 0.02), 0.004),
        slot(0.05, 0.02, 0.015, 0.003),
        rect(0.03, 0.035, 0.045, 0.045),
    ]
    wall = [circle((0.04, 0.025), 0.005)]
    part = SheetMetalPart.from_spec(
        spec([h.tolist() if isinstance(h, np.ndarray) else h for h in holes], [wall[0].tolist()])
    )
    hole_area = sum(area(h) for h in holes) + area(wall[0])
    full = W * (0.06 + 0.04 + bend_allowance(R, T, np.pi / 2))
    for step in (0, 0.5, 1):
        mesh = part.fold(step).solid()
        assert mesh.is_watertight and mesh.is_winding_consistent
        # Closed form: the bend keeps its volume; the flanges lose hole area x thickness.
        assert mesh.volume == pytest.approx(T * (full - hole_area), rel=1e-9)
        assert part.blank_area() == pytest.approx(full - hole_area, rel=1e-12)
    # Brute force: points on the mid-surface at each hole centre are outside the solid,
    # points on the mid-surface between the holes are inside (trimesh ray test).
    flat = part.fold(0)
    mesh = flat.solid()
    centres = np.array([[0.02, 0.02, 0], [0.05, 0.02, 0], [0.0375, 0.04, 0]])
    assert not mesh.contains(centres).any()
    assert mesh.contains(np.array([[0.035, 0.02, 0], [0.07, 0.05, 0]])).all()
    # The wall's hole, carried by the fold: its centre in the part frame is outside.
    Tw = part.fold(1).T_part_flange[1]
    c = Tw[:3, :3] @ np.array([0.04, 0.025, 0]) + Tw[:3, 3]
    assert not trimesh.Trimesh.contains(part.fold(1).solid(), c[None])[0]


def test_circle_chords_within_tolerance() -> None:
    for r in (0.001, 0.005, 0.05):
        ring = circle((0.1, -0.2), r)
        mids = (ring + np.roll(ring, -1, axis=0)) / 2
        sag = r - np.linalg.norm(mids - [0.1, -0.2], axis=1)
        assert sag.max() <= CHORD_TOLERANCE + 1e-15
        assert np.allclose(np.linalg.norm(ring - [0.1, -0.2], axis=1), r)


@pytest.mark.parametrize(
    ("holes", "wall", "words"),
    [
        ([rect(-0.01, 0.01, 0.01, 0.02)], None, "inside the flange's outline"),
        ([rect(MIN_HOLE_GAP / 2, 0.01, 0.01, 0.02)], None, "inside the flange's outline"),
        ([rect(0.01, 0.01, 0.03, 0.03), rect(0.02, 0.02, 0.04, 0.04)], None, "holes[0]"),
        (
            [rect(0.01, 0.01, 0.03, 0.03), rect(0.03 + MIN_HOLE_GAP / 2, 0.01, 0.04, 0.02)],
            None,
            "holes[0]",
        ),
        ([[[0.01, 0.01], [0.03, 0.03], [0.03, 0.01], [0.01, 0.03]]], None, "simple"),
        ([rect(0.01, 0.06 - R - T + 0.0005, 0.02, 0.059)], None, "bend 'b1'"),
        ([], [rect(0.01, 0.001, 0.02, 0.01)], "bend 'b1'"),
    ],
)
def test_bad_holes_are_refused_naming_flange_and_hole(holes, wall, words) -> None:
    with pytest.raises(InputError, match="holes") as exc:
        SheetMetalPart.from_spec(spec(holes, wall))
    assert words in str(exc.value)
    assert ("'wall'" if wall else "'base'") in str(exc.value)


def test_clockwise_hole_is_made_counter_clockwise() -> None:
    ring = rect(0.01, 0.01, 0.02, 0.02)[::-1]
    part = SheetMetalPart.from_spec(spec([ring]))
    assert shapely.Polygon(part.flanges[0].holes[0]).exterior.is_ccw
