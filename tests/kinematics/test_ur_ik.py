"""Tests of workbench/kinematics/ur_ik.py: the closed-form UR inverse kinematics.

The twin is pinocchio's forward kinematics of a model built from the same DH rows, and an
independent product of standard DH matrices written out here from the published UR table
(Universal Robots, "DH parameters for calculations of kinematics and dynamics", UR5e and UR10e).
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from workbench.kinematics.pinocchio_dh import build_dh_model
from workbench.kinematics.ur_ik import ur_geometry, ur_solutions

_ALPHA = (math.pi / 2, 0.0, 0.0, math.pi / 2, -math.pi / 2, 0.0)
# (d1, a2, a3, d4, d5, d6) [m] from the UR table
_UR5E = (0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996)
_UR10E = (0.1807, -0.6127, -0.57155, 0.17415, 0.11985, 0.11655)


def _dh(consts: tuple[float, ...], offsets: tuple[float, ...] = (0.0,) * 6) -> np.ndarray:
    d1, a2, a3, d4, d5, d6 = consts
    d = (d1, 0.0, 0.0, d4, d5, d6)
    a = (0.0, a2, a3, 0.0, 0.0, 0.0)
    return np.array([[offsets[i], d[i], a[i], _ALPHA[i]] for i in range(6)])


def _dh_fk(dh: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Standard DH: T = prod Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i), theta the DH angle."""
    T = np.eye(4)
    for (_, d, a, al), t in zip(dh, theta, strict=True):
        ct, st, ca, sa = math.cos(t), math.sin(t), math.cos(al), math.sin(al)
        T = T @ np.array(
            [
                [ct, -st * ca, st * sa, a * ct],
                [st, ct * ca, -ct * sa, a * st],
                [0.0, sa, ca, d],
                [0.0, 0.0, 0.0, 1.0],
            ]
        )
    return T


class _PinFK:
    def __init__(self, dh: np.ndarray) -> None:
        lim = np.tile([-2 * math.pi, 2 * math.pi], (6, 1))
        self.model = build_dh_model(dh, lim, np.full(6, 3.0))
        self.data = self.model.createData()
        self.frame = self.model.getFrameId("flange")

    def __call__(self, q: np.ndarray) -> np.ndarray:
        pin.framesForwardKinematics(self.model, self.data, q)
        return np.asarray(self.data.oMf[self.frame].homogeneous)


def _wrap(x: np.ndarray) -> np.ndarray:
    return (x + math.pi) % (2 * math.pi) - math.pi


def test_published_table_fk_matches_pinocchio() -> None:
    """The two FKs agree, so the twin below checks the IK against the UR convention itself."""
    rng = np.random.default_rng(1)
    dh = _dh(_UR5E)
    fk = _PinFK(dh)
    for _ in range(20):
        q = rng.uniform(-math.pi, math.pi, 6)
        assert np.allclose(fk(q), _dh_fk(dh, q), atol=1e-12)


@pytest.mark.parametrize("consts", [_UR5E, _UR10E], ids=["ur5e", "ur10e"])
@pytest.mark.parametrize("offsets", [(0.0,) * 6, (0.3, -1.2, 0.4, 2.0, -0.7, 1.1)])
def test_every_candidate_reaches_the_pose_and_the_source_is_among_them(consts, offsets) -> None:
    dh = _dh(consts, offsets)
    g = ur_geometry(dh)
    assert g is not None
    fk = _PinFK(dh)
    off = np.array(offsets)
    rng = np.random.default_rng(7)
    counts = []
    for _ in range(60):
        q = rng.uniform(-math.pi, math.pi, 6)
        T = fk(q)
        sols = ur_solutions(g, T)
        counts.append(len(sols))
        assert sols.shape[1] == 6 and len(sols) <= 8
        for theta in sols:  # DH angles: the joint value is theta - offset
            assert np.allclose(fk(theta - off), T, atol=1e-9), theta
        err = np.abs(_wrap(sols - (q + off))).max(axis=1)
        assert err.min() < 1e-7, (q, sols)
    assert max(counts) == 8  # a generic pose has all eight branches


def test_candidates_are_distinct_and_wrapped() -> None:
    dh = _dh(_UR5E)
    g = ur_geometry(dh)
    assert g is not None
    T = _dh_fk(dh, np.array([0.4, -1.1, 1.3, -0.6, 0.9, 0.2]))
    sols = ur_solutions(g, T)
    assert len(sols) == 8
    assert np.all(np.abs(sols) <= math.pi + 1e-12)
    gaps = [np.abs(_wrap(sols[i] - sols[j])).max() for i in range(8) for j in range(i + 1, 8)]
    assert min(gaps) > 1e-3


def test_singular_wrist_takes_theta6_from_the_reference() -> None:
    """With sin(theta5) = 0 axes 4 and 6 line up: theta6 is the reference plus its offset."""
    offsets = (0.0, 0.0, 0.0, 0.0, 0.0, 0.25)
    dh = _dh(_UR5E, offsets)
    g = ur_geometry(dh)
    assert g is not None
    theta = np.array([0.3, -1.0, 1.2, -0.4, 0.0, 0.25 + 0.5])
    T = _dh_fk(dh, theta)
    sols = ur_solutions(g, T, theta6_ref=0.5)
    singular = sols[np.abs(np.sin(sols[:, 4])) < 1e-6]
    assert len(singular) > 0
    assert np.allclose(_wrap(singular[:, 5] - 0.75), 0.0, atol=1e-9)
    for s in singular:
        assert np.allclose(_dh_fk(dh, s), T, atol=1e-9)


def test_unreachable_pose_has_no_candidate() -> None:
    dh = _dh(_UR5E)
    g = ur_geometry(dh)
    assert g is not None
    far = np.eye(4)
    far[:3, 3] = [3.0, 0.0, 0.2]  # beyond a2 + a3 + the wrist
    assert ur_solutions(g, far).shape == (0, 6)
    # the wrist centre on axis 1 closer than d4: no shoulder solution
    near = np.eye(4)
    near[:3, 3] = [0.0, 0.0, 0.5 + _UR5E[5]]
    assert ur_solutions(g, near).shape == (0, 6)


def test_geometry_reads_the_table_and_rejects_other_arms() -> None:
    dh = _dh(_UR10E, (0.1, 0.2, 0.3, 0.4, 0.5, 0.6))
    g = ur_geometry(dh)
    assert g is not None
    assert (g.d1, g.a2, g.a3, g.d4, g.d5, g.d6) == _UR10E
    assert g.offsets == (0.1, 0.2, 0.3, 0.4, 0.5, 0.6)
    # alpha equal modulo 2 pi is still the family
    shifted = dh.copy()
    shifted[0, 3] += 2 * math.pi
    assert ur_geometry(shifted) is not None
    for row, col, value in [(4, 3, math.pi / 2), (0, 2, 0.05), (1, 1, 0.1), (5, 1, 0.0)]:
        other = dh.copy()
        other[row, col] = value
        assert ur_geometry(other) is None, (row, col)
    assert ur_geometry(dh[:5]) is None
