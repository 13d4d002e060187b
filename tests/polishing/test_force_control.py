"""Hybrid force/position control: the seed's three results, and the linear loop's twins.

Twins: scipy.signal.dlsim of the exact discrete model of the z loop, and the continuous
transfer function k (k_fp s + k_fi) / (s^2 + k k_fp s + k k_fi) (scipy.signal.step).
Orientation loop (eq. 7): a constant tilt decays as exp(-t/tau), tau = (1 + kod)/kop (with
latency and an I term it follows the loop's angle recurrence: tests/polishing/test_orientation.py);
held along the planned normal the error is the tilt of the actual surface, its normal taken
from finite differences of the surface points.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from scipy import signal

from workbench.errors import InputError
from workbench.polishing.force_control import HybridForceParams, simulate_hybrid_force_control
from workbench.polishing.toolpath import spiral_toolpath
from workbench.polishing.workpiece import load_workpiece

PANEL = Path(__file__).resolve().parents[2] / "web_assets" / "workpieces" / "panel.stl"
LINE = np.array([[0.0, 0.0, 0.0], [0.02, 0.0, 0.0]])
UP = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
DEFAULT = HybridForceParams()
FORM_SLOPE = 2 * np.pi * DEFAULT.form_error / DEFAULT.form_wavelength  # amplitude of h'(s)
IDEAL = HybridForceParams(
    latency=0.0,
    filter_cutoff=np.inf,
    damping=0.0,
    friction=0.0,
    form_error=0.0,
    noise_std=0.0,
    max_speed=np.inf,
    max_accel=np.inf,
)


def test_r100_arc_tracking_error_below_0_3_mm() -> None:
    # Seed Table 1: centre [0, -520, 0] mm, radius 100 mm, in the plane x + y = 0; 10 mm/s.
    centre = np.array([0.0, -0.52, 0.0])
    a, b = np.array([1.0, -1.0, 0.0]) / np.sqrt(2), np.array([0.0, 0.0, 1.0])
    th = np.linspace(0.0, np.pi / 2, 300)
    pts = centre + 0.1 * (np.cos(th)[:, None] * a + np.sin(th)[:, None] * b)
    assert np.allclose(np.linalg.norm(pts - centre, axis=1), 0.1)
    assert np.allclose(pts[:, 0] + pts[:, 1], -0.52)  # the plane x + y = 0 through the centre
    normals = (pts - centre) / 0.1
    res = simulate_hybrid_force_control(pts, normals, 20.0, 0.01, dwell=0.5)
    assert res.tracking_error.max() < 3e-4
    # The orientation loop keeps the tool z along the actual (form-error tilted) normal.
    slope = np.arctan(FORM_SLOPE)
    assert res.orientation_error[res.t >= 0.5].max() < 0.1 * slope
    # The feed is held: the tool's angle about the centre advances at 10 mm/s on R100.
    moving = (res.t > 1.0) & (res.t < res.t[-1] - 0.5)
    rel = res.position[moving] - centre
    ang = np.unwrap(np.arctan2(rel @ b, rel @ a))
    rate = np.polyfit(res.t[moving], ang, 1)[0]
    assert rate * 0.1 == pytest.approx(0.01, rel=1e-3)


def test_20_n_step_settles_within_half_a_second_and_stays_within_3_n() -> None:
    res = simulate_hybrid_force_control(LINE, UP, 20.0, 0.01, dwell=1.0)
    after = res.t >= 0.5
    assert np.all(np.abs(res.force[after] - 20.0) <= 3.0)
    assert np.abs(res.force[res.t >= 1.0] - 20.0).mean() < 0.5
    assert res.force[res.t < 0.05].max() < 20.0  # it starts from zero contact force


def test_spiral_on_example_workpiece_stays_within_4_n() -> None:
    mesh, _ = load_workpiece(PANEL)  # the example panel as shipped (STL in mm)
    path = spiral_toolpath(mesh, 0.002, 0.01)
    pts, nrm = path.points[path.is_process][:400], path.normals[path.is_process][:400]
    res = simulate_hybrid_force_control(pts, nrm, 20.0, 0.01, dwell=0.5)
    after = res.t >= 0.5
    assert np.all(np.abs(res.force[after] - 20.0) <= 4.0)
    assert res.tracking_error.max() < 3e-4
    # The tool axis follows the actual surface normal far closer than the planned normal does.
    held = simulate_hybrid_force_control(
        pts, nrm, 20.0, 0.01, dwell=0.5, params=HybridForceParams(orientation_loop=False)
    )
    assert res.orientation_error[after].max() < 0.25 * held.orientation_error[after].max()


def test_steady_state_and_discrete_model_twin() -> None:
    params = dataclasses.replace(IDEAL, control_rate=250.0)
    res = simulate_hybrid_force_control(LINE, UP, 20.0, 0.01, params=params, dwell=2.0)
    assert res.force[-1] == pytest.approx(20.0, abs=1e-6)
    # Exact discrete model: state [delta_k, I_{k-1}], input F_d, output F_k = k delta_k.
    k, kp, ki, dt = params.stiffness, params.kfp, params.kfi, 1.0 / params.control_rate
    A = np.array([[1 - dt * kp * k - dt * dt * ki * k, dt * ki], [-dt * k, 1.0]])
    B = np.array([[dt * kp + dt * dt * ki], [dt]])
    C = np.array([[k, 0.0]])
    _, y, _ = signal.dlsim((A, B, C, np.zeros((1, 1)), dt), np.full(len(res.t), 20.0))
    np.testing.assert_allclose(res.force, y[:, 0], atol=1e-9)


def test_step_matches_continuous_transfer_function() -> None:
    params = dataclasses.replace(IDEAL, control_rate=5000.0)
    res = simulate_hybrid_force_control(LINE, UP, 20.0, 0.02, params=params, dwell=0.0)
    k, kp, ki = params.stiffness, params.kfp, params.kfi
    sys = signal.lti([k * kp, k * ki], [1.0, k * kp, k * ki])
    t = res.t[res.t <= 0.6]
    _, y = signal.step(sys, T=t)
    np.testing.assert_allclose(res.force[: len(t)], 20.0 * y, atol=0.02 * 20.0)


def _tilted(angle: float) -> np.ndarray:
    """Return the tool z (into the surface, -z) tilted by `angle` [rad] about the y axis."""
    return np.array([np.sin(angle), 0.0, -np.cos(angle)])


def test_constant_tilt_decays_with_the_pd_time_constant() -> None:
    # Flat surface, no form error: a 5 degree start tilt about y is the only orientation error.
    th0 = np.radians(5.0)
    params = dataclasses.replace(IDEAL, control_rate=5000.0, max_angular_speed=np.inf)
    res = simulate_hybrid_force_control(
        LINE, UP, 20.0, 0.01, params=params, dwell=0.5, tool_z0=_tilted(th0)
    )
    assert res.orientation_error[0] == pytest.approx(th0)
    # Continuous time: theta' = -kop theta - kod theta'  =>  tau = (1 + kod) / kop.
    tau = (1 + params.kod) / params.kop
    early = res.t <= 5 * tau
    np.testing.assert_allclose(
        res.orientation_error[early], th0 * np.exp(-res.t[early] / tau), atol=0.005 * th0
    )
    # The tilt stays about y: the tool z stays in the xz plane and turns back to -z.
    np.testing.assert_allclose(res.tool_z[:, 1], 0.0, atol=1e-15)
    np.testing.assert_allclose(res.tool_z[-1], [0.0, 0.0, -1.0], atol=1e-9)


def test_angular_speed_limit_and_form_error_tilt() -> None:
    # A 30 degree tilt with a 0.5 rad/s limit turns back at the limit: a straight ramp.
    params = dataclasses.replace(IDEAL, max_angular_speed=0.5)
    res = simulate_hybrid_force_control(
        LINE, UP, 20.0, 0.01, params=params, dwell=1.0, tool_z0=_tilted(np.radians(30.0))
    )
    ramp = res.orientation_error > np.radians(10.0)
    rate = -np.polyfit(res.t[ramp], res.orientation_error[ramp], 1)[0]
    assert rate == pytest.approx(0.5, rel=1e-6)
    assert np.abs(res.commanded_rate).max() <= 0.5 + 1e-12
    # Held along the planned normal, the tool's error is the tilt of the actual surface. Twin:
    # the normal of the surface points themselves (central differences along the line, in
    # the xz plane), not the simulator's slope formula.
    held = dataclasses.replace(DEFAULT, orientation_loop=False)
    line = np.array([[0.0, 0.0, 0.0], [0.2, 0.0, 0.0]])
    res = simulate_hybrid_force_control(line, UP, 20.0, 0.05, params=held)
    surf = res.surface
    np.testing.assert_allclose(surf[:, :2], res.reference[:, :2], atol=1e-15)  # moved along z
    assert np.ptp(surf[:, 2]) > 1.9 * DEFAULT.form_error  # the form error is there
    moving = np.flatnonzero(np.diff(res.reference[:, 0]) > 0)  # before the feed stops
    i = moving[1:-1]  # with a moving neighbour on both sides
    d = surf[i + 1] - surf[i - 1]
    normal = np.stack([-d[:, 2], np.zeros(len(i)), d[:, 0]], axis=1)  # d turned by +90 deg
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    np.testing.assert_allclose(res.surface_normal[i], normal, atol=1e-5)
    tilt = np.arctan2(np.abs(d[:, 2]), d[:, 0])
    np.testing.assert_allclose(res.orientation_error[i], tilt, atol=1e-5)
    assert tilt.max() > 0.9 * np.arctan(FORM_SLOPE)  # the whole wave is sampled
    np.testing.assert_allclose(res.tool_z, np.tile([0.0, 0.0, -1.0], (len(res.t), 1)), atol=0)


def test_bad_input() -> None:
    with pytest.raises(InputError, match="target_force"):
        simulate_hybrid_force_control(LINE, UP, 0.0, 0.01)
    with pytest.raises(InputError, match="max_force"):
        simulate_hybrid_force_control(LINE, UP, 150.0, 0.01)
    with pytest.raises(InputError, match="feed_speed"):
        simulate_hybrid_force_control(LINE, UP, 20.0, 0.0)
    with pytest.raises(InputError, match="normals"):
        simulate_hybrid_force_control(LINE, UP[:1], 20.0, 0.01)
    with pytest.raises(InputError, match="points"):
        simulate_hybrid_force_control(LINE[:1], UP[:1], 20.0, 0.01)
    with pytest.raises(InputError, match="tool_z0"):
        simulate_hybrid_force_control(LINE, UP, 20.0, 0.01, tool_z0=[0.0, 0.0])
    with pytest.raises(
        InputError, match=r"^params\.kop = 600 /s, .* unstable .*; lower params\.kop"
    ):
        simulate_hybrid_force_control(LINE, UP, 20.0, 0.01, params=HybridForceParams(kop=600.0))
    # With an I term the fix can be more P: lowering kop here makes the loop worse.
    ki_bound = HybridForceParams(kop=1.0, kod=0.05, koi=3000.0)
    with pytest.raises(InputError, match=r"unstable .*; raise params\.kop to") as err:
        simulate_hybrid_force_control(LINE, UP, 20.0, 0.01, params=ki_bound)
    assert "lower params.kop" not in str(err.value)
    with pytest.raises(InputError, match="kop and params.koi"):
        simulate_hybrid_force_control(LINE, UP, 20.0, 0.01, params=HybridForceParams(kop=0.0))
    with pytest.raises(InputError, match="max_angular_speed"):
        simulate_hybrid_force_control(
            LINE, UP, 20.0, 0.01, params=HybridForceParams(max_angular_speed=-1.0)
        )
    # Off, the orientation gains are not used (nor checked).
    simulate_hybrid_force_control(
        LINE, UP, 20.0, 0.01, params=HybridForceParams(kop=600.0, orientation_loop=False)
    )
