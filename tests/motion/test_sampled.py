"""SampledMotion: shapes checked, TCP speed by central differences against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.motion import SampledMotion, smooth_joint_path


def test_tcp_speed_of_a_circle_is_its_closed_form() -> None:
    # A TCP on a circle of radius 0.3 m at 2 rad/s: speed 0.6 m/s; central differences
    # err by r w (1 - sinc(w dt)) ~ r w^3 dt^2 / 6, forward ones by the same at the chord.
    t = np.linspace(0.0, 2.0, 401)
    p = np.stack([0.3 * np.cos(2 * t), 0.3 * np.sin(2 * t), np.zeros_like(t)], axis=1)
    m = SampledMotion(t, np.zeros((len(t), 1)), tcp=p)
    dt = t[1] - t[0]
    inner = m.tcp_speed[1:-1]
    np.testing.assert_allclose(inner, 0.6 * np.sinc(2 * dt / np.pi), rtol=1e-12)
    # Never above the largest chord speed (the forward differences a plan's bound checks).
    chord = np.linalg.norm(np.diff(p, axis=0), axis=1) / np.diff(t)
    assert m.tcp_speed.max() <= chord.max() + 1e-15


def test_poses_and_positions_give_the_same_speed() -> None:
    rng = np.random.default_rng(0)
    t = np.cumsum(rng.uniform(0.01, 0.02, 50))
    p = rng.normal(size=(50, 3))
    T = np.tile(np.eye(4), (50, 1, 1))
    T[:, :3, 3] = p
    a = SampledMotion(t, np.zeros((50, 2)), tcp=p)
    b = SampledMotion(t, np.zeros((50, 2)), tcp=T)
    np.testing.assert_array_equal(a.tcp_speed, b.tcp_speed)
    # Twin: np.gradient per axis, by hand for one interior sample.
    i = 10
    h0, h1 = t[i] - t[i - 1], t[i + 1] - t[i]
    v = (h0**2 * p[i + 1] - h1**2 * p[i - 1] + (h1**2 - h0**2) * p[i]) / (h0 * h1 * (h0 + h1))
    assert a.tcp_speed[i] == pytest.approx(np.linalg.norm(v), rel=1e-12)


def test_at_interpolates_and_clamps() -> None:
    t = np.array([0.0, 1.0, 3.0])
    q = np.array([[0.0, 1.0], [1.0, 1.0], [3.0, -1.0]])
    m = SampledMotion(t, q, name="m")
    np.testing.assert_allclose(m.at(2.0), [2.0, 0.0])
    np.testing.assert_allclose(m.at(-1.0), q[0])
    np.testing.assert_allclose(m.at(9.0), q[-1])
    assert m.index_at([0.5, 1.0, 5.0]).tolist() == [0, 1, 2]
    assert m.duration == 3.0 and m.dof == 2
    assert m.summary() == "m: 3.000 s, 3 samples, collision-free"
    # Without given velocities: central differences of the joints.
    np.testing.assert_allclose(m.velocity[:, 0], np.gradient(q[:, 0], t))


def test_from_trajectory_matches_the_trajectory() -> None:
    q = np.array([[0.0, 0.0], [0.5, -0.3], [1.0, 0.2]])
    tr = smooth_joint_path(q, np.full(2, 1.0), np.full(2, 4.0), np.full(2, 40.0))
    m = SampledMotion.from_trajectory(tr, 0.01, tcp_of=lambda j: np.c_[j, np.zeros(len(j))])
    t, p, v, a = tr.sample(0.01)
    np.testing.assert_array_equal(m.times, t)
    np.testing.assert_array_equal(m.velocity, v)
    assert m.tcp_positions is not None and m.tcp_positions.shape == (len(t), 3)
    # Central differences of positions approximate the trajectory's own velocity.
    speed = np.linalg.norm(v, axis=1)
    assert np.abs(m.tcp_speed[1:-1] - speed[1:-1]).max() < 0.01


def test_bad_shapes_name_the_field() -> None:
    with pytest.raises(InputError, match="joints"):
        SampledMotion(np.arange(3.0), np.zeros((2, 6)))
    with pytest.raises(InputError, match="tcp"):
        SampledMotion(np.arange(3.0), np.zeros((3, 6)), tcp=np.zeros((3, 2)))
    with pytest.raises(InputError, match="non-decreasing"):
        SampledMotion(np.array([0.0, 2.0, 1.0]), np.zeros((3, 6)))
    with pytest.raises(InputError, match="colliding"):
        SampledMotion(np.arange(3.0), np.zeros((3, 6)), colliding=np.zeros(2, bool))
