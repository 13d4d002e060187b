"""Bent sheet-metal profiles as Open CASCADE solids and STEP files: the example parts' generator.

A profile is the sheet's mid-line in the cross-section plane (u, v): straight runs joined by
bends of a given inner radius and signed bend angle (+ turns left, towards +v of the run's
left normal). The sheet's two faces are the mid-line offset by ±t/2 (lines and arcs), and
the closed outline is extruded along x by the part's length (``BRepPrimAPI_MakePrism``);
(u, v) become (y, z). Lengths are SI [m] here; OCP works in mm and writes STEP in mm.

`python -m workbench.cad.bent_profile` writes the example parts ``projects/parts/u_channel.step``
(the channel of ``projects/parts/u_channel.json``, inner radius 1.92 mm: the air-bending radius
of that project's 12 mm die) and ``tab_bracket.step`` (bends on two sides: two prisms fused).
The STEP header's time stamp and product name are fixed: the bytes are reproducible.
"""

from __future__ import annotations

import os
import re
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

MM_PER_M = 1e3  # OCP's length unit is the millimetre


@dataclass(frozen=True)
class Profile:
    """A bent profile: `runs` (n,) straight lengths [m] on the mid-line, `angles` (n-1,) signed
    bend angles [rad] (+ left), `radii` (n-1,) inner radii [m], `thickness` [m], extruded by
    `length` [m] along x; the mid-line starts at `start` (u, v) [m] heading `heading` [rad]."""

    thickness: float
    runs: tuple[float, ...]
    angles: tuple[float, ...]
    radii: tuple[float, ...]
    length: float
    start: tuple[float, float] = (0.0, 0.0)
    heading: float = 0.0


def _rot(a: float) -> NDArray[np.float64]:
    return np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])


def outline(p: Profile) -> list[tuple[NDArray[np.float64], ...]]:
    """Return the closed cross-section outline: pieces (p0, p1) lines or (p0, mid, p1) arcs [m].

    Order: the start cap, the left face forward, the end cap, the right face backward.
    """
    if len(p.angles) != len(p.runs) - 1 or len(p.radii) != len(p.angles):
        raise ValueError("a profile of n runs needs n - 1 bend angles and radii")
    h = p.thickness / 2
    pos = np.asarray(p.start, float)
    d = np.array([np.cos(p.heading), np.sin(p.heading)])
    left: list[tuple[NDArray[np.float64], ...]] = []
    right: list[tuple[NDArray[np.float64], ...]] = []
    for i, run in enumerate(p.runs):
        nl = np.array([-d[1], d[0]])
        end = pos + run * d
        left.append((pos + h * nl, end + h * nl))
        right.append((pos - h * nl, end - h * nl))
        pos = end
        if i == len(p.angles):
            break
        a, r = p.angles[i], p.radii[i]
        s = 1.0 if a > 0 else -1.0
        c = pos + s * (r + h) * nl
        pts = []
        for side in (h, -h):
            q = pos + side * nl - c
            pts.append(tuple(c + _rot(f * a) @ q for f in (0.0, 0.5, 1.0)))
        left.append(pts[0])
        right.append(pts[1])
        pos = c + _rot(a) @ (pos - c)
        d = _rot(a) @ d
    caps_start = (right[0][0], left[0][0])
    caps_end = (left[-1][-1], right[-1][-1])
    back = [tuple(reversed(piece)) for piece in reversed(right)]
    return [caps_start, *left, caps_end, *back]


def _pnt(uv: NDArray[np.float64]) -> Any:
    from OCP.gp import gp_Pnt

    return gp_Pnt(0.0, float(uv[0]) * MM_PER_M, float(uv[1]) * MM_PER_M)


def profile_face(p: Profile) -> Any:
    """Return the OCP planar face [mm] of the profile's cross-section in the plane x = 0."""
    from OCP.BRepBuilderAPI import (
        BRepBuilderAPI_MakeEdge,
        BRepBuilderAPI_MakeFace,
        BRepBuilderAPI_MakeWire,
    )
    from OCP.GC import GC_MakeArcOfCircle, GC_MakeSegment

    wire = BRepBuilderAPI_MakeWire()
    for piece in outline(p):
        if len(piece) == 2:
            curve = GC_MakeSegment(_pnt(piece[0]), _pnt(piece[1])).Value()
        else:
            curve = GC_MakeArcOfCircle(*(_pnt(q) for q in piece)).Value()
        wire.Add(BRepBuilderAPI_MakeEdge(curve).Edge())
    return BRepBuilderAPI_MakeFace(wire.Wire(), True).Face()


def profile_solid(p: Profile, offset: Sequence[float] = (0.0, 0.0, 0.0)) -> Any:
    """Return the OCP solid [mm] of the profile extruded along +x by its length, moved by
    `offset` [m]."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
    from OCP.BRepPrimAPI import BRepPrimAPI_MakePrism
    from OCP.gp import gp_Trsf, gp_Vec

    shape = BRepPrimAPI_MakePrism(profile_face(p), gp_Vec(p.length * MM_PER_M, 0.0, 0.0)).Shape()
    if any(offset):
        tr = gp_Trsf()
        tr.SetTranslation(gp_Vec(*(float(v) * MM_PER_M for v in offset)))
        shape = BRepBuilderAPI_Transform(shape, tr, True).Shape()
    return shape


def step_bytes(shape: Any, name: str = "part") -> bytes:
    """Return `shape` [mm] as STEP AP214 text, the header's time stamp fixed (reproducible)."""
    from OCP.Interface import Interface_Static
    from OCP.Message import Message, Message_Gravity
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer

    for printer in Message.DefaultMessenger_s().Printers():
        printer.SetTraceLevel(Message_Gravity.Message_Fail)
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    writer = STEPControl_Writer()
    writer.Transfer(shape, STEPControl_AsIs)
    fd, tmp = tempfile.mkstemp(suffix=".step")
    os.close(fd)
    try:
        writer.Write(tmp)
        text = Path(tmp).read_text()
    finally:
        os.unlink(tmp)
    text = re.sub(
        r"FILE_NAME\('[^']*','[^']*'",
        f"FILE_NAME('{name}','2026-01-01T00:00:00'",
        text,
        count=1,
    )
    # the product's name carries a per-process counter: name it after the part
    text = re.sub(r"'Open CASCADE STEP translator [0-9.]+ [0-9]+'", f"'{name}'", text)
    return text.encode()


def u_channel(
    base: float, a: float, b: float, *, thickness: float, radius: float, length: float
) -> Profile:
    """Return a U-channel: flange `b` [m] at the base's y = 0 edge, the base `base` wide, flange
    `a` at its far edge, both bent up 90 deg (straight lengths; the base's mid-surface in z = 0
    from y = 0 to `base`)."""
    c = radius + thickness / 2
    return Profile(
        thickness,
        (b, base, a),
        (np.pi / 2, np.pi / 2),
        (radius, radius),
        length,
        start=(-c, c + b),
        heading=-np.pi / 2,
    )


def tab_bracket() -> Any:
    """Return an L-bracket with a tab on a second side: a 200 x 100 mm base (t = 2 mm), a 50 mm
    flange bent up 90 deg along its y = 100 edge (axis along x) and a 30 mm tab bent up 60 deg
    along its x = 200 edge over y = 20..80 (axis along y); r = 2 mm. Two prisms, fused."""
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Fuse
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
    from OCP.gp import gp_Ax1, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec
    from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain

    t, r = 0.002, 0.002
    body = profile_solid(Profile(t, (0.100, 0.050), (np.pi / 2,), (r,), 0.200))
    tab = profile_solid(Profile(t, (0.050, 0.030), (np.pi / 3,), (r,), 0.060, start=(0.150, 0.0)))
    turn = gp_Trsf()
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), -np.pi / 2)  # (0,u,v) -> (u,0,v)
    move = gp_Trsf()
    move.SetTranslation(gp_Vec(0, 80.0, 0))
    tab = BRepBuilderAPI_Transform(tab, move.Multiplied(turn), True).Shape()
    unify = ShapeUpgrade_UnifySameDomain(BRepAlgoAPI_Fuse(body, tab).Shape(), True, True, True)
    unify.Build()
    return unify.Shape()


def main() -> None:
    """Write the example STEP part(s) under projects/parts/."""
    parts = Path(__file__).resolve().parents[2] / "projects" / "parts"
    p = u_channel(0.100, 0.110, 0.025, thickness=0.002, radius=0.00192, length=0.200)
    for name, shape in (("u_channel", profile_solid(p)), ("tab_bracket", tab_bracket())):
        (parts / f"{name}.step").write_bytes(step_bytes(shape, name))
        print(f"wrote {parts / name}.step")


if __name__ == "__main__":
    main()
