"""Sheet-metal faces of a B-rep: flanges (parallel face pairs t apart) and bends (coaxial
cylinder pairs r and r + t), or the face that makes a solid something else.

Input is `workbench.cad.sheet_brep.SheetBrep` (plain data, m). The rules, each a refusal naming
the face when broken:

- one solid, only planar and cylindrical faces;
- every cylinder face has a coaxial partner with the same angular span on the same side of the
  axis: the concave one (radius r) is the bend's inside, the convex one (r + t) its outside;
- a flange is two planar faces with opposite outward normals, t apart, whose outlines match;
- t is one number for the whole part (every flange pair and every bend);
- every other planar face is a side face: square to the flanges it meets, along the bends'
  axes (it is ignored: it only closes the sheet's edges).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely
from numpy.typing import NDArray

from workbench.cad.sheet_brep import BrepFace, SheetBrep
from workbench.errors import MeshError

TOL = 1e-6  # m (0.001 mm): positions, thickness, outline match; STEP files carry 1e-7 mm
PARALLEL = 1e-9  # 1 - |cos| below which two directions are parallel
SQUARE = 1e-6  # |cos| below which two directions are square
ANGLE_TOL = 1e-5  # rad: a bend's span against its flanges' normals


@dataclass(frozen=True)
class BendFaces:
    """A bend: its `inner` (radius r) and `outer` (r + t) cylinder face indices."""

    inner: int
    outer: int
    radius: float  # inner radius r [m]
    span: float  # bend angle [rad]


@dataclass(frozen=True)
class FlangeFaces:
    """A flange: two planar face indices t apart (`first` has the lower index)."""

    first: int
    second: int


@dataclass(frozen=True)
class SheetFaces:
    """The recognised faces: `thickness` [m], flanges and bends (each sorted by lowest face)."""

    thickness: float
    flanges: tuple[FlangeFaces, ...]
    bends: tuple[BendFaces, ...]


def _mm(x: float) -> str:
    return f"{x * 1e3:.4g} mm"


def _frame(n: NDArray[np.float64]) -> NDArray[np.float64]:
    """Return (2, 3) rows: two unit vectors spanning the plane of normal `n`."""
    a = np.eye(3)[int(np.argmin(np.abs(n)))]
    x = a - np.dot(a, n) * n
    x /= np.linalg.norm(x)
    return np.stack([x, np.cross(n, x)])


def outline(face: BrepFace, axes: NDArray[np.float64]) -> shapely.Polygon:
    """Return the outer loop of planar `face` projected on `axes` (2, 3) as a polygon [m]."""
    assert face.loop is not None
    return shapely.Polygon(face.loop @ axes.T).buffer(0)


def _check_surfaces(brep: SheetBrep, where: str) -> None:
    if brep.solids != 1:
        raise MeshError(
            f"the file holds {brep.solids} solids; a sheet-metal part is one solid", field=where
        )
    for f in brep.faces:
        if f.kind not in ("plane", "cylinder"):
            raise MeshError(
                f"face {f.index} is a {f.kind}: a sheet-metal part has only planar "
                "and cylindrical faces (flanges and bends)",
                field=where,
            )


def _coaxial(a: BrepFace, b: BrepFace) -> bool:
    assert a.axis is not None and b.axis is not None and a.origin is not None
    assert b.origin is not None and a.mid is not None and b.mid is not None
    if 1 - abs(float(np.dot(a.axis, b.axis))) > PARALLEL:
        return False
    d = b.origin - a.origin
    off = d - np.dot(d, a.axis) * a.axis
    return bool(
        np.linalg.norm(off) < TOL
        and abs(a.span - b.span) < ANGLE_TOL
        and np.dot(a.mid, b.mid) > np.cos(ANGLE_TOL)
    )


def _pair_bends(brep: SheetBrep, where: str) -> list[BendFaces]:
    cyl = [f for f in brep.faces if f.kind == "cylinder"]
    used: set[int] = set()
    bends = []
    for c in sorted(cyl, key=lambda f: f.radius):
        if c.index in used:
            continue
        partners = [
            o
            for o in cyl
            if o.index not in used and o.index != c.index and o.radius > c.radius + TOL
            if _coaxial(c, o)
        ]
        if c.convex or not partners:
            side = "r - t, inside it" if c.convex else "r + t, outside it"
            raise MeshError(
                f"cylinder face {c.index} (radius {_mm(c.radius)}, "
                f"{'convex' if c.convex else 'concave'}) has no coaxial partner at {side}: "
                "a bend has an inner and an outer cylinder face, one thickness apart; a fillet "
                "or a rounded edge is not sheet metal",
                field=where,
            )
        o = min(partners, key=lambda f: f.radius)
        if not o.convex:
            raise MeshError(
                f"cylinder faces {c.index} and {o.index} are both concave: "
                "a bend's outer face is convex",
                field=where,
            )
        used |= {c.index, o.index}
        bends.append(BendFaces(c.index, o.index, c.radius, c.span))
    return sorted(bends, key=lambda b: min(b.inner, b.outer))


def _pair_flanges(brep: SheetBrep) -> dict[int, tuple[int, float]]:
    """Return, per planar face, its flange partner and their distance [m] (mutual nearest)."""
    planes = [f for f in brep.faces if f.kind == "plane"]
    best: dict[int, tuple[int, float]] = {}
    for p in planes:
        assert p.normal is not None and p.origin is not None
        axes = _frame(p.normal)
        mine = outline(p, axes)
        for q in planes:
            assert q.normal is not None and q.origin is not None
            if q.index == p.index or np.dot(p.normal, q.normal) > -1 + PARALLEL:
                continue
            d = float(np.dot(p.origin - q.origin, p.normal))  # q lies behind p, in the material
            if d <= TOL or (p.index in best and best[p.index][1] <= d):
                continue
            theirs = outline(q, axes)
            if mine.intersection(theirs).area > 0.5 * min(mine.area, theirs.area):
                best[p.index] = (q.index, d)
    return {i: (j, d) for i, (j, d) in best.items() if best.get(j, (0, 0.0))[0] == i}


def _meets_a_bend(brep: SheetBrep, face: int) -> bool:
    """Return whether planar `face` runs into a cylinder face tangentially (a bend's flange)."""
    f = brep.faces[face - 1]
    assert f.normal is not None
    return any(
        brep.faces[n - 1].kind == "cylinder"
        and abs(float(np.dot(f.normal, brep.faces[n - 1].axis))) < SQUARE  # type: ignore[arg-type]
        for n in f.neighbours
    )


def _check_outlines(brep: SheetBrep, a: int, b: int, where: str) -> None:
    fa, fb = brep.faces[a - 1], brep.faces[b - 1]
    assert fa.normal is not None
    axes = _frame(fa.normal)
    pa, pb = outline(fa, axes), outline(fb, axes)
    gap = pa.symmetric_difference(pb).area
    if gap > TOL * max(pa.length, pb.length):
        raise MeshError(
            f"faces {a} and {b} (a flange's two sides) have outlines differing by "
            f"{gap * 1e6:.4g} mm²: a flange's edges must be square to the sheet",
            field=where,
        )


def _check_side_face(brep: SheetBrep, f: BrepFace, flange_faces: set[int], where: str) -> None:
    assert f.normal is not None
    for n in f.neighbours:
        g = brep.faces[n - 1]
        if g.kind == "cylinder":
            assert g.axis is not None
            if 1 - abs(float(np.dot(f.normal, g.axis))) > SQUARE:
                raise MeshError(
                    f"face {f.index} meets bend face {n} off its axis: a sheet-metal "
                    "part's side faces are square to the sheet",
                    field=where,
                )
        elif n in flange_faces:
            assert g.normal is not None
            if abs(float(np.dot(f.normal, g.normal))) > SQUARE:
                raise MeshError(
                    f"face {f.index} has no parallel partner one thickness away and "
                    f"is not square to flange face {n}: it is neither a flange nor a side face",
                    field=where,
                )


def sheet_faces(brep: SheetBrep, where: str) -> SheetFaces:
    """Return the flanges and bends of `brep`; MeshError names the face and `where` when the
    solid is not a sheet-metal part (see the module docstring)."""
    _check_surfaces(brep, where)
    bends = _pair_bends(brep, where)
    if not bends:
        raise MeshError(
            "no bends found (no pair of coaxial cylinder faces r and r + t): this is "
            "a solid block or a flat plate, not a bent sheet-metal part",
            field=where,
        )
    pairs = _pair_flanges(brep)
    flanges = sorted(
        {
            FlangeFaces(min(i, j), max(i, j))
            for i, (j, _) in pairs.items()
            if _meets_a_bend(brep, i) or _meets_a_bend(brep, j)
        },
        key=lambda f: f.first,
    )
    if not flanges:
        raise MeshError("no flange found (two parallel planar faces t apart)", field=where)
    b0 = bends[0]
    t = brep.faces[b0.outer - 1].radius - b0.radius
    ref = f"bend faces {b0.inner} and {b0.outer}"
    for b in bends:
        d = brep.faces[b.outer - 1].radius - b.radius
        if abs(d - t) > TOL:
            raise MeshError(
                f"bend faces {b.inner} and {b.outer}: thickness {_mm(d)} here, "
                f"{_mm(t)} elsewhere ({ref}); a sheet-metal part has one thickness",
                field=where,
            )
    for f in flanges:
        d = pairs[f.first][1]
        if abs(d - t) > TOL:
            raise MeshError(
                f"faces {f.first} and {f.second}: thickness {_mm(d)} here, "
                f"{_mm(t)} elsewhere ({ref}); a sheet-metal part has one thickness",
                field=where,
            )
        _check_outlines(brep, f.first, f.second, where)
    on_flange = {i for f in flanges for i in (f.first, f.second)}
    for face in brep.faces:
        if face.kind == "plane" and face.index not in on_flange:
            _check_side_face(brep, face, on_flange, where)
    return SheetFaces(float(t), tuple(flanges), tuple(bends))
