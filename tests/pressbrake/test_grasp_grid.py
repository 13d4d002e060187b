"""Candidate grasps of the sequence search against a brute-force lattice walk.

The twin lists every point of the square lattice (spacing s, first point s/2 in from the
flange's bounding box) and keeps those inside the polygon at least `inset` from its edges
by shapely's point-to-boundary distance. The module uses a negative buffer instead: exact
along straight edges and convex corners, but round near a reflex corner, where shapely
draws the arc with chords (8 per quarter circle) that lie inside the circle, so a kept point
may sit up to inset * (1 - cos(pi/32)) closer to a reflex corner. Lattice points within that
band of the inset are left out of the comparison.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest
import shapely

from workbench.errors import InputError
from workbench.pressbrake.grasp_grid import MAX_GRASPS, grasp_grid
from workbench.project.bending import PartSpec
from workbench.sheetmetal import SheetMetalPart
from workbench.sheetmetal.part import Flange

ROOT = Path(__file__).resolve().parents[2]


def seed_part() -> SheetMetalPart:
    text = (ROOT / "projects" / "parts" / "seed_part.json").read_text()
    return SheetMetalPart.from_spec(
        dataclasses.asdict(PartSpec.model_validate(json.loads(text)).to_si())
    )


def one_flange(poly: np.ndarray, name: str = "f") -> SheetMetalPart:
    return SheetMetalPart(0.002, [Flange(name, np.asarray(poly, float))], [])


L_SHAPE = np.array([[0, 0], [0.2, 0], [0.2, 0.06], [0.07, 0.06], [0.07, 0.15], [0, 0.15]])


def star(rng: np.random.Generator, n: int = 9) -> np.ndarray:
    """Return a seeded random star-shaped polygon (CCW, simple) about the origin [m]."""
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    radii = rng.uniform(0.03, 0.12, n)
    return np.c_[radii * np.cos(angles), radii * np.sin(angles)] + rng.uniform(-0.05, 0.05, 2)


def lattice(poly: np.ndarray, spacing: float, inset: float) -> tuple[list, list]:
    """Return the lattice points (row by row, y then x) kept and those too near to call."""
    shape = shapely.Polygon(poly)
    tol = inset * (1 - np.cos(np.pi / 32)) + 1e-9
    lo, hi = poly.min(axis=0), poly.max(axis=0)
    keep, unsure = [], []
    y = lo[1] + spacing / 2
    while y < hi[1]:
        x = lo[0] + spacing / 2
        while x < hi[0]:
            p = shapely.Point(x, y)
            d = shape.exterior.distance(p) if shape.contains(p) else -shape.exterior.distance(p)
            if d >= inset + tol:
                keep.append((x, y))
            elif d > inset - tol:
                unsure.append((x, y))
            x += spacing
        y += spacing
    return keep, unsure


def check_flange_grid(
    part: SheetMetalPart, name: str, grasps: list, spacing: float, inset: float
) -> None:
    """Compare the grid of one flange (one yaw, one face) with the twin."""
    poly = part.flanges[part.flange_index(name)].polygon
    shape = shapely.Polygon(poly)
    points = [np.asarray(g.offset) for g in grasps]
    c = shape.centroid
    np.testing.assert_allclose(points[0], [c.x, c.y], atol=1e-15)  # the centroid first
    keep, unsure = lattice(poly, spacing, inset)
    keep = [p for p in keep if np.hypot(p[0] - c.x, p[1] - c.y) > 1e-6]
    got = [tuple(p) for p in points[1:]]
    assert len(got) == len(set(got))
    # every point in the grid: on the lattice, inside, `inset` from the edges
    lo = poly.min(axis=0)
    tol = inset * (1 - np.cos(np.pi / 32)) + 1e-9
    for p in points[1:]:
        k = (p - lo - spacing / 2) / spacing
        np.testing.assert_allclose(k, np.round(k), atol=1e-9)
        pt = shapely.Point(*p)
        assert shape.contains(pt)
        assert shape.exterior.distance(pt) >= inset - tol, (p, shape.exterior.distance(pt))
    # same points, same order, where the twin can tell
    sure = [p for p in got if not any(np.allclose(p, u, atol=1e-12) for u in unsure)]
    np.testing.assert_allclose(
        np.array(sure).reshape(-1, 2), np.array(keep).reshape(-1, 2), atol=1e-12
    )


@pytest.mark.parametrize("spacing, inset", [(0.025, 0.008), (0.013, 0.0), (0.04, 0.02)])
def test_seed_part_grid_equals_the_lattice_twin(spacing: float, inset: float) -> None:
    part = seed_part()
    grasps = grasp_grid(part, spacing=spacing, inset=inset)
    names = [f.name for f in part.flanges]
    assert [g.flange for g in grasps] == sorted((g.flange for g in grasps), key=names.index), (
        "flanges in the part's order"
    )
    for name in names:
        mine = [g for g in grasps if g.flange == name]
        assert mine, name  # at least the centroid
        assert all(g.yaw == 0.0 and g.face == 1 for g in mine)
        check_flange_grid(part, name, mine, spacing, inset)


def test_reflex_and_random_polygons_equal_the_lattice_twin() -> None:
    rng = np.random.default_rng(30)
    polys = [L_SHAPE] + [star(rng) for _ in range(12)]
    for poly in polys:
        assert shapely.Polygon(poly).is_valid
        part = one_flange(poly)
        spacing = float(rng.uniform(0.008, 0.03))
        inset = float(rng.uniform(0.0, 0.015))
        check_flange_grid(part, "f", grasp_grid(part, spacing=spacing, inset=inset), spacing, inset)


def test_order_is_flange_point_yaw_face_and_repeatable() -> None:
    part = seed_part()
    yaws, faces = (0.0, np.pi / 2, -np.pi / 2), (1, -1)
    flanges = ["3", "1"]
    grasps = grasp_grid(part, spacing=0.03, inset=0.008, yaws=yaws, faces=faces, flanges=flanges)
    again = grasp_grid(part, spacing=0.03, inset=0.008, yaws=yaws, faces=faces, flanges=flanges)
    plain = grasp_grid(part, spacing=0.03, inset=0.008, flanges=flanges)
    assert len(grasps) == len(plain) * len(yaws) * len(faces)
    expected = [
        (p.flange, tuple(p.offset), yaw, face) for p in plain for yaw in yaws for face in faces
    ]
    for run in (grasps, again):
        assert [(g.flange, tuple(g.offset), g.yaw, g.face) for g in run] == expected
    assert [g.flange for g in plain][0] == "3" and [g.flange for g in plain][-1] == "1"


def test_a_flange_narrower_than_twice_the_inset_keeps_only_its_centroid() -> None:
    part = one_flange(np.array([[0, 0], [0.2, 0], [0.2, 0.01], [0, 0.01]]))
    grasps = grasp_grid(part, spacing=0.002, inset=0.008)
    assert len(grasps) == 1
    np.testing.assert_allclose(grasps[0].offset, [0.1, 0.005], atol=1e-15)


def test_more_than_max_grasps_is_an_input_error() -> None:
    part = seed_part()
    n = len(grasp_grid(part, spacing=0.02, inset=0.008))
    yaws = MAX_GRASPS // n
    assert 1 <= yaws and n * (yaws + 1) > MAX_GRASPS
    ok = grasp_grid(part, spacing=0.02, inset=0.008, yaws=np.linspace(0, 1, yaws))
    assert len(ok) == n * yaws <= MAX_GRASPS
    with pytest.raises(InputError, match="MAX_GRASPS") as caught:
        grasp_grid(part, spacing=0.02, inset=0.008, yaws=np.linspace(0, 1, yaws + 1))
    assert f"{n * (yaws + 1)} candidates, above {MAX_GRASPS}" in str(caught.value)
    square = one_flange(np.array([[0, 0], [0.25, 0], [0.25, 0.25], [0, 0.25]]))
    with pytest.raises(InputError, match="MAX_GRASPS"):
        grasp_grid(square, spacing=0.005, inset=0.0)  # 2,500 points and the centroid


@pytest.mark.parametrize("spacing", [0.0, -0.01, np.nan, np.inf])
def test_spacing_must_be_positive_and_finite(spacing: float) -> None:
    with pytest.raises(InputError, match="grasp spacing: must be > 0 m"):
        grasp_grid(seed_part(), spacing=spacing, inset=0.008)
