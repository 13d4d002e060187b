"""A frame from three measured points, as each vendor's pendant defines them.

- KUKA, the 3-point base calibration: the origin, a point on the positive X axis and a point in
  the XY plane on the positive Y side (KUKA System Software 8.x, "Operating and Programming
  Instructions for System Integrators", "Base calibration: 3-point method").
- FANUC, the three-point user frame: the orient origin point, the X direction point and the Y
  direction point (in the XY plane, positive Y) (FANUC R-30iB/R-30iB Plus Controller,
  "Operator's Manual (Basic Operation)" B-83284EN, "Setting a User Frame: Three Point Method").
  The same construction as KUKA's: X from the origin through the X point, Y the Y point's part
  across X, Z = X x Y.
- ABB, the user frame's 3-point method: X1 and X2 on the X axis (X1 to X2 the positive
  direction) and Y1 on the positive Y axis; the origin is the foot of Y1 on the line X1-X2
  (ABB, "Operating manual - IRC5 with FlexPendant", 3HAC050941-001, "Defining the work object
  coordinate system": the user method's points X1, X2, Y1).

Points closer than `MIN_SPACING` to each other, or a Y point that close to the X line, leave
the frame at the mercy of the measuring noise: refused, naming the points.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError

FloatArray = NDArray[np.float64]

MIN_SPACING = 0.010
"""The least distance [m] between two of the points and of the Y point from the X line."""

THREE_POINT_METHODS: dict[str, tuple[str, str, str]] = {
    "kuka": ("origin", "x", "y"),
    "fanuc": ("origin", "x", "y"),
    "abb": ("x1", "x2", "y1"),
}
"""Each vendor's three points, by the labels a readings file gives them (KUKA's and FANUC's
construction is the same; `method_of` names it "kuka/fanuc")."""


@dataclass(frozen=True)
class ThreePointFrame:
    """A frame fitted to three points: `T` (4, 4) [m] the frame in the points' frame, `method`
    ("abb" or "kuka/fanuc"), `labels` and `local` (3, 3) [m] each point in the new frame."""

    T: FloatArray
    method: str
    labels: tuple[str, str, str]
    local: FloatArray


def method_of(labels: Iterable[str]) -> str:
    """Return "abb" or "kuka/fanuc" for a set of point labels; InputError naming the sets."""
    given = {str(label) for label in labels}
    if given == {"origin", "x", "y"}:
        return "kuka/fanuc"
    if given == {"x1", "x2", "y1"}:
        return "abb"
    raise InputError(
        f"three-point labels {sorted(given)}: give origin, x, y (KUKA's and FANUC's origin,"
        " +X point, XY-plane point) or x1, x2, y1 (ABB's user frame)"
    )


def _spaced(points: Mapping[str, FloatArray], min_spacing: float) -> None:
    names = list(points)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            d = float(np.linalg.norm(points[a] - points[b]))
            if d < min_spacing:
                raise InputError(
                    f"points {a} and {b} are {d * 1e3:.2f} mm apart: too close to fix a frame;"
                    f" measure them at least {min_spacing * 1e3:.0f} mm apart (further is better)"
                )


def _frame(
    start: FloatArray,
    through_x: FloatArray,
    y: FloatArray,
    min_spacing: float,
    names: tuple[str, str, str],
) -> tuple[FloatArray, FloatArray]:
    """Return (X, Y) unit axes: X from `start` through `through_x`, Y toward `y` across X."""
    ex = (through_x - start) / np.linalg.norm(through_x - start)
    across = (y - start) - np.dot(y - start, ex) * ex
    if np.linalg.norm(across) < min_spacing:
        raise InputError(
            f"points {', '.join(names)} are collinear: {names[2]} lies"
            f" {np.linalg.norm(across) * 1e3:.2f} mm from the line {names[0]}-{names[1]}, so the"
            f" XY plane is undetermined; measure {names[2]} at least {min_spacing * 1e3:.0f} mm"
            " off that line, on the frame's +Y side"
        )
    return ex, across / np.linalg.norm(across)


def three_point_frame(
    points: Mapping[str, object], *, min_spacing: float = MIN_SPACING
) -> ThreePointFrame:
    """Return the frame of three labelled points (3,) [m]: origin, x, y (KUKA, FANUC) or
    x1, x2, y1 (ABB), in the points' frame. InputError for other labels, NaN, points closer
    than `min_spacing` [m] or a Y point that close to the X line."""
    method = method_of(points)
    names = THREE_POINT_METHODS["abb" if method == "abb" else "kuka"]
    p = {n: np.asarray(points[n], dtype=float).reshape(-1) for n in names}
    for n, v in p.items():
        if v.shape != (3,) or not np.all(np.isfinite(v)):
            raise InputError(f"point {n}: give three finite coordinates, got {v}")
    _spaced(p, min_spacing)
    a, b, c = (p[n] for n in names)
    ex, ey = _frame(a, b, c, min_spacing, names)
    origin = a + np.dot(c - a, ex) * ex if method == "abb" else a  # ABB: Y1's foot on X
    T = np.eye(4)
    T[:3, :3] = np.column_stack([ex, ey, np.cross(ex, ey)])
    T[:3, 3] = origin
    local = (np.stack([a, b, c]) - origin) @ T[:3, :3]
    return ThreePointFrame(T, method, names, local)
