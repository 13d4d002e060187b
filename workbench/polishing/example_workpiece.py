"""The example free-form workpiece: a doubly-curved panel about 300 x 200 mm.

Run ``python -m workbench.polishing.example_workpiece`` to (re)write
``web_assets/workpieces/panel.stl`` (in mm, as industrial STL files are) and
``web_assets/workpieces/panel.step`` (the same panel as one B-spline face through the heights
on a 10 mm grid, for ``projects/step_cell.json``). Deterministic.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh

#: Half extents of the panel in x and y [m].
HALF_X = 0.15
HALF_Y = 0.10


def panel_height(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Return the panel height z [m] over (x, y) [m]: a dome with a gentle cross wave."""
    return 0.03 * (1.0 - (x / 0.2) ** 2 - (y / 0.15) ** 2) + 0.004 * np.sin(
        2 * np.pi * x / 0.15
    ) * np.cos(np.pi * y / 0.2)


def make_panel(
    nx: int = 60, ny: int = 40, *, half_x: float = HALF_X, half_y: float = HALF_Y
) -> trimesh.Trimesh:
    """Return the panel as a trimesh in metres, a grid of (nx-1)(ny-1)*2 triangles facing +z."""
    xs = np.linspace(-half_x, half_x, nx)
    ys = np.linspace(-half_y, half_y, ny)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    vertices = np.stack([gx, gy, panel_height(gx, gy)], axis=-1).reshape(-1, 3)
    idx = np.arange(nx * ny).reshape(nx, ny)
    a, b = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel()
    c, d = idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    faces = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    return trimesh.Trimesh(vertices=vertices, faces=faces, process=False)


def panel_step(grid_mm: float = 10.0) -> bytes:
    """Return the panel as a STEP file (one B-spline face [mm] through `panel_height` sampled
    every `grid_mm` over the panel, interpolated within 1e-3 mm of the samples)."""
    from workbench.cad.example_parts import height_field_face
    from workbench.cad.step import write_step

    hx, hy = HALF_X * 1000.0, HALF_Y * 1000.0  # mm
    xs = np.arange(-hx, hx + 1e-9, grid_mm)
    ys = np.arange(-hy, hy + 1e-9, grid_mm)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    z = panel_height(gx / 1000.0, gy / 1000.0) * 1000.0
    return write_step(height_field_face(z, -hx, grid_mm, -hy, grid_mm), "panel.step")


def main(out: str | Path | None = None) -> Path:
    """Write the example panel STL (in mm) and its STEP file beside it; return the STL's path."""
    path = (
        Path(out)
        if out
        else Path(__file__).resolve().parents[2] / "web_assets" / "workpieces" / "panel.stl"
    )
    path.parent.mkdir(parents=True, exist_ok=True)
    mesh = make_panel()
    mesh_mm = trimesh.Trimesh(vertices=mesh.vertices * 1000.0, faces=mesh.faces, process=False)
    mesh_mm.export(str(path))
    path.with_suffix(".step").write_bytes(panel_step())
    return path


if __name__ == "__main__":
    print(main())
