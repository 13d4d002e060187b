"""One bend on the press brake: the bend line frame, the part on the die, the back-gauge stop
and the press's obstacles, each against an independent construction.

Parts: the U-channel of `projects/u_channel_cell.json` and the seed part (Fig. 7) of
`projects/parts/seed_part.json`, both on the U-channel cell's press (converted to SI by the
project layer, as the service does it).
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest
import shapely
import trimesh

from workbench import Workbench
from workbench.pressbrake.airbend import apex_depth
from workbench.pressbrake.bend_setup import (
    GaugeStop,
    PressObstacles,
    bend_line_frame,
    bend_pose,
    contact_zone,
    gauge_stop,
    part_obstacles,
    part_points,
    robot_obstacles,
)
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.obstacles import Obstacles, cell_obstacles
from workbench.pressbrake.press import PressBrake, clipped_profile, piece_solid, prism
from workbench.project.bending import PartSpec
from workbench.sheetmetal import SheetMetalPart
from workbench.sheetmetal.folding import FoldedState, bend_profile, fold_state

ROOT = Path(__file__).resolve().parents[2]
FRACTIONS = (0.0, 0.2, 0.45, 0.7, 1.0)


@pytest.fixture(scope="module")
def u_cell() -> tuple[SheetMetalPart, PressBrake]:
    """Return the U-channel and the press of its cell (SI)."""
    svc = Workbench.open(ROOT / "projects" / "u_channel_cell.json").bending
    press = svc.si().press
    assert press is not None
    return svc.part, press


@pytest.fixture(scope="module")
def seed_part() -> SheetMetalPart:
    """Return the seed part (mm/deg in the file, SI here)."""
    text = (ROOT / "projects" / "parts" / "seed_part.json").read_text()
    return SheetMetalPart.from_spec(
        dataclasses.asdict(PartSpec.model_validate(json.loads(text)).to_si())
    )


@pytest.fixture(scope="module", params=["u_channel", "seed_part"])
def part(
    request: pytest.FixtureRequest,
    u_cell: tuple[SheetMetalPart, PressBrake],
    seed_part: SheetMetalPart,
) -> SheetMetalPart:
    """Return each part in turn."""
    return u_cell[0] if request.param == "u_channel" else seed_part


def apply(T: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Return points (P, 3) moved by the transform T (4, 4)."""
    return pts @ T[:3, :3].T + T[:3, 3]


def state_at(part: SheetMetalPart, k: int, fraction: float) -> FoldedState:
    """Return the part with bends 0..k-1 folded and bend k folded by `fraction`."""
    return fold_state(part, k, fraction)


# --- (a) the bend line frame -----------------------------------------------------------


def test_bend_line_frame_flat_is_mid_bend_zone_on_the_outer_face(part: SheetMetalPart) -> None:
    t = part.thickness
    for k, b in enumerate(part.bends):
        state = state_at(part, k, 0.0)
        T = bend_line_frame(state, k)
        poly = part.flanges[b.parent].polygon
        a, c = poly[b.parent_edge], poly[(b.parent_edge + 1) % len(poly)]
        d = (c - a) / np.linalg.norm(c - a)
        n = np.array([d[1], -d[0]])  # the edge's outward normal (CCW polygon)
        # in the parent's frame: the edge's middle, half the flat bend zone out, on the
        # outer face (an up bend's outside is the bottom face z = -t/2)
        mid = (a + c) / 2 + n * part.bend_allowances[k] / 2
        expected = np.array([mid[0], mid[1], -b.direction * t / 2])
        T_pf = state.T_part_flange[b.parent]
        np.testing.assert_allclose(T[:3, 3], apply(T_pf, expected[None])[0], atol=1e-12)
        z = T_pf[:3, :3] @ np.array([0.0, 0.0, float(b.direction)])
        np.testing.assert_allclose(T[:3, 2], z, atol=1e-12)  # into the bend's inside
        assert abs(T[:3, 0] @ (T_pf[:3, :3] @ np.r_[d, 0.0])) == pytest.approx(1.0, abs=1e-12)
        np.testing.assert_allclose(T[:3, :3].T @ T[:3, :3], np.eye(3), atol=1e-12)
        assert np.linalg.det(T[:3, :3]) == pytest.approx(1.0, abs=1e-12)


def test_bend_line_frame_folded_is_the_outer_arc_apex(part: SheetMetalPart) -> None:
    t = part.thickness
    for k, b in enumerate(part.bends):
        for frac in (0.3, 0.7, 1.0):
            state = state_at(part, k, frac)
            r = float(state.radii[k])
            if frac == 1.0:
                assert r == pytest.approx(b.inner_radius, rel=1e-12)
            T = bend_line_frame(state, k)
            o = T[:3, 3]
            T_pf, T_cf = state.T_part_flange[b.parent], state.T_part_flange[b.child]
            poly = part.flanges[b.parent].polygon
            a, c = poly[b.parent_edge], poly[(b.parent_edge + 1) % len(poly)]
            w = np.array([0.0, 0.0, float(b.direction)])
            # the arc's centre: r + t/2 over the parent's mid-surface at its edge...
            centre_l = np.r_[a, 0.0] + (r + t / 2) * w
            centre_r = np.r_[c, 0.0] + (r + t / 2) * w
            ends = apply(T_pf, np.array([centre_l, centre_r]))
            # ...and as far from the child's mid-surface (an independent check of the fold)
            for e in ends:
                height = T_cf[:3, 2] @ (e - T_cf[:3, 3])
                assert abs(height) == pytest.approx(r + t / 2, abs=1e-9)
            axis = (ends[1] - ends[0]) / np.linalg.norm(ends[1] - ends[0])
            rel = o - ends[0]
            along = rel @ axis
            radial = rel - along * axis
            assert along == pytest.approx(part.bend_lengths[k] / 2, abs=1e-9)  # mid bend line
            assert np.linalg.norm(radial) == pytest.approx(r + t, abs=1e-9)  # on the outer arc
            # the apex lies as far from the child's outer face as from the parent's
            out_p = T_pf[:3, 2] * b.direction
            out_c = T_cf[:3, 2] * b.direction
            h_p = out_p @ (o - T_pf[:3, 3]) + t / 2
            h_c = out_c @ (o - T_cf[:3, 3]) + t / 2
            assert h_p == pytest.approx(h_c, abs=1e-9)
            # z points from the apex to the arc's centre (into the bend's inside)
            np.testing.assert_allclose(T[:3, 2], -radial / np.linalg.norm(radial), atol=1e-9)


def test_bend_line_frame_apex_lies_on_the_solid_within_its_thinning(
    u_cell: tuple[SheetMetalPart, PressBrake],
) -> None:
    # The solid's bend is an N-gon whose outer vertices sit at r + t − σ·sin(πi/N) (volume
    # kept: the sheet thins where K < 0.5): the apex lies within σ plus the chord's sag.
    part = u_cell[0]
    t = part.thickness
    for k in range(len(part.bends)):
        for frac in (0.0, 0.5, 1.0):
            state = state_at(part, k, frac)
            o = bend_line_frame(state, k)[:3, 3]
            d = float(np.abs(trimesh.proximity.signed_distance(state.solid(), o[None]))[0])
            th, r = float(state.angles[k]), float(state.radii[k])
            n, sigma, _ = bend_profile(th, r, t, part.bend_allowances[k])
            sag = (r + t) * (1 - np.cos(th / (2 * n))) if th > 0 else 0.0
            assert d <= abs(sigma) + sag + 1e-9, (k, frac, d, sigma)


# --- (b) the part on the die -----------------------------------------------------------


def _grasps_of(part: SheetMetalPart, k: int) -> list[str]:
    b = part.bends[k]
    return [part.flanges[b.child].name, part.flanges[b.parent].name]


def test_bend_pose_touches_both_shoulders_and_sinks_to_the_apex_depth(
    part: SheetMetalPart, u_cell: tuple[SheetMetalPart, PressBrake]
) -> None:
    press = u_cell[1]
    station = press.stations[0]
    v, rs, t = press.die.v_opening, press.die.shoulder_radius, part.thickness
    bends = range(len(part.bends)) if len(part.bends) <= 2 else (0, 2, 5)
    for k in bends:
        half = part.bend_lengths[k] / 2
        xs = station.x + np.linspace(-0.8, 0.8, 5) * half  # along the shoulder, within the bend
        for frac in FRACTIONS:
            state = state_at(part, k, frac)
            mesh = state.solid()
            th, r = float(state.angles[k]), float(state.radii[k])
            depth = float(apex_depth(th, r, t, v, rs))
            for g in _grasps_of(part, k):
                pose = bend_pose(state, k, Grasp(g), press, station)
                assert pose.depth == pytest.approx(depth, abs=1e-15)
                assert pose.punch_z == pytest.approx(t - depth, abs=1e-15)
                assert pose.fraction == pytest.approx(frac, abs=1e-12)
                placed = mesh.copy()
                placed.apply_transform(pose.T_die_part)
                for sign in (1.0, -1.0):
                    shoulder = np.c_[xs, np.full(len(xs), sign * v / 2), np.full(len(xs), -rs)]
                    sd = trimesh.proximity.signed_distance(placed, shoulder)  # > 0 inside
                    # touching: the shoulder circle's centre lies Rs from the solid, outside it.
                    # The contact is on a flange's flat outer face, which the mesh holds
                    # exactly (the bend's N-gon lies inside the true arc, only farther away).
                    np.testing.assert_allclose(-sd, rs, atol=1e-9, err_msg=f"{k} {frac} {g}")
                # the lowest point is the outer apex, at -depth; the solid's bend is an N-gon
                # inside the true arc (bend_profile: vertices at r + t − σ·sin(πi/N)), so its
                # lowest vertex sits higher by at most σ plus the sag of half a segment
                n, sigma, _ = bend_profile(th, r, t, part.bend_allowances[k])
                sag = (r + t) * (1 - np.cos(th / (2 * n))) if th > 0 else 0.0
                low = float(placed.vertices[:, 2].min())
                assert -depth - 1e-12 <= low <= -depth + max(sigma, 0.0) + sag + 1e-12, (
                    k,
                    frac,
                    g,
                )
                if frac == 0.0:
                    assert low == pytest.approx(0.0, abs=1e-12)  # flat on the die's top
                # the gripped flange faces the robot (-y)
                f = part.flange_index(g)
                poly = part.flanges[f].polygon
                c = shapely.Polygon(poly).centroid
                T = pose.T_die_part @ state.T_part_flange[f]
                assert apply(T, np.array([[c.x, c.y, 0.0]]))[0, 1] < 0, (k, frac, g)
                # and the other side of the bend lies behind the bend line (+y)
                b = part.bends[k]
                other = b.parent if f == b.child else b.child
                poly = part.flanges[other].polygon
                c = shapely.Polygon(poly).centroid
                T = pose.T_die_part @ state.T_part_flange[other]
                assert apply(T, np.array([[c.x, c.y, 0.0]]))[0, 1] > 0, (k, frac, g)


# --- (c) the back-gauge stop -----------------------------------------------------------


def _placed(part: SheetMetalPart, k: int, g: str, press: PressBrake) -> tuple[np.ndarray, ...]:
    """Return the corners (part_points) and the solid's vertices in the die frame at the
    placement of bend k held at flange g."""
    state = state_at(part, k, 0.0)
    pose = bend_pose(state, k, Grasp(g), press, press.stations[0])
    return (
        apply(pose.T_die_part, part_points(state)),
        apply(pose.T_die_part, np.asarray(state.solid().vertices)),
    )


def test_gauge_stop_equals_the_farthest_solid_vertex_in_the_fingers_band(
    part: SheetMetalPart, u_cell: tuple[SheetMetalPart, PressBrake]
) -> None:
    press = u_cell[1]
    bg = press.backgauge
    depth, width, height = bg.finger
    for k in range(len(part.bends)):
        for g in _grasps_of(part, k):
            corners, verts = _placed(part, k, g, press)
            stop = gauge_stop(corners, press, press.stations[0])
            assert stop.problem is None, stop.problem
            r = max(bg.r_range[0], min(0.0, bg.r_range[1]))
            assert stop.r == r
            band = verts[
                (verts[:, 1] > 0) & (verts[:, 2] >= r - 1e-9) & (verts[:, 2] <= r + height)
            ]
            x = float(band[:, 1].max())
            # the flange corners are solid vertices too; the bend's N-gon vertices never lie
            # farther back than the corners where the arc ends (an arc turns towards its
            # flange), so the corner stop and the vertex stop agree
            assert stop.x == pytest.approx(x, abs=1e-9), (k, g, stop.x, x)
            back = band[band[:, 1] >= x - 1e-3]
            lo, hi = float(back[:, 0].min()), float(back[:, 0].max())
            assert hi - lo >= 2 * width
            np.testing.assert_allclose(
                stop.z, [lo + (hi - lo) / 4, lo + 3 * (hi - lo) / 4], atol=1e-9
            )


def _with_gauge(press: PressBrake, **changes: object) -> PressBrake:
    return dataclasses.replace(press, backgauge=dataclasses.replace(press.backgauge, **changes))


def test_gauge_stop_problems_name_the_axis(u_cell: tuple[SheetMetalPart, PressBrake]) -> None:
    part, press = u_cell
    corners, _ = _placed(part, 0, part.flanges[part.bends[0].child].name, press)
    x = gauge_stop(corners, press, press.stations[0]).x
    short = _with_gauge(press, x_range=(0.005, x - 0.01))
    stop = gauge_stop(corners, short, short.stations[0])
    assert stop.problem is not None and "(bending.press.backgauge.x)" in stop.problem
    assert f"{x * 1e3:.1f} mm" in stop.problem and stop.z == ()
    deep = _with_gauge(press, x_range=(x + 0.01, 0.6))
    assert "(bending.press.backgauge.x)" in (
        gauge_stop(corners, deep, deep.stations[0]).problem or ""
    )
    narrow = _with_gauge(press, z_range=(-0.01, 0.01))
    stop = gauge_stop(corners, narrow, narrow.stations[0])
    assert stop.problem is not None and "(bending.press.backgauge.z)" in stop.problem
    high = _with_gauge(press, r_range=(0.2, 0.3))  # fingers over the flat part
    stop = gauge_stop(corners, high, high.stations[0])
    assert stop.problem is not None and "no edge of the part behind the bend line" in stop.problem
    assert np.isnan(stop.x)
    one = _with_gauge(press, fingers=1)
    stop = gauge_stop(corners, one, one.stations[0])
    assert stop.problem is None and len(stop.z) == 1
    assert stop.z[0] == pytest.approx(np.mean(gauge_stop(corners, press, press.stations[0]).z))


# --- (d) the press's obstacles moved with the ram ---------------------------------------


def assert_same_obstacles(a: Obstacles, b: Obstacles) -> None:
    assert a.names == b.names
    # a mesh's box is fitted to its vertices: the same box may come with its axes permuted or
    # flipped, so compare the boxes as point sets (their corners)
    ca, cb = a.boxes.corners(), b.boxes.corners()
    assert ca.shape == cb.shape
    for i in range(len(ca)):
        sa = ca[i][np.lexsort(np.round(ca[i], 9).T)]
        sb = cb[i][np.lexsort(np.round(cb[i], 9).T)]
        np.testing.assert_allclose(sa, sb, atol=1e-12, err_msg=f"box {i} ({a.names[i]})")
    assert len(a.exact) == len(b.exact)
    for ea, eb in zip(a.exact, b.exact, strict=True):
        assert (ea is None) == (eb is None)
        if ea is None or eb is None:
            continue
        assert type(ea.geometry) is type(eb.geometry)
        np.testing.assert_allclose(ea.T_world, eb.T_world, atol=1e-12)
        assert (ea.mesh is None) == (eb.mesh is None)
        if ea.mesh is not None and eb.mesh is not None:
            np.testing.assert_allclose(ea.mesh.vertices, eb.mesh.vertices, atol=1e-12)
            np.testing.assert_array_equal(ea.mesh.faces, eb.mesh.faces)


def test_press_obstacles_at_equals_building_them_afresh(
    u_cell: tuple[SheetMetalPart, PressBrake],
) -> None:
    part, press = u_cell
    station = press.stations[0]
    corners, _ = _placed(part, 0, part.flanges[part.bends[0].child].name, press)
    stop = gauge_stop(corners, press, station)
    assert stop.problem is None
    bad = GaugeStop(np.nan, 0.0, (), "no stop")
    scene = PressObstacles(press)
    rng = np.random.default_rng(10)
    cut0 = contact_zone(float(part.bend_allowances[0]), part.thickness, press.tolerance)
    for z in [0.002, -0.002, 0.0, *rng.uniform(-0.005, 0.15, 5)]:
        for cut in (cut0, 0.0, 0.05):
            for s in (stop, None, bad):
                fresh = cell_obstacles(part_obstacles(press, station, float(z), cut, s))
                assert_same_obstacles(scene.at(station, float(z), cut, s), fresh)


# --- (e) profiles, pieces and the robot's view of the press ------------------------------


GOOSENECK = np.array(  # a non-convex punch profile (y, z) [m], CCW, tip at the origin
    [
        [0.0, 0.0],
        [0.012, 0.012],
        [0.012, 0.04],
        [-0.02, 0.07],
        [0.01, 0.1],
        [0.01, 0.14],
        [-0.03, 0.14],
        [-0.03, 0.06],
        [-0.004, 0.03],
        [-0.012, 0.012],
    ]
)


def test_clipped_profile_equals_the_shapely_clip(u_cell: tuple[SheetMetalPart, PressBrake]) -> None:
    rng = np.random.default_rng(11)
    for profile in (u_cell[1].punch.profile, GOOSENECK):
        poly = shapely.Polygon(profile)
        assert poly.is_valid
        top = float(profile[:, 1].max())
        for z in [0.0, 0.0125, 0.07, *rng.uniform(-0.01, top + 0.01, 12)]:
            pieces = clipped_profile(profile, float(z))
            ref = poly.intersection(shapely.box(-10, z, 10, 10))
            shapes = [shapely.Polygon(p) for p in pieces]
            assert sum(s.area for s in shapes) == pytest.approx(ref.area, abs=1e-12)
            if ref.area > 0:
                union = shapely.union_all(shapes)
                assert union.symmetric_difference(ref).area <= 1e-12
            for p, s in zip(pieces, shapes, strict=True):
                assert s.is_valid and s.area > 0
                assert s.convex_hull.area == pytest.approx(s.area, rel=1e-9)  # convex
                x, y = p[:, 0], p[:, 1]
                assert np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) > 0  # CCW


def test_piece_solid_is_a_box_for_rectangles_else_a_closed_prism() -> None:
    rect = np.array([[0.01, -0.06], [0.02, -0.06], [0.02, 0.0], [0.01, 0.0]])
    solid, T = piece_solid("die", rect, -0.4, 0.4)
    assert solid.kind == "box" and solid.size == pytest.approx((0.8, 0.01, 0.06), abs=1e-15)
    np.testing.assert_allclose(T[:3, 3], [0.0, 0.015, -0.03], atol=1e-15)
    np.testing.assert_allclose(T[:3, :3], np.eye(3))
    box = solid.to_trimesh()
    box.apply_transform(T)
    ref = prism(rect, -0.4, 0.4)
    np.testing.assert_allclose(box.bounds, ref.bounds, atol=1e-15)
    assert box.volume == pytest.approx(ref.volume, rel=1e-12)
    tri = np.array([[0.0, -0.008], [0.006, -0.008], [0.006, 0.0]])
    solid, T = piece_solid("die", tri, -0.2, 0.3)
    assert solid.kind == "mesh" and np.allclose(T, np.eye(4))
    mesh = solid.to_trimesh()
    assert mesh.is_watertight and mesh.is_winding_consistent
    assert mesh.volume == pytest.approx(0.5 * 0.006 * 0.008 * 0.5, rel=1e-12)
    np.testing.assert_allclose(mesh.bounds, [[-0.2, 0.0, -0.008], [0.3, 0.006, 0.0]], atol=1e-15)


def test_robot_obstacles_are_closed_and_uniquely_named(
    u_cell: tuple[SheetMetalPart, PressBrake],
) -> None:
    press = u_cell[1]
    two = dataclasses.replace(
        press,
        stations=(
            dataclasses.replace(
                press.stations[0], name="L", x=-0.3, punch_length=0.2, die_length=0.2
            ),
            dataclasses.replace(
                press.stations[0], name="R", x=0.25, punch_length=0.3, die_length=0.3
            ),
        ),
    )
    for p in (press, two):
        bodies = robot_obstacles(p)
        names = [n for n, _, _ in bodies]
        assert len(set(names)) == len(names), names
        for name, solid, T in bodies:
            assert solid.name == name
            mesh = solid.to_trimesh()
            assert mesh.is_watertight and mesh.volume > 0, name
            assert T.shape == (4, 4)
        kinds = {n.split(" ")[0] for n in names}
        assert {"die", "ram", "beam", "back-gauge", "housing"} <= kinds
        assert sum(n.startswith("die") for n in names) == len(p.stations)
