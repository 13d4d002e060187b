"""Air bending on a V-die: the inner radius the die gives, and how deep the punch goes.

SI units (m, rad). Cross-section of a symmetric air bend in the die frame (y across the
die, z up, origin on the die's top at the middle of the V): the die's shoulders are circles
of radius `Rs` centred at (±V/2, −Rs), so the die's top surface starts at y = ±V/2. The
punch pushes the bend's apex down; each flange turns by half the bend angle, α = θ/2, and its
outer surface stays tangent to its shoulder.

Depth of the outer apex (derived here, tested against a brute-force tangency search): the
bend's outer surface near the apex is an arc of radius ρ = r' + t (r' the current inner
radius) about a centre C = (0, z_c); the flange's outer line, at slope α, is tangent to both
that arc and the shoulder circle S = (V/2, −Rs). With the line's unit normal
n = (−sin α, cos α) pointing into the part, n·(C − S) = ρ + Rs, so

    z_c = (ρ + Rs − (V/2)·sin α) / cos α − Rs,    depth h = ρ − z_c   (>= 0).

With r' = t = Rs = 0 this is the textbook h = (V/2)·tan(θ/2). The punch tip touches the
inner apex, a thickness above the outer one: its height over the die's top is t − h.

Inner radius in air bending: the part takes a radius set by the die, not by the punch (as
long as the punch radius is smaller). The rule of thumb used by press-brake makers and
Benson's "20 percent rule" (S. D. Benson, The Fabricator, "The 20 percent rule of air
bending", 2008; and "Understanding the inside radius in air bending"): r ≈ 16 % of the
V-opening for cold-rolled mild steel (15-17 %), 20-22 % for 304 stainless, 13-15 % for
5052-H32 aluminium. `AIR_BEND_RATIO` is the mild-steel value; a press sets its own.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError

if TYPE_CHECKING:
    from workbench.sheetmetal.part import SheetMetalPart

#: Inner radius / V-opening in air bending for cold-rolled mild steel (Benson's 20 % rule).
AIR_BEND_RATIO = 0.16


def air_bend_radius(v_opening: float, ratio: float = AIR_BEND_RATIO) -> float:
    """Return the inner radius [m] an air bend takes in a V-die of opening `v_opening` [m].

    `ratio` is the material's radius / V-opening (0.16 mild steel, ~0.21 stainless, ~0.14
    aluminium).
    """
    v, k = float(v_opening), float(ratio)
    if not (np.isfinite(v) and v > 0):
        raise InputError(f"v_opening: must be > 0 m, got {v_opening!r}")
    if not (np.isfinite(k) and 0 < k < 1):
        raise InputError(f"radius_ratio: must be in (0, 1), got {ratio!r}")
    return v * k


def apex_depth(
    bend_angle: ArrayLike,
    inner_radius: ArrayLike,
    thickness: float,
    v_opening: float,
    shoulder_radius: float,
) -> NDArray[np.float64]:
    """Return how far [m] the bend's outer apex lies below the die's top at bend angle θ [rad].

    `inner_radius` [m] is the bend's current inner radius (inf when flat: depth 0).
    Broadcasts over `bend_angle` and `inner_radius`.
    """
    th = np.asarray(bend_angle, dtype=float)
    r = np.asarray(inner_radius, dtype=float)
    t, v, rs = float(thickness), float(v_opening), float(shoulder_radius)
    a = th / 2.0
    with np.errstate(invalid="ignore", over="ignore"):
        rho = r + t
        # rho·(1/cos a − 1) is finite as a -> 0 with rho·a bounded; write it without the
        # cancellation: 1/cos a − 1 = 2 sin²(a/2) / cos a.
        lift = rho * (2.0 * np.sin(a / 2.0) ** 2) / np.cos(a)
        zc_minus_rho = lift + (rs - 0.5 * v * np.sin(a)) / np.cos(a) - rs
    depth = -zc_minus_rho
    return np.where(th > 0, depth, 0.0)  # type: ignore[no-any-return]


def punch_height(
    bend_angle: ArrayLike,
    inner_radius: ArrayLike,
    thickness: float,
    v_opening: float,
    shoulder_radius: float,
) -> NDArray[np.float64]:
    """Return the punch tip's height [m] over the die's top at bend angle θ: t − depth."""
    return float(thickness) - apex_depth(  # type: ignore[no-any-return]
        bend_angle, inner_radius, thickness, v_opening, shoulder_radius
    )


def short_flanges(part: SheetMetalPart, v_opening: float) -> list[str]:
    """Return a message per flange too short to bridge the V-die: a flange next to a bend must
    reach at least V/2 from the bend line to lie on the die's far shoulder (else it drops
    into the V). Measured in the flange's plane, perpendicular to the bend line."""
    out = []
    for b in part.bends:
        for f, e in ((b.parent, b.parent_edge), (b.child, b.child_edge)):
            poly = part.flanges[f].polygon
            a, c = poly[e], poly[(e + 1) % len(poly)]
            d = (c - a) / np.linalg.norm(c - a)
            inward = np.array([-d[1], d[0]])  # CCW polygon: the interior is to the left
            reach = float(np.max((poly - a) @ inward))
            if reach < v_opening / 2 - 1e-9:
                out.append(
                    f"bend {b.name!r}: flange {part.flanges[f].name!r} reaches "
                    f"{reach * 1e3:.1f} mm from the bend line; the die's V-opening is "
                    f"{v_opening * 1e3:g} mm, so a flange must reach at least V/2 = "
                    f"{v_opening * 1e3 / 2:g} mm to lie on both shoulders: use a narrower die "
                    "(bending.press.die.v_opening) or a longer flange"
                )
    return out
