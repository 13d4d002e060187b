"""Joint-turn selection: map angles to the +-360 deg turn nearest a reference within limits."""

from __future__ import annotations

import itertools
import math

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
TWO_PI = 2.0 * np.pi
LIMIT_SLACK = 1e-10  # rad; rounding noise allowed at a limit before clipping onto it


def wrap_to_pi(q: FloatArray) -> FloatArray:
    """Return angles [rad] wrapped into [-pi, pi] (rint-based: fast, ties may land on +pi)."""
    return q - TWO_PI * np.rint(q / TWO_PI)


def select_turns(
    q: FloatArray, limits: FloatArray, ref: FloatArray
) -> tuple[FloatArray, NDArray[np.bool_]]:
    """Return (q', ok): per joint the q + 2 pi k nearest `ref` within limits, and whether all fit.

    q: (..., n) [rad], limits: (n, 2) [rad], ref: broadcastable to q [rad]. Joints whose limits
    lie inside [-pi, pi] only get a range check; the others pick their turn.
    """
    qw = wrap_to_pi(q)
    lo, hi = limits[:, 0], limits[:, 1]
    ok = np.ones(q.shape[:-1], dtype=bool)
    narrow = (lo >= -np.pi) & (hi <= np.pi)
    for j in np.nonzero(narrow)[0]:
        ok &= (qw[..., j] >= lo[j] - LIMIT_SLACK) & (qw[..., j] <= hi[j] + LIMIT_SLACK)
    refb = np.broadcast_to(ref, q.shape)
    for j in np.nonzero(~narrow)[0]:
        qj = qw[..., j]
        kmin = np.ceil((lo[j] - LIMIT_SLACK - qj) / TWO_PI)
        kmax = np.floor((hi[j] + LIMIT_SLACK - qj) / TWO_PI)
        ok &= kmin <= kmax
        qw[..., j] = qj + TWO_PI * np.clip(np.rint((refb[..., j] - qj) / TWO_PI), kmin, kmax)
    return np.clip(qw, lo, hi), ok


def joint_turn(
    q: FloatArray, lo: float, hi: float, ref: FloatArray | float
) -> tuple[FloatArray, NDArray[np.bool_]]:
    """Return (q', ok) for one joint: the turn q + 2 pi k nearest ref within [lo, hi] [rad]."""
    qw = wrap_to_pi(q)
    if lo >= -np.pi and hi <= np.pi:
        ok = (qw >= lo - LIMIT_SLACK) & (qw <= hi + LIMIT_SLACK)
        return np.clip(qw, lo, hi), ok
    kmin = np.ceil((lo - LIMIT_SLACK - qw) / TWO_PI)
    kmax = np.floor((hi + LIMIT_SLACK - qw) / TWO_PI)
    k = np.clip(np.rint((ref - qw) / TWO_PI), kmin, kmax)
    return np.clip(qw + TWO_PI * k, lo, hi), kmin <= kmax


def all_turns(q: FloatArray, limits: FloatArray) -> FloatArray:
    """Return every (k, n) variant q + 2 pi k_j of one solution q (n,) [rad] within limits."""
    per_joint = []
    for qj, (lo, hi) in zip(wrap_to_pi(q), limits, strict=False):
        kmin = int(np.ceil((lo - LIMIT_SLACK - qj) / TWO_PI))
        kmax = int(np.floor((hi + LIMIT_SLACK - qj) / TWO_PI))
        per_joint.append([float(np.clip(qj + TWO_PI * k, lo, hi)) for k in range(kmin, kmax + 1)])
    rows = list(itertools.product(*per_joint))
    return np.asarray(rows, dtype=float).reshape(len(rows), q.shape[0])


def turns_scalar(
    theta: tuple[float, ...],
    specs: list[tuple[float, float, float, bool]],
    ref: list[float],
    start: int,
    stop: int,
) -> list[float] | None:
    """Return q_j = theta_j - offset_j for j in [start, stop) at the turn nearest ref within limits.

    specs: per joint (offset, lower, upper, narrow) with narrow = limits inside [-pi, pi].
    Returns None when a joint cannot fit its limits at any turn.
    """
    two_pi, pi, slack, floor, ceil = TWO_PI, math.pi, LIMIT_SLACK, math.floor, math.ceil
    out = []
    for j in range(start, stop):
        o, lj, hj, narrow = specs[j]
        q = (theta[j] - o + pi) % two_pi - pi
        if not narrow:
            # The turn nearest ref, clipped to the turns within limits: in turns, not by
            # stepping, so a far reference (q_near = 1e16) costs no more than a near one.
            kmin, kmax = ceil((lj - slack - q) / two_pi), floor((hj + slack - q) / two_pi)
            if kmin > kmax:
                return None
            q += two_pi * min(max(floor((ref[j] - q) / two_pi + 0.5), kmin), kmax)
        if q < lj - slack or q > hj + slack:
            return None
        out.append(lj if q < lj else hj if q > hj else q)
    return out
