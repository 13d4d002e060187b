"""A triangle mesh of the fitted Bézier surface for display: each patch split into four."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.polishing.bezier import BezierSurface

#: Largest mesh whose fitted surface is subdivided (one level: 4 triangles per patch).
MAX_SUBDIVIDED_FACES = 60000
# Barycentric coordinates of a patch's edge midpoints ab, bc, ca.
_MIDPOINTS = np.array([[0.5, 0.5, 0.0], [0.0, 0.5, 0.5], [0.5, 0.0, 0.5]])


def subdivided_surface_mesh(
    surface: BezierSurface, max_faces: int = MAX_SUBDIVIDED_FACES
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Return (vertices (V, 3) [m], faces (F, 3)) of the fitted surface, each patch split into 4
    triangles through its edge midpoints evaluated on the patch; the flat mesh when it has
    more than `max_faces` faces.

    Midpoints are not shared between neighbouring patches (3 new vertices per patch): the
    patches meet with C0 continuity, so shared edges evaluate to the same points."""
    faces = np.asarray(surface.faces)
    if len(faces) > max_faces:
        return np.asarray(surface.vertices), faces
    f = np.arange(len(faces))
    pts = surface.evaluate(np.repeat(f, 3), np.tile(_MIDPOINTS, (len(faces), 1))).reshape(-1, 3, 3)
    nv = len(surface.vertices)
    m = nv + 3 * f[:, None] + np.arange(3)[None, :]  # ab, bc, ca midpoints of each patch
    a, b, c = faces[:, 0], faces[:, 1], faces[:, 2]
    tris = np.concatenate(
        [
            np.stack([a, m[:, 0], m[:, 2]], 1),
            np.stack([m[:, 0], b, m[:, 1]], 1),
            np.stack([m[:, 2], m[:, 1], c], 1),
            np.stack([m[:, 0], m[:, 1], m[:, 2]], 1),
        ]
    )
    return np.vstack([surface.vertices, pts.reshape(-1, 3)]), tris
