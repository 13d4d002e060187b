"""Tests of workbench/motion/limits.py: waypoints and joint limits checked into float arrays.

Each check is compared with a brute-force scan written here (first bad element in row-major
order), so the index and joint the message names are the ones a user would look for.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.motion.limits import check_limits, check_position_limits, check_waypoints


def test_waypoints_pass_through_as_float() -> None:
    q = check_waypoints([[0, 1], [2, 3]])
    assert q.dtype == np.float64 and q.shape == (2, 2)
    assert q.tolist() == [[0.0, 1.0], [2.0, 3.0]]


@pytest.mark.parametrize(
    ("bad", "text"),
    [
        ([[0, "a"], [1, 2]], "must be an (N, dof) array of numbers"),
        ([[0, 1], [2]], "must be an (N, dof) array of numbers"),
        ([0.0, 1.0], "must have shape (N, dof), got shape (2,)"),
        (np.zeros((3, 0)), "must have shape (N, dof)"),
        ([[0.0, 1.0]], "got a single waypoint (shape (1, 2))"),
    ],
)
def test_waypoints_bad_shape(bad, text) -> None:
    with pytest.raises(InputError) as exc:
        check_waypoints(bad, name="path")
    assert str(exc.value).startswith("path")
    assert text in str(exc.value)


def test_waypoints_first_non_finite_is_named() -> None:
    rng = np.random.default_rng(0)
    for _ in range(50):
        q = rng.normal(size=(rng.integers(2, 6), rng.integers(1, 7)))
        cells = rng.integers(0, q.size, size=rng.integers(1, 4))
        for c in cells:
            q.flat[c] = rng.choice([np.nan, np.inf, -np.inf])
        first = min(int(c) for c in cells)  # brute force: row-major first bad cell
        i, j = divmod(first, q.shape[1])
        with pytest.raises(InputError) as exc:
            check_waypoints(q)
        assert f"waypoints[{i}] joint {j + 1} is" in str(exc.value)


def test_limits_scalar_and_per_segment() -> None:
    assert check_limits("v", 2.0, 3).tolist() == [2.0, 2.0, 2.0]
    assert check_limits("v", [1, 2, 3], 3).tolist() == [1.0, 2.0, 3.0]
    seg = check_limits("v", np.ones((4, 3)), 3, n_segments=4)
    assert seg.shape == (4, 3)
    with pytest.raises(InputError, match=r"shape \(3,\) \(one per joint\), got shape \(4, 3\)"):
        check_limits("v", np.ones((4, 3)), 3)
    with pytest.raises(InputError, match=r"shape \(3,\) or \(5, 3\)"):
        check_limits("v", np.ones((4, 3)), 3, n_segments=5)
    with pytest.raises(InputError, match="must be 3 positive numbers"):
        check_limits("v", ["x", 1, 2], 3)


def test_limits_first_non_positive_joint_is_named() -> None:
    rng = np.random.default_rng(1)
    for _ in range(50):
        arr = rng.uniform(0.1, 2.0, size=(3, 4))
        k = rng.integers(0, arr.size)
        arr.flat[k] = rng.choice([0.0, -1.0, np.nan, np.inf])
        j = int(k) % 4
        with pytest.raises(InputError) as exc:
            check_limits("max_velocity", arr, 4, n_segments=3)
        assert f"max_velocity for joint {j + 1} is" in str(exc.value)
        assert "finite and > 0" in str(exc.value)


def test_position_limits() -> None:
    q = np.array([[0.0, 0.5], [1.0, -0.5]])
    lim = check_position_limits([[-1, 1], [-1, 1]], q)
    assert lim.tolist() == [[-1.0, 1.0], [-1.0, 1.0]]
    # on the boundary is inside
    assert check_position_limits([[0, 1], [-0.5, 0.5]], q).shape == (2, 2)
    with pytest.raises(InputError, match=r"shape \(2, 2\)"):
        check_position_limits([-1, 1], q)
    with pytest.raises(InputError, match=r"joint 2 are \[1.0, 1.0\]; need lower < upper"):
        check_position_limits([[-1, 1], [1, 1]], q)
    with pytest.raises(InputError, match=r"joint 1 are \[nan, 1.0\]"):
        check_position_limits([[math.nan, 1], [-1, 1]], q)
    with pytest.raises(InputError) as exc:
        check_position_limits([[-1, 0.9], [-1, 1]], q)
    assert "waypoints[1] joint 1 = 1 rad is outside its position limits [-1, 0.9]" in str(exc.value)


def test_position_limits_first_outside_is_named_brute_force() -> None:
    rng = np.random.default_rng(2)
    for _ in range(100):
        q = rng.uniform(-2, 2, size=(5, 3))
        lim = np.sort(rng.uniform(-2.5, 2.5, size=(3, 2)), axis=1)
        outside = [
            (i, j) for i in range(5) for j in range(3) if not lim[j, 0] <= q[i, j] <= lim[j, 1]
        ]
        if not outside:
            assert check_position_limits(lim, q).shape == (3, 2)
            continue
        i, j = outside[0]
        with pytest.raises(InputError) as exc:
            check_position_limits(lim, q)
        assert f"waypoints[{i}] joint {j + 1} =" in str(exc.value)
