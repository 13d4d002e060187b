"""Neutral-layer K factor (seed 000, Table 1), bend allowance and the flange OBB extension.

Geometry of one bend (cross-section, derived again rather than copied from the seed):
the inner surface is an arc of radius r, the neutral layer an arc of radius r + K·t, both
about the same centre, swept through the bend (deflection) angle θ = π − included angle.

- Bend allowance (seed eq. 1): BA = θ·(r + K·t). The seed writes π(r + Kδ)(180 − a)/180
  with `a` the *included* angle in degrees (180° = flat), i.e. the same formula.
- Flange extension (seed eq. 2 replaced): split the bend zone at its bisector; the half next
  to a flange lies within ``extension = (r + t)·sin(θ/2)`` of the bend line along the flange
  and rises at most ``rise = r·(1 − cos(θ/2))`` above the flange's inner surface. The seed's
  l_c = r·cot((180 − a)/2) grows without bound as the bend vanishes and, being a pure
  in-plane extension, cannot cover the inner arc, which leaves the flange slab.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError

#: Seed 000 Table 1: r/δ (inner radius over thickness) and the neutral-layer factor K.
R_OVER_T = np.array([0.5, 0.6, 0.7, 1.0, 1.1, 1.2, 1.5, 1.8, 2.0, 2.5, 3.0, 4.0, 8.0])
K_TABLE = np.array([0.24, 0.25, 0.26, 0.30, 0.32, 0.33, 0.36, 0.39, 0.40, 0.43, 0.46, 0.48, 0.50])
#: Smallest r/t the table covers; smaller radii are rejected.
MIN_R_OVER_T = float(R_OVER_T[0])


def k_factor(r_over_t: ArrayLike) -> NDArray[np.float64]:
    """Return the neutral-layer factor K [-] for inner radius / thickness (seed 000 Table 1).

    Linear interpolation in r/t between table entries; r/t >= 8 gives K = 0.5 (the table's
    last column reads "≥ 8.0"). r/t below 0.5 raises InputError.
    """
    x = np.asarray(r_over_t, dtype=float)
    if not np.all(np.isfinite(x)):
        raise InputError(f"k_factor r_over_t: must be finite, got {r_over_t!r}")
    if np.any(x < MIN_R_OVER_T - 1e-12):
        raise InputError(
            f"k_factor r_over_t: {float(np.min(x)):.6g} is below Table 1's range; "
            f"the inner radius must be at least {MIN_R_OVER_T} x thickness"
        )
    return np.interp(x, R_OVER_T, K_TABLE)


def _check(inner_radius: ArrayLike, thickness: ArrayLike, bend_angle: ArrayLike):
    r = np.asarray(inner_radius, dtype=float)
    t = np.asarray(thickness, dtype=float)
    a = np.asarray(bend_angle, dtype=float)
    for name, v in (("inner_radius", r), ("thickness", t), ("bend_angle", a)):
        if not np.all(np.isfinite(v)):
            raise InputError(f"{name}: must be finite, got {v!r}")
    if np.any(t <= 0):
        raise InputError(f"thickness: must be > 0 m, got {float(np.min(t)):.6g}")
    if np.any(a < 0) or np.any(a >= np.pi):
        raise InputError(
            f"bend_angle: must be in [0, pi) rad (0 = flat; included angle = pi - bend_angle), "
            f"got {a!r}"
        )
    if np.any(r < MIN_R_OVER_T * t - 1e-12):
        i = np.argmin(r - MIN_R_OVER_T * t)
        raise InputError(
            f"inner_radius: {float(np.ravel(r)[i] if r.ndim else r) * 1e3:.4g} mm is below Table 1's "
            f"range; the minimum is {MIN_R_OVER_T} x thickness = "
            f"{float(np.ravel(MIN_R_OVER_T * t)[0]) * 1e3:.4g} mm"
        )
    return r, t, a


def bend_allowance(
    inner_radius: ArrayLike,
    thickness: ArrayLike,
    bend_angle: ArrayLike,
    k: ArrayLike | None = None,
) -> NDArray[np.float64]:
    """Return the neutral-layer arc length [m] of a bend: bend_angle·(r + K·t).

    inner_radius r [m], thickness t [m], bend_angle θ [rad] is the deflection (0 = flat,
    π − included angle); k overrides Table 1's K (0 <= k <= 1).
    """
    r, t, a = _check(inner_radius, thickness, bend_angle)
    if k is None:
        kk = k_factor(r / t)
    else:
        kk = np.asarray(k, dtype=float)
        if not np.all(np.isfinite(kk)) or np.any(kk < 0) or np.any(kk > 1):
            raise InputError(f"k: must be in [0, 1], got {k!r}")
    return a * (r + kk * t)


def flange_extension(
    inner_radius: ArrayLike, thickness: ArrayLike, bend_angle: ArrayLike
) -> NDArray[np.float64]:
    """Return how far [m] a flange's box must reach past its bend line to cover half the bend zone.

    (r + t)·sin(θ/2) with θ the bend angle [rad]; see the module docstring.
    """
    r, t, a = (np.asarray(v, dtype=float) for v in (inner_radius, thickness, bend_angle))
    return (r + t) * np.sin(a / 2)


def flange_rise(inner_radius: ArrayLike, bend_angle: ArrayLike) -> NDArray[np.float64]:
    """Return how far [m] half the bend zone rises above the flange's inner surface: r·(1 − cos(θ/2))."""
    r, a = np.asarray(inner_radius, dtype=float), np.asarray(bend_angle, dtype=float)
    return 2.0 * r * np.sin(a / 4) ** 2
