"""One bend on the press brake: where the part lies, where the back-gauge stops it, where the
punch is, and what the part may touch (SI units: m, rad).

Orientation: the die frame's z points into the bend's inside (the punch makes the bend from
the inside), and the side of the bend holding the gripped flange faces the robot (−y); the
other side goes to the back-gauge. So a grasp fixes the part's orientation at every bend;
"top up" says whether the part's base flange shows its +z face upwards.

The part is placed with the bend's outer apex on the die's x axis at the station's x, sunk
by the air-bending depth of the bend angle reached (`airbend.apex_depth`); the moving
flanges turn about the bend line as the punch descends (`SheetMetalPart.fold` partway).

Contact is not collision. Against the press, the part is checked with the die lowered by
the press's `tolerance`, the back-gauge fingers set back by it, and the punch cut above its
tip by the bend's contact zone, BA + 2t + tolerance (BA the bend allowance): the half-bend
growth of the flange boxes next to the bend (`FoldedState.flange_obbs`) lies within it.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.collision.shapes import Solid
from workbench.geometry.obb import OBB
from workbench.geometry.transforms import invert_transform, make_transform, rot_z
from workbench.pressbrake.airbend import apex_depth
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.obstacles import ExactShape, Obstacles, cell_obstacles
from workbench.pressbrake.press import PressBrake, Station, clipped_profile, piece_solid, prism
from workbench.sheetmetal.folding import FoldedState
from workbench.sheetmetal.part import SheetMetalPart

F64 = NDArray[np.float64]
Body = tuple[str, Solid, F64]


def bend_line_frame(state: FoldedState, i: int) -> F64:
    """Return T_part_line (4, 4) [m] of bend `i` in `state`: origin on the outer surface at the
    middle of the bend zone (the apex), x along the bend line, z into the bend's inside."""
    part, t = state.part, state.part.thickness
    b = part.bends[i]
    geo = state.bend_cross_section(i)
    d, n, w = geo["d"], geo["n"], geo["w"]
    th = float(state.angles[i])
    r = float(state.radii[i]) if np.isfinite(state.radii[i]) else 0.0
    arc = th * (r + t / 2.0) if th > 0 else float(part.bend_allowances[i])  # mid-surface arc
    half = th / 2.0
    along = arc * (np.sin(half) / th if th > 0 else 0.5)
    up = arc * ((1.0 - np.cos(half)) / th if th > 0 else 0.0)
    mid = (geo["pa"] + geo["pb"]) / 2.0 + along * n + up * w
    u = -np.cos(half) * w + np.sin(half) * n  # from the bend's centre towards the apex
    z = -u
    T_parent_line = make_transform(np.column_stack([d, np.cross(z, d), z]), mid + u * t / 2.0)
    return state.T_part_flange[b.parent] @ T_parent_line  # type: ignore[no-any-return]


def in_child_side(part: SheetMetalPart, i: int, flange: int) -> bool:
    """Return whether `flange` lies beyond bend `i` (in its child's subtree)."""
    f = flange
    while f != 0:
        k = int(part.parent_bend[f])
        if k == i:
            return True
        f = part.bends[k].parent
    return False


@dataclass(frozen=True, eq=False)
class BendPose:
    """The part on the die for bend `step` at a fraction of it: `T_die_part` (4, 4) [m],
    the outer apex's `depth` [m] below the die's top and the punch tip's height `punch_z` [m]."""

    step: int
    fraction: float
    T_die_part: F64
    depth: float
    punch_z: float


def bend_pose(
    state: FoldedState, step: int, grasp: Grasp, press: PressBrake, station: Station
) -> BendPose:
    """Return where the part of `state` (bend `step` folded partway or not at all) lies on the
    die at `station`, held at `grasp` (whose flange faces the robot)."""
    part, t = state.part, state.part.thickness
    T_part_line = bend_line_frame(state, step)
    # The line frame's -y side is the child's; turn the part when the grip is on the parent's.
    if not in_child_side(part, step, part.flange_index(grasp.flange)):
        T_part_line = T_part_line @ make_transform(rot_z(np.pi), np.zeros(3))
    depth = float(
        apex_depth(
            state.angles[step],
            state.radii[step],
            t,
            press.die.v_opening,
            press.die.shoulder_radius,
        )
    )
    T_die_apex = make_transform(np.eye(3), [station.x, 0.0, -depth])
    frac = float(np.clip(state.step - step, 0.0, 1.0))
    return BendPose(step, frac, T_die_apex @ invert_transform(T_part_line), depth, t - depth)


def part_points(state: FoldedState) -> F64:
    """Return the corners (P, 3) [m] of every flange's top and bottom face in the part frame."""
    t = state.part.thickness
    pts = []
    for f, fl in enumerate(state.part.flanges):
        n = len(fl.polygon)
        for z in (t / 2.0, -t / 2.0):
            local = np.c_[fl.polygon, np.full(n, z), np.ones(n)]
            pts.append((state.T_part_flange[f] @ local.T).T[:, :3])
    return np.concatenate(pts)


@dataclass(frozen=True)
class GaugeStop:
    """Back-gauge setting for one bend: stop depth `x`, finger height `r`, finger centres `z`
    (along the bed) [m]; `problem` says why no stop is possible (then the rest is NaN)."""

    x: float
    r: float
    z: tuple[float, ...]
    problem: str | None = None


def gauge_stop(points_die: F64, press: PressBrake, station: Station) -> GaugeStop:
    """Return the back-gauge stop against the part's points (P, 3) [m] in the die frame.

    The fingers' bottom sits at the lowest height the R axis allows (not below the die's
    top); the stop is the part's farthest point behind the bend line within the fingers'
    height; the fingers stand at the quarter points of that edge along the bed (one finger
    in its middle when it is shorter than two fingers).
    """
    bg, where = press.backgauge, f"{press.where}.backgauge"
    depth, width, height = bg.finger
    r = float(np.clip(0.0, *bg.r_range))
    band = points_die[(points_die[:, 1] > 1e-9) & (points_die[:, 2] >= r - 1e-9)]
    band = band[band[:, 2] <= r + height]
    if not len(band):
        return GaugeStop(
            np.nan,
            r,
            (),
            f"no edge of the part behind the bend line at the fingers' height "
            f"({r * 1e3:.0f}..{(r + height) * 1e3:.0f} mm over the die)",
        )
    x = float(band[:, 1].max())
    if not bg.x_range[0] - 1e-9 <= x <= bg.x_range[1] + 1e-9:
        return GaugeStop(
            x,
            r,
            (),
            f"the back-gauge stop X = {x * 1e3:.1f} mm is outside its range "
            f"{bg.x_range[0] * 1e3:g}..{bg.x_range[1] * 1e3:g} mm ({where}.x)",
        )
    edge = band[band[:, 1] >= x - 1e-3, 0]
    lo, hi = float(edge.min()), float(edge.max())
    if bg.fingers >= 2 and hi - lo >= 2 * width:
        zs = tuple(lo + (hi - lo) * (k + 0.5) / bg.fingers for k in range(bg.fingers))
    else:
        zs = ((lo + hi) / 2.0,)
    if any(not bg.z_range[0] - 1e-9 <= z <= bg.z_range[1] + 1e-9 for z in zs):
        return GaugeStop(
            x,
            r,
            (),
            f"the back-gauge fingers would stand at Z = "
            f"{', '.join(f'{z * 1e3:.0f}' for z in zs)} mm, outside their range "
            f"{bg.z_range[0] * 1e3:g}..{bg.z_range[1] * 1e3:g} mm ({where}.z)",
        )
    del station  # the fingers' Z is measured along the bed like the station's x
    return GaugeStop(x, r, zs)


def finger_bodies(press: PressBrake, stop: GaugeStop, setback: float) -> list[Body]:
    """Return the fingers as boxes in the die frame, their stop faces `setback` [m] behind X."""
    d, w, h = press.backgauge.finger
    return [
        (
            f"back-gauge finger {k + 1}",
            Solid(f"back-gauge finger {k + 1}", "box", size=(w, d, h)),
            make_transform(np.eye(3), [z, stop.x + setback + d / 2, stop.r + h / 2]),
        )
        for k, z in enumerate(stop.z)
    ]


def punch_bodies(press: PressBrake, station: Station, punch_z: float, cut: float) -> list[Body]:
    """Return the station's punch (its tip at height `punch_z` [m]) in the die frame, without
    the `cut` [m] above its tip (the contact zone; 0 keeps the whole punch)."""
    x0, x1 = station.x - station.punch_length / 2, station.x + station.punch_length / 2
    T = make_transform(np.eye(3), [0.0, 0.0, punch_z])
    out = []
    for piece in clipped_profile(press.punch.profile, cut):
        solid, T_piece = piece_solid("punch", piece, x0, x1)
        out.append(("punch", solid, T @ T_piece))
    return out


def die_bodies(press: PressBrake, drop: float = 0.0) -> list[Body]:
    """Return every station's die in the die frame, lowered by `drop` [m]."""
    T = make_transform(np.eye(3), [0.0, 0.0, -drop])
    out = []
    for s in press.stations:
        x0, x1 = s.x - s.die_length / 2, s.x + s.die_length / 2
        for piece in press.die.profile_pieces():
            solid, T_piece = piece_solid("die", piece, x0, x1)
            out.append(("die", solid, T @ T_piece))
    return out


def frame_bodies(press: PressBrake) -> list[Body]:
    """Return the bed (under the dies, down to the floor), the side housings and the upper
    beam over the open punch, as boxes in the die frame."""
    T_wd = press.T_world_die
    floor = -float(T_wd[2, 3])  # the world's z = 0 in the die frame (an upright die)
    die_bottom = -press.die.height
    half = press.length / 2 + press.frame_gap
    hd, hw = press.housing
    top = press.ram.open + press.punch.height + press.beam_height + 0.05
    width = max(press.die.width, 0.2)
    out: list[Body] = []
    if die_bottom - floor > 1e-3:
        out.append(
            (
                "bed",
                Solid("bed", "box", size=(2 * half, width, die_bottom - floor)),
                make_transform(np.eye(3), [0.0, 0.0, (die_bottom + floor) / 2]),
            )
        )
    for side, sign in (("left", 1.0), ("right", -1.0)):
        out.append(
            (
                f"housing {side}",
                Solid(f"housing {side}", "box", size=(hw, hd, top - floor)),
                make_transform(
                    np.eye(3), [sign * (half + hw / 2), hd / 2 - width / 2, (top + floor) / 2]
                ),
            )
        )
    return out


def beam_body(press: PressBrake, punch_z: float) -> Body:
    """Return the upper beam (the ram) over the punch whose tip is at `punch_z` [m]."""
    half = press.length / 2 + press.frame_gap
    z0 = punch_z + press.punch.height
    width = max(float(np.ptp(press.punch.profile[:, 0])), 0.1)
    return (
        "upper beam",
        Solid("upper beam", "box", size=(2 * half, width, press.beam_height)),
        make_transform(np.eye(3), [0.0, 0.0, z0 + press.beam_height / 2]),
    )


def contact_zone(ba: float, thickness: float, tolerance: float) -> float:
    """Return the height [m] over the punch tip that is the bend's contact, not a collision."""
    return ba + 2.0 * thickness + tolerance


def part_obstacles(
    press: PressBrake, station: Station, punch_z: float, cut: float, stop: GaugeStop | None
) -> list[Body]:
    """Return what the part may not touch at one instant, in the WORLD frame: frame and bed,
    the dies lowered by the tolerance, the punch (tip at `punch_z`, `cut` above it removed),
    the beam and the back-gauge fingers (`stop`, set back by the tolerance)."""
    tol = press.tolerance
    bodies = frame_bodies(press) + die_bodies(press, tol)
    bodies += punch_bodies(press, station, punch_z, cut) + [beam_body(press, punch_z)]
    if stop is not None and stop.problem is None:
        bodies += finger_bodies(press, stop, tol)
    T = press.T_world_die
    return [(n, s, T @ Td) for n, s, Td in bodies]


def unique_names(bodies: list[Body]) -> list[Body]:
    """Return `bodies` with repeated names numbered ("die", "die 2", ...), solids renamed."""
    seen: dict[str, int] = {}
    out: list[Body] = []
    for n, s, T in bodies:
        seen[n] = seen.get(n, 0) + 1
        name = n if seen[n] == 1 else f"{n} {seen[n]}"
        out.append((name, replace(s, name=name), T))
    return out


@dataclass(eq=False)
class PressObstacles:
    """The press's obstacles for the part, built once and moved with the ram.

    `at(station, punch_z, cut, stop)` equals `cell_obstacles(part_obstacles(...))` (tested):
    the frame and the lowered dies are built once, the punch once per station and cut at
    punch height 0, then shifted along the die's z with the beam.
    """

    press: PressBrake
    _static: Obstacles | None = None
    _ram: dict[tuple[str, float], Obstacles] = field(default_factory=dict)

    def at(self, station: Station, punch_z: float, cut: float, stop: GaugeStop | None) -> Obstacles:
        """Return the obstacles (world) of the press at this instant."""
        press, T = self.press, self.press.T_world_die
        if self._static is None:
            bodies = frame_bodies(press) + die_bodies(press, press.tolerance)
            self._static = cell_obstacles([(n, s, T @ Td) for n, s, Td in bodies])
        key = (station.name, round(cut, 9))
        if key not in self._ram:
            bodies = punch_bodies(press, station, 0.0, cut) + [beam_body(press, 0.0)]
            self._ram[key] = cell_obstacles([(n, s, T @ Td) for n, s, Td in bodies])
        parts = [self._static, shift_obstacles(self._ram[key], T[:3, 2] * punch_z)]
        if stop is not None and stop.problem is None:
            fingers = finger_bodies(press, stop, press.tolerance)
            parts.append(cell_obstacles([(n, s, T @ Td) for n, s, Td in fingers]))
        return merge_obstacles(*parts)


def shift_obstacles(obs: Obstacles, v: F64) -> Obstacles:
    """Return `obs` moved by the world vector `v` (3,) [m]."""
    if not np.any(v):
        return obs
    boxes = OBB(obs.boxes.center + v, obs.boxes.rotation, obs.boxes.half_extents)
    M = make_transform(np.eye(3), v)
    exact = tuple(
        None
        if e is None
        else ExactShape(e.geometry, M @ e.T_world, None if e.mesh is None else _moved(e.mesh, v))
        for e in obs.exact
    )
    return Obstacles(obs.names, boxes, exact)


def _moved(mesh: trimesh.Trimesh, v: F64) -> trimesh.Trimesh:
    return trimesh.Trimesh(mesh.vertices + v, mesh.faces, process=False)


def merge_obstacles(*parts: Obstacles) -> Obstacles:
    """Return the obstacles of every part, in order."""
    parts = tuple(p for p in parts if p.names)
    if not parts:
        return cell_obstacles([])
    if len(parts) == 1:
        return parts[0]
    boxes = OBB(
        np.concatenate([p.boxes.center for p in parts]),
        np.concatenate([p.boxes.rotation for p in parts]),
        np.concatenate([p.boxes.half_extents for p in parts]),
    )
    return Obstacles(
        tuple(n for p in parts for n in p.names), boxes, tuple(e for p in parts for e in p.exact)
    )


def robot_obstacles(press: PressBrake) -> list[Body]:
    """Return the press as the robot sees it, in the WORLD frame: frame, bed, dies, the
    ram's stroke (every station's punch, and the upper beam, over their whole travel from
    closed to open) and the back-gauge's reach (its fingers' travel) as boxes."""
    # One closed prism per die (the robot's distance field needs every body watertight and
    # apart: pieces sharing faces would not be).
    bodies = frame_bodies(press) + [
        (
            "die",
            Solid(
                "die",
                "mesh",
                mesh=prism(press.die.profile(), s.x - s.die_length / 2, s.x + s.die_length / 2),
            ),
            np.eye(4),
        )
        for s in press.stations
    ]
    # the ram's stroke: every station's punch and the beam over it, from the punch tip on
    # the die's top (closed) to open
    prof = press.punch.profile
    for s in press.stations:
        w = float(np.ptp(prof[:, 0]))
        top = press.ram.open + press.punch.height
        bodies.append(
            (
                "ram stroke",
                Solid("ram stroke", "box", size=(s.punch_length, w, top)),
                make_transform(np.eye(3), [s.x, float(prof[:, 0].mean()), top / 2]),
            )
        )
    beam_closed = beam_body(press, 0.0)[2][2, 3] - press.beam_height / 2
    half = press.length / 2 + press.frame_gap
    width = max(float(np.ptp(prof[:, 0])), 0.1)
    height = press.ram.open + press.beam_height
    bodies.append(
        (
            "beam stroke",
            Solid("beam stroke", "box", size=(2 * half, width, height)),
            make_transform(np.eye(3), [0.0, 0.0, beam_closed + height / 2]),
        )
    )
    bg = press.backgauge
    d, w, h = bg.finger
    size = (
        bg.z_range[1] - bg.z_range[0] + w,
        bg.x_range[1] - bg.x_range[0] + d,
        bg.r_range[1] - bg.r_range[0] + h,
    )
    centre = [
        (bg.z_range[0] + bg.z_range[1]) / 2,
        (bg.x_range[0] + bg.x_range[1] + d) / 2,
        (bg.r_range[0] + bg.r_range[1] + h) / 2,
    ]
    bodies.append(
        ("back-gauge", Solid("back-gauge", "box", size=size), make_transform(np.eye(3), centre))
    )
    T = press.T_world_die
    return unique_names([(n, s, T @ Td) for n, s, Td in bodies])


def press_display_bodies(press: PressBrake) -> list[Body]:
    """Return the moving press bodies as drawn, in the WORLD frame, ram open and fingers
    parked at the back of their X range: each station's punch (its whole profile), the
    upper beam, the back-gauge fingers."""
    T = press.T_world_die
    out: list[Body] = []
    z_open = press.ram.open
    for s in press.stations:
        mesh = prism(press.punch.profile, s.x - s.punch_length / 2, s.x + s.punch_length / 2)
        name = "punch" if len(press.stations) == 1 else f"punch {s.name}"
        out.append(
            (name, Solid(name, "mesh", mesh=mesh), T @ make_transform(np.eye(3), [0, 0, z_open]))
        )
    name, solid, T_beam = beam_body(press, z_open)
    out.append((name, solid, T @ T_beam))
    bg = press.backgauge
    park = GaugeStop(
        bg.x_range[1],
        bg.r_range[0],
        tuple(np.linspace(bg.z_range[0], bg.z_range[1], bg.fingers + 2)[1:-1]),
    )
    out += [(n, s, T @ Td) for n, s, Td in finger_bodies(press, park, 0.0)]
    return out


def press_poses(press: PressBrake, punch_z: float, stop: GaugeStop | None) -> dict[str, F64]:
    """Return the world poses of the moving press bodies (names of `press_display_bodies`)
    with the punch tip at `punch_z` [m] over the die's top and the fingers at `stop` (None:
    parked)."""
    T = press.T_world_die
    out: dict[str, F64] = {}
    lift = make_transform(np.eye(3), [0.0, 0.0, punch_z])
    for s in press.stations:
        out["punch" if len(press.stations) == 1 else f"punch {s.name}"] = T @ lift
    out["upper beam"] = T @ beam_body(press, punch_z)[2]
    if stop is not None and stop.problem is None:
        for name, _, Td in finger_bodies(press, stop, 0.0):
            out[name] = T @ Td
    return out
