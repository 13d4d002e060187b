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
from workbench.pressbrake.press import PressBrake, ram_time
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
    frame_dt: float = 0.05
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


def cycle_path(part: SheetMetalPart, steps: list[CycleStep], cell: CycleCell) -> CyclePath:
    """Return the waypoints and phases of one cycle of `part` (its bends in sequence order,
    one `CycleStep` per bend). InputError: steps that do not match the sequence, a station
    the press lacks, a back-gauge stop that cannot be made (naming the bend)."""
    nb = len(part.bends)
    if [s.bend for s in steps] != [b.name for b in part.bends]:
        raise InputError(
            f"steps: expected one per bend in sequence order {[b.name for b in part.bends]}, "
            f"got {[s.bend for s in steps]}"
        )
    press = cell.press
    R_wd = press.T_world_die[:3, :3]
    fr = follow_fractions(cell.follow_steps)
    wps: list[Waypoint] = [Waypoint(None, "home", stop=True)]
    phases: list[Phase] = []
    bend_poses: list[tuple[BendPose, ...]] = []
    stops: list[GaugeStop] = []

    def add(w: Waypoint) -> int:
        """Append `w`; a vertical move (lift) from the previous TCP pose goes straight, by IK
        waypoints every `line_step` (the part is near a table)."""
        prev = wps[-1].T_world_tcp if wps else None
        if prev is not None and w.T_world_tcp is not None:
            d = w.T_world_tcp[:3, 3] - prev[:3, 3]
            vertical = np.linalg.norm(d[:2]) < 1e-9 and abs(d[2]) > 1e-9
            if vertical and np.allclose(prev[:3, :3], w.T_world_tcp[:3, :3]):
                step = min(cell.line_step, abs(d[2]) / 5)
                for j, T in enumerate(_line(prev, w.T_world_tcp, step)[1:-1]):
                    wps.append(Waypoint(T, f"{w.label} ({j + 1})"))
        wps.append(w)
        return len(wps) - 1

    lift = cell.lift
    g0 = steps[0].grasp
    T_blank_tcp = cell.T_world_blank @ T_part_tcp(part, g0, 0)
    phases.append(Phase("rest", 0, 2, 0.0, None, cell.T_world_blank, label="blank on the stack"))
    add(Waypoint(_lift(T_blank_tcp, lift), "above the blank", stop=True, free=True))
    i_pick = add(
        Waypoint(T_blank_tcp, "pick the blank", stop=True, hold=cell.settle, action="grip")
    )
    add(Waypoint(_lift(T_blank_tcp, lift), "lift the blank off the stack"))
    start = i_pick
    prev: Grasp | None = g0
    ram = press.ram
    for k, st in enumerate(steps):
        station = press.station(st.station)
        g = st.grasp
        if prev is not None and k > 0 and not _same(prev, g):
            # Regrip: put the part down at the station, take it again at the new grasp.
            T_rest = cell.T_world_regrip
            T_put = T_rest @ T_part_tcp(part, prev, k)
            if cell.via_home:
                add(
                    Waypoint(
                        None, f"via home to the regrip station (before bend {st.bend!r})", free=True
                    )
                )
            add(
                Waypoint(
                    _lift(T_put, lift),
                    f"above the regrip station (before bend {st.bend!r})",
                    free=True,
                )
            )
            i_put = add(
                Waypoint(
                    T_put,
                    "put the part on the regrip station",
                    stop=True,
                    hold=cell.release,
                    action="release",
                )
            )
            phases.append(
                Phase("carried", start, i_put, float(k), prev, label="to the regrip station")
            )
            T_new = T_rest @ T_part_tcp(part, g, k)
            add(Waypoint(_lift(T_put, lift), "off the regrip station"))
            add(Waypoint(_lift(T_new, lift), "above the new grasp", free=True))
            i_take = add(
                Waypoint(
                    T_new,
                    "take the part at its new grasp",
                    stop=True,
                    hold=cell.settle,
                    action="grip",
                )
            )
            phases.append(
                Phase("rest", i_put, i_take, float(k), None, T_rest, label="on the regrip station")
            )
            add(Waypoint(_lift(T_new, lift), "off the regrip station with the part"))
            start = i_take
        states = [fold_state(part, k + f, check=False) for f in fr]
        poses = tuple(bend_pose(s, k, g, press, station) for s in states)
        bend_poses.append(poses)
        pts_die = [
            (p.T_die_part @ np.c_[pts, np.ones(len(pts))].T).T[:, :3]
            for p, pts in ((poses[0], part_points(states[0])), (poses[-1], part_points(states[-1])))
        ]
        stop = gauge_stop(pts_die[0], press, station)
        if stop.problem is not None:
            raise InputError(f"bend {st.bend!r}: {stop.problem}")
        stops.append(stop)
        tcp = [
            press.T_world_die @ p.T_die_part @ T_part_tcp(part, g, k + f)
            for p, f in zip(poses, fr, strict=True)
        ]
        close = press_wait(ram.open / ram.approach_speed)
        opening = press_wait((ram.open + poses[-1].depth) / ram.return_speed)
        # In front of the die, over to just above the stop, then straight down onto the die
        # (`DROP` above it: the joints' path between the IK waypoints of the slide may sag).
        if cell.via_home and wps[-1].label.startswith(("lift the blank", "off the regrip")):
            add(Waypoint(None, f"via home to the die for bend {st.bend!r}", free=True))
        # in front: the approach offset, or farther until the whole part is in front of the
        # punch and beam (`CLEAR` before the bend line), so the moves to and from it do not
        # sweep the part through the press
        front = _shift(tcp[0], R_wd, clear_of_tools(cell.approach, pts_die[0]))
        over = _shift(tcp[0], R_wd, np.array([0.0, 0.0, DROP]))
        add(Waypoint(front, f"in front of the die for bend {st.bend!r}", stop=True, free=True))
        for j, T in enumerate(_line(front, over, cell.line_step)[1:]):
            add(Waypoint(T, f"onto the die for bend {st.bend!r} ({j + 1})"))
        wps[-1] = Waypoint(over, f"over the stop for bend {st.bend!r}", stop=True)
        i_stop = add(Waypoint(tcp[0], f"bend {st.bend!r} against the back-gauge", stop=True))
        phases.append(
            Phase(
                "carried",
                start,
                i_stop,
                float(k),
                g,
                punch_z=ram.open + part.thickness,
                stop=stop,
                station=station.name,
                label=f"to the die for bend {st.bend!r}",
            )
        )
        depth = np.array([p.depth for p in poses])
        if cell.follow:
            wps[i_stop] = Waypoint(
                tcp[0], wps[i_stop].label, stop=True, hold=close, action="press_close"
            )
            for j in range(1, len(fr)):
                dt = (depth[j] - depth[j - 1]) / ram.bending_speed
                last = j == len(fr) - 1
                add(
                    Waypoint(
                        tcp[j],
                        f"bend {st.bend!r} at {np.degrees(states[j].angles[k]):.0f}°",
                        stop=last,
                        hold=opening if last else 0.0,
                        action="press_open" if last else "",
                        bend_time=max(dt, 1e-3),
                    )
                )
            i_end = len(wps) - 1
            phases.append(
                Phase(
                    "bend",
                    i_stop,
                    i_end,
                    float(k),
                    g,
                    bend=k,
                    f0=0.0,
                    f1=1.0,
                    stop=stop,
                    station=station.name,
                    label=f"bend {st.bend!r}",
                )
            )
        else:
            # Let go, stand back along the tool, wait for the bend, grip the bent part again.
            bend_total = press_wait(ram_time(press, poses[-1].depth))
            wps[i_stop] = Waypoint(
                tcp[0], wps[i_stop].label, stop=True, hold=cell.release, action="release"
            )
            back = tcp[0] @ _tz(-lift)
            i_back = add(
                Waypoint(
                    back,
                    f"clear of the part during bend {st.bend!r}",
                    stop=True,
                    hold=bend_total,
                    action="press_bend",
                )
            )
            add(Waypoint(tcp[-1] @ _tz(-lift), f"over the bent part after {st.bend!r}"))
            i_end = add(
                Waypoint(
                    tcp[-1],
                    f"grip the part after bend {st.bend!r}",
                    stop=True,
                    hold=cell.settle,
                    action="grip",
                )
            )
            phases.append(
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
                    stop=stop,
                    station=station.name,
                    label=f"bend {st.bend!r} (the press holds the part)",
                )
            )
            del i_back
        up = _shift(tcp[-1], R_wd, np.array([0.0, 0.0, cell.approach[2] + poses[-1].depth]))
        for j, T in enumerate(_line(tcp[-1], up, cell.line_step)[1:-1]):
            add(Waypoint(T, f"out of the die after bend {st.bend!r} ({j + 1})"))
        add(Waypoint(up, f"lift out of the die after bend {st.bend!r}", stop=True))
        back = clear_of_tools(cell.approach, pts_die[-1])
        out = _shift(up, R_wd, np.array([0.0, back[1], 0.0]))
        for j, T in enumerate(_line(up, out, cell.line_step)[1:-1]):
            add(Waypoint(T, f"back from the die after bend {st.bend!r} ({j + 1})"))
        add(Waypoint(out, f"pull back from the die after bend {st.bend!r}"))
        start = i_end
        prev = g
    g_last = steps[-1].grasp
    for i, T in enumerate(cell.T_world_vias):
        add(Waypoint(T, f"transfer via {i + 1}", free=True))
    T_drop = cell.T_world_pallet @ T_part_tcp(part, g_last, nb)
    if cell.via_home and not len(cell.T_world_vias):
        add(Waypoint(None, "via home to the pallet", free=True))
    add(Waypoint(_lift(T_drop, lift), "above the pallet", free=True))
    i_drop = add(
        Waypoint(
            T_drop, "put the part on the pallet", stop=True, hold=cell.release, action="release"
        )
    )
    phases.append(Phase("carried", start, i_drop, float(nb), g_last, label="to the pallet"))
    add(Waypoint(_lift(T_drop, lift), "off the pallet"))
    i_home = add(Waypoint(None, "home", stop=True, free=True))
    phases.append(
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
    phases.sort(key=lambda p: (p.start, p.end))
    return CyclePath(tuple(wps), tuple(phases), fr, tuple(bend_poses), tuple(stops))


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
