"""The part spec of `SheetMetalPart.from_spec` recognised from a bent solid's B-rep (SI).

`sheet_faces` (solid_faces.py) finds the flanges and bends; here they become the part model:

- the base is the largest flange (or a named one); the other flanges hang from it through the
  bends (a tree: a closed ring of bends is refused);
- each flange's frame has z along its top face's outward normal and its polygon on the
  mid-surface: the top face's outer loop projected there. The base's top is the side most of
  its bends turn towards (ties: the side facing the model's +x, +y or +z, whichever the normal
  is closest to); a child's top is the face joined to its parent's top through the bend's
  cylinder, so a bend whose inner cylinder meets the parent's top is "up";
- the loop edge that meets a bend's cylinder is that bend's edge; a child's frame starts at
  its bend edge (edge 0, along +x). The flat blank then puts the child a bend allowance beyond
  its parent's edge, and folding it back puts every face where the solid has it;
- bend angle: the cylinders' angular span, checked against the flanges' normals; inner radius:
  the concave cylinder's radius;
- names: flanges F1, F2, ... and bends B1, B2, ... in the order of their lowest face index
  (stable whichever flange is the base); the sequence is left to the default (B1, B2, ...).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from workbench.cad.sheet_brep import SheetBrep
from workbench.errors import InputError, MeshError
from workbench.geometry.polygon import signed_area
from workbench.sheetmetal.solid_faces import ANGLE_TOL, TOL, SheetFaces, sheet_faces


@dataclass(frozen=True, eq=False)
class RecognisedPart:
    """A part recognised in a solid: `spec` (SI, for `SheetMetalPart.from_spec`), the part
    frame in the model's `T_model_part` (4, 4) [m], and the faces behind each flange (top,
    bottom) and bend (inner, outer), by name."""

    spec: dict[str, Any]
    T_model_part: NDArray[np.float64]
    flange_faces: dict[str, tuple[int, int]]
    bend_faces: dict[str, tuple[int, int]]


def _model_axes(z: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return (3, 3) columns x, y, z: x the model axis most square to `z`, projected."""
    e = np.eye(3)[int(np.argmin(np.abs(z) + 1e-12 * np.arange(3)))]
    x = e - np.dot(e, z) * z
    x /= np.linalg.norm(x)
    return np.column_stack([x, np.cross(z, x), z])


def _loop_2d(
    brep: SheetBrep, face: int, R: NDArray[np.float64], o: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Return the face's loop in the frame (R, o), counter-clockwise, and the face across each
    edge."""
    f = brep.faces[face - 1]
    assert f.loop is not None and f.loop_faces is not None
    pts = (f.loop - o) @ R[:, :2]
    across = f.loop_faces.copy()
    if signed_area(pts) < 0:  # edge i (i -> i+1) becomes edge n-2-i of the reversed loop
        pts, across = pts[::-1], np.roll(across[::-1], -1)
    return pts, across


def _bend_edge(across: NDArray[np.int64], cylinder: int, flange: str, where: str) -> int:
    hits = np.flatnonzero(across == cylinder)
    if len(hits) != 1:
        raise MeshError(
            f"flange {flange} meets bend face {cylinder} along {len(hits)} edges of "
            "its outline; a bend edge must be one straight edge",
            field=where,
        )
    return int(hits[0])


def _base_top(brep: SheetBrep, faces: tuple[int, int], inners: list[int], outers: list[int]) -> int:
    votes = [
        sum(c in brep.faces[f - 1].neighbours for c in inners)
        - sum(c in brep.faces[f - 1].neighbours for c in outers)
        for f in faces
    ]
    if votes[0] != votes[1]:
        return faces[int(np.argmax(votes))]
    n = brep.faces[faces[0] - 1].normal
    assert n is not None
    return faces[0] if n[int(np.argmax(np.abs(n)))] > 0 else faces[1]


def _joins(
    brep: SheetBrep, sf: SheetFaces, flange_of: dict[int, str], where: str
) -> list[list[str]]:
    """Return, per bend, the names of the two flanges its cylinder faces meet."""
    joined = []
    for b in sf.bends:
        touched = sorted(
            {
                flange_of[n]
                for c in (b.inner, b.outer)
                for n in brep.faces[c - 1].neighbours
                if n in flange_of
            }
        )
        if len(touched) != 2:
            raise MeshError(
                f"bend faces {b.inner} and {b.outer} join {len(touched)} flange(s) "
                f"{touched}; a bend joins two flanges",
                field=where,
            )
        joined.append(touched)
    return joined


def _base_polygon(
    brep: SheetBrep, top: int, t: float
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]]:
    """Return the base's T_model_part (4, 4) and its polygon (from its lowest-then-leftmost
    corner, bounding box at the origin) with the face across each edge."""
    face = brep.faces[top - 1]
    assert face.normal is not None and face.origin is not None
    R = _model_axes(face.normal)
    o = face.origin - 0.5 * t * face.normal
    pts, across = _loop_2d(brep, top, R, o)
    lo = pts.min(axis=0)
    pts = pts - lo
    start = min(range(len(pts)), key=lambda i: (round(pts[i, 1] / TOL), round(pts[i, 0] / TOL)))
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, o + R[:, :2] @ lo
    return T, np.roll(pts, -start, axis=0), np.roll(across, -start)


def _child_polygon(
    brep: SheetBrep, top: int, cylinder: int, t: float, name: str, where: str
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Return a child's polygon starting with its bend edge (along +x from the origin) and the
    face across each edge."""
    face = brep.faces[top - 1]
    assert face.normal is not None and face.loop is not None
    pts, across = _loop_2d(brep, top, _model_axes(face.normal), face.loop[0])
    e = _bend_edge(across, cylinder, name, where)
    pts, across = np.roll(pts, -e, axis=0), np.roll(across, -e)
    d = (pts[1] - pts[0]) / np.linalg.norm(pts[1] - pts[0])
    return (pts - pts[0]) @ np.array([[d[0], -d[1]], [d[1], d[0]]]), across


def recognise_part(brep: SheetBrep, *, where: str, base: str | None = None) -> RecognisedPart:
    """Return the part recognised in `brep` (SI); MeshError names the face and `where` when it
    is not a sheet-metal part, InputError names `base` when no flange has that name."""
    sf = sheet_faces(brep, where)
    t = sf.thickness
    names = [f"F{i + 1}" for i in range(len(sf.flanges))]
    faces_of = {n: (f.first, f.second) for n, f in zip(names, sf.flanges, strict=True)}
    joined = _joins(brep, sf, {i: n for n, pair in faces_of.items() for i in pair}, where)
    if base is None:
        areas = [brep.faces[f.first - 1].area for f in sf.flanges]
        base = names[int(np.argmax(np.round(np.asarray(areas) / TOL**2)))]
    elif base not in names:
        raise InputError(
            f"no flange {base!r}; the part's flanges are {', '.join(names)}", field="base"
        )
    near = [b for b, j in zip(sf.bends, joined, strict=True) if base in j]
    top = {base: _base_top(brep, faces_of[base], [b.inner for b in near], [b.outer for b in near])}
    T, pts, across = _base_polygon(brep, top[base], t)
    polys = {base: (pts, across)}
    bends: list[dict[str, Any]] = []
    frontier = [base]
    while frontier:  # breadth first from the base: a parent's polygon comes before its child's
        parent = frontier.pop(0)
        for k, b in enumerate(sf.bends):
            if parent not in joined[k] or any(x["name"] == f"B{k + 1}" for x in bends):
                continue
            child = next(n for n in joined[k] if n != parent)
            if child in top:
                raise MeshError(
                    f"bend faces {b.inner} and {b.outer} close a ring of bends "
                    f"(flange {child} is reached twice): the part cannot be unfolded flat",
                    field=where,
                )
            up = b.inner in brep.faces[top[parent] - 1].neighbours
            cyl = b.inner if up else b.outer
            top[child] = next(f for f in faces_of[child] if cyl in brep.faces[f - 1].neighbours)
            polys[child] = _child_polygon(brep, top[child], cyl, t, child, where)
            zp, zc = brep.faces[top[parent] - 1].normal, brep.faces[top[child] - 1].normal
            between = float(np.arccos(np.clip(np.dot(zp, zc), -1.0, 1.0)))  # type: ignore[arg-type]
            if abs(between - b.span) > ANGLE_TOL:
                raise MeshError(
                    f"bend faces {b.inner} and {b.outer} span "
                    f"{np.degrees(b.span):.4g} deg, but flanges {parent} and {child} are "
                    f"{np.degrees(between):.4g} deg apart",
                    field=where,
                )
            bends.append(
                {
                    "name": f"B{k + 1}",
                    "parent": parent,
                    "parent_edge": _bend_edge(polys[parent][1], cyl, parent, where),
                    "child": child,
                    "child_edge": 0,
                    "bend_angle": float(b.span),
                    "inner_radius": float(b.radius),
                    "direction": "up" if up else "down",
                }
            )
            frontier.append(child)
    missing = [n for n in names if n not in top]
    if missing:
        raise MeshError(f"flanges {missing} are not joined to {base} by bends", field=where)
    spec = {
        "thickness": t,
        "k_factor": None,
        "flanges": [{"name": n, "polygon": p} for n, (p, _) in polys.items()],
        "bends": sorted(bends, key=lambda b: int(b["name"][1:])),
    }
    return RecognisedPart(
        spec,
        T,
        {n: (top[n], next(f for f in faces_of[n] if f != top[n])) for n in names},
        {f"B{k + 1}": (b.inner, b.outer) for k, b in enumerate(sf.bends)},
    )
