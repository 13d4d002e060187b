"""The assembly cell of seed 003's Fig. 11: a table, two plates with holes and five screws.

Everything in metres, world z up, table top at z = 0.70. The plates are placed first
(plate A on the table, plate B on plate A, their five holes aligned), then the screws go
through both plates. Goals keep a 1 mm gap at every face contact, since touching counts
as interference. Screws come from a feeder above the cell, so their insertion axis (z)
is also the dominant axis of their move.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.geometry.transforms import xyz_rpy_to_transform

TABLE_TOP = 0.70
PLATE_SIZE = (0.20, 0.15, 0.010)  # x, y, thickness [m]
HOLE_RADIUS = 0.005
SCREW_SHANK_RADIUS = 0.004
SCREW_SHANK_LENGTH = 0.018
SCREW_HEAD = (0.007, 0.005)  # radius, height [m]
GAP = 0.001
TILE = 0.05
HOLE_TILES = ((0, 0), (3, 0), (0, 2), (3, 2), (1, 1))


@dataclass(frozen=True, eq=False)
class PartMove:
    """One part: its mesh in its own frame and its start and goal poses (4, 4) in the world [m]."""

    name: str
    mesh: trimesh.Trimesh
    start: NDArray[np.float64]
    goal: NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class AssemblyScene:
    """Static obstacles (world frame) and the parts in assembly order (plates, then screws)."""

    fixed: tuple[trimesh.Trimesh, ...]
    parts: tuple[PartMove, ...]

    def obstacles_for(self, index: int) -> list[trimesh.Trimesh]:
        """Return world meshes around part `index`: fixed ones, earlier parts at goal, later at start."""
        out = list(self.fixed)
        for i, p in enumerate(self.parts):
            if i != index:
                out.append(p.mesh.copy().apply_transform(p.goal if i < index else p.start))
        return out


def _tile(hole: bool, n: int) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Return a triangulated square tile [-TILE/2, TILE/2]^2, with a hole of n sides if asked."""
    a = TILE / 2.0
    th = 2.0 * np.pi * np.arange(n) / n
    d = np.stack([np.cos(th), np.sin(th)], axis=1)
    square = d * (a / np.max(np.abs(d), axis=1))[:, None]  # radial projection onto the square
    k = np.arange(n)
    k1 = (k + 1) % n
    if hole:
        verts = np.concatenate([HOLE_RADIUS * d, square])
        faces = np.concatenate([np.stack([k, n + k, n + k1], 1), np.stack([k, n + k1, k1], 1)])
    else:
        verts = np.concatenate([square, [[0.0, 0.0]]])
        faces = np.stack([np.full(n, n), k, k1], 1)
    return verts, faces


def _extrude(v2: NDArray[np.float64], f2: NDArray[np.int64], height: float) -> trimesh.Trimesh:
    """Return the closed prism of a planar triangulation (CCW faces), from z = -h/2 to h/2."""
    m = len(v2)
    v = np.concatenate([np.c_[v2, np.full(m, -height / 2)], np.c_[v2, np.full(m, height / 2)]])
    edges = np.concatenate([f2[:, [0, 1]], f2[:, [1, 2]], f2[:, [2, 0]]])
    key = np.sort(edges, axis=1)
    _, inv, cnt = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    b = edges[cnt[inv.ravel()] == 1]  # boundary edges, oriented with the interior on the left
    walls = np.concatenate(
        [
            np.stack([b[:, 0], b[:, 1], b[:, 1] + m], 1),
            np.stack([b[:, 0], b[:, 1] + m, b[:, 0] + m], 1),
        ]
    )
    faces = np.concatenate([f2[:, ::-1], f2 + m, walls])
    return trimesh.Trimesh(v, faces, process=True)


def plate_mesh(n_sides: int = 32) -> trimesh.Trimesh:
    """Return a plate PLATE_SIZE [m] centred at its frame origin with five through holes."""
    vs, fs, off = [], [], 0
    nx, ny = round(PLATE_SIZE[0] / TILE), round(PLATE_SIZE[1] / TILE)
    for i in range(nx):
        for j in range(ny):
            v, f = _tile((i, j) in HOLE_TILES, n_sides)
            vs.append(
                v + [(i + 0.5) * TILE - PLATE_SIZE[0] / 2, (j + 0.5) * TILE - PLATE_SIZE[1] / 2]
            )
            fs.append(f + off)
            off += len(v)
    v2, f2 = np.concatenate(vs), np.concatenate(fs)
    v2, inv = np.unique(np.round(v2, 12), axis=0, return_inverse=True)
    return _extrude(v2, inv.ravel()[f2], PLATE_SIZE[2])


def hole_centers() -> NDArray[np.float64]:
    """Return (5, 2) hole centres [m] in the plate frame."""
    return np.array(
        [
            [(i + 0.5) * TILE - PLATE_SIZE[0] / 2, (j + 0.5) * TILE - PLATE_SIZE[1] / 2]
            for i, j in HOLE_TILES
        ]
    )


def screw_mesh(n_sides: int = 16) -> trimesh.Trimesh:
    """Return a screw (revolved profile) with its frame at the head's underside, shank along -z."""
    rs, L = SCREW_SHANK_RADIUS, SCREW_SHANK_LENGTH
    rh, H = SCREW_HEAD
    profile = np.array([[0, -L], [rs, -L], [rs, 0], [rh, 0], [rh, H], [0, H]], dtype=float)
    return trimesh.creation.revolve(profile, sections=n_sides)


def example_scene() -> AssemblyScene:
    """Return the seed's Fig. 11 cell: table, plates A and B, five screws, with start and goal poses."""
    table = trimesh.creation.box([0.8, 0.6, TABLE_TOP])
    table.apply_translation([0.0, 0.0, TABLE_TOP / 2])
    t = PLATE_SIZE[2]
    za = TABLE_TOP + GAP + t / 2
    zb = za + t + GAP
    plate = plate_mesh()
    parts = [
        PartMove(
            "plate_a",
            plate,
            xyz_rpy_to_transform([-0.55, 0.10, 0.85], [0, 0, np.radians(30)]),
            xyz_rpy_to_transform([0.0, 0.0, za], [0, 0, 0]),
        ),
        PartMove(
            "plate_b",
            plate.copy(),
            xyz_rpy_to_transform([0.55, -0.10, 0.86], [0, 0, -np.radians(20)]),
            xyz_rpy_to_transform([0.0, 0.0, zb], [0, 0, 0]),
        ),
    ]
    z_head = zb + t / 2 + GAP
    screw = screw_mesh()
    for k, (x, y) in enumerate(hole_centers()):
        start = xyz_rpy_to_transform(
            [-0.12 + 0.06 * k, 0.14, z_head + 0.25], [0, 0, np.radians(15 * k)]
        )
        parts.append(
            PartMove(
                f"screw_{k}", screw.copy(), start, xyz_rpy_to_transform([x, y, z_head], [0, 0, 0])
            )
        )
    return AssemblyScene(fixed=(table,), parts=tuple(parts))


def write_part_meshes(folder: str) -> list[str]:
    """Write plate.stl and screw.stl (in millimetres) into `folder`; return the paths written."""
    from pathlib import Path

    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, mesh in (("plate", plate_mesh()), ("screw", screw_mesh())):
        m = mesh.copy()
        m.apply_scale(1000.0)
        p = out / f"{name}.stl"
        m.export(p)
        paths.append(str(p))
    return paths


if __name__ == "__main__":
    import sys

    print("\n".join(write_part_meshes(sys.argv[1] if len(sys.argv) > 1 else "web_assets/parts")))
