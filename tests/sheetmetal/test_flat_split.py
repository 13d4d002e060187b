"""Flat patterns (workbench.cad.flat_pattern): outline + bend lines <-> the part model.

Checked against hand computations (flange lengths solved back from the flat width: flat width
= sum of flanges + sum of bend allowances, K read from seed Table 1 by hand), against the
example parts themselves (their flat blank cut back into flanges gives the same flanges,
bends and folded frames), and every refusal names the field and the fix.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import shapely

from workbench.cad.flat_pattern import (
    BendLine,
    FlatPattern,
    FlatPatternError,
)
from workbench.errors import InputError
from workbench.sheetmetal.flat_blank import flat_pattern_of_part
from workbench.sheetmetal.flat_split import part_spec_from_flat_pattern
from workbench.sheetmetal.part import SheetMetalPart

ROOT = Path(__file__).resolve().parents[2]
MM = 1e-3
FIELD = "bending.part_file (flat.dxf)"
# The example parts and the inner radius [mm] their bends take where the file gives none
# (the pan's and the U-channel's come from the press's die in their cells).
EXAMPLES = {"u_channel": 2.0, "pan": 1.92, "seed_part": 1.5}


def load_part(name: str, radius_mm: float) -> SheetMetalPart:
    """Return projects/parts/<name>.json as a part (mm/deg -> m/rad by hand)."""
    d = json.loads((ROOT / "projects" / "parts" / f"{name}.json").read_text())
    spec = {
        "thickness": d["thickness"] * MM,
        "k_factor": d.get("k_factor"),
        "flanges": [
            {"name": f["name"], "polygon": (np.array(f["polygon"]) * MM).tolist()}
            for f in d["flanges"]
        ],
        "bends": [
            dict(
                b,
                included_angle=np.radians(b["included_angle"]),
                inner_radius=b.get("inner_radius", radius_mm) * MM,
            )
            for b in d["bends"]
        ],
        "sequence": d.get("sequence"),
    }
    return SheetMetalPart.from_spec(spec)


def _rect(x0: float, y0: float, x1: float, y1: float) -> np.ndarray:
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]]) * MM


def _line(a: Any, b: Any, deg: float = 90.0, direction: int = 1, r_mm: float | None = None):
    r = None if r_mm is None else r_mm * MM
    return BendLine(np.array(a, float) * MM, np.array(b, float) * MM, np.radians(deg), direction, r)


def _spec(pattern: FlatPattern, t_mm: float, r_mm: float | None = None, k=None) -> dict:
    r = None if r_mm is None else r_mm * MM
    return part_spec_from_flat_pattern(
        pattern, thickness=t_mm * MM, inner_radius=r, k_factor=k, field=FIELD
    )


def test_u_channel_flange_lengths_solve_back_from_the_flat_width() -> None:
    # t = 2, r = 2 mm: r/t = 1, Table 1 gives K = 0.30; BA = (pi/2)(2 + 0.30 * 2) mm.
    ba = np.pi / 2 * (2.0 + 0.30 * 2.0)
    a, b, c = 25.0, 100.0, 110.0  # the flanges a designer wants
    width = a + b + c + 2 * ba  # flat width = sum of flanges + sum of bend allowances
    y1, y2 = a + ba / 2, a + ba + b + ba / 2  # the bend lines: middles of the zones
    pattern = FlatPattern(
        _rect(0, 0, 200, width), (_line((0, y1), (200, y1)), _line((200, y2), (0, y2)))
    )
    part = SheetMetalPart.from_spec(_spec(pattern, 2.0, 2.0))
    # Each flange's length across the bend lines (its own frame has the bend edge along x;
    # the base keeps the drawing's frame, where the lines also run along x).
    lengths = {f.name: float(np.ptp(f.polygon[:, 1])) / MM for f in part.flanges}
    # the base F1 is the largest (c); B2 reaches F2 (b) from it, B1 then F3 (a)
    assert lengths == pytest.approx({"F1": c, "F2": b, "F3": a}, abs=1e-9)
    assert [(x.parent, x.child) for x in part.bends] == [(1, 2), (0, 1)]
    assert part.bend_allowances / MM == pytest.approx([ba, ba], abs=1e-12)
    assert [b.name for b in part.bends] == ["B1", "B2"]
    assert part.blank_area() == pytest.approx(200 * width * MM**2, rel=1e-12)


def test_the_k_factor_and_radius_arguments_set_the_zone_width() -> None:
    pattern = FlatPattern(_rect(0, 0, 100, 100), (_line((0, 40), (100, 40), 60.0, -1, 3.0),))
    part = SheetMetalPart.from_spec(_spec(pattern, 1.0, 1.0, k=0.45))
    # the line's own radius (3 mm) wins over the argument; K = 0.45 given: BA = (pi/3)(3 + 0.45)
    ba = np.pi / 3 * (3.0 + 0.45 * 1.0)
    assert part.bends[0].inner_radius == pytest.approx(3.0 * MM)
    assert part.bends[0].direction == -1 and np.degrees(part.bends[0].angle) == pytest.approx(60)
    assert part.bend_allowances[0] / MM == pytest.approx(ba)
    areas = sorted(float(shapely.Polygon(f.polygon).area) / MM**2 for f in part.flanges)
    assert areas == pytest.approx(sorted([100 * (40 - ba / 2), 100 * (60 - ba / 2)]))


def _flat(part: SheetMetalPart) -> list[np.ndarray]:
    T = part.fold(0).T_part_flange
    return [f.polygon @ T[i, :2, :2].T + T[i, :2, 3] for i, f in enumerate(part.flanges)]


def match_parts(a: SheetMetalPart, b: SheetMetalPart) -> tuple[list[int], list[int]]:
    """Return (flange of `b` per flange of `a`, bend of `b` per bend of `a`), matched in the flat
    blank (same part frame) by flange centroid and bend-line midpoint."""
    ca = [shapely.Polygon(p).centroid for p in _flat(a)]
    cb = [shapely.Polygon(p).centroid for p in _flat(b)]
    flanges = [int(np.argmin([x.distance(y) for y in cb])) for x in ca]
    la, lb = flat_pattern_of_part(a).bend_lines, flat_pattern_of_part(b).bend_lines
    mids = [0.5 * (ln.start + ln.end) for ln in lb]
    bends = [
        int(np.argmin([np.linalg.norm(0.5 * (ln.start + ln.end) - m) for m in mids])) for ln in la
    ]
    return flanges, bends


def assert_same_part(a: SheetMetalPart, b: SheetMetalPart, tol: float = 0.1 * MM) -> None:
    """The same flanges (flat polygons, areas), bends (angle, direction, radius) and folded frames."""
    flanges, bends = match_parts(a, b)
    assert sorted(flanges) == list(range(len(b.flanges))) and len(a.flanges) == len(b.flanges)
    assert sorted(bends) == list(range(len(b.bends))) and len(a.bends) == len(b.bends)
    fa, fb = _flat(a), _flat(b)
    for i, j in enumerate(flanges):
        pa, pb = shapely.Polygon(fa[i]), shapely.Polygon(fb[j])
        assert pb.area == pytest.approx(pa.area, abs=tol * pa.length)
        for p, q in ((fa[i], fb[j]), (fb[j], fa[i])):
            d = np.linalg.norm(p[:, None, :] - q[None, :, :], axis=2).min(axis=1)
            assert d.max() < tol, (a.flanges[i].name, d.max())
    for i, j in enumerate(bends):
        x, y = a.bends[i], b.bends[j]
        assert np.degrees(y.angle) == pytest.approx(np.degrees(x.angle), abs=0.01)
        assert y.direction == x.direction
        assert y.inner_radius == pytest.approx(x.inner_radius, abs=tol)
    # Folded, step by step in the same order: the same flange frames (up to each flange's
    # in-plane choice of polygon frame, fixed in the flat blank), relative to a's base.
    order = [b.bends[j].name for j in bends]
    b_in_a_order = SheetMetalPart(b.thickness, list(b.flanges), [b.bends[j] for j in bends])
    assert [x.name for x in b_in_a_order.bends] == order
    Ta0, Tb0 = a.fold(0).T_part_flange, b_in_a_order.fold(0).T_part_flange
    ref = flanges[0]
    for step in range(len(a.bends) + 1):
        Ta = a.fold(step).T_part_flange
        Tb = b_in_a_order.fold(step).T_part_flange
        Tb = Tb0[ref] @ np.linalg.inv(Tb[ref]) @ Tb  # b's frames with a's base held (T = I)
        for i, j in enumerate(flanges):
            M = np.linalg.inv(Ta0[i]) @ Tb0[j]  # b's flange frame in a's, flat
            err = Ta[i] @ M - Tb[j]
            assert np.abs(err[:3, :3]).max() < 1e-6 and np.abs(err[:3, 3]).max() < tol


@pytest.mark.parametrize("name", list(EXAMPLES))
def test_an_example_parts_flat_blank_cuts_back_into_the_same_part(name: str) -> None:
    part = load_part(name, EXAMPLES[name])
    pattern = flat_pattern_of_part(part)
    # the blank is fused on a 1 nm grid
    assert shapely.Polygon(pattern.outline).area == pytest.approx(part.blank_area(), rel=1e-7)
    again = SheetMetalPart.from_spec(
        part_spec_from_flat_pattern(
            pattern, thickness=part.thickness, inner_radius=None, k_factor=None, field=FIELD
        )
    )
    assert_same_part(part, again)
    assert again.flanges[0].name == "F1"
    big = max(shapely.Polygon(f.polygon).area for f in again.flanges)
    assert shapely.Polygon(again.flanges[0].polygon).area == pytest.approx(big)


def _refused(pattern: FlatPattern, *fix: str, t_mm: float = 2.0, r_mm: float | None = 2.0) -> str:
    with pytest.raises(FlatPatternError) as err:
        _spec(pattern, t_mm, r_mm)
    msg = str(err.value)
    assert isinstance(err.value, InputError) and err.value.field == FIELD
    assert msg.startswith(FIELD + ":"), msg
    for part in fix:
        assert part in msg, msg
    return msg


def test_refusals_name_the_field_the_bend_line_and_the_fix() -> None:
    box = _rect(0, 0, 200, 100)
    short = FlatPattern(box, (_line((5, 50), (200, 50)),))
    _refused(short, "bend line 1 from (5, 50) to (200, 50) mm", "5 mm inside", "edge to edge")
    u = np.array([[0, 0], [200, 0], [200, 100], [120, 100], [120, 40], [80, 40], [80, 100],
                  [0, 100]]) * MM  # fmt: skip
    across_the_slot = FlatPattern(u, (_line((0, 70), (200, 70)),))
    _refused(across_the_slot, "leaves the blank at (80, 70) mm", "from edge to edge")
    crossing = FlatPattern(box, (_line((0, 50), (200, 50)), _line((100, 0), (100, 100))))
    _refused(crossing, "cross or touch at (100, 50) mm", "corner relief")
    close = FlatPattern(box, (_line((0, 50), (200, 50)), _line((0, 52), (200, 52))))
    _refused(close, "overlap", "move the bend lines apart")
    one = FlatPattern(box, (_line((0, 50), (200, 50)),))
    _refused(one, "has no inner radius", "give inner_radius", "R1.5", r_mm=None)
    _refused(one, "below Table 1's minimum", "use a larger radius", r_mm=0.5)
    flat = FlatPattern(box, (_line((0, 50), (200, 50), deg=0.0),))
    _refused(flat, "bend angle 0 deg is not in (0, 180)", "write the bend angle")
    bow = FlatPattern(np.array([[0, 0], [1, 1], [1, 0], [0, 1]]) * 0.1, ())
    _refused(bow, "not a simple polygon", "redraw it")
    holed = FlatPattern(box, (_line((0, 50), (200, 50)),), holes=(_rect(90, 45, 110, 55),))
    _refused(holed, "crosses or touches an inner contour", "remove the hole")


def test_an_outline_crossing_a_zone_obliquely_is_approximated_within_its_bound() -> None:
    # sides at tan(phi) = 0.2 to the zone's normal: the rectangle of the zone differs from the
    # drawn trapezoid by at most BA/2 * tan(phi); the area is kept
    trapezoid = np.array([[0, 0], [200, 0], [180, 100], [20, 100]]) * MM
    pattern = FlatPattern(trapezoid, (_line((10, 50), (190, 50), r_mm=2.0),))
    part = SheetMetalPart.from_spec(_spec(pattern, 2.0))
    a, b = shapely.Polygon(trapezoid), shapely.Polygon(flat_pattern_of_part(part).outline)
    assert a.hausdorff_distance(b) <= part.bend_allowances[0] / 2 * 0.2 + 1e-9
    assert b.area == pytest.approx(a.area, rel=1e-9)


@pytest.mark.parametrize(
    "ends", [((0.3, 50), (199.6, 50)), ((-5, 50), (212, 50)), ((-0.3, 50), (199.8, 50))]
)
def test_a_bend_line_a_hair_short_or_drawn_past_the_edge_is_cut_to_the_outline(
    ends: tuple,
) -> None:
    pattern = FlatPattern(_rect(0, 0, 200, 100), (_line(*ends),))
    part = SheetMetalPart.from_spec(_spec(pattern, 2.0, 2.0))
    assert part.bend_lengths[0] == pytest.approx(200 * MM, abs=1e-12)
    _refused(FlatPattern(_rect(0, 0, 200, 100), (_line((0.6, 50), (200, 50)),)), "0.6 mm inside")
    _refused(FlatPattern(_rect(0, 0, 200, 100), (_line((0, 150), (200, 150)),)), "not reach")
