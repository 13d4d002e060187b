"""Grasp footprints against holes and edges, checked by brute force: points sampled densely
over the cup or pad (a polar/lattice grid, no shapely) tested against the hole polygons and
the outline by a ray-crossing point-in-polygon written here."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.grasp_footprint import Footprint, footprint_problem, screen_grasps
from workbench.pressbrake.grasp_grid import grasp_grid
from workbench.sheetmetal import SheetMetalPart
from workbench.sheetmetal.holes import CHORD_TOLERANCE, circle

T = 0.002


def inside(poly: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Even-odd ray crossing: which points (N, 2) lie inside `poly` (k, 2)."""
    x, y = pts[:, 0:1], pts[:, 1:2]
    a, b = poly, np.roll(poly, -1, axis=0)
    crosses = ((a[:, 1] > y) != (b[:, 1] > y)) & (
        x < a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1] + 1e-300)
    )
    return crosses.sum(axis=1) % 2 == 1


def samples(part: SheetMetalPart, g: Grasp, fp: Footprint) -> np.ndarray:
    """Points (N, 2) filling the footprint at `g` in the flange frame (lattice inside it)."""
    lo, hi = fp.polygon.min(axis=0), fp.polygon.max(axis=0)
    xs, ys = np.meshgrid(np.linspace(lo[0], hi[0], 61), np.linspace(lo[1], hi[1], 61))
    pts = np.c_[xs.ravel(), ys.ravel()]
    pts = pts[inside(fp.polygon, pts)]
    c, s = np.cos(g.yaw), np.sin(g.yaw)
    return pts @ np.array([[c, s], [-s, c]]) + g.offset


def bracket() -> SheetMetalPart:
    return SheetMetalPart.from_spec(
        {
            "thickness": T,
            "flanges": [
                {
                    "name": "F1",
                    "polygon": [[0, 0], [0.12, 0], [0.12, 0.08], [0, 0.08]],
                    "holes": [
                        circle((0.03, 0.04), 0.006).tolist(),
                        [[0.07, 0.03], [0.1, 0.03], [0.1, 0.045], [0.07, 0.045]],
                    ],
                },
                {"name": "F2", "polygon": [[0, 0], [0.12, 0], [0.12, 0.04], [0, 0.04]]},
            ],
            "bends": [
                {
                    "name": "B1",
                    "parent": "F1",
                    "parent_edge": 2,
                    "child": "F2",
                    "child_edge": 0,
                    "included_angle": np.pi / 2,
                    "inner_radius": 0.002,
                }
            ],
        }
    )


@pytest.mark.parametrize("fp", [Footprint.cup(0.02), Footprint.pad(0.03, 0.012)])
def test_footprint_verdict_agrees_with_sampled_points(fp: Footprint) -> None:
    part = bracket()
    grasps = grasp_grid(part, spacing=0.008, inset=0.0, yaws=(0.0, 0.6), flanges=["F1"])
    fl = part.flanges[0]
    seen = set()
    for g in grasps:
        pts = samples(part, g, fp)
        hole_hit = [bool(inside(h, pts).any()) for h in fl.holes]
        over = float((~inside(fl.polygon, pts)).mean())
        why = footprint_problem(part, g, fp)
        if any(hole_hit):
            k = hole_hit.index(True)
            assert why == f"covers hole H{k + 1} of flange F1", (g.offset, g.yaw)
        elif over > 0.01:  # sampling resolves overhangs down to about 1/100 of the area
            assert why is not None and "hangs" in why
        if why is None:  # the converse: an accepted footprint has no sample in a hole or off
            assert not any(hole_hit) and over == 0
        seen.add(why.split(" of")[0] if why else None)
    assert {None, "covers hole H1", "covers hole H2"} <= seen


def test_overhang_fraction_is_a_setting() -> None:
    part = bracket()
    edge = Grasp("F1", np.array([0.12, 0.07]), 0.0)  # pad centred on the edge: half over it
    fp = Footprint.pad(0.02, 0.01)
    assert "hangs 50 %" in footprint_problem(part, edge, fp)
    assert footprint_problem(part, edge, fp, max_overhang=0.5) is None


def test_a_part_whose_only_grasps_cover_holes_is_refused_naming_the_flange() -> None:
    part = bracket()
    on_holes = [
        Grasp("F1", np.array([0.03, 0.04]), 0.0),
        Grasp("F1", np.array([0.085, 0.0375]), 1.0),
    ]
    with pytest.raises(InputError, match="flange F1: covers hole H1 of flange F1"):
        screen_grasps(part, on_holes, Footprint.cup(0.01))
    kept, refused = screen_grasps(
        part, [*on_holes, Grasp("F1", np.array([0.06, 0.065]))], Footprint.cup(0.01)
    )
    assert len(kept) == 1 and [w for _, w in refused] == [
        "covers hole H1 of flange F1",
        "covers hole H2 of flange F1",
    ]


def test_holding_force_against_a_hand_computation() -> None:
    from workbench.pressbrake.grasp_holding import holding

    part = bracket()
    cup = Footprint.cup(0.04)
    h = holding(part, cup, peak_accel=5.0)
    # by hand: area of the blank (two rectangles, the bend strip, less two holes) x t x 7850
    strip = part.bend_allowances[0] * 0.12
    holes = sum(
        abs(np.sum(h_[:, 0] * np.roll(h_[:, 1], -1) - np.roll(h_[:, 0], -1) * h_[:, 1])) / 2
        for h_ in part.flanges[0].holes  # shoelace
    )
    mass = (0.12 * 0.08 + 0.12 * 0.04 + strip - holes) * T * 7850.0
    assert h.mass == pytest.approx(mass, rel=1e-12)
    assert h.needed == pytest.approx(mass * (9.80665 + 5.0) * 1.5, rel=1e-12)
    r = 0.02
    # chorded cup: between the circles through its chords' midpoints and its vertices
    assert np.pi * (r - CHORD_TOLERANCE) ** 2 * 60e3 < h.available <= np.pi * r**2 * 60e3
    assert h.holds and "holds" in h.report()
    weak = holding(part, Footprint.cup(0.004), peak_accel=5.0)
    assert not weak.holds and "does NOT hold" in weak.report()
