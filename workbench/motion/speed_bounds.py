"""Closed-form bounds of one jerk-limited joint: speed reachable over a distance, rest-to-rest time.

Both assume zero acceleration at the start and the end of the move.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def max_speed_change(
    s_from: ArrayLike, d: ArrayLike, a_max: ArrayLike, j_max: ArrayLike
) -> NDArray[np.float64]:
    """Return the largest speed [rad/s] reachable from speed `s_from` within distance |d|.

    Both ends have zero acceleration; the jerk-limited velocity profile between speeds s0
    and s1 is point-symmetric, so its distance is (s0 + s1)/2 times its time, which is
    2 sqrt(D/j) for D = |s1 - s0| <= a^2/j and D/a + a/j otherwise. Solved for D in closed
    form (a depressed cubic in sqrt(D), or a quadratic in D). Braking is the same problem
    run backwards.
    """
    s1 = np.asarray(s_from, float)
    dist = np.abs(np.asarray(d, float))
    a, j = np.asarray(a_max, float), np.asarray(j_max, float)
    p, q = 2.0 * s1, -dist * np.sqrt(j)  # x^3 + p x + q = 0 with x = sqrt(D)
    disc = np.sqrt((q / 2.0) ** 2 + (p / 3.0) ** 3)
    x = np.cbrt(-q / 2.0 + disc) + np.cbrt(-q / 2.0 - disc)
    delta_small = x * x
    qa, qb, qc = 1.0 / a, a / j + 2.0 * s1 / a, 2.0 * s1 * a / j - 2.0 * dist
    delta_big = (-qb + np.sqrt(np.maximum(qb * qb - 4.0 * qa * qc, 0.0))) / (2.0 * qa)
    delta = np.where(delta_small <= a * a / j, delta_small, delta_big)
    return s1 + np.maximum(delta, 0.0)


def rest_to_rest_time(
    d: ArrayLike, v_max: ArrayLike, a_max: ArrayLike, j_max: ArrayLike
) -> NDArray[np.float64]:
    """Return the shortest time [s] for one joint to move |d| from rest to rest, jerk-limited."""
    dist = np.abs(np.asarray(d, float))
    v, a, j = np.asarray(v_max, float), np.asarray(a_max, float), np.asarray(j_max, float)
    peak = np.minimum(v, max_speed_change(0.0, dist / 2.0, a, j))
    t_ramp = np.where(peak <= a * a / j, 2.0 * np.sqrt(peak / j), peak / a + a / j)
    ramp = 0.5 * peak * t_ramp
    with np.errstate(divide="ignore", invalid="ignore"):
        cruise = np.where(peak > 0.0, np.maximum(dist - 2.0 * ramp, 0.0) / peak, 0.0)
    return 2.0 * t_ramp * (peak > 0.0) + cruise
