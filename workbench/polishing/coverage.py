"""Coverage of a surface by a tool path: the share of the surface within the tool radius."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.spatial import cKDTree

from workbench.errors import InputError
from workbench.polishing.bezier import BezierSurface
from workbench.polishing.toolpath import ToolPath

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Coverage:
    """fraction: share of the surface area within tool_radius of the path [-]; max_distance:
    the largest distance of a surface point from the path [m]; largest_gap: width of the
    widest uncovered strip, 2 (max_distance - tool_radius) clipped at 0 [m]; samples (S, 3)
    and distance (S,) the surface samples and their distances [m]."""

    fraction: float
    max_distance: float
    largest_gap: float
    tool_radius: float
    samples: F64
    distance: F64


def sample_surface(
    surface: BezierSurface, n: int, *, seed: int = 0
) -> tuple[F64, NDArray[np.int64], F64]:
    """Return (points (n, 3) [m], face (n,), bary (n, 3)) spread uniformly by flat-face area."""
    rng = np.random.default_rng(seed)
    tri = surface.vertices[surface.faces]
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    face = rng.choice(len(area), size=n, p=area / area.sum())
    r1, r2 = np.sqrt(rng.random(n)), rng.random(n)
    bary = np.stack([1 - r1, r1 * (1 - r2), r1 * r2], axis=1)
    return surface.evaluate(face, bary), face, bary


def polyline_distance(points: F64, path: F64, *, resolution: float) -> F64:
    """Return the distance (S,) [m] from each point (S, 3) to the polyline path (N, 3).

    The path is densified to segments <= resolution [m]; distances are within resolution/2
    of the exact point-to-polyline distance (and never below it)."""
    seg = np.diff(path, axis=0)
    k = np.maximum(np.ceil(np.linalg.norm(seg, axis=1) / resolution).astype(np.int64), 1)
    i = np.arange(k.sum()) - np.repeat(np.cumsum(k) - k, k)
    dense = np.vstack(
        [
            np.repeat(path[:-1], k, 0) + (i / np.repeat(k, k))[:, None] * np.repeat(seg, k, 0),
            path[-1:],
        ]
    )
    dist, _ = cKDTree(dense).query(points)
    return dist


def path_coverage(
    surface: BezierSurface,
    path: ToolPath,
    tool_radius: float,
    *,
    n_samples: int = 20000,
    seed: int = 0,
) -> Coverage:
    """Return the `Coverage` of `surface` by the process part of `path` for a tool of radius [m].

    Samples n_samples points uniformly on the surface (seeded) and measures their distance
    to the path polyline (resolution tool_radius / 20). Raises `InputError` for
    tool_radius <= 0 or n_samples < 1.
    """
    if not np.isfinite(tool_radius) or tool_radius <= 0:
        raise InputError(f"tool_radius must be > 0 m, got {tool_radius!r}")
    if n_samples < 1:
        raise InputError(f"n_samples must be >= 1, got {n_samples!r}")
    pts, _, _ = sample_surface(surface, n_samples, seed=seed)
    dist = polyline_distance(pts, path.points[path.is_process], resolution=tool_radius / 20.0)
    dmax = float(dist.max())
    return Coverage(
        fraction=float(np.mean(dist <= tool_radius)),
        max_distance=dmax,
        largest_gap=max(0.0, 2.0 * (dmax - tool_radius)),
        tool_radius=float(tool_radius),
        samples=pts,
        distance=dist,
    )
