"""Cutting a checked flat pattern into flanges along its bend zones: the part spec it makes.

Each bend line splits the blank (a simple polygon; an edge-to-edge chord cuts it in two), so
B bend lines leave B + 1 regions joined in a tree. A region's edge along a bend line moves half
a bend allowance into the region: the flange's bend edge. Where the outline crosses a bend zone
at right angles (the usual case, and every corner relief) the flanges and zones tile the
blank exactly; an outline crossing a zone obliquely at angle φ is approximated there within
BA/2·tan φ, since the part model's bend zones are rectangles.
"""

from __future__ import annotations

import numpy as np
import shapely
import shapely.ops
from numpy.typing import NDArray

from workbench.cad.flat_pattern import (
    TOUCH_TOL,
    FlatPattern,
    FlatPatternError,
    bend_label,
    check_flat_pattern,
)
from workbench.geometry.polygon import clean_ring, signed_area
from workbench.sheetmetal.kfactor import MIN_R_OVER_T, bend_allowance

_MATCH_TOL = 1e-7  # [m] a region vertex this close to a bend line's end is that end


def _radii(pattern: FlatPattern, t: float, default: float | None, field: str) -> list[float]:
    radii = []
    for i, line in enumerate(pattern.bend_lines):
        r = line.inner_radius if line.inner_radius is not None else default
        if r is None:
            raise FlatPatternError(
                f"{bend_label(i, line)} has no inner radius: write it in its bend note "
                "('UP 90° R1.5') or give inner_radius (the import setting) for the bends "
                "without one; the bend zones' width, and so every flange's size, depends on it",
                field=field,
            )
        if not np.isfinite(r) or r < MIN_R_OVER_T * t - 1e-12:
            raise FlatPatternError(
                f"{bend_label(i, line)}: inner radius {r * 1e3:.4g} mm is below Table 1's "
                f"minimum {MIN_R_OVER_T} x thickness = {MIN_R_OVER_T * t * 1e3:.4g} mm; "
                "use a larger radius",
                field=field,
            )
        radii.append(float(r))
    return radii


def _regions(pattern: FlatPattern) -> list[NDArray[np.float64]]:
    faces = [shapely.Polygon(pattern.outline)]
    for line in pattern.bend_lines:
        d = (line.end - line.start) / line.length
        cutter = shapely.LineString([line.start - 1e-6 * d, line.end + 1e-6 * d])
        faces = [g for f in faces for g in shapely.ops.split(f, cutter).geoms]
    rings = []
    for f in faces:
        ring = clean_ring(np.asarray(f.exterior.coords)[:-1])
        rings.append(ring if signed_area(ring) > 0 else ring[::-1].copy())
    return rings


def _bend_edge(ring: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]) -> int:
    nxt = np.roll(ring, -1, axis=0)
    fwd = (np.linalg.norm(ring - a, axis=1) < _MATCH_TOL) & (
        np.linalg.norm(nxt - b, axis=1) < _MATCH_TOL
    )
    back = (np.linalg.norm(ring - b, axis=1) < _MATCH_TOL) & (
        np.linalg.norm(nxt - a, axis=1) < _MATCH_TOL
    )
    hit = np.flatnonzero(fwd | back)
    return int(hit[0]) if len(hit) else -1


def split_flanges(
    pattern: FlatPattern,
    *,
    thickness: float,
    inner_radius: float | None,
    k_factor: float | None,
    field: str,
) -> dict:
    """Return the SI part spec of a pattern already checked by `check_flat_pattern`.

    See `part_spec_from_flat_pattern` (the public entry) for the arguments and the naming.
    """
    t = float(thickness)
    if not (np.isfinite(t) and t > 0):
        raise FlatPatternError(f"thickness: must be > 0 m, got {thickness!r}", field=field)
    if k_factor is not None and not (np.isfinite(k_factor) and 0.0 <= k_factor <= 1.0):
        raise FlatPatternError(f"k_factor: must be in [0, 1], got {k_factor!r}", field=field)
    lines = pattern.bend_lines
    radii = _radii(pattern, t, inner_radius, field)
    ba = [
        float(bend_allowance(r, t, ln.angle, k_factor)) for r, ln in zip(radii, lines, strict=True)
    ]
    zones = []
    for i, ln in enumerate(lines):
        d = (ln.end - ln.start) / ln.length
        h = 0.5 * ba[i] * np.array([-d[1], d[0]])
        zones.append(shapely.Polygon([ln.start - h, ln.end - h, ln.end + h, ln.start + h]))
    for i in range(len(zones)):
        for j in range(i + 1, len(zones)):
            if zones[i].intersection(zones[j]).area > TOUCH_TOL**2:
                raise FlatPatternError(
                    f"the bend zones of {bend_label(i, lines[i])} and {bend_label(j, lines[j])} "
                    f"({ba[i] * 1e3:.3g} and {ba[j] * 1e3:.3g} mm wide) overlap; move the bend "
                    "lines apart or enlarge the relief between them",
                    field=field,
                )
    rings = _regions(pattern)
    if len(rings) != len(lines) + 1:
        raise FlatPatternError(
            f"{len(lines)} bend lines cut the blank into {len(rings)} pieces, not {len(lines) + 1}",
            field=field,
        )
    # sides[i] = (region on the bend line's left, region on its right)
    polys = [shapely.Polygon(r) for r in rings]
    sides, edges = [], [dict[int, int]() for _ in rings]
    for i, ln in enumerate(lines):
        d = (ln.end - ln.start) / ln.length
        n = np.array([-d[1], d[0]])
        mid = 0.5 * (ln.start + ln.end)
        pair = []
        for s in (1.0, -1.0):
            probe = shapely.Point(mid + s * 1e-6 * n)
            k = int(np.argmin([p.distance(probe) for p in polys]))
            e = _bend_edge(rings[k], ln.start, ln.end)
            if e < 0:
                raise FlatPatternError(
                    f"{bend_label(i, ln)}: cannot find its bend edge", field=field
                )
            edges[k][i] = e
            pair.append(k)
        sides.append(tuple(pair))
    for k, ring in enumerate(rings):
        moved, ends = ring.copy(), {}
        for i, e in edges[k].items():
            ln = lines[i]
            d = (ln.end - ln.start) / ln.length
            inward = np.array([-d[1], d[0]]) * (1.0 if sides[i][0] == k else -1.0)
            for v in (e, (e + 1) % len(ring)):
                moved[v] = ring[v] + 0.5 * ba[i] * inward
            ends[i] = (ln.start + 0.5 * ba[i] * inward, ln.end + 0.5 * ba[i] * inward)
        kept = np.array([p for pair in ends.values() for p in pair]).reshape(-1, 2)
        moved = clean_ring(moved, keep=kept)
        poly = shapely.Polygon(moved) if len(moved) >= 3 else None
        found = {i: _bend_edge(moved, a, b) for i, (a, b) in ends.items()}
        if poly is None or not poly.is_valid or signed_area(moved) <= 0 or -1 in found.values():
            names = ", ".join(bend_label(i, lines[i]) for i in edges[k])
            raise FlatPatternError(
                f"cutting the bend zones of {names} out of the blank leaves no simple flange "
                "between them: the outline must run across each bend zone (make corner reliefs "
                "at least half a bend allowance deep, or the flange wider than its zones)",
                field=field,
            )
        rings[k], edges[k] = moved, found
    holes = _holes_of_regions(pattern, rings, zones, field)
    return _spec(rings, edges, sides, lines, radii, t, k_factor, holes)


def _holes_of_regions(
    pattern: FlatPattern,
    rings: list[NDArray[np.float64]],
    zones: list[shapely.Polygon],
    field: str,
) -> list[list[NDArray[np.float64]]]:
    """Return each region's holes (pattern frame); a hole reaching into a bend zone is refused."""
    polys = [shapely.Polygon(r) for r in rings]
    out: list[list[NDArray[np.float64]]] = [[] for _ in rings]
    for j, hole in enumerate(pattern.holes):
        h = shapely.Polygon(hole)
        c = h.centroid
        at = f"inner contour {j + 1} (centre {c.x * 1e3:.4g}, {c.y * 1e3:.4g} mm)"
        for i, zone in enumerate(zones):
            if zone.intersection(h).area > TOUCH_TOL**2:
                raise FlatPatternError(
                    f"{at} reaches into the bend zone of {bend_label(i, pattern.bend_lines[i])}; "
                    "a hole across a bend is not sheet metal the model can fold: move it off "
                    "the zone or remove it",
                    field=field,
                )
        k = [i for i, p in enumerate(polys) if p.contains(h)]
        if not k:
            raise FlatPatternError(f"{at} lies in no flange", field=field)
        out[k[0]].append(np.asarray(hole, dtype=float))
    return out


def _spec(
    rings: list[NDArray[np.float64]],
    edges: list[dict[int, int]],
    sides: list[tuple[int, ...]],
    lines: tuple,
    radii: list[float],
    t: float,
    k_factor: float | None,
    holes: list[list[NDArray[np.float64]]],
) -> dict:
    base = int(np.argmax([signed_area(r) for r in rings]))
    order, parent_of = [base], {base: (-1, -1)}
    for k in order:  # breadth first; `order` grows while it is walked
        for i in sorted(edges[k]):
            other = sides[i][1] if sides[i][0] == k else sides[i][0]
            if other not in parent_of:
                parent_of[other] = (k, i)
                order.append(other)
    name = {k: f"F{j + 1}" for j, k in enumerate(order)}
    flanges, edge_of = [], [dict(e) for e in edges]
    for k in order:
        ring, bend = rings[k], parent_of[k][1]
        inner = holes[k]
        if bend >= 0:  # a child: its bend edge becomes edge 0, from the origin along +x
            shift = edge_of[k][bend]
            ring = np.roll(ring, -shift, axis=0)
            edge_of[k] = {i: (e - shift) % len(ring) for i, e in edge_of[k].items()}
            d = (ring[1] - ring[0]) / np.linalg.norm(ring[1] - ring[0])
            rel = ring - ring[0]
            n = np.array([-d[1], d[0]])
            inner = [np.column_stack([(h - ring[0]) @ d, (h - ring[0]) @ n]) for h in inner]
            ring = np.column_stack([rel @ d, rel @ n])
        flange: dict = {"name": name[k], "polygon": ring.tolist()}
        if inner:
            flange["holes"] = [h.tolist() for h in inner]
        flanges.append(flange)
    bends = []
    for i, ln in enumerate(lines):
        child = sides[i][0] if parent_of[sides[i][0]][1] == i else sides[i][1]
        parent = parent_of[child][0]
        bends.append(
            {
                "name": f"B{i + 1}",
                "parent": name[parent],
                "parent_edge": int(edge_of[parent][i]),
                "child": name[child],
                "child_edge": int(edge_of[child][i]),
                "bend_angle": float(ln.angle),
                "inner_radius": radii[i],
                "direction": "up" if ln.direction > 0 else "down",
            }
        )
    return {"thickness": t, "k_factor": k_factor, "flanges": flanges, "bends": bends}


def part_spec_from_flat_pattern(
    pattern: FlatPattern,
    *,
    thickness: float,
    inner_radius: float | None,
    k_factor: float | None,
    field: str,
) -> dict:
    """Return the SI spec of `SheetMetalPart.from_spec` for the part `pattern` folds into.

    thickness [m] > 0; inner_radius [m] for the bend lines without their own (None: each must
    carry one; the project passes its import setting or, as for a part without radii, the
    press's air-bending radius); k_factor overrides Table 1's K for every bend (None: Table 1).
    The outline is cut along each bend zone (centred on its line, one bend allowance wide) into
    flanges "F1".. ("F1", the base, the largest; the rest in the order the bends reach them from
    it) joined by bends "B1".. in bend-line order. The base keeps the drawing's coordinates;
    every other flange starts its polygon at its bend edge, along +x from the origin.
    FlatPatternError names `field` and the fix.
    """
    return split_flanges(
        check_flat_pattern(pattern, field),
        thickness=thickness,
        inner_radius=inner_radius,
        k_factor=k_factor,
        field=field,
    )
