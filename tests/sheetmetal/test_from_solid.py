"""Sheet-metal parts recognised in STEP solids (sheetmetal/from_solid.py, solid_faces.py).

Against the generator's own parameters (tests/bent_parts.py: L, U, Z, hat profiles, bends of
30 to 135 deg both ways, radii r != t): thickness, bend angles, inner radii, directions and
flange sizes. The flat blank against the closed form Σ runs + Σ θ (r + K t) (K from Table 1).
fold(unfold(STEP)): the part folded fully puts every vertex of every flange face of the STEP
on its flange's face (top at +t/2, bottom at -t/2, inside the polygon) and every polygon
corner on a STEP vertex; the volume differs from OCP's GProp by exactly the bends' thinning
Σ θ L t² (1/2 - K) (the model keeps the blank's volume, the solid keeps r and r + t).
Refusals name the face: a block, a fillet, B-spline faces, a second thickness.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import shapely
from bent_parts import (
    PROFILES,
    block,
    brep_of_step,
    doubled_channel,
    expected_directions,
    filleted_channel,
    nurbs_channel,
    profile_step,
    step_of,
    two_channels,
)

from workbench.cad.bent_profile import Profile, tab_bracket
from workbench.cad.sheet_brep import SheetBrep
from workbench.errors import InputError, MeshError
from workbench.sheetmetal import SheetMetalPart, k_factor
from workbench.sheetmetal.from_solid import RecognisedPart, recognise_part

VERTEX_TOL = 1e-8  # m (1e-5 mm): stated in docs/sheetmetal.md as 0.01 mm; measured ~1e-13 m


@functools.cache
def _recognised(name: str, base: str | None = None) -> tuple[SheetBrep, RecognisedPart]:
    brep = brep_of_step(profile_step(name))
    return brep, recognise_part(brep, where="test", base=base)


def _base_index(p: Profile) -> int:
    """Return the profile index of the largest flange (the default base; first on ties)."""
    return int(np.argmax(np.round(np.asarray(p.runs) * 1e6)))


@pytest.mark.parametrize("name", sorted(PROFILES))
def test_recognised_part_has_the_generators_parameters(name: str) -> None:
    p = PROFILES[name]
    _, rec = _recognised(name)
    spec = rec.spec
    base = _base_index(p)
    assert spec["thickness"] == pytest.approx(p.thickness, abs=1e-12)
    assert spec["flanges"][0]["name"] == f"F{base + 1}"
    bends = {b["name"]: b for b in spec["bends"]}
    assert sorted(bends) == [f"B{k + 1}" for k in range(len(p.angles))]
    directions = expected_directions(p, base)
    got = [bends[f"B{k + 1}"]["direction"] for k in range(len(p.angles))]
    tie = sum(np.sign(p.angles[k]) for k in (base - 1, base) if 0 <= k < len(p.angles)) == 0
    if tie:  # either side may be the base's top: all flip together
        flipped = ["down" if d == "up" else "up" for d in directions]
        assert got in (directions, flipped)
    else:
        assert got == directions
    for k, (a, r) in enumerate(zip(p.angles, p.radii, strict=True)):
        b = bends[f"B{k + 1}"]
        assert b["bend_angle"] == pytest.approx(abs(a), abs=1e-9)
        assert b["inner_radius"] == pytest.approx(r, abs=1e-12)
        assert {b["parent"], b["child"]} == {f"F{k + 1}", f"F{k + 2}"}
    polygons = {f["name"]: np.asarray(f["polygon"]) for f in spec["flanges"]}
    for i, run in enumerate(p.runs):
        ext = np.ptp(polygons[f"F{i + 1}"], axis=0)
        assert sorted(ext) == pytest.approx(sorted([run, p.length]), abs=1e-9)
    SheetMetalPart.from_spec(spec)  # a valid part, every fold step free of self-intersection


def test_the_u_channel_is_projects_parts_u_channel_json() -> None:
    _, rec = _recognised("U", "F2")
    spec = rec.spec
    assert [f["name"] for f in spec["flanges"]] == ["F2", "F1", "F3"]
    assert np.allclose(spec["flanges"][0]["polygon"], [[0, 0], [0.2, 0], [0.2, 0.1], [0, 0.1]])
    assert np.allclose(spec["flanges"][2]["polygon"], [[0, 0], [0.2, 0], [0.2, 0.11], [0, 0.11]])
    b1, b2 = spec["bends"]
    assert (b1["parent_edge"], b1["child"], b1["child_edge"]) == (0, "F1", 0)
    assert (b2["parent_edge"], b2["child"], b2["child_edge"]) == (2, "F3", 0)
    assert np.allclose(rec.T_model_part, np.eye(4))


@pytest.mark.parametrize("name", sorted(PROFILES))
def test_flat_length_matches_the_k_factor_closed_form(name: str) -> None:
    p = PROFILES[name]
    _, rec = _recognised(name)
    part = SheetMetalPart.from_spec(rec.spec)
    flat = part.fold(0)
    t = p.thickness
    closed = sum(p.runs) + sum(
        abs(a) * (r + float(k_factor(r / t)) * t) for a, r in zip(p.angles, p.radii, strict=True)
    )
    # the bend lines are parallel: the blank's extent across them is its flat length
    edge = part.flanges[0].polygon
    pts = np.concatenate(
        [
            (np.c_[f.polygon, np.zeros(len(f.polygon)), np.ones(len(f.polygon))] @ T.T)[:, :3]
            for f, T in zip(part.flanges, flat.T_part_flange, strict=True)
        ]
    )
    b0 = part.bends[[b.parent for b in part.bends].index(0)]
    a, c = edge[b0.parent_edge], edge[(b0.parent_edge + 1) % len(edge)]
    along = np.r_[(c - a) / np.linalg.norm(c - a), 0.0]
    across = np.cross([0.0, 0.0, 1.0], along)
    assert np.ptp(pts[:, 2]) < 1e-12  # flat
    assert np.ptp(pts @ across) == pytest.approx(closed, abs=1e-7)  # 1e-4 mm (asked: 0.1 mm)
    assert np.ptp(pts @ along) == pytest.approx(p.length, abs=1e-9)
    assert part.blank_area() == pytest.approx(closed * p.length, rel=1e-9)


def _face_deviation(brep: SheetBrep, rec: RecognisedPart) -> tuple[float, float]:
    """Return the largest distance [m] of a STEP flange-face vertex from its folded face, and
    of a folded polygon corner from the nearest STEP vertex of that face."""
    part = SheetMetalPart.from_spec(rec.spec)
    state = part.fold(len(part.bends))
    t = part.thickness
    worst_on, worst_back = 0.0, 0.0
    for f, flange in enumerate(part.flanges):
        T = rec.T_model_part @ state.T_part_flange[f]
        poly = shapely.Polygon(flange.polygon)
        for face, z in zip(rec.flange_faces[flange.name], (t / 2, -t / 2), strict=True):
            v = brep.faces[face - 1].vertices
            local = (v - T[:3, 3]) @ T[:3, :3]
            off = [poly.distance(shapely.Point(x, y)) for x, y in local[:, :2]]
            worst_on = max(worst_on, float(np.max(np.abs(local[:, 2] - z))), max(off))
            corners = np.c_[flange.polygon, np.full(len(flange.polygon), z)] @ T[:3, :3].T
            corners += T[:3, 3]
            d = np.linalg.norm(corners[:, None] - v[None], axis=2).min(axis=1)
            worst_back = max(worst_back, float(d.max()))
    return worst_on, worst_back


@pytest.mark.parametrize("name", sorted(PROFILES))
def test_fold_of_the_unfolded_step_is_the_step(name: str) -> None:
    brep, rec = _recognised(name)
    on, back = _face_deviation(brep, rec)
    assert on < VERTEX_TOL and back < VERTEX_TOL, (on, back)


@pytest.mark.parametrize("name", sorted(PROFILES))
def test_folded_volume_and_box_match_ocp(name: str) -> None:
    p = PROFILES[name]
    brep, rec = _recognised(name)
    part = SheetMetalPart.from_spec(rec.spec)
    solid = part.fold(len(part.bends)).solid()
    t, L = p.thickness, p.length
    exact = (
        t
        * L
        * (sum(p.runs) + sum(abs(a) * (r + t / 2) for a, r in zip(p.angles, p.radii, strict=True)))
    )
    assert brep.volume == pytest.approx(exact, rel=1e-9)
    thinning = sum(
        abs(a) * L * t * t * (0.5 - float(k_factor(r / t)))
        for a, r in zip(p.angles, p.radii, strict=True)
    )
    assert solid.volume == pytest.approx(brep.volume - thinning, rel=1e-9)
    verts = solid.vertices @ rec.T_model_part[:3, :3].T + rec.T_model_part[:3, 3]
    # the mesh's arcs are chords of the outer arc, thinned by sigma: within 0.5 mm of OCP's box
    assert np.abs(verts.min(axis=0) - brep.bbox[0]).max() < 5e-4
    assert np.abs(verts.max(axis=0) - brep.bbox[1]).max() < 5e-4


def test_a_bracket_with_bends_on_two_sides() -> None:
    brep = brep_of_step(step_of(tab_bracket()))
    rec = recognise_part(brep, where="test")
    spec = rec.spec
    assert [f["name"] for f in spec["flanges"]] == ["F1", "F2", "F3"]
    assert np.allclose(
        spec["flanges"][0]["polygon"],
        [[0, 0], [0.2, 0], [0.2, 0.02], [0.2, 0.08], [0.2, 0.1], [0, 0.1]],
        atol=1e-12,
    )
    assert np.allclose(spec["flanges"][2]["polygon"], [[0, 0], [0.06, 0], [0.06, 0.03], [0, 0.03]])
    b1, b2 = spec["bends"]
    assert (b1["parent_edge"], b1["child"], b2["parent_edge"], b2["child"]) == (4, "F2", 2, "F3")
    assert b1["bend_angle"] == pytest.approx(np.pi / 2) and b2["bend_angle"] == pytest.approx(
        np.pi / 3
    )
    assert b1["direction"] == b2["direction"] == "up"
    part = SheetMetalPart.from_spec(spec)
    ba = part.bend_allowances
    assert np.allclose(ba, [np.pi / 2 * (0.002 + 0.3 * 0.002), np.pi / 3 * (0.002 + 0.3 * 0.002)])
    closed = 0.2 * 0.1 + 0.2 * 0.05 + 0.06 * 0.03 + 0.2 * ba[0] + 0.06 * ba[1]
    assert part.blank_area() == pytest.approx(closed, rel=1e-12)
    on, back = _face_deviation(brep, rec)
    assert on < VERTEX_TOL and back < VERTEX_TOL, (on, back)
    thinning = (np.pi / 2 * 0.2 + np.pi / 3 * 0.06) * 0.002**2 * (0.5 - 0.3)
    solid = part.fold(2).solid()
    assert solid.volume == pytest.approx(brep.volume - thinning, rel=1e-9)


def test_a_named_base_keeps_the_geometry() -> None:
    brep, rec = _recognised("hat", "F1")
    assert rec.spec["flanges"][0]["name"] == "F1"
    on, back = _face_deviation(brep, rec)
    assert on < VERTEX_TOL and back < VERTEX_TOL
    with pytest.raises(InputError, match=r"base: no flange 'F9'; the part's flanges are F1, F2"):
        recognise_part(brep, where="test", base="F9")


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (block, r"test: no bends found .* a solid block or a flat plate"),
        (filleted_channel, r"cylinder face 3 \(radius 0.5 mm, convex\) has no coaxial partner"),
        (nurbs_channel, r"face 1 is a B-spline surface: a sheet-metal part has only planar"),
        (doubled_channel, r"faces 13 and 15: thickness 3.5 mm here, 2 mm elsewhere"),
        (two_channels, r"test: the file holds 2 solids; a sheet-metal part is one solid"),
    ],
    ids=["block", "fillet", "bspline", "two_thicknesses", "two_solids"],
)
def test_solids_that_are_not_sheet_metal_are_refused_naming_the_face(
    make: object, message: str
) -> None:
    brep = brep_of_step(step_of(make()))  # type: ignore[operator]
    with pytest.raises(MeshError, match=message):
        recognise_part(brep, where="test")
