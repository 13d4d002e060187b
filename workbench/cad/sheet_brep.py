"""The faces of an Open CASCADE solid as plain numpy data [m]: planes, cylinders and the rest.

What sheet-metal recognition needs from a B-rep, and nothing else: per face its index (1-based,
in ``TopExp.MapShapes`` order: "face 7" in messages is the seventh face of the file's solid),
its surface kind, and for planes the outward normal and the outer loop with the face across
each loop edge; for cylinders the axis, radius, angular span, convexity and neighbours. Also
the solid's volume and bounding box (``GProp``, ``Bnd_Box``). OCP works in mm: lengths are
converted to metres here, where they leave OCP.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from workbench.errors import MeshError

M_PER_MM = 1e-3  # Open CASCADE's STEP reader gives millimetres (workbench/cad/step.py)
ARC_SEGMENTS_PER_RAD = 8  # a curved loop edge of a planar face becomes a polyline this fine

_KINDS = {
    "GeomAbs_Plane": "plane",
    "GeomAbs_Cylinder": "cylinder",
    "GeomAbs_Cone": "cone",
    "GeomAbs_Sphere": "sphere",
    "GeomAbs_Torus": "torus",
    "GeomAbs_BezierSurface": "Bezier surface",
    "GeomAbs_BSplineSurface": "B-spline surface",
    "GeomAbs_SurfaceOfRevolution": "surface of revolution",
    "GeomAbs_SurfaceOfExtrusion": "surface of extrusion",
    "GeomAbs_OffsetSurface": "offset surface",
}


@dataclass(frozen=True, eq=False)
class BrepFace:
    """One face [m]: `kind` ('plane', 'cylinder' or another surface's name), `neighbours`
    (the indices of faces sharing an edge with it) and `vertices` (k, 3) of its edges.

    Planes: `normal` (3,) outward, `origin` (3,) a point of the plane, `loop` (n, 3) the outer
    wire's vertices in order (curved edges as polylines) and `loop_faces` (n,) the face across
    loop edge i (vertex i to i + 1; 0 where none), `area` [m²].
    Cylinders: `origin` a point of the axis, `axis` (3,) unit, `radius`, `span` [rad] the
    angular extent, `convex` (the outward normal points away from the axis), `mid` (3,) the
    unit radial direction at the middle of the span.
    """

    index: int
    kind: str
    neighbours: tuple[int, ...]
    vertices: NDArray[np.float64]
    area: float
    origin: NDArray[np.float64] | None = None
    normal: NDArray[np.float64] | None = None
    loop: NDArray[np.float64] | None = None
    loop_faces: NDArray[np.int64] | None = None
    axis: NDArray[np.float64] | None = None
    radius: float = 0.0
    span: float = 0.0
    convex: bool = False
    mid: NDArray[np.float64] | None = None


@dataclass(frozen=True, eq=False)
class SheetBrep:
    """A shape's faces (`faces[i].index == i + 1`), its number of solids, volume [m³] and
    bounding box (2, 3) [m]."""

    faces: tuple[BrepFace, ...]
    solids: int
    volume: float
    bbox: NDArray[np.float64]


def _xyz(p: Any) -> NDArray[np.float64]:
    return np.array([p.X(), p.Y(), p.Z()], float)


def _edge_points(edge: Any, start: NDArray[np.float64]) -> list[NDArray[np.float64]]:
    """Return the points of `edge` [mm] from the end nearest `start`, without its last point."""
    from OCP.BRepAdaptor import BRepAdaptor_Curve
    from OCP.GeomAbs import GeomAbs_CurveType

    curve = BRepAdaptor_Curve(edge)
    a, b = curve.FirstParameter(), curve.LastParameter()
    n = 1
    if curve.GetType() != GeomAbs_CurveType.GeomAbs_Line:
        sweep = abs(b - a) if curve.GetType() == GeomAbs_CurveType.GeomAbs_Circle else 1.0
        n = max(2, int(np.ceil(sweep * ARC_SEGMENTS_PER_RAD)))
    pts = [_xyz(curve.Value(a + (b - a) * i / n)) for i in range(n + 1)]
    if np.linalg.norm(pts[-1] - start) < np.linalg.norm(pts[0] - start):
        pts.reverse()
    return pts[:-1]


def _plane_loop(face: Any, index_of: Any) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    from OCP.BRep import BRep_Tool
    from OCP.BRepTools import BRepTools, BRepTools_WireExplorer

    explorer = BRepTools_WireExplorer(BRepTools.OuterWire_s(face), face)
    pts: list[NDArray[np.float64]] = []
    across: list[int] = []
    while explorer.More():
        edge = explorer.Current()
        start = _xyz(BRep_Tool.Pnt_s(explorer.CurrentVertex()))
        piece = _edge_points(edge, start)
        pts += piece
        across += [index_of(edge)] * len(piece)
        explorer.Next()
    return np.array(pts) * M_PER_MM, np.array(across, dtype=np.int64)


def read_sheet_brep(shape: Any, field: str) -> SheetBrep:
    """Return the faces of OCP `shape` [mm] as a `SheetBrep` [m]; MeshError names `field` if
    it has no faces."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRep import BRep_Tool
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.BRepBndLib import BRepBndLib
    from OCP.BRepGProp import BRepGProp
    from OCP.BRepLProp import BRepLProp_SLProps
    from OCP.collections import (
        IndexedDataMap_TopoDS_Shape_List_TopoDS_Shape_TopTools_ShapeMapHasher as EdgeFaces,
    )
    from OCP.collections import IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as ShapeMap
    from OCP.GeomAbs import GeomAbs_SurfaceType
    from OCP.GProp import GProp_GProps
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_REVERSED, TopAbs_SOLID, TopAbs_VERTEX
    from OCP.TopExp import TopExp
    from OCP.TopoDS import TopoDS

    faces, solids, edge_faces = ShapeMap(), ShapeMap(), EdgeFaces()
    TopExp.MapShapes_s(shape, TopAbs_FACE, faces)
    TopExp.MapShapes_s(shape, TopAbs_SOLID, solids)
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces)
    if faces.Extent() == 0:
        raise MeshError("the STEP file holds no faces; export the part as a solid", field=field)

    def across(edge: Any, here: int) -> int:
        if not edge_faces.Contains(edge):
            return 0
        for f in edge_faces.FindFromKey(edge):
            i = faces.FindIndex(f)
            if i != here:
                return int(i)
        return 0

    out = []
    for i in range(1, faces.Extent() + 1):
        face = TopoDS.Face(faces.FindKey(i))
        surf = BRepAdaptor_Surface(face, True)
        kind = _KINDS.get(surf.GetType().name, "surface of another kind")
        edges, verts = ShapeMap(), ShapeMap()
        TopExp.MapShapes_s(face, TopAbs_EDGE, edges)
        TopExp.MapShapes_s(face, TopAbs_VERTEX, verts)
        nb = sorted({n for k in range(1, edges.Extent() + 1) if (n := across(edges.FindKey(k), i))})
        vertices = (
            np.array(
                [
                    _xyz(BRep_Tool.Pnt_s(TopoDS.Vertex(verts.FindKey(k))))
                    for k in range(1, verts.Extent() + 1)
                ]
            ).reshape(-1, 3)
            * M_PER_MM
        )
        props = GProp_GProps()
        BRepGProp.SurfaceProperties_s(face, props)
        common = dict(
            index=i,
            kind=kind,
            neighbours=tuple(nb),
            vertices=vertices,
            area=props.Mass() * M_PER_MM**2,
        )
        flip = -1.0 if face.Orientation() == TopAbs_REVERSED else 1.0
        if surf.GetType() == GeomAbs_SurfaceType.GeomAbs_Plane:
            pln = surf.Plane()
            loop, loop_faces = _plane_loop(face, lambda e, here=i: across(e, here))
            out.append(
                BrepFace(
                    **common,  # type: ignore[arg-type]
                    origin=_xyz(pln.Location()) * M_PER_MM,
                    normal=flip * _xyz(pln.Axis().Direction()),
                    loop=loop,
                    loop_faces=loop_faces,
                )
            )
        elif surf.GetType() == GeomAbs_SurfaceType.GeomAbs_Cylinder:
            cyl = surf.Cylinder()
            u0, u1 = surf.FirstUParameter(), surf.LastUParameter()
            v = 0.5 * (surf.FirstVParameter() + surf.LastVParameter())
            lp = BRepLProp_SLProps(surf, 0.5 * (u0 + u1), v, 1, 1e-9)
            p, normal = _xyz(lp.Value()), flip * _xyz(lp.Normal())
            o, ax = _xyz(cyl.Axis().Location()), _xyz(cyl.Axis().Direction())
            radial = (p - o) - np.dot(p - o, ax) * ax
            radial /= np.linalg.norm(radial)
            out.append(
                BrepFace(
                    **common,  # type: ignore[arg-type]
                    origin=o * M_PER_MM,
                    axis=ax,
                    radius=cyl.Radius() * M_PER_MM,
                    span=float(u1 - u0),
                    convex=bool(np.dot(normal, radial) > 0),
                    mid=radial,
                )
            )
        else:
            out.append(BrepFace(**common))  # type: ignore[arg-type]
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, props)
    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape, box, False, False)
    lo, hi = box.CornerMin(), box.CornerMax()
    return SheetBrep(
        faces=tuple(out),
        solids=solids.Extent(),
        volume=props.Mass() * M_PER_MM**3,
        bbox=np.array([_xyz(lo), _xyz(hi)]) * M_PER_MM,
    )
