"""Bent sheet-metal test parts made with OCP (workbench.cad.bent_profile), through STEP bytes.

Each profile is the generator's mid-line: straight runs [m], signed bend angles (+ left) and
inner radii, thickness, extruded by a length. Recognition must give back exactly these: the
flanges F1.. in profile order (their lowest faces come in that order), bends B1.. likewise.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from workbench.cad.bent_profile import Profile, profile_solid, step_bytes, u_channel
from workbench.cad.sheet_brep import SheetBrep, read_sheet_brep
from workbench.cad.step import read_step_shape

D = np.pi / 180

PROFILES: dict[str, Profile] = {
    "L90": Profile(0.0015, (0.060, 0.040), (90 * D,), (0.0015,), 0.120),
    "L30": Profile(0.002, (0.050, 0.045), (30 * D,), (0.002,), 0.100),
    "L135": Profile(0.002, (0.070, 0.030), (-135 * D,), (0.003,), 0.080),
    "U": u_channel(0.100, 0.110, 0.025, thickness=0.002, radius=0.00192, length=0.200),
    "Z": Profile(0.0015, (0.030, 0.080, 0.035), (90 * D, -90 * D), (0.0015, 0.0015), 0.150),
    "hat": Profile(
        0.002,
        (0.025, 0.040, 0.090, 0.040, 0.025),
        (90 * D, -90 * D, -90 * D, 90 * D),
        (0.002,) * 4,
        0.160,
    ),
    "mixed": Profile(
        0.0015,
        (0.040, 0.070, 0.030, 0.020),
        (60 * D, -45 * D, 120 * D),
        (0.0015, 0.003, 0.001),
        0.090,
        start=(0.01, -0.02),
        heading=0.3,
    ),
}


def step_of(shape: Any, name: str = "part") -> bytes:
    """Return the STEP bytes of OCP `shape` [mm]."""
    return step_bytes(shape, name)


def brep_of_step(data: bytes) -> SheetBrep:
    """Return the faces of STEP `data`, read as the project reads it."""
    return read_sheet_brep(read_step_shape(data, "part.step", "test"), "test")


def profile_step(name: str) -> bytes:
    """Return the STEP bytes of profile `name`."""
    return step_of(profile_solid(PROFILES[name]), name)


def expected_directions(p: Profile, base: int) -> list[str]:
    """Return each bend's "up"/"down" when flange `base` (profile index) is the base.

    The base's top is the side most of its bends turn to; a bend is up when it turns to the
    side that is the top (the sheet's left side stays its left side along the profile).
    """
    near = [np.sign(p.angles[k]) for k in (base - 1, base) if 0 <= k < len(p.angles)]
    left = sum(near) > 0 if sum(near) != 0 else None
    if left is None:  # a tie: either side; report relative to the left
        left = True
    return ["up" if (a > 0) == left else "down" for a in p.angles]


def filleted_channel() -> Any:
    """Return the U-channel with its tall flange's free outer edge rounded (r 0.5 mm)."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp, TopExp_Explorer
    from OCP.TopoDS import TopoDS

    shape = profile_solid(PROFILES["U"])
    fillet = BRepFilletAPI_MakeFillet(shape)
    exp = TopExp_Explorer(shape, TopAbs_EDGE)
    while exp.More():
        edge = TopoDS.Edge(exp.Current())
        ends = [BRep_Tool.Pnt_s(v) for v in (TopExp.FirstVertex_s(edge), TopExp.LastVertex_s(edge))]
        # the tall flange's tip (z = 112.92 mm) on its outer face (y = 103.92 mm), along x
        if all(abs(p.Z() - 112.92) < 1e-6 and abs(p.Y() - 103.92) < 1e-6 for p in ends):
            fillet.Add(0.5, edge)
        exp.Next()
    return fillet.Shape()


def doubled_channel() -> Any:
    """Return the U-channel with a 1.5 mm plate fused onto its base (3.5 mm there, 2 elsewhere)."""
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Fuse
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox
    from OCP.gp import gp_Pnt
    from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain

    plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 1.0), gp_Pnt(200, 100, 2.5)).Shape()
    fused = BRepAlgoAPI_Fuse(profile_solid(PROFILES["U"]), plate).Shape()
    unify = ShapeUpgrade_UnifySameDomain(fused, True, True, True)
    unify.Build()
    return unify.Shape()


def nurbs_channel() -> Any:
    """Return the U-channel with every face converted to a B-spline surface."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_NurbsConvert

    return BRepBuilderAPI_NurbsConvert(profile_solid(PROFILES["U"]), True).Shape()


def block() -> Any:
    """Return a solid block 100 x 50 x 20 mm."""
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox

    return BRepPrimAPI_MakeBox(100.0, 50.0, 20.0).Shape()


def two_channels() -> Any:
    """Return a compound of two U-channels side by side (two solids)."""
    from OCP.BRep import BRep_Builder
    from OCP.TopoDS import TopoDS_Compound

    compound, builder = TopoDS_Compound(), BRep_Builder()
    builder.MakeCompound(compound)
    builder.Add(compound, profile_solid(PROFILES["U"]))
    builder.Add(compound, profile_solid(PROFILES["U"], offset=(0.3, 0.0, 0.0)))
    return compound
