"""`Workbench.bending` on the bending-cell example: die placements, transfer checks, bad input."""

from __future__ import annotations

import copy
import json
import re
from pathlib import Path

import fcl
import numpy as np
import pytest

from workbench import Workbench
from workbench.errors import InputError, ProjectError, UnreachableError
from workbench.geometry.transforms import invert_transform
from workbench.motion import validate_trajectory
from workbench.project.units import DEG, MM, pose_to_matrix

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "projects" / "bending_cell.json"
SEED_PART = ROOT / "projects" / "parts" / "seed_part.json"


def example_dict() -> dict:
    return json.loads(EXAMPLE.read_text())


def inline_dict() -> dict:
    """The example with the seed part inline (so the file's own checks apply)."""
    d = example_dict()
    del d["bending"]["part_file"]
    d["bending"]["part"] = json.loads(SEED_PART.read_text())
    return d


@pytest.fixture(scope="module")
def wb() -> Workbench:
    return Workbench.open(EXAMPLE)


@pytest.fixture(scope="module")
def plan(wb: Workbench):  # type: ignore[no-untyped-def]
    return wb.bending.plan()


def colliding_dict() -> dict:
    """The example with its first transfer via lowered into the flip rack (z 355 mm): the part's
    flanges hit a rack cup (the example itself passes over the rack, collision-free)."""
    d = example_dict()
    d["bending"]["transfer"][0]["xyz"][2] = 355
    return d


@pytest.fixture(scope="module")
def hit_wb() -> Workbench:
    return Workbench.from_dict(colliding_dict(), base_dir=EXAMPLE.parent)


@pytest.fixture(scope="module")
def hit_plan(hit_wb: Workbench):  # type: ignore[no-untyped-def]
    return hit_wb.bending.plan()


def test_example_transfer_is_collision_free(plan) -> None:  # type: ignore[no-untyped-def]
    assert plan.ok and plan.first_collision is None and not plan.part_colliding.any()


def test_example_loads_seed_part_and_stored_joints_are_free(wb: Workbench) -> None:
    part = wb.bending.part
    assert len(part.flanges) == 7 and len(part.bends) == 6
    assert wb.bending.sequence == ["b23", "b45", "b12", "b14", "b16", "b17"]
    assert part.thickness == pytest.approx(1.5e-3)
    assert not wb.collision_status().in_collision


def test_each_bend_line_lies_on_the_die_with_one_configuration(wb: Workbench, plan) -> None:  # type: ignore[no-untyped-def]
    part, svc = wb.bending.part, wb.bending
    T_die = pose_to_matrix(wb.project.bending.die.pose)
    branches = set()
    lo, hi = wb.robot.limits.T
    for pl in plan.placements:
        b = part.bends[pl.step]
        state = part.fold(pl.step)
        poly = part.flanges[b.parent].polygon
        a, c = poly[b.parent_edge], poly[(b.parent_edge + 1) % len(poly)]
        d = (c - a) / np.linalg.norm(c - a)
        n = np.array([d[1], -d[0]])  # outward normal of a CCW polygon's edge
        s = b.direction * part.thickness / 2
        ends = [p + n * part.bend_allowances[pl.step] / 2 for p in (a, c)]
        local = np.array([[p[0], p[1], -s, 1.0] for p in ends])  # the sheet's outer side
        world = (
            invert_transform(T_die) @ pl.T_world_part @ state.T_part_flange[b.parent] @ local.T
        ).T
        # In the die frame both ends of the bend line are on the x axis, centred on the die.
        np.testing.assert_allclose(world[:, 1:3], 0.0, atol=1e-9)
        assert world[:, 0].sum() == pytest.approx(0.0, abs=1e-9)
        # The robot's flange pose at q puts the TCP at the grasp on the gripped flange.
        T_tcp = wb.tcp_pose(pl.q)
        np.testing.assert_allclose(T_tcp, pl.T_world_tcp, atol=1e-7)
        g = part.flange_index(svc.grasp_flange)
        T_grasp = pl.T_world_part @ state.T_part_flange[g] @ svc.T_flange_grasp()
        np.testing.assert_allclose(T_tcp, T_grasp, atol=1e-7)
        assert np.all(pl.q >= lo - 1e-9) and np.all(pl.q <= hi + 1e-9)
        qb, ok = wb.robot.ik_batch(
            (
                invert_transform(wb.setup.T_world_base)
                @ T_tcp
                @ invert_transform(wb.setup.T_flange_tcp)
            )[None],
            q_near=pl.q,
        )
        match = [k for k in range(8) if ok[0, k] and np.allclose(qb[0, k], pl.q, atol=1e-6)]
        assert match
        branches.add(match[0])
    assert len(branches) == 1


def test_transfer_is_jerk_limited_and_ends_on_the_pallet(wb: Workbench, plan) -> None:  # type: ignore[no-untyped-def]
    r = wb.robot
    rep = validate_trajectory(
        plan.trajectory,
        max_velocity=r.max_velocity,
        max_acceleration=r.max_acceleration,
        max_jerk=r.max_jerk,
        position_limits=r.limits,
    )
    assert rep.ok, rep.violations[:3]
    assert len(plan.times) >= 22 and plan.times[-1] == pytest.approx(plan.trajectory.duration)
    np.testing.assert_allclose(
        plan.T_world_part[-1], pose_to_matrix(wb.project.bending.pallet), atol=1e-7
    )
    # Frames are the trajectory's samples; the grasp frame follows the robot's TCP.
    np.testing.assert_allclose(plan.joints, plan.trajectory.at(plan.times)[0])
    for f in (0, len(plan.times) // 2, -1):
        np.testing.assert_allclose(
            wb.tcp_pose(plan.joints[f]),
            plan.T_world_grasp[f] @ wb.bending.T_flange_grasp(),
            atol=1e-9,
        )


def _fcl_twin(wb: Workbench, plan) -> tuple[np.ndarray, list[set]]:  # type: ignore[no-untyped-def]
    """Every flange box against every cell solid with python-fcl, frame by frame."""
    part = wb.bending.part
    boxes = part.fold(len(part.bends)).flange_obbs()
    objs = [
        (
            body.name,
            fcl.CollisionObject(
                body.solid.fcl_geometry(),
                fcl.Transform(body.T_world_body[:3, :3], body.T_world_body[:3, 3]),
            ),
        )
        for body in wb.cell
        if body.collide
    ]
    req = fcl.CollisionRequest()
    verdict, pairs = [], []
    for T in plan.T_world_part:
        world = boxes.transformed(T)
        hits = set()
        for k in range(len(part.flanges)):
            box = fcl.CollisionObject(
                fcl.Box(*(2 * world.half_extents[k])),
                fcl.Transform(world.rotation[k], world.center[k]),
            )
            for name, o in objs:
                if fcl.collide(box, o, req) > 0:
                    hits.add((part.flanges[k].name, name))
        verdict.append(bool(hits))
        pairs.append(hits)
    return np.array(verdict), pairs


def test_frames_equal_python_fcl_and_first_hit_is_a_rack_cup(hit_wb: Workbench, hit_plan) -> None:  # type: ignore[no-untyped-def]
    wb, plan = hit_wb, hit_plan
    verdict, pairs = _fcl_twin(wb, plan)
    np.testing.assert_array_equal(plan.part_colliding, verdict)
    for f in range(len(plan.times)):
        rep = plan.part_report.frame(f)
        got = {(wb.bending.part.flanges[a].name, plan.obstacle_names[b]) for a, b in rep.hit_pairs}
        assert got == pairs[f], f
    first = plan.first_collision
    assert first is not None and first.kind == "part"
    f0 = int(np.argmax(verdict))
    assert first.frame == f0 and set(first.obstacles) == {o for _, o in pairs[f0]}
    assert all(o.startswith("rack_cup") for o in first.obstacles)
    assert "rack_cup" in plan.summary() and "flange" in plan.summary()
    # The robot is checked too: python-fcl on every frame.
    for f in range(len(plan.times)):
        assert (
            plan.robot_colliding[f] == wb.checker.check(plan.joints[f], distance=False).in_collision
        )


def test_tree_needs_a_third_of_the_flat_tests_on_free_frames(wb: Workbench, plan) -> None:  # type: ignore[no-untyped-def]
    free = ~plan.part_colliding
    assert free.sum() >= 20
    cost = wb.bending.check_cost(plan, repeat=1)  # on request (the GUI's Fig. 12), not in plan
    np.testing.assert_array_equal(cost.tree_tests, plan.tree_tests)
    assert cost.tree_tests[free].sum() * 3 <= cost.flat_tests[free].sum()
    assert cost.ratio(free) <= 1 / 3
    assert np.all(cost.flat_tests == 7 * len(plan.obstacle_names))
    assert np.all(cost.tree_seconds > 0) and np.all(cost.flat_seconds > 0)
    # The plan itself measures nothing: its summary holds no timing or test ratio.
    assert "tree/flat" not in plan.summary()


def test_playback_and_progress(wb: Workbench, plan, hit_wb: Workbench, hit_plan) -> None:  # type: ignore[no-untyped-def]
    seen: list[float] = []
    wb.bending.plan(progress=lambda f, m: seen.append(f))
    assert seen[0] == 0.0 and seen[-1] == 1.0 and seen == sorted(seen)
    pb = wb.bending.playback(plan, dt=0.02)
    assert pb.times[-1] == pytest.approx(plan.trajectory.duration)
    assert not pb.colliding.any() and pb.tcp_speed.max() > 0
    assert hit_wb.bending.playback(hit_plan, dt=0.02).colliding.any()
    np.testing.assert_allclose(
        wb.bending.part_pose_at(plan, plan.times[-1]), plan.T_world_part[-1], atol=1e-9
    )


# -- bad input through the API -----------------------------------------------------------------
def test_api_rejects_bad_sequences_and_grasps() -> None:
    w = Workbench.open(EXAMPLE)
    svc = w.bending
    with pytest.raises(InputError, match=r"sequence.*repeated \['b12'\]"):
        svc.set_sequence(["b12", "b12", "b23", "b14", "b45", "b16"])
    with pytest.raises(InputError, match=r"sequence.*missing \['b17'\]"):
        svc.set_sequence(["b12", "b23", "b14", "b45", "b16"])
    with pytest.raises(InputError, match=r"grasp\.flange: no flange '9'"):
        svc.set_grasp("9")
    with pytest.raises(InputError, match=r"grasp\.offset.*outside flange '1'"):
        svc.set_grasp("1", [0.5, 0.1])
    assert svc.sequence == ["b23", "b45", "b12", "b14", "b16", "b17"]  # unchanged
    svc.set_sequence(["b12", "b23", "b14", "b45", "b16", "b17"])
    assert w.project.bending.sequence == svc.sequence == ["b12", "b23", "b14", "b45", "b16", "b17"]
    svc.set_grasp("1", [0.1, 0.08], yaw=0.0)
    assert w.project.bending.grasp.offset == pytest.approx([100.0, 80.0])


def test_unreachable_die_and_short_die_name_the_bend() -> None:
    d = example_dict()
    d["bending"]["die"]["pose"]["xyz"] = [2500, 0, 350]
    w = Workbench.from_dict(d, base_dir=EXAMPLE.parent)
    with pytest.raises(
        UnreachableError,
        match=r"bending\.die: bend 'b23' \(step 1\) on the die at \[.*\] mm is unreachable",
    ):
        w.bending.plan()
    d = example_dict()
    d["bending"]["die"]["length"] = 250
    w = Workbench.from_dict(d, base_dir=EXAMPLE.parent)
    with pytest.raises(InputError, match=r"bend 'b23'.*300.0 mm long.*250 mm"):
        w.bending.placements()


def test_infeasible_sequence_names_the_flanges() -> None:
    """A lip bent before its wall would be pushed into the base: reject with both flanges."""
    d = inline_dict()
    part = d["bending"]["part"]
    for b in part["bends"]:
        if b["name"] == "b23":
            b["included_angle"] = 10  # lip folded back flat over its wall
            b["direction"] = "up"
    d["bending"]["part"]["flanges"][2]["polygon"] = [[0, 0], [300, 0], [300, 60], [0, 60]]
    w = Workbench.from_dict(d, base_dir=EXAMPLE.parent)
    with pytest.raises(InputError, match=r"flanges '\w' and '\w' intersect after bend"):
        _ = w.bending.part


# -- bad input through the project file --------------------------------------------------------
def _problem(d: dict) -> str:
    with pytest.raises(ProjectError) as exc:
        Workbench.from_dict(d, base_dir=EXAMPLE.parent)
    return str(exc.value)


@pytest.mark.parametrize(
    ("edit", "expected"),
    [
        (
            lambda p: p.update(thickness=-1.5),
            r"bending\.part\.thickness: must be > 0 mm, got -1\.5",
        ),
        (
            lambda p: p["bends"][2].update(inner_radius=0.5),
            r"bending\.part: bends\[2\]\.inner_radius: 0\.5 mm is below Table 1's range; the minimum is 0\.5 x thickness = 0\.75 mm",
        ),
        (
            lambda p: p["bends"][1].update(included_angle=180),
            r"bending\.part\.bends\[1\]\.included_angle: must be in \(0, 180\) deg",
        ),
        (
            lambda p: p["bends"][1].update(included_angle=0),
            r"bending\.part\.bends\[1\]\.included_angle: must be in \(0, 180\) deg",
        ),
        (
            lambda p: p.update(sequence=["b23", "b23", "b12", "b14", "b16", "b17"]),
            r"bending\.part\.sequence: must name every bend exactly once; repeated \['b23'\]",
        ),
        (
            lambda p: p.update(sequence=["b23", "b12", "b14", "b16", "b17"]),
            r"bending\.part: sequence: must name every bend exactly once; missing \['b45'\]",
        ),
    ],
)
def test_project_file_rejects_bad_parts(edit, expected: str) -> None:  # type: ignore[no-untyped-def]
    d = inline_dict()
    edit(d["bending"]["part"])
    assert re.search(expected, _problem(d)), _problem(d)


def test_project_file_rejects_bad_sequence_and_grasp() -> None:
    d = inline_dict()
    d["bending"]["sequence"] = ["b12", "b12", "b23", "b14", "b45", "b16", "b17"]
    assert "bending.sequence: must name every bend exactly once; repeated ['b12']" in _problem(d)
    d = inline_dict()
    d["bending"]["sequence"] = ["b12", "b23", "b14", "b45", "b16"]
    assert "sequence: must name every bend exactly once; missing ['b17']" in _problem(d)
    d = inline_dict()
    d["bending"]["grasp"]["flange"] = "9"
    assert "grasp.flange: no flange '9'" in _problem(d)
    d = inline_dict()
    d["bending"]["frames"] = 10
    assert "bending.frames" in _problem(d)
    # With a part file the grasp is checked when the part is read.
    d = example_dict()
    d["bending"]["grasp"]["flange"] = "9"
    w = Workbench.from_dict(d, base_dir=EXAMPLE.parent)
    with pytest.raises(InputError, match=r"bending\.grasp\.flange: no flange '9'"):
        _ = w.bending.part


def test_part_file_errors_name_the_file_field(tmp_path: Path) -> None:
    part = json.loads(SEED_PART.read_text())
    part["thickness"] = -2
    (tmp_path / "bad_part.json").write_text(json.dumps(part))
    d = example_dict()
    d["bending"]["part_file"] = "bad_part.json"
    # refused at open (the part file is checked with the project), not first at plan
    with pytest.raises(ProjectError, match=r"bending\.part_file.*thickness: must be > 0 mm"):
        Workbench.from_dict(copy.deepcopy(d), base_dir=tmp_path)
    d["bending"]["part_file"] = "missing.json"
    with pytest.raises(ProjectError, match=r"bending\.part_file: cannot read"):
        Workbench.from_dict(d, base_dir=tmp_path)


def test_units_of_the_grasp(wb: Workbench) -> None:
    """The default grasp is the gripped flange's centroid, on its top face, TCP z into the sheet."""
    T = wb.bending.T_flange_grasp()
    np.testing.assert_allclose(T[:3, 3], [0.150, 0.100, 0.75e-3], atol=1e-12)
    np.testing.assert_allclose(T[:3, 2], [0, 0, -1], atol=1e-12)
    assert MM == 1e-3 and DEG == pytest.approx(np.pi / 180)


def test_section_to_si_is_in_metres_and_radians(wb: Workbench) -> None:
    """The service sees the section only through `to_si()`: SI values, the sequence resolved."""
    spec = wb.project.bending
    si = spec.to_si(wb.bending.part_spec())
    assert si.part.thickness == pytest.approx(1.5e-3) and si.frames == spec.frames
    assert si.die.length == pytest.approx(spec.die.length * 1e-3)
    np.testing.assert_allclose(si.die.T_world_die, pose_to_matrix(spec.die.pose), atol=0)
    np.testing.assert_allclose(si.transfer.retract, np.asarray(spec.retract) * 1e-3)
    assert si.transfer.T_world_vias.shape == (len(spec.transfer), 4, 4)
    np.testing.assert_allclose(si.transfer.T_world_pallet, pose_to_matrix(spec.pallet), atol=0)
    b = wb.bending.part_spec().bends[0]
    assert si.part.bends[0].included_angle == pytest.approx(np.radians(b.included_angle))
    assert si.part.bends[0].inner_radius == pytest.approx(b.inner_radius * 1e-3)
    assert si.grasp.flange == spec.grasp.flange and si.grasp.yaw == pytest.approx(0.0)
    # One meaning for the two sequence fields: the project's order replaces the part's own.
    assert si.part.sequence == tuple(wb.bending.part_spec().sequence)
    w = Workbench.open(EXAMPLE)
    w.bending.set_sequence(["b12", "b23", "b14", "b45", "b16", "b17"])
    assert w.bending.si().part.sequence == ("b12", "b23", "b14", "b45", "b16", "b17")
    assert w.bending.part_spec().sequence == ["b23", "b45", "b12", "b14", "b16", "b17"]


# -- the robot through the conservative engine ------------------------------------------------
def _dense(wb: Workbench, q: np.ndarray) -> list[bool]:
    """Twin: python-fcl (plus containment) of every robot pair at every frame."""
    return [wb.checker.check(qi, distance=False).in_collision for qi in q]


def test_robot_is_checked_fast_and_equals_the_dense_exact_check(wb: Workbench, plan) -> None:  # type: ignore[no-untyped-def]
    from workbench.collision.engine import EnginePathReport

    rep = plan.robot_report
    assert isinstance(rep, EnginePathReport) and rep.mode == "spheres" and rep.fallback is None
    dense = wb.checker.check_path(plan.joints)
    np.testing.assert_array_equal(plan.robot_colliding, _dense(wb, plan.joints))
    assert set(np.flatnonzero(plan.robot_colliding)) == set(dense.colliding_indices)
    # Collision-free between frames too, with a clearance the report states in the summary.
    assert rep.collision_free and rep.certified and not plan.robot_between.any()
    assert rep.clearance > 0 and rep.evaluated >= len(plan.times)
    assert "including between samples" in plan.summary() and rep.message in plan.summary()
    # The part is the tree's: the robot's checker holds links and tool only, so the tool and
    # the part it grips are never a pair.
    flanges = {f.name for f in wb.bending.part.flanges}
    bodies = set(wb.checker.scene.moving)
    assert not flanges & bodies and all(b in bodies for b, _ in wb.checker.scene.pairs)


def _intruder(wb: Workbench, frame: int, body: int) -> dict:
    """The example with a 120 mm box on robot frame `body`'s origin at transfer frame `frame`."""
    q = wb.bending.last_plan.joints[frame]  # type: ignore[union-attr]
    L = wb.setup.T_world_base @ wb.robot.link_transforms(q)
    p = L[body, :3, 3] / MM
    d = example_dict()
    d["cell"]["objects"].append(
        {
            "name": "intruder",
            "shape": "box",
            "size": [120, 120, 120],
            "pose": {"xyz": [float(v) for v in p], "rpy": [0, 0, 0]},
            "collide": True,
        }
    )
    return d


def test_a_box_in_the_transfer_path_is_found_at_the_same_frame_as_the_dense_check(
    wb: Workbench, plan
) -> None:  # type: ignore[no-untyped-def]
    F = len(plan.times)
    wb2 = Workbench.from_dict(_intruder(wb, F // 2, 3), base_dir=EXAMPLE.parent)
    p2 = wb2.bending.plan()
    rep = p2.robot_report
    assert rep is not None and rep.mode == "spheres"
    dense = wb2.checker.check_path(p2.joints)
    np.testing.assert_array_equal(p2.robot_colliding, _dense(wb2, p2.joints))
    assert p2.robot_colliding[F // 2] and not rep.collision_free
    assert tuple(np.flatnonzero(p2.robot_colliding)) == dense.colliding_indices
    # The first failure: the same frame as the dense check, unless the engine found a
    # collision between two earlier free frames (then it is one the dense check misses).
    if rep.between:
        assert rep.first_index < dense.first_index and rep.link is not None
        assert wb2.checker.check(rep.first_q, distance=False).in_collision  # confirmed exactly
    else:
        assert rep.first_index == dense.first_index
    assert rep.obstacle == "intruder" and rep.link in wb2.checker.scene.moving
    assert "intruder" in p2.summary() and rep.message in p2.summary()
    first = p2.first_collision
    assert first is not None and not p2.ok
    if first.kind == "robot" and not first.between:
        assert first.frame == dense.first_index and "intruder" in first.obstacles
