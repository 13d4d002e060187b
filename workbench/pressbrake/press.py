"""The press brake: punch, V-die, tool stations, back-gauge, ram, bed and frame (SI units).

All geometry is in the die frame D: origin on the die's top at the middle of the bend line,
x along the bed, y away from the robot (towards the back-gauge), z up. `PressBrake.T_world_die`
places D in the world.

- Punch: a profile polygon (y, z) [m] with its tip at the origin, extruded along x over the
  station's punch length. Its tip sits `t − depth` over the die's top while bending
  (`airbend.punch_height`), `ram.open` above the sheet when the ram is open.
- Die: a block `width` × `height` with a V-groove of opening `v_opening` and angle `angle`;
  shoulders of radius `shoulder_radius` (used by the depth rule; the block's corners are
  sharp, which is within the shoulder circle's tangent for any bend the angle rule admits).
- Stations: tool segments along the bed, each a punch and a die length at an x offset.
- Back-gauge: fingers (boxes) whose stop face is at X (depth from the bend line), bottom at
  R (height over the die's top), centre at Z along the bed, each within its axis range.
- Ram: open gap [m], approach, bending and return speeds [m/s].
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import shapely
import trimesh
from numpy.typing import NDArray

from workbench.collision.shapes import Solid
from workbench.errors import InputError
from workbench.geometry.polygon import signed_area, triangulate
from workbench.geometry.transforms import make_transform

F64 = NDArray[np.float64]


def punch_profile(width: float, height: float, tip_angle: float) -> F64:
    """Return a straight punch's profile (5, 2) [m] (y, z), tip at the origin, CCW.

    `tip_angle` [rad] is the included angle of the tip's flanks; above the flanks the punch
    is `width` wide up to `height`.
    """
    half = width / 2.0
    zw = half / np.tan(tip_angle / 2.0)
    if zw >= height:
        raise InputError(
            f"flanks of a {np.degrees(tip_angle):.1f} deg tip {width * 1e3:g} mm wide reach "
            f"{zw * 1e3:.1f} mm, above the punch's height {height * 1e3:g} mm",
            field="punch",
        )
    return np.array([[0.0, 0.0], [half, zw], [half, height], [-half, height], [-half, zw]])


@dataclass(frozen=True, eq=False)
class Punch:
    """The upper tool: `profile` (n, 2) [m] (y, z) CCW with the tip at (0, 0), `tip_radius`,
    and the `tip_angle` [rad] its flanks make at the tip (the sharpest bend it can make)."""

    profile: F64
    tip_radius: float
    tip_angle: float

    @property
    def height(self) -> float:
        """Return the punch's height [m] over its tip."""
        return float(self.profile[:, 1].max())


@dataclass(frozen=True)
class DieTool:
    """The lower tool: V `v_opening`, `shoulder_radius`, `angle` [rad] of the V, block
    `width` × `height` [m]."""

    v_opening: float
    shoulder_radius: float
    angle: float
    width: float
    height: float

    @property
    def groove_depth(self) -> float:
        """Return the V-groove's depth [m] below the die's top."""
        return float(self.v_opening / 2.0 / np.tan(self.angle / 2.0))

    def profile(self) -> F64:
        """Return the die's cross-section (y, z) [m] as one CCW polygon (sharp shoulders)."""
        v2, w2, h, d = self.v_opening / 2, self.width / 2, self.height, self.groove_depth
        return np.array(
            [[-w2, -h], [w2, -h], [w2, 0.0], [v2, 0.0], [0.0, -d], [-v2, 0.0], [-w2, 0.0]]
        )

    def profile_pieces(self) -> list[F64]:
        """Return the die's cross-section as convex pieces (y, z) [m]: two shoulder blocks, the
        block under the groove and the groove's two flanks."""
        v2, w2, h, d = self.v_opening / 2, self.width / 2, self.height, self.groove_depth
        return [
            np.array([[v2, -h], [w2, -h], [w2, 0.0], [v2, 0.0]]),
            np.array([[-w2, -h], [-v2, -h], [-v2, 0.0], [-w2, 0.0]]),
            np.array([[-v2, -h], [v2, -h], [v2, -d], [-v2, -d]]),
            np.array([[0.0, -d], [v2, -d], [v2, 0.0]]),
            np.array([[-v2, -d], [0.0, -d], [-v2, 0.0]]),
        ]


@dataclass(frozen=True)
class Station:
    """A tool station along the bed: punch and die segments of given lengths centred at `x` [m]."""

    name: str
    x: float
    punch_length: float
    die_length: float


@dataclass(frozen=True)
class BackGauge:
    """Back-gauge fingers: `finger` (depth y, width x, height z) [m]; axis ranges [m] of the
    stop depth X (from the bend line), height R (finger bottom over the die's top) and the
    finger centres Z along the bed."""

    finger: tuple[float, float, float]
    x_range: tuple[float, float]
    r_range: tuple[float, float]
    z_range: tuple[float, float]
    fingers: int = 2


@dataclass(frozen=True)
class Ram:
    """The ram: `open` gap [m] between the punch tip and the sheet when open; speeds [m/s]."""

    open: float
    approach_speed: float
    bending_speed: float
    return_speed: float


@dataclass(frozen=True, eq=False)
class PressBrake:
    """A press brake placed by `T_world_die` (4, 4) [m]: tools, stations, back-gauge, ram,
    bed and frame; `radius_ratio` (inner radius / V in air bending) and the contact
    `tolerance` [m] (see `tool_obstacles`)."""

    T_world_die: F64
    punch: Punch
    die: DieTool
    stations: tuple[Station, ...]
    backgauge: BackGauge
    ram: Ram
    radius_ratio: float
    tolerance: float
    frame_gap: float = 0.1  # [m] from the longest tool's end to a side housing
    housing: tuple[float, float] = (0.3, 0.08)  # side housings: depth y, width x [m]
    beam_height: float = 0.25  # [m] upper beam over the punch
    names: tuple[str, ...] = field(default=("press",), repr=False)
    where: str = "bending.press"

    @property
    def length(self) -> float:
        """Return the bed's length [m]: every station's tools, end to end."""
        ends = [abs(s.x) + max(s.punch_length, s.die_length) / 2 for s in self.stations] or [0.0]
        return 2.0 * max(ends)

    def station(self, name: str) -> Station:
        """Return the station called `name`; InputError lists the stations."""
        for s in self.stations:
            if s.name == name:
                return s
        raise InputError(
            f"{self.where}.stations: no station {name!r}; stations are "
            f"{[s.name for s in self.stations]}"
        )


def prism(poly_yz: F64, x0: float, x1: float) -> trimesh.Trimesh:
    """Return the closed prism of a CCW polygon (y, z) [m] extruded along x from x0 to x1."""
    n = len(poly_yz)
    tris = triangulate(np.asarray(poly_yz, float))
    a = np.c_[np.full(n, x0), poly_yz]
    b = np.c_[np.full(n, x1), poly_yz]
    j = np.arange(n)
    # In (y, z) CCW seen from +x; the x0 cap faces -x (reversed), the x1 cap faces +x.
    walls = np.concatenate(
        [np.c_[j, (j + 1) % n, n + j], np.c_[(j + 1) % n, n + (j + 1) % n, n + j]]
    )
    faces = np.concatenate([tris[:, ::-1], tris + n, walls[:, ::-1]])
    mesh = trimesh.Trimesh(np.concatenate([a, b]), faces, process=True)
    mesh.fix_normals()
    return mesh


def convex_pieces(poly_yz: F64) -> list[F64]:
    """Return a simple CCW polygon (y, z) split into convex CCW pieces (its triangles, merged
    where the union stays convex)."""
    poly = np.asarray(poly_yz, float)
    if shapely.Polygon(poly).convex_hull.area <= shapely.Polygon(poly).area * (1 + 1e-9):
        return [poly]
    return [poly[t] for t in triangulate(poly)]


def clipped_profile(profile: F64, z_min: float) -> list[F64]:
    """Return the punch profile above height `z_min` [m] as convex CCW pieces (y, z)."""
    cut = shapely.Polygon(profile).intersection(shapely.box(-1e3, z_min, 1e3, 1e3))
    polys = [cut] if cut.geom_type == "Polygon" else list(getattr(cut, "geoms", []))
    out: list[F64] = []
    for p in polys:
        if p.geom_type != "Polygon" or p.area <= 1e-12:
            continue
        ring = np.asarray(p.exterior.coords, float)[:-1]
        if signed_area(ring) < 0:
            ring = ring[::-1]
        out += convex_pieces(ring)
    return out


def piece_solid(name: str, poly_yz: F64, x0: float, x1: float) -> tuple[Solid, F64]:
    """Return a convex profile piece extruded from x0 to x1 as a solid: a box when it is an
    axis-aligned rectangle (exact OBB), else a closed mesh; with its pose in the die frame."""
    lo, hi = poly_yz.min(axis=0), poly_yz.max(axis=0)
    area = float((hi - lo).prod())
    if abs(signed_area(poly_yz) - area) <= 1e-12 + 1e-9 * area:
        centre = np.array([(x0 + x1) / 2, (lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2])
        size = (float(x1 - x0), float(hi[0] - lo[0]), float(hi[1] - lo[1]))
        return Solid(name, "box", size=size), make_transform(np.eye(3), centre)
    return Solid(name, "mesh", mesh=prism(poly_yz, x0, x1)), np.eye(4)


def ram_time(press: PressBrake, depth: float) -> float:
    """Return the ram's time [s] for one bend: close onto the sheet at the approach speed,
    bend `depth` [m] at the bending speed, open at the return speed."""
    ram = press.ram
    return (
        ram.open / ram.approach_speed
        + depth / ram.bending_speed
        + (ram.open + depth) / ram.return_speed
    )
