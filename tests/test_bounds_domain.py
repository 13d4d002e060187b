"""Issue 16, part 3 in the domain: bad or extreme inputs end in a WorkbenchError naming the
cause, and work over its budget is refused before it starts (with the estimate)."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest
import trimesh

from workbench.errors import InputError, MeshError, PlanningError
from workbench.kinematics.joint_turns import TWO_PI, turns_scalar
from workbench.motion.trajectory import MAX_SAMPLES, RUCKIG_CAUSES, smooth_joint_path

V, A, J = np.full(2, 1.0), np.full(2, 5.0), np.full(2, 50.0)


# -- joint turns: the nearest turn in closed form, checked against enumerating the turns -----------
def _brute_turn(q: float, lo: float, hi: float, ref: float) -> float | None:
    """The turn q + 2 pi k (k in -6..6) within [lo, hi] nearest ref, by enumeration (ties: lower)."""
    fits = [q + TWO_PI * k for k in range(-6, 7) if lo - 1e-10 <= q + TWO_PI * k <= hi + 1e-10]
    return min(fits, key=lambda x: (abs(x - ref), x)) if fits else None


def test_turns_match_enumerating_every_turn() -> None:
    rng = np.random.default_rng(3)
    checked = 0
    for _ in range(3000):
        lo = float(rng.uniform(-4 * math.pi, 0.5))
        hi = lo + float(rng.uniform(0.1, 4 * math.pi))
        theta = float(rng.uniform(-math.pi, math.pi))
        ref = float(rng.uniform(-3 * math.pi, 3 * math.pi))
        narrow = lo >= -math.pi and hi <= math.pi
        got = turns_scalar((theta,), [(0.0, lo, hi, narrow)], [ref], 0, 1)
        if narrow:
            continue  # a range check only (no turn to choose)
        want = _brute_turn(theta, lo, hi, ref)
        if want is None:
            assert got is None
            continue
        assert got is not None
        # the two nearest turns tie within rounding only at exactly half a turn from ref
        if abs(abs(want - ref) - math.pi) > 1e-9:
            assert got[0] == pytest.approx(min(max(want, lo), hi), abs=1e-9)
            checked += 1
    assert checked > 1000


@pytest.mark.parametrize("far", [1e16, -1e16, 1e300])
def test_ik_with_a_far_reference_returns_at_once(far: float) -> None:
    from workbench.kinematics.dh_robot import DHRobot
    from workbench.kinematics.presets import MZ07_DH, MZ07_LIMITS

    robot = DHRobot(MZ07_DH, MZ07_LIMITS)
    T = robot.fk(np.array([0.1, 0.2, -0.3, 0.4, -0.5, 0.6]))
    t0 = time.perf_counter()
    with np.errstate(over="ignore"):
        sols = robot.ik(T, q_near=np.full(6, far))
    assert time.perf_counter() - t0 < 1.0
    assert np.all(sols >= MZ07_LIMITS[:, 0] - 1e-9) and np.all(sols <= MZ07_LIMITS[:, 1] + 1e-9)
    assert np.allclose(robot.fk(sols[0]), T, atol=1e-9)


def test_ik_says_a_reflection_is_not_a_rotation() -> None:
    from workbench.kinematics.dh_robot import DHRobot
    from workbench.kinematics.presets import MZ07_DH, MZ07_LIMITS

    robot = DHRobot(MZ07_DH, MZ07_LIMITS)
    T = robot.fk(np.zeros(6))
    T[:3, 0] *= -1.0  # orthonormal, det -1
    with pytest.raises(InputError, match="reflection.*not a rotation"):
        robot.ik(T)


# -- trajectories: ruckig's results in words, the move named, the sample budget --------------------
def test_ruckig_result_the_binding_cannot_name_becomes_a_planning_error() -> None:
    """Limits so small that a 3 rad segment would last 3e4 s: ruckig's -101, named in words."""
    q = np.array([[0.0, 0.0], [3.0, 0.0]])
    with pytest.raises(PlanningError) as info:
        smooth_joint_path(q, V * 1e-4, A, J, labels=["the start", "move 1 (far)"])
    msg = str(info.value)
    assert "move 1 (far), segment 0" in msg
    assert RUCKIG_CAUSES[-101] in msg and "not a valid Result" not in msg


def test_a_waypoint_a_hundredth_of_a_micrometre_away_is_merged() -> None:
    """A 1e-5 mm linear move gives joint steps ~1e-8 rad: merged into the waypoint before it
    (its jerk-limited profile would overshoot), so the motion equals the one without it."""
    q = np.array([[0.0, 0.0], [0.5, 0.2], [0.5 + 1e-8, 0.2 - 1e-8], [1.0, 0.0]])
    with_tiny = smooth_joint_path(q, V, A, J)
    without = smooth_joint_path(q[[0, 1, 3]], V, A, J)
    assert with_tiny.duration == pytest.approx(without.duration, rel=1e-9)
    assert with_tiny.waypoint_times[1] == with_tiny.waypoint_times[2]


def test_sampling_over_the_budget_is_refused_with_the_estimate() -> None:
    traj = smooth_joint_path(np.array([[0.0, 0.0], [1.0, 0.0]]), V, A, J)
    dt = traj.duration / (MAX_SAMPLES + 10)
    with pytest.raises(
        PlanningError, match=rf"samples every .* above the budget of {MAX_SAMPLES:,}"
    ):
        traj.sample(dt)
    times = traj.sample(traj.duration / (MAX_SAMPLES - 10))[0]
    assert len(times) <= MAX_SAMPLES


# -- solids and spheres -----------------------------------------------------------------------------
@pytest.mark.parametrize(
    "kwargs",
    [
        {"kind": "cylinder", "radius": 1e-12, "height": 0.1},
        {"kind": "box", "size": (1e308, 1.0, 1.0)},
        {"kind": "box", "size": (1e-9, 1.0, 1.0)},
    ],
)
def test_solids_too_small_or_too_large_are_input_errors(kwargs: dict) -> None:
    from workbench.collision.shapes import Solid

    with pytest.raises(InputError, match=r"pillar: a (box|cylinder)'s dimensions must lie in"):
        Solid("pillar", **kwargs)


def test_a_solid_of_a_micrometre_is_still_checked() -> None:
    from workbench.collision.fcl_checker import SceneBody
    from workbench.collision.shapes import Solid

    body = SceneBody(Solid("pin", "cylinder", radius=1e-6, height=1e-6))
    assert np.all(np.isfinite(body.aabb[0]))


@pytest.mark.parametrize("extents", [(0.0, 0.0, 0.0), (0.0, 0.0, 0.1)])
def test_spheres_of_a_mesh_with_no_area_are_a_mesh_error(extents: tuple) -> None:
    from workbench.geometry.spheres import fit_spheres

    with pytest.raises(MeshError, match="no area"):
        fit_spheres(trimesh.creation.box(extents=extents), 4)


# -- budgets of assembly and polishing ---------------------------------------------------------------
def test_a_part_cut_into_too_many_cells_is_refused_with_the_estimate() -> None:
    from workbench.assembly.cells import MAX_CELLS, check_cell_size

    plate = trimesh.creation.box(extents=(0.2, 0.15, 0.01))
    assert check_cell_size(0.001, plate) == 0.001  # 201 x 151 x 11 cells
    with pytest.raises(InputError) as info:
        check_cell_size(1e-4, plate)
    cells = 2001 * 1501 * 101
    assert f"{cells:.3g} cells" in str(info.value) and f"{MAX_CELLS:,}" in str(info.value)


def test_a_polishing_path_over_its_budget_is_refused_before_planning() -> None:
    from workbench.polishing.process_path import MAX_PASSES, check_path_budget

    panel = trimesh.creation.box(extents=(0.3, 0.2, 0.03))
    check_path_budget(panel, "spiral", 0.003, 0.003)  # 33 passes, ~16,700 points
    check_path_budget(panel, "raster", 0.2, 0.2 / MAX_PASSES["raster"] * 1.01)  # 990 passes
    with pytest.raises(InputError, match=r"spacing: 0.5 mm lays about 200 spiral passes"):
        check_path_budget(panel, "spiral", 0.003, 0.0005)
    with pytest.raises(InputError, match=r"step: 0.1 mm .* path points"):
        check_path_budget(panel, "raster", 0.0001, 0.002)


def test_a_simulation_over_its_budget_is_refused_with_the_estimate() -> None:
    from workbench.polishing.force_control import MAX_STEPS, simulate_hybrid_force_control

    pts = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    nrm = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    t0 = time.perf_counter()
    with pytest.raises(InputError) as info:
        simulate_hybrid_force_control(pts, nrm, 10.0, 1e-4)  # 1e4 s at 250 Hz
    assert time.perf_counter() - t0 < 1.0
    assert "2,500,001 control steps" in str(info.value) and f"{MAX_STEPS:,}" in str(info.value)


def test_urdf_errors_name_the_callers_field(tmp_path) -> None:  # type: ignore[no-untyped-def]
    from workbench.kinematics.urdf_robot import URDFRobot

    with pytest.raises(InputError, match=r"^robot\.urdf: URDF file .* does not exist"):
        URDFRobot.from_file(tmp_path / "missing.urdf", field="robot.urdf")
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='x'><link name='a'/><joint name='j' type='nonsense'/></robot>")
    with pytest.raises(InputError, match=r"^robot\.urdf: cannot read URDF"):
        URDFRobot.from_file(bad, field="robot.urdf")
