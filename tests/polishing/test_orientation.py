"""Orientation helpers of eq. 7 against scipy's rotations and the loop's own recurrence.

The recurrence (the loop's angle stepped directly) is the twin of the poles, of the
suggested fixes for unstable gains and of the simulator's tool axis."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.polishing.force_control import HybridForceParams, simulate_hybrid_force_control
from workbench.polishing.orientation import (
    SUGGEST_BELOW,
    instability_message,
    orientation_loop_poles,
    orientation_loop_radius,
    rotate3,
    rotation_vector3,
    rotation_vectors,
    stabilising_changes,
)


def _unit(rng: np.random.Generator, n: int) -> np.ndarray:
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def test_rotation_vectors_take_a_to_b_by_the_angle_between_them() -> None:
    rng = np.random.default_rng(0)
    a, b = _unit(rng, 200), _unit(rng, 200)
    w = rotation_vectors(a, b)
    # Twin: scipy's rotation from the rotation vector maps a onto b ...
    np.testing.assert_allclose(Rotation.from_rotvec(w).apply(a), b, atol=1e-12)
    # ... by the angle between them (arccos), about an axis normal to both.
    ang = np.arccos(np.clip(np.sum(a * b, axis=1), -1, 1))
    np.testing.assert_allclose(np.linalg.norm(w, axis=1), ang, atol=1e-12)
    np.testing.assert_allclose(np.sum(w * a, axis=1), 0.0, atol=1e-12)
    # The scalar twin used in the simulation loop agrees.
    for i in range(20):
        ex, ey, ez, th = rotation_vector3(*a[i], *b[i])
        np.testing.assert_allclose([ex, ey, ez], w[i], atol=1e-14)
        assert th == pytest.approx(ang[i], abs=1e-12)
    assert rotation_vector3(0.0, 0.0, 1.0, 0.0, 0.0, 1.0)[:3] == (0.0, 0.0, 0.0)
    # Beyond 90 degrees the angle keeps growing (|a x b| = sin would fall again: the seed's norm).
    big = rotation_vectors(np.array([1.0, 0, 0]), np.array([-0.6, 0.8, 0.0]))
    assert np.linalg.norm(big) == pytest.approx(np.arccos(-0.6))


def test_rotate3_is_rodrigues() -> None:
    rng = np.random.default_rng(1)
    z, w = _unit(rng, 50), rng.normal(scale=0.5, size=(50, 3))
    ref = Rotation.from_rotvec(w).apply(z)
    got = np.array([rotate3(*z[i], *w[i]) for i in range(50)])
    np.testing.assert_allclose(got, ref, atol=1e-13)
    assert rotate3(0.0, 0.0, 1.0, 0.0, 0.0, 0.0) == (0.0, 0.0, 1.0)


def _recurrence(
    kop: float, kod: float, koi: float, dt: float, lag: int, n: int, th0: float = 1.0
) -> np.ndarray:
    """Twin: the loop's angle recurrence for a tilt th0 about a fixed axis, stepped directly."""
    th = np.zeros(n)
    th[0] = th0
    u = np.zeros(n)
    integ, prev = 0.0, th[0]
    for k in range(n - 1):
        integ += th[k] * dt
        u[k] = kop * th[k] + kod * (th[k] - prev) / dt + koi * integ
        prev = th[k]
        th[k + 1] = th[k] - dt * (u[k - lag] if k >= lag else 0.0)
    return th


@pytest.mark.parametrize(
    ("kop", "kod", "koi", "lag"), [(40.0, 0.05, 0.0, 2), (20.0, 0.0, 0.0, 0), (30.0, 0.1, 200.0, 2)]
)
def test_poles_give_the_recurrences_decay_rate(
    kop: float, kod: float, koi: float, lag: int
) -> None:
    dt = 1 / 250
    poles = orientation_loop_poles(kop, kod, koi, dt, lag)
    rho = np.abs(poles).max()
    assert rho < 1
    th = _recurrence(kop, kod, koi, dt, lag, 6000)
    # Once the dominant pole rules, the envelope (a window's peak, robust to the oscillation
    # of complex poles) shrinks by its modulus per cycle.
    n0 = int(np.ceil(np.log(1e-3) / np.log(rho)))  # the others have died out well before here
    n1 = n0 + int(np.ceil(np.log(1e-6) / np.log(rho)))
    w = 40
    a, b = np.abs(th[n0 : n0 + w]).max(), np.abs(th[n1 : n1 + w]).max()
    assert np.log(b / a) / (n1 - n0) == pytest.approx(np.log(rho), rel=0.02)


def test_unstable_gains_have_a_pole_outside_the_unit_circle() -> None:
    dt = 1 / 250
    assert np.abs(orientation_loop_poles(600.0, 0.0, 0.0, dt, 0)).max() > 1  # dt kop = 2.4
    assert np.abs(orientation_loop_poles(200.0, 0.05, 0.0, dt, 2)).max() > 1  # latency
    th = _recurrence(200.0, 0.05, 0.0, dt, 2, 400)
    assert np.abs(th[-50:]).max() > 10  # the twin blows up too


def test_radius_rounds_the_latency_to_whole_cycles() -> None:
    for latency, lag in ((0.008, 2), (0.0099, 2), (0.011, 3), (0.0, 0)):
        rho, got = orientation_loop_radius(40.0, 0.05, 10.0, 250.0, latency)
        assert got == lag
        assert rho == np.abs(orientation_loop_poles(40.0, 0.05, 10.0, 1 / 250, lag)).max()
    assert instability_message(40.0, 0.05, 0.0, 250.0, 0.008) is None  # the defaults: stable


@pytest.mark.parametrize(
    ("gains", "fix"),
    [
        ((600.0, 0.0, 0.0), "lower kp"),
        ((200.0, 0.05, 0.0), "lower kp"),
        # With an I term more P damps the integral's swing: lowering kp makes it worse.
        ((1.0, 0.05, 3000.0), "raise kp"),
        ((0.0, 0.0, 100.0), "raise kp"),
    ],
)
def test_suggested_fix_makes_the_recurrence_decay(
    gains: tuple[float, float, float], fix: str
) -> None:
    dt, lag, n = 1 / 250, 2, 3000
    grow = 1500  # long enough for |z| = 1.002 to grow 20x, short of overflow for |z| = 1.5
    assert np.abs(_recurrence(*gains, dt, lag, grow)[-50:]).max() > 1.0  # unstable: it grows
    msg = instability_message(*gains, 250.0, 0.008, ("kp", "kd", "ki"))
    assert msg is not None and msg.startswith(f"kp = {gains[0]:g} /s, kd = {gains[1]:g}, ")
    assert f"; {fix} to " in msg
    changes = stabilising_changes(*gains, 250.0, 0.008)
    assert changes and changes[0][0] == "kop"
    short = {"kop": "kp", "kod": "kd", "koi": "ki"}  # the names given to the message
    for name, value, rho in changes:
        i = ("kop", "kod", "koi").index(name)
        g = list(gains)
        g[i] = value
        assert rho < SUGGEST_BELOW
        th = _recurrence(g[0], g[1], g[2], dt, lag, n)
        assert np.abs(th[-50:]).max() < 1e-9  # the suggested change decays in the twin
        way = "lower" if value < gains[i] else "raise"
        assert f"{way} {short[name]} to {value:g}" in msg
    if fix == "raise kp":
        assert "lower kp" not in msg
        # The twin agrees that lowering kp is no fix: at half the kp it still grows.
        assert np.abs(_recurrence(gains[0] / 2, *gains[1:], dt, lag, grow)[-50:]).max() > 1.0


def test_tilt_matches_the_discrete_recurrence_with_latency_and_integral() -> None:
    # At 250 Hz with 2 cycles of latency and an I term the simulated angle follows the
    # loop's recurrence exactly (Rodrigues rotations about one axis add up angles exactly).
    params = HybridForceParams(
        latency=0.008,
        kod=0.1,
        koi=150.0,
        max_angular_speed=np.inf,
        filter_cutoff=np.inf,
        damping=0.0,
        friction=0.0,
        form_error=0.0,
        noise_std=0.0,
        max_speed=np.inf,
        max_accel=np.inf,
    )
    th0 = np.radians(3.0)
    line = np.array([[0.0, 0.0, 0.0], [0.02, 0.0, 0.0]])
    up = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    tool_z0 = [np.sin(th0), 0.0, -np.cos(th0)]  # tilted about y
    res = simulate_hybrid_force_control(
        line, up, 20.0, 0.01, params=params, dwell=1.0, tool_z0=tool_z0
    )
    dt, lag = 1 / params.control_rate, 2
    th = _recurrence(params.kop, params.kod, params.koi, dt, lag, len(res.t), th0)
    # The reported error is the unsigned angle; the signed one may overshoot through zero.
    np.testing.assert_allclose(res.orientation_error, np.abs(th), atol=1e-12)
