"""Polishing planner timing: Bézier fit and spiral path against trimesh's plane-slicing raster.

Run: ``python benchmarks/polishing.py``. Meshes are the example panel (300 x 200 mm,
doubly curved) at 1k-300k triangles; step 2 mm, spacing 10 mm. The peer slices the same
mesh with planes `spacing` apart (``trimesh.intersections.mesh_multiplane``), the usual
plane-slicing raster. Times are the best of `repeats` rounds, each on a fresh mesh (no caches);
a round runs the spiral and the peer once each, in turn (the fit is timed on its own).
"""

from __future__ import annotations

import time

import numpy as np
import trimesh

from workbench.polishing.bezier import fit_bezier_triangles
from workbench.polishing.example_workpiece import make_panel
from workbench.polishing.toolpath import spiral_toolpath

SIZES = [(26, 21), (81, 64), (150, 120), (300, 237), (435, 350)]
STEP, SPACING = 0.002, 0.01


def _best(fns, mesh: trimesh.Trimesh, repeats: int) -> tuple[list[float], list[object]]:
    """Best time of each fn over `repeats` rounds; each round runs every fn once, in turn,
    so ours and the peer see the same load on a shared machine."""
    best, out = [np.inf] * len(fns), [None] * len(fns)
    for _ in range(repeats):
        for i, fn in enumerate(fns):
            fresh = trimesh.Trimesh(np.array(mesh.vertices), np.array(mesh.faces), process=False)
            t0 = time.perf_counter()
            out[i] = fn(fresh)
            best[i] = min(best[i], time.perf_counter() - t0)
    return best, out


def _full_fit(mesh: trimesh.Trimesh) -> np.ndarray:
    return fit_bezier_triangles(mesh).control_points


def _spiral(mesh: trimesh.Trimesh):
    return spiral_toolpath(mesh, STEP, SPACING)


def _peer_raster(mesh: trimesh.Trimesh):
    lo, hi = mesh.bounds[:, 1]
    heights = np.arange(lo + SPACING / 2, hi, SPACING) - lo
    origin = np.array([0.0, lo, 0.0])
    return trimesh.intersections.mesh_multiplane(mesh, origin, [0.0, 1.0, 0.0], heights)


def main(repeats: int = 7) -> list[dict[str, float]]:
    """Print and return fit, spiral and peer raster times [s] per mesh size."""
    rows = []
    print(
        f"{'triangles':>10} {'fit all [s]':>12} {'spiral [s]':>11} {'points':>7} {'peer raster [s]':>16} {'spiral/peer':>12}"
    )
    for nx, ny in SIZES:
        mesh = make_panel(nx, ny)
        (t_fit,), _ = _best([_full_fit], mesh, repeats)
        (t_sp, t_peer), (path, _) = _best([_spiral, _peer_raster], mesh, repeats)
        row = {
            "triangles": len(mesh.faces),
            "fit": t_fit,
            "spiral": t_sp,
            "points": int(path.is_process.sum()),  # type: ignore[attr-defined]
            "peer": t_peer,
            "ratio": t_sp / t_peer,
        }
        rows.append(row)
        print(
            f"{row['triangles']:>10d} {t_fit:>12.3f} {t_sp:>11.3f} {row['points']:>7d} {t_peer:>16.3f} {row['ratio']:>12.2f}"
        )
    return rows


if __name__ == "__main__":
    main()
