"""Tests of workbench/cad/dxf_contours.py: DXF curves flattened and open pieces chained.

The chaining's twin is a brute-force chainer written here (every piece end against every other,
no tree); the flattening's is the closed form of a chord's sagitta, r (1 - cos(dtheta / 2)).
"""

from __future__ import annotations

import math

import ezdxf
import numpy as np
import pytest

from workbench.cad.dxf_contours import CHORD_TOL, JOIN_TOL, Curve, chain_curves, flatten


def _canon_closed(pts: np.ndarray) -> tuple:
    """The same cycle read from any start and in either direction gives the same key."""
    rows = [tuple(np.round(p, 9)) for p in pts]
    n = len(rows)
    keys = []
    for seq in (rows, rows[::-1]):
        for k in range(n):
            keys.append(tuple(seq[k:] + seq[:k]))
    return min(keys)


def _canon_open(pts: np.ndarray) -> tuple:
    rows = [tuple(np.round(p, 9)) for p in pts]
    return min(tuple(rows), tuple(rows[::-1]))


def _brute_chain(pieces: list[np.ndarray]) -> tuple[list, list]:
    def near(a, b):
        return math.dist(a, b) <= JOIN_TOL

    left = list(range(len(pieces)))
    closed, chains = [], []
    while left:
        chain = list(pieces[left.pop(0)])
        grew = True
        while grew:
            grew = False
            for k in list(left):
                p = pieces[k]
                if near(chain[-1], p[0]):
                    chain += list(p[1:])
                elif near(chain[-1], p[-1]):
                    chain += list(p[::-1][1:])
                elif near(chain[0], p[-1]):
                    chain = list(p[:-1]) + chain
                elif near(chain[0], p[0]):
                    chain = list(p[::-1][:-1]) + chain
                else:
                    continue
                left.remove(k)
                grew = True
        if near(chain[0], chain[-1]) and len(chain) > 3:
            closed.append(np.array(chain[:-1]))
        else:
            chains.append(np.array(chain))
    return closed, chains


def _cut(poly: np.ndarray, rng: np.random.Generator, closed: bool) -> list[np.ndarray]:
    """Cut a polyline (closed: the cycle) into pieces of 2+ points sharing their ends."""
    pts = np.vstack([poly, poly[:1]]) if closed else poly
    cuts = sorted(rng.choice(np.arange(1, len(pts) - 1), size=min(3, len(pts) - 2), replace=False))
    bounds = [0, *cuts, len(pts) - 1]
    pieces = [pts[a : b + 1].copy() for a, b in zip(bounds, bounds[1:], strict=False)]
    return [p[::-1].copy() if rng.random() < 0.5 else p for p in pieces]


def test_chaining_matches_brute_force_on_random_drawings() -> None:
    rng = np.random.default_rng(5)
    for _ in range(30):
        pieces: list[np.ndarray] = []
        for s in range(rng.integers(1, 5)):  # closed outlines, far apart
            n = int(rng.integers(5, 12))
            ang = np.sort(rng.uniform(0, 2 * math.pi, n))
            r = rng.uniform(0.01, 0.05, n)
            poly = np.c_[r * np.cos(ang), r * np.sin(ang)] + [s * 0.2, 0.0]
            pieces += _cut(poly, rng, closed=True)
        for s in range(rng.integers(0, 3)):  # open polylines
            poly = np.cumsum(rng.uniform(0.005, 0.02, (int(rng.integers(4, 9)), 2)), axis=0)
            pieces += _cut(poly + [s * 0.2, 1.0], rng, closed=False)
        order = rng.permutation(len(pieces))
        curves = [Curve(pieces[i], False, "0") for i in order]
        closed, chains = chain_curves(curves)
        b_closed, b_chains = _brute_chain([pieces[i] for i in order])
        assert sorted(map(_canon_closed, closed)) == sorted(map(_canon_closed, b_closed))
        assert sorted(map(_canon_open, chains)) == sorted(map(_canon_open, b_chains))


def test_gap_within_tolerance_joins_and_beyond_does_not() -> None:
    a = np.array([[0.0, 0.0], [0.01, 0.0], [0.01, 0.01]])
    b = np.array([[0.01, 0.01 + 0.5 * JOIN_TOL], [0.0, 0.01], [0.0, 0.0]])
    closed, chains = chain_curves([Curve(a, False, "0"), Curve(b, False, "0")])
    assert len(closed) == 1 and chains == []
    assert len(closed[0]) == 4
    far = b.copy()
    far[0, 1] += 3 * JOIN_TOL
    far[-1] += [0.0, 3 * JOIN_TOL]
    closed, chains = chain_curves([Curve(a, False, "0"), Curve(far, False, "0")])
    assert closed == [] and len(chains) == 2


def test_closed_curves_pass_and_degenerate_ones_drop() -> None:
    tri = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    seg = np.array([[0.0, 0.0], [1.0, 0.0]])
    closed, chains = chain_curves([Curve(tri, True, "0"), Curve(seg, True, "0")])
    assert len(closed) == 1 and closed[0] is tri and chains == []
    # one open piece whose ends meet: closed when it has more than three points
    ring = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]])
    closed, chains = chain_curves([Curve(ring, False, "0")])
    assert len(closed) == 1 and len(closed[0]) == 4
    closed, chains = chain_curves([Curve(ring[[0, 1, 4]], False, "0")])
    assert closed == [] and len(chains) == 1


def _msp():
    doc = ezdxf.new()
    return doc.modelspace()


def _arc_deviation(points: np.ndarray, centre, r: float) -> float:
    """Largest distance [m] from the circle of any point on the polyline's chords (dense)."""
    t = np.linspace(0.0, 1.0, 41)[:, None, None]
    s = points[:-1] + t * (points[1:] - points[:-1])
    return float(np.abs(np.linalg.norm(s - np.asarray(centre), axis=2) - r).max())


@pytest.mark.parametrize("radius_mm", [5.0, 40.0, 400.0, 2000.0])
def test_flatten_arc_within_chord_tolerance(radius_mm: float) -> None:
    """Every chord stays within CHORD_TOL of the true arc, for small and large radii (ezdxf's
    default Bézier fit alone strays 10x CHORD_TOL from a 400 mm arc)."""
    msp = _msp()
    arc = msp.add_arc((10, 20), radius_mm, 10, 350)
    c = flatten(arc, 1e-3, "cut")
    assert c is not None and not c.closed and c.layer == "cut"
    r = radius_mm * 1e-3
    a0, a1 = math.radians(10), math.radians(350)
    assert np.allclose(c.points[0], [0.01 + r * math.cos(a0), 0.02 + r * math.sin(a0)])
    assert np.allclose(c.points[-1], [0.01 + r * math.cos(a1), 0.02 + r * math.sin(a1)])
    assert _arc_deviation(c.points, (0.01, 0.02), r) <= CHORD_TOL
    # not over-sampled either: a chord of the closed-form sagitta CHORD_TOL spans
    # 2 acos(1 - CHORD_TOL / r); the flattening may use up to ~4x as many
    n_min = (a1 - a0) / (2 * math.acos(1 - CHORD_TOL / r))
    assert n_min <= len(c.points) - 1 <= 4 * n_min + 8


def test_flatten_bulge_polyline_within_chord_tolerance() -> None:
    """A polyline's bulge (a half circle of r = 300 mm here) is flattened as tightly as an arc."""
    msp = _msp()
    e = msp.add_lwpolyline([(0, 0, 1.0), (600, 0, 0.0)], format="xyb")
    c = flatten(e, 1e-3, "0")
    assert c is not None and not c.closed
    assert _arc_deviation(c.points, (0.3, 0.0), 0.3) <= CHORD_TOL


@pytest.mark.parametrize("kind", ["circle", "lwpolyline", "polyline"])
def test_flatten_closed_entities_drop_the_repeat(kind: str) -> None:
    msp = _msp()
    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    if kind == "circle":
        e = msp.add_circle((5, 5), 5)
    elif kind == "lwpolyline":
        e = msp.add_lwpolyline(square, close=True)
    else:
        e = msp.add_polyline2d(square, close=True)
    c = flatten(e, 1e-3, "0")
    assert c is not None and c.closed
    assert np.linalg.norm(c.points[0] - c.points[-1]) > JOIN_TOL
    if kind != "circle":
        assert np.allclose(c.points, np.array(square) * 1e-3)


def test_flatten_line_scale_and_empty() -> None:
    msp = _msp()
    c = flatten(msp.add_line((1, 2), (3, 2)), 0.0254, "0")
    assert c is not None and not c.closed
    assert np.allclose(c.points, [[0.0254, 0.0508], [0.0762, 0.0508]])
    assert flatten(msp.add_lwpolyline([(1, 1)]), 1e-3, "0") is None
