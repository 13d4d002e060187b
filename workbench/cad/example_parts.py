"""Example CAD parts built with Open CASCADE, written as STEP by deterministic generators.

Run ``python -m workbench.cad.example_parts`` to (re)write ``web_assets/parts/fixture_block.step``
(the polishing fixture of ``projects/step_cell.json``); the free-form panel's STEP file is
written by ``python -m workbench.polishing.example_workpiece``. Shapes are in mm; the same
shape gives the same bytes (`write_step` fixes the header's time stamp).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from workbench.cad.step import write_step

ASSETS = Path(__file__).resolve().parents[2] / "web_assets"

#: The fixture block: edge lengths [mm], the corner holes' radius and inset [mm], the vertical
#: edges' fillet radius [mm], and the central pocket's radius and depth [mm].
BLOCK_SIZE = (200.0, 120.0, 25.0)
HOLE_RADIUS, HOLE_INSET = 6.0, 20.0
EDGE_FILLET = 8.0
POCKET_RADIUS, POCKET_DEPTH = 30.0, 8.0


def fixture_block() -> Any:
    """Return the fixture block [mm], centred on the origin: a box with filleted vertical
    edges, four through holes near its corners and a round pocket in its top face."""
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
    from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet
    from OCP.BRepGProp import BRepGProp
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder
    from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt
    from OCP.GProp import GProp_GProps
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    sx, sy, sz = BLOCK_SIZE
    shape = BRepPrimAPI_MakeBox(gp_Pnt(-sx / 2, -sy / 2, -sz / 2), sx, sy, sz).Shape()
    fillet = BRepFilletAPI_MakeFillet(shape)
    explorer = TopExp_Explorer(shape, TopAbs_EDGE)
    while explorer.More():
        edge = TopoDS.Edge(explorer.Current())
        props = GProp_GProps()
        BRepGProp.LinearProperties_s(edge, props)
        if abs(props.Mass() - sz) < 1e-9:  # the four vertical edges
            fillet.Add(EDGE_FILLET, edge)
        explorer.Next()
    shape = fillet.Shape()
    up = gp_Dir(0.0, 0.0, 1.0)
    for kx in (-1, 1):
        for ky in (-1, 1):
            x, y = kx * (sx / 2 - HOLE_INSET), ky * (sy / 2 - HOLE_INSET)
            axis = gp_Ax2(gp_Pnt(x, y, -sz), up)
            hole = BRepPrimAPI_MakeCylinder(axis, HOLE_RADIUS, 2 * sz).Shape()
            shape = BRepAlgoAPI_Cut(shape, hole).Shape()
    pocket_axis = gp_Ax2(gp_Pnt(0.0, 0.0, sz / 2 - POCKET_DEPTH), up)
    pocket = BRepPrimAPI_MakeCylinder(pocket_axis, POCKET_RADIUS, sz).Shape()
    return BRepAlgoAPI_Cut(shape, pocket).Shape()


def height_field_face(z: ArrayLike, x0: float, dx: float, y0: float, dy: float) -> Any:
    """Return a B-spline face [mm] through the heights `z` (nx, ny) [mm] given on the grid
    x = x0 + i dx, y = y0 + j dy (cubic to degree 8, C2, within 1e-3 mm of the points)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace
    from OCP.collections import Array2_double
    from OCP.GeomAPI import GeomAPI_PointsToBSplineSurface

    heights = np.asarray(z, dtype=float)
    nx, ny = heights.shape
    grid = Array2_double(1, nx, 1, ny)
    for i in range(nx):
        for j in range(ny):
            grid.SetValue(i + 1, j + 1, float(heights[i, j]))
    surface = GeomAPI_PointsToBSplineSurface(grid, x0, dx, y0, dy).Surface()
    return BRepBuilderAPI_MakeFace(surface, 1e-6).Face()


def main(out: str | Path | None = None) -> Path:
    """Write the fixture block's STEP file and return its path."""
    path = Path(out) if out else ASSETS / "parts" / "fixture_block.step"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(write_step(fixture_block(), path.name))
    return path


if __name__ == "__main__":
    print(main())
