"""Trajectories through waypoints, checked against single ruckig calls and closed forms."""

from __future__ import annotations

import numpy as np
import pytest
import ruckig

from workbench.errors import InputError
from workbench.motion.speed_bounds import max_speed_change, rest_to_rest_time
from workbench.motion.trajectory import smooth_joint_path
from workbench.motion.validation import validate_trajectory

V, A, J = np.full(6, 2.0), np.full(6, 8.0), np.full(6, 60.0)


def _ruckig_1dof(p0, v0, p1, v1, vmax, amax, jmax, interface=None):
    otg, inp, out = ruckig.Ruckig(1), ruckig.InputParameter(1), ruckig.Trajectory(1)
    inp.current_position, inp.current_velocity = [p0], [v0]
    inp.target_position, inp.target_velocity = [p1], [v1]
    inp.max_velocity, inp.max_acceleration, inp.max_jerk = [vmax], [amax], [jmax]
    if interface is not None:
        inp.control_interface = interface
    assert otg.calculate(inp, out) == ruckig.Result.Working
    return out


def _gentle(n, rng, step=(0.1, 0.3)):
    d = rng.uniform(-1, 1, 6)
    pts = [np.zeros(6)]
    for _ in range(n - 1):
        d = d / np.linalg.norm(d) + rng.normal(0, 0.15, 6)
        pts.append(pts[-1] + d / np.linalg.norm(d) * rng.uniform(*step))
    return np.array(pts)


def test_rest_to_rest_time_matches_ruckig():
    rng = np.random.default_rng(0)
    for _ in range(200):
        d, v, a, j = (
            rng.uniform(1e-3, 2),
            rng.uniform(0.1, 3),
            rng.uniform(0.5, 10),
            rng.uniform(2, 100),
        )
        ref = _ruckig_1dof(0.0, 0.0, d, 0.0, v, a, j).duration
        assert rest_to_rest_time(d, v, a, j) == pytest.approx(ref, abs=1e-12)


def test_max_speed_change_matches_ruckig_velocity_control():
    rng = np.random.default_rng(1)
    for _ in range(200):
        s0, d, a, j = (
            rng.uniform(0, 2),
            rng.uniform(1e-3, 1),
            rng.uniform(0.5, 10),
            rng.uniform(2, 100),
        )
        s1 = float(max_speed_change(s0, d, a, j))
        # Time-optimal velocity change from s0 to s1 (zero acceleration at both ends) covers d.
        tr = _ruckig_1dof(0.0, s0, 0.0, s1, 10.0, a, j, ruckig.ControlInterface.Velocity)
        p_end, v_end, _ = tr.at_time(tr.duration)
        assert v_end[0] == pytest.approx(s1, abs=1e-9)
        assert p_end[0] == pytest.approx(d, rel=1e-9, abs=1e-12)


def test_at_matches_ruckig_at_time():
    rng = np.random.default_rng(2)
    q = _gentle(12, rng)
    tr = smooth_joint_path(q, V, A, J)
    times = rng.uniform(0, tr.duration, 300)
    p, v, a = tr.at(times)
    for t, pp, vv, aa in zip(times, p, v, a, strict=True):
        k = int(np.searchsorted(tr.segment_start_times, t, side="right") - 1)
        rp, rv, ra = tr.segments[k].at_time(t - tr.segment_start_times[k])
        np.testing.assert_allclose(pp, rp, atol=1e-12)
        np.testing.assert_allclose(vv, rv, atol=1e-12)
        np.testing.assert_allclose(aa, ra, atol=1e-12)


def test_two_waypoints_equal_one_ruckig_call():
    q = np.array([[0.0, 0.1, -0.2, 0.3, 0.0, 1.0], [0.5, -0.4, 0.2, 0.3, 0.1, 0.0]])
    tr = smooth_joint_path(q, V, A, J)
    ref = max(rest_to_rest_time(abs(q[1] - q[0]), V, A, J))
    assert tr.duration == pytest.approx(ref, abs=1e-12)
    np.testing.assert_allclose(tr.waypoint_times, [0.0, tr.duration])
    p, v, a = tr.at([0.0, tr.duration])
    np.testing.assert_allclose(p, q, atol=1e-12)
    np.testing.assert_allclose(v, 0.0, atol=1e-12)


def test_stop_and_go_is_sum_of_rest_to_rest_and_flowing_is_faster():
    rng = np.random.default_rng(3)
    q = _gentle(10, rng)
    stop = smooth_joint_path(q, V, A, J, exact_stop=range(10))
    ref = np.max(rest_to_rest_time(np.abs(np.diff(q, axis=0)), V, A, J), axis=1).sum()
    assert stop.duration == pytest.approx(ref, rel=1e-12)
    assert stop.stop_indices == tuple(range(10))
    flow = smooth_joint_path(q, V, A, J)
    assert flow.duration < 0.8 * stop.duration
    assert len(flow.stop_indices) < 10
    _, v, _ = flow.at(flow.waypoint_times[1:-1])
    assert np.all(np.linalg.norm(v, axis=1) > 0)


def test_stops_where_a_joint_reverses_and_at_exact_stops():
    q = np.zeros((5, 6))
    q[:, 0] = [0.0, 0.5, 1.0, 0.5, 0.0]  # reverses at waypoint 2
    q[:, 1] = [0.0, 0.2, 0.4, 0.6, 0.8]
    tr = smooth_joint_path(q, V, A, J, exact_stop=[3])
    _, v, _ = tr.at(tr.waypoint_times)
    assert v[2, 0] == 0.0 and v[1, 0] > 0 and v[1, 1] > 0
    np.testing.assert_array_equal(v[3], 0.0)
    assert 3 in tr.stop_indices


def test_duplicate_waypoints_are_merged():
    q = np.array([[0.0] * 6, [0.3] * 6, [0.3] * 6, [0.6] * 6])
    tr = smooth_joint_path(q, V, A, J)
    ref = smooth_joint_path(q[[0, 1, 3]], V, A, J)
    assert tr.waypoint_times[1] == tr.waypoint_times[2]
    assert tr.duration == pytest.approx(ref.duration, abs=1e-12)


def test_per_segment_velocity_limits():
    q = np.array([[0.0] * 6, [1.0] * 6, [2.0] * 6])
    vseg = np.array([[2.0] * 6, [0.5] * 6])
    tr = smooth_joint_path(q, vseg, A, J)
    t1 = tr.waypoint_times[1]
    _, v1, _ = tr.at(np.linspace(0, t1, 200))
    _, v2, _ = tr.at(np.linspace(t1, tr.duration, 200))
    assert v1.max() > 1.5 and v2.max() <= 0.5 + 1e-9


def test_sample_spacing_and_end():
    q = np.array([[0.0] * 6, [0.3] * 6])
    tr = smooth_joint_path(q, V, A, J, dt=0.01)
    t, p, v, a = tr.sample()
    assert t[0] == 0.0 and t[-1] == tr.duration
    assert np.all(np.diff(t) <= 0.01 + 1e-12) and np.all(np.diff(t) > 0)
    assert p.shape == v.shape == a.shape == (t.shape[0], 6)
    np.testing.assert_allclose(p[-1], q[-1], atol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"max_velocity": np.zeros(6)}, "max_velocity for joint 1"),
        ({"max_acceleration": -np.ones(6)}, "max_acceleration for joint 1"),
        ({"max_jerk": [1, 1, np.nan, 1, 1, 1]}, "max_jerk for joint 3"),
        ({"max_velocity": np.ones(5)}, "shape"),
        ({"waypoints": [[0.0] * 6]}, "single waypoint"),
        ({"waypoints": [[0.0] * 6, [np.nan] + [0.0] * 5]}, r"waypoints\[1\] joint 1"),
        ({"waypoints": np.zeros(6)}, "shape"),
        ({"waypoints": [[0.2] * 6, [0.2] * 6]}, "same position"),
        ({"position_limits": [[-1, 1]] * 5 + [[-1, 0.5]]}, r"waypoints\[1\] joint 6"),
        ({"position_limits": [[1, -1]] * 6}, "lower < upper"),
        ({"exact_stop": [7]}, "exact_stop index 7"),
        ({"dt": 0.0}, "dt"),
    ],
)
def test_bad_input_raises(kwargs, match):
    args = {
        "waypoints": [[0.0] * 6, [0.8] * 6],
        "max_velocity": V,
        "max_acceleration": A,
        "max_jerk": J,
    }
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        smooth_joint_path(**args)


def test_failed_segment_falls_back_to_a_stop_then_raises_naming_it(monkeypatch):
    import workbench.motion.trajectory as trajectory
    from workbench.errors import PlanningError

    q = np.array([[0.0] * 6, [0.3] * 6, [0.6] * 6, [0.9] * 6])
    solve = trajectory._SegmentSolver.solve

    def picky(self, q0, v0, q1, v1, vmax):  # segment 1 only solves when it ends at rest
        if q0[0] == 0.3 and np.any(v1 != 0):
            return None, "test: refused"
        return solve(self, q0, v0, q1, v1, vmax)

    monkeypatch.setattr(trajectory._SegmentSolver, "solve", picky)
    tr = smooth_joint_path(q, V, A, J)
    assert 2 in tr.stop_indices and 1 not in tr.stop_indices
    _, v, _ = tr.at(tr.waypoint_times)
    np.testing.assert_array_equal(v[2], 0.0)

    def never(self, q0, v0, q1, v1, vmax):
        return (None, "test: refused") if q0[0] == 0.3 else solve(self, q0, v0, q1, v1, vmax)

    monkeypatch.setattr(trajectory._SegmentSolver, "solve", never)
    with pytest.raises(PlanningError, match=r"segment 1 \(waypoint 1 -> 2\).*test: refused"):
        smooth_joint_path(q, V, A, J)


def test_holds_wait_at_exact_stops_and_shift_the_rest() -> None:
    """A program's waits: the robot stands still at the stop, then runs the rest unchanged."""
    q = np.array([[0, 0, 0, 0, 0, 0], [0.5, 0.2, 0, 0, 0, 0], [0.6, -0.3, 0.2, 0, 0, 0]], float)
    V, A, J = np.full(6, 2.0), np.full(6, 8.0), np.full(6, 60.0)
    traj = smooth_joint_path(q, V, A, J, exact_stop=(0, 1, 2))
    held = traj.with_holds([(1, 0.7), (0, 0.25)])
    assert held.duration == pytest.approx(traj.duration + 0.95)
    t1 = traj.waypoint_times[1]
    assert held.waypoint_times[1] == pytest.approx(t1 + 0.25)
    assert held.waypoint_times[2] == pytest.approx(traj.waypoint_times[2] + 0.95)
    # twin: the held trajectory is the original with its clock stopped twice
    t = np.linspace(0.0, traj.duration, 500)
    shifted = t + np.where(t > 0.0, 0.25, 0.0) + np.where(t > t1, 0.7, 0.0)
    np.testing.assert_allclose(held.at(shifted)[0], traj.at(t)[0], atol=1e-12)
    still = held.at(np.linspace(t1 + 0.25, t1 + 0.95, 30))
    np.testing.assert_allclose(still[0], np.broadcast_to(q[1], still[0].shape), atol=1e-12)
    assert np.abs(still[1]).max() == 0.0 and np.abs(still[2]).max() == 0.0
    assert validate_trajectory(held, max_velocity=V, max_acceleration=A, max_jerk=J).ok
    moving = smooth_joint_path(q, V, A, J)  # flows through waypoint 1
    if 1 not in moving.stop_indices:
        with pytest.raises(InputError, match="waypoint 1: a wait needs an exact stop"):
            moving.with_holds([(1, 0.5)])
