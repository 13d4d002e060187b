"""The press-brake cycle as robot waypoints and part phases (SI units: m, rad, s).

One cycle: from home, pick the flat blank off the stack; per bend (a regrip at the regrip
station first when the grasp changes) move the part in front of the die (`approach`, die
frame), slide it against the back-gauge, wait while the ram closes, follow the rising
flange through the bend (or, with `follow` off, let go before the bend and grip again
after it), wait while the ram opens, lift the part out and pull it back; after the last
bend pass the transfer's via poses, put the part on the pallet and go home.

Waypoints are TCP poses (world) the robot passes, with an exact stop and a hold [s] where
the gripper acts or the press works. Phases say what the part does between two waypoints:
rests somewhere, is carried at one fold step, or is being bent (carried by the robot, or
held by the press), and where the punch and the back-gauge are.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.pressbrake.bend_setup import (
    BendPose,
    GaugeStop,
    bend_pose,
    gauge_stop,
    part_points,
)
from workbench.pressbrake.grasp import Grasp, T_flange_grasp
from workbench.pressbrake.press import PressBrake, Station, ram_time
from workbench.sheetmetal.folding import FoldedState, fold_state
from workbench.sheetmetal.part import SheetMetalPart

F64 = NDArray[np.float64]


#: How high [m] over the die the part slides in before it is put down on it.
DROP = 0.005
#: Default spacing [m] of the IK waypoints of the straight moves onto the die and out.
LINE_STEP = 0.01

#: Bend-following waypoints per bend: the robot's IK is solved at each (the search checks
#: the same fractions).
FOLLOW_STEPS = 24


def follow_fractions(steps: int = FOLLOW_STEPS) -> NDArray[np.float64]:
    """Return the fractions of a bend at which the following robot has a waypoint."""
    return np.linspace(0.0, 1.0, max(2, steps) + 1)


#: The cycle's checked frames' spacing [s] (`CycleCell.frame_dt`).
FRAME_DT = 0.05


@dataclass(frozen=True, eq=False)
class CycleCell:
    """The cycle's cell, SI: the press; where the blank lies (T_world_part of the flat blank
    on its stack), where the part lies on the regrip station (T_world_part: a fixture with
    stops that takes the part in any state), the pallet (T_world_part of the finished part); the transfer's TCP via poses (N, 4, 4); the
    die-frame `approach` offset (3,) and the `lift` [m] at the stack, station and pallet;
    `follow`; home joints (dof,); the gripper's settle times [s] after closing (`settle`) and
    opening (`release`); bend-following waypoints
    per bend (`follow_steps`), the checked frames' spacing `frame_dt` [s] and the spacing
    [m] of the IK waypoints of the straight moves onto the die and out (`line_step`);
    `via_home`: the moves between the stack, the die, the regrip station and the pallet
    pass through the home joints (a safe pose: no transit planner)."""

    press: PressBrake
    T_world_blank: F64
    T_world_regrip: F64
    T_world_pallet: F64
    T_world_vias: F64
    approach: F64
    lift: float
    follow: bool
    q_home: F64
    settle: float = 0.3
    release: float = 0.3
    follow_steps: int = FOLLOW_STEPS
    frame_dt: float = FRAME_DT
    line_step: float = LINE_STEP
    via_home: bool = True


@dataclass(frozen=True)
class CycleStep:
    """One bend of the cycle: the bend's name, the grasp that makes it and its tool station."""

    bend: str
    grasp: Grasp
    station: str


Action = Literal["", "grip", "release", "press_close", "press_open", "press_bend"]


@dataclass(frozen=True, eq=False)
class Waypoint:
    """A robot target: TCP pose (4, 4) [m] in the world (None: the home joints), its label,
    whether the robot stops there, the hold [s] after it and what happens during the hold;
    `bend_time` [s]: for a bend-following segment ending here, how long the ram takes for it;
    `free`: the move to it is a transit between stations, not a straight or following move,
    and may go around obstacles (`transit.route_transits`)."""

    T_world_tcp: F64 | None
    label: str
    stop: bool = False
    hold: float = 0.0
    action: Action = ""
    bend_time: float = 0.0
    free: bool = False


@dataclass(frozen=True, eq=False)
class Phase:
    """What the part does from waypoint `start` to waypoint `end` (indices, holds included).

    kind: "rest" (at `T_world_part`, the robot away), "carried" (gripped at `grasp`, folded
    `step` bends), "bend" (bend `bend` of the sequence going from fraction `f0` to `f1`,
    carried by the robot, or held by the press when `pressed`). The punch tip stands at
    `punch_z` [m] over the die's top (NaN: follows the bend); `stop`: the back-gauge setting.
    """

    kind: Literal["rest", "carried", "bend"]
    start: int
    end: int
    step: float
    grasp: Grasp | None
    T_world_part: F64 | None = None
    bend: int = -1
    f0: float = 0.0
    f1: float = 0.0
    pressed: bool = False
    punch_z: float = np.nan
    stop: GaugeStop | None = None
    station: str = ""
    label: str = ""


@dataclass(frozen=True, eq=False)
class CyclePath:
    """Waypoints and phases of a cycle, and the bend poses on the die (per bend: the pose at
    each following fraction)."""

    waypoints: tuple[Waypoint, ...]
    phases: tuple[Phase, ...]
    fractions: F64
    bend_poses: tuple[tuple[BendPose, ...], ...] = field(repr=False)
    stops: tuple[GaugeStop, ...] = ()


def _lift(T: F64, dz: float) -> F64:
    out = T.copy()
    out[2, 3] += dz
    return out


def _shift(T: F64, R_world_die: F64, offset: F64) -> F64:
    out = T.copy()
    out[:3, 3] += R_world_die @ offset
    return out


def T_part_tcp(
    part: SheetMetalPart, grasp: Grasp, step: float, state: FoldedState | None = None
) -> F64:
    """Return the TCP (4, 4) [m] in the part frame at fold `step` (float: partway); `state`:
    the part folded to `step` where the caller has it."""
    state = fold_state(part, step, check=False) if state is None else state
    g = part.flange_index(grasp.flange)
    return state.T_part_flange[g] @ T_flange_grasp(part, grasp)  # type: ignore[no-any-return]


def T_world_part_on_die(part: SheetMetalPart, k: int, st: CycleStep, press: PressBrake) -> F64:
    """Return T_world_part (4, 4) [m] of bend k against its stop as the cycle puts it on the
    die: the step's station and grasp (whose flange faces the robot), the bend not begun."""
    state = fold_state(part, k, check=False)
    pose = bend_pose(state, k, st.grasp, press, press.station(st.station))
    return press.T_world_die @ pose.T_die_part  # type: ignore[no-any-return]


def cycle_path(part: SheetMetalPart, steps: list[CycleStep], cell: CycleCell) -> CyclePath:
    """Return the waypoints and phases of one cycle of `part` (its bends in sequence order,
    one `CycleStep` per bend). InputError: steps that do not match the sequence, a station
    the press lacks, a back-gauge stop that cannot be made (naming the bend)."""
    if [s.bend for s in steps] != [b.name for b in part.bends]:
        raise InputError(
            f"steps: expected one per bend in sequence order {[b.name for b in part.bends]}, "
            f"got {[s.bend for s in steps]}"
        )
    path = _PathBuilder(part, cell, follow_fractions(cell.follow_steps))
    start = _pick_the_blank(path, steps[0].grasp)
    prev = steps[0].grasp
    for k, st in enumerate(steps):
        if k > 0 and not _same(prev, st.grasp):
            start = _regrip(path, k, st, prev, start)
        on_die = _on_die(path, k, st)
        i_stop = _onto_the_die(path, k, st, on_die, start)
        if cell.follow:
            start = _follow_the_bend(path, k, st, on_die, i_stop)
        else:
            start = _let_the_press_bend(path, k, st, on_die, i_stop)
        _out_of_the_die(path, st, on_die)
        prev = st.grasp
    _to_the_pallet(path, steps[-1].grasp, start)
    path.phases.sort(key=lambda p: (p.start, p.end))
    return CyclePath(
        tuple(path.waypoints),
        tuple(path.phases),
        path.fractions,
        tuple(path.bend_poses),
        tuple(path.stops),
    )


@dataclass(eq=False)
class _PathBuilder:
    """The cycle's path as it is built: waypoints, phases, the bend poses and the back-gauge
    stops so far, of `part` in `cell` with bend-following `fractions`."""

    part: SheetMetalPart
    cell: CycleCell
    fractions: F64
    waypoints: list[Waypoint] = field(default_factory=lambda: [Waypoint(None, "home", stop=True)])
    phases: list[Phase] = field(default_factory=list)
    bend_poses: list[tuple[BendPose, ...]] = field(default_factory=list)
    stops: list[GaugeStop] = field(default_factory=list)

    def add(self, w: Waypoint) -> int:
        """Append `w` and return its index; a vertical move (lift) from the previous TCP
        pose goes straight, by IK waypoints every `line_step` (the part is near a table)."""
        wps = self.waypoints
        prev = wps[-1].T_world_tcp if wps else None
        if prev is not None and w.T_world_tcp is not None:
            d = w.T_world_tcp[:3, 3] - prev[:3, 3]
            vertical = np.linalg.norm(d[:2]) < 1e-9 and abs(d[2]) > 1e-9
            if vertical and np.allclose(prev[:3, :3], w.T_world_tcp[:3, :3]):
                step = min(self.cell.line_step, abs(d[2]) / 5)
                for j, T in enumerate(_line(prev, w.T_world_tcp, step)[1:-1]):
                    wps.append(Waypoint(T, f"{w.label} ({j + 1})"))
        wps.append(w)
        return len(wps) - 1

    def add_line(self, T_a: F64, T_b: F64, label: str, *, to_end: bool = False) -> None:
        """Append the IK waypoints of the straight move from `T_a` to `T_b`, every
        `line_step` or less, both ends left out (`to_end`: `T_b` kept), labelled
        `label (1)`, `label (2)`, ..."""
        poses = _line(T_a, T_b, self.cell.line_step)
        for j, T in enumerate(poses[1:] if to_end else poses[1:-1]):
            self.add(Waypoint(T, f"{label} ({j + 1})"))


def _pick_the_blank(path: _PathBuilder, grasp: Grasp) -> int:
    """Add the blank on its stack and its pick; return the pick's waypoint index."""
    cell, lift = path.cell, path.cell.lift
    T_blank_tcp = cell.T_world_blank @ T_part_tcp(path.part, grasp, 0)
    path.phases.append(
        Phase("rest", 0, 2, 0.0, None, cell.T_world_blank, label="blank on the stack")
    )
    path.add(Waypoint(_lift(T_blank_tcp, lift), "above the blank", stop=True, free=True))
    i_pick = path.add(
        Waypoint(T_blank_tcp, "pick the blank", stop=True, hold=cell.settle, action="grip")
    )
    path.add(Waypoint(_lift(T_blank_tcp, lift), "lift the blank off the stack"))
    return i_pick


def _regrip(path: _PathBuilder, k: int, st: CycleStep, old: Grasp, start: int) -> int:
    """Add the regrip before bend k: put the part down at the station (held at `old` since
    waypoint `start`), take it again at the step's grasp; return the take's index."""
    part, cell, lift = path.part, path.cell, path.cell.lift
    T_rest = cell.T_world_regrip
    T_put = T_rest @ T_part_tcp(part, old, k)
    if cell.via_home:
        path.add(
            Waypoint(None, f"via home to the regrip station (before bend {st.bend!r})", free=True)
        )
    path.add(
        Waypoint(
            _lift(T_put, lift), f"above the regrip station (before bend {st.bend!r})", free=True
        )
    )
    i_put = path.add(
        Waypoint(
            T_put,
            "put the part on the regrip station",
            stop=True,
            hold=cell.release,
            action="release",
        )
    )
    path.phases.append(Phase("carried", start, i_put, float(k), old, label="to the regrip station"))
    T_new = T_rest @ T_part_tcp(part, st.grasp, k)
    path.add(Waypoint(_lift(T_put, lift), "off the regrip station"))
    path.add(Waypoint(_lift(T_new, lift), "above the new grasp", free=True))
    i_take = path.add(
        Waypoint(
            T_new, "take the part at its new grasp", stop=True, hold=cell.settle, action="grip"
        )
    )
    path.phases.append(
        Phase("rest", i_put, i_take, float(k), None, T_rest, label="on the regrip station")
    )
    path.add(Waypoint(_lift(T_new, lift), "off the regrip station with the part"))
    return i_take


@dataclass(frozen=True, eq=False)
class _OnDie:
    """Bend k on the die at the following fractions: the fold states, the part's poses on
    the die, its points (P, 3) [m] in the die frame at the stop and at the end, the station,
    the back-gauge stop and the TCP poses (world) of the step's grasp."""

    states: list[FoldedState]
    poses: tuple[BendPose, ...]
    points_die: tuple[F64, F64]
    station: Station
    stop: GaugeStop
    tcp: list[F64]


def _on_die(path: _PathBuilder, k: int, st: CycleStep) -> _OnDie:
    """Return bend k of the step on the die and record its poses and stop. InputError: a
    station the press lacks, a stop that cannot be made."""
    part, press = path.part, path.cell.press
    station = press.station(st.station)
    states = [fold_state(part, k + f, check=False) for f in path.fractions]
    poses = tuple(bend_pose(s, k, st.grasp, press, station) for s in states)
    path.bend_poses.append(poses)
    pts_die = [
        (p.T_die_part @ np.c_[pts, np.ones(len(pts))].T).T[:, :3]
        for p, pts in ((poses[0], part_points(states[0])), (poses[-1], part_points(states[-1])))
    ]
    stop = gauge_stop(pts_die[0], press, station)
    if stop.problem is not None:
        raise InputError(f"bend {st.bend!r}: {stop.problem}")
    path.stops.append(stop)
    tcp = [
        press.T_world_die @ p.T_die_part @ T_part_tcp(part, st.grasp, k + f)
        for p, f in zip(poses, path.fractions, strict=True)
    ]
    return _OnDie(states, poses, (pts_die[0], pts_die[1]), station, stop, tcp)


def _onto_the_die(path: _PathBuilder, k: int, st: CycleStep, on_die: _OnDie, start: int) -> int:
    """Add the move of the part (carried since waypoint `start`) to the die for bend k: in
    front of it, over to just above the stop, then straight down onto the die (`DROP` above
    it: the joints' path between the IK waypoints of the slide may sag); return the stop's
    waypoint index."""
    cell, press = path.cell, path.cell.press
    R_wd = press.T_world_die[:3, :3]
    at_stop = on_die.tcp[0]
    if cell.via_home and path.waypoints[-1].label.startswith(("lift the blank", "off the regrip")):
        path.add(Waypoint(None, f"via home to the die for bend {st.bend!r}", free=True))
    # in front: the approach offset, or farther until the whole part is in front of the
    # punch and beam (`CLEAR` before the bend line), so the moves to and from it do not
    # sweep the part through the press
    front = _shift(at_stop, R_wd, clear_of_tools(cell.approach, on_die.points_die[0]))
    over = _shift(at_stop, R_wd, np.array([0.0, 0.0, DROP]))
    path.add(Waypoint(front, f"in front of the die for bend {st.bend!r}", stop=True, free=True))
    path.add_line(front, over, f"onto the die for bend {st.bend!r}", to_end=True)
    path.waypoints[-1] = Waypoint(over, f"over the stop for bend {st.bend!r}", stop=True)
    i_stop = path.add(Waypoint(at_stop, f"bend {st.bend!r} against the back-gauge", stop=True))
    path.phases.append(
        Phase(
            "carried",
            start,
            i_stop,
            float(k),
            st.grasp,
            punch_z=press.ram.open + path.part.thickness,
            stop=on_die.stop,
            station=on_die.station.name,
            label=f"to the die for bend {st.bend!r}",
        )
    )
    return i_stop


def _follow_the_bend(path: _PathBuilder, k: int, st: CycleStep, on_die: _OnDie, i_stop: int) -> int:
    """Add bend k with the robot following the flange: the ram closes while it holds at the
    stop, a waypoint per fraction timed by the ram, the ram opens at the last; return the
    last's index."""
    ram = path.cell.press.ram
    poses, tcp = on_die.poses, on_die.tcp
    close = press_wait(ram.open / ram.approach_speed)
    opening = press_wait((ram.open + poses[-1].depth) / ram.return_speed)
    depth = np.array([p.depth for p in poses])
    wps = path.waypoints
    wps[i_stop] = Waypoint(tcp[0], wps[i_stop].label, stop=True, hold=close, action="press_close")
    n_fractions = len(path.fractions)
    for j in range(1, n_fractions):
        dt = (depth[j] - depth[j - 1]) / ram.bending_speed
        last = j == n_fractions - 1
        path.add(
            Waypoint(
                tcp[j],
                f"bend {st.bend!r} at {np.degrees(on_die.states[j].angles[k]):.0f}°",
                stop=last,
                hold=opening if last else 0.0,
                action="press_open" if last else "",
                bend_time=max(dt, 1e-3),
            )
        )
    i_end = len(wps) - 1
    path.phases.append(
        Phase(
            "bend",
            i_stop,
            i_end,
            float(k),
            st.grasp,
            bend=k,
            f0=0.0,
            f1=1.0,
            stop=on_die.stop,
            station=on_die.station.name,
            label=f"bend {st.bend!r}",
        )
    )
    return i_end


def _let_the_press_bend(
    path: _PathBuilder, k: int, st: CycleStep, on_die: _OnDie, i_stop: int
) -> int:
    """Add bend k made by the press alone: let go, stand back along the tool, wait for the
    bend, grip the bent part again; return the grip's index."""
    cell, press = path.cell, path.cell.press
    tcp = on_die.tcp
    bend_total = press_wait(ram_time(press, on_die.poses[-1].depth))
    wps = path.waypoints
    wps[i_stop] = Waypoint(
        tcp[0], wps[i_stop].label, stop=True, hold=cell.release, action="release"
    )
    path.add(
        Waypoint(
            tcp[0] @ _tz(-cell.lift),
            f"clear of the part during bend {st.bend!r}",
            stop=True,
            hold=bend_total,
            action="press_bend",
        )
    )
    path.add(Waypoint(tcp[-1] @ _tz(-cell.lift), f"over the bent part after {st.bend!r}"))
    i_end = path.add(
        Waypoint(
            tcp[-1],
            f"grip the part after bend {st.bend!r}",
            stop=True,
            hold=cell.settle,
            action="grip",
        )
    )
    path.phases.append(
        Phase(
            "bend",
            i_stop,
            i_end,
            float(k),
            None,
            bend=k,
            f0=0.0,
            f1=1.0,
            pressed=True,
            stop=on_die.stop,
            station=on_die.station.name,
            label=f"bend {st.bend!r} (the press holds the part)",
        )
    )
    return i_end


def _out_of_the_die(path: _PathBuilder, st: CycleStep, on_die: _OnDie) -> None:
    """Add the moves after the bend: lift the part straight out of the die, then pull it
    back until it is clear of the tools."""
    cell = path.cell
    R_wd = cell.press.T_world_die[:3, :3]
    at_end = on_die.tcp[-1]
    up = _shift(at_end, R_wd, np.array([0.0, 0.0, cell.approach[2] + on_die.poses[-1].depth]))
    path.add_line(at_end, up, f"out of the die after bend {st.bend!r}")
    path.add(Waypoint(up, f"lift out of the die after bend {st.bend!r}", stop=True))
    back = clear_of_tools(cell.approach, on_die.points_die[1])
    out = _shift(up, R_wd, np.array([0.0, back[1], 0.0]))
    path.add_line(up, out, f"back from the die after bend {st.bend!r}")
    path.add(Waypoint(out, f"pull back from the die after bend {st.bend!r}"))


def _to_the_pallet(path: _PathBuilder, grasp: Grasp, start: int) -> None:
    """Add the transfer (carried at `grasp` since waypoint `start`) through the via poses to
    the pallet, the part put down there, and the robot's way home."""
    part, cell, lift = path.part, path.cell, path.cell.lift
    nb = len(part.bends)
    for i, T in enumerate(cell.T_world_vias):
        path.add(Waypoint(T, f"transfer via {i + 1}", free=True))
    T_drop = cell.T_world_pallet @ T_part_tcp(part, grasp, nb)
    if cell.via_home and not len(cell.T_world_vias):
        path.add(Waypoint(None, "via home to the pallet", free=True))
    path.add(Waypoint(_lift(T_drop, lift), "above the pallet", free=True))
    i_drop = path.add(
        Waypoint(
            T_drop, "put the part on the pallet", stop=True, hold=cell.release, action="release"
        )
    )
    path.phases.append(Phase("carried", start, i_drop, float(nb), grasp, label="to the pallet"))
    path.add(Waypoint(_lift(T_drop, lift), "off the pallet"))
    i_home = path.add(Waypoint(None, "home", stop=True, free=True))
    path.phases.append(
        Phase(
            "rest",
            i_drop,
            i_home,
            float(nb),
            None,
            cell.T_world_pallet,
            label="finished part on the pallet",
        )
    )


#: How far [m] in front of the bend line the part's rearmost point must be before the
#: robot moves it anywhere but straight in or out (the punch and the beam over it).
CLEAR = 0.06


def clear_of_tools(approach: F64, points_die: F64) -> F64:
    """Return the approach offset (3,) [m] (die frame), its y made far enough in front that
    the part's points (P, 3) [m] in the die frame, moved by it, lie `CLEAR` before the line."""
    out = np.asarray(approach, float).copy()
    out[1] = min(out[1], -(float(points_die[:, 1].max()) + CLEAR))
    return out


#: The step [s] of the press's waits as every program can state them (FANUC's `WAIT t(sec)`
#: has two decimals).
WAIT_STEP = 0.01


def press_wait(seconds: float) -> float:
    """Return the robot's wait for a press motion of `seconds` [s]: rounded up to `WAIT_STEP`,
    so plan and program wait alike and never less than the ram takes."""
    return round(float(np.ceil(seconds / WAIT_STEP - 1e-9)) * WAIT_STEP, 6)


def _line(T_a: F64, T_b: F64, step: float) -> list[F64]:
    """Return poses from T_a to T_b (same orientation) every `step` [m] or less, ends included:
    a straight move near the tools is followed by IK waypoints, not left to the joints."""
    n = max(1, int(np.ceil(np.linalg.norm(T_b[:3, 3] - T_a[:3, 3]) / step)))
    out = []
    for f in np.linspace(0.0, 1.0, n + 1):
        T = T_a.copy()
        T[:3, 3] = (1 - f) * T_a[:3, 3] + f * T_b[:3, 3]
        out.append(T)
    return out


def _tz(dz: float) -> F64:
    T = np.eye(4)
    T[2, 3] = dz
    return T


def _same(a: Grasp, b: Grasp) -> bool:
    off_a = None if a.offset is None else tuple(np.round(a.offset, 9))
    off_b = None if b.offset is None else tuple(np.round(b.offset, 9))
    return (a.flange, off_a, round(a.yaw, 9), getattr(a, "face", 1)) == (
        b.flange,
        off_b,
        round(b.yaw, 9),
        getattr(b, "face", 1),
    )
