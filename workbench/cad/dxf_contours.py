"""Closed contours of a DXF drawing: closed polylines and circles, and open curves chained end to end.

Curves are flattened by ezdxf's `path` module (lines, arcs, polyline bulges, circles, ellipses,
splines) so that no chord strays more than `CHORD_TOL` from the curve; open curves whose ends
lie within `JOIN_TOL` of each other are joined into chains, and a chain whose two ends meet is
a closed contour.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.spatial import cKDTree

#: Largest distance [m] between a flattened arc's chord and the arc.
CHORD_TOL = 0.01e-3
#: Curve ends closer than this [m] are joined.
JOIN_TOL = 0.01e-3
#: Cubic Bézier pieces per full turn of an arc, circle or ellipse before flattening. ezdxf's
#: default (one per quarter turn) strays 2.7e-4 r from the arc (0.1 mm at r = 400 mm), beyond
#: CHORD_TOL for r > ~40 mm; 16 pieces stray ~6.6e-8 r (under 1 µm up to r = 10 m).
ARC_SEGMENTS = 16
#: Entity types read as outline geometry.
CURVE_TYPES = ("LINE", "ARC", "CIRCLE", "ELLIPSE", "SPLINE", "LWPOLYLINE", "POLYLINE")


@dataclass(frozen=True, eq=False)
class Curve:
    """A flattened drawing curve: `points` (n, 2) [m], whether it is `closed`, its `layer`."""

    points: NDArray[np.float64]
    closed: bool
    layer: str


def flatten(entity: Any, scale: float, layer: str) -> Curve | None:
    """Return the entity flattened to points [m] (`scale` m per drawing unit), or None if empty."""
    from ezdxf import path

    p = path.make_path(entity, segments=ARC_SEGMENTS)
    pts = np.array([(v.x, v.y) for v in p.flattening(distance=CHORD_TOL / scale)], dtype=float)
    if len(pts) < 2:
        return None
    pts *= scale
    closed = bool(p.is_closed) or bool(getattr(entity, "closed", False))
    closed = closed or (
        entity.dxftype() == "POLYLINE" and bool(getattr(entity, "is_closed", False))
    )
    if closed and np.linalg.norm(pts[0] - pts[-1]) <= JOIN_TOL:
        pts = pts[:-1]
    return Curve(pts, closed, layer)


def _ends_match(a: NDArray[np.float64], b: NDArray[np.float64]) -> bool:
    return bool(np.linalg.norm(a - b) <= JOIN_TOL)


def chain_curves(
    curves: list[Curve],
) -> tuple[list[NDArray[np.float64]], list[NDArray[np.float64]]]:
    """Return (closed contours, open chains), each (n, 2) [m]; closed ones without the repeat."""
    closed = [c.points for c in curves if c.closed and len(c.points) >= 3]
    pieces = [c.points for c in curves if not c.closed]
    if not pieces:
        return closed, []
    ends = np.array([[p[0], p[-1]] for p in pieces]).reshape(-1, 2)
    tree = cKDTree(ends)
    used = np.zeros(len(pieces), dtype=bool)
    chains = []
    for s in range(len(pieces)):
        if used[s]:
            continue
        used[s] = True
        chain, flipped = [pieces[s]], False
        while True:
            start, end = chain[0][0], chain[-1][-1]
            if (
                len(chain) > 1
                and _ends_match(start, end)
                or (len(chain) == 1 and len(chain[0]) > 3 and _ends_match(start, end))
            ):
                pts = np.concatenate([chain[0]] + [c[1:] for c in chain[1:]])[:-1]
                closed.append(pts)
                break
            near = [j for j in tree.query_ball_point(end, JOIN_TOL) if not used[j // 2]]
            if near:
                j = min(near, key=lambda j: float(np.linalg.norm(ends[j] - end)))
                used[j // 2] = True
                piece = pieces[j // 2]
                chain.append(piece if j % 2 == 0 else piece[::-1])
                continue
            if flipped:
                chains.append(np.concatenate([chain[0]] + [c[1:] for c in chain[1:]]))
                break
            chain, flipped = [c[::-1] for c in reversed(chain)], True
    return closed, chains
