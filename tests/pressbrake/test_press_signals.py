"""press_signals: a followed bend starts on the press's clamping signal and the robot leaves on
its top-dead-centre signal, in every format: a program with a followed bend, EXPORTED by each
post and read back by its reader, played (`motion.programs.io_playback`) against a simulated
press whose stroke takes 2.4 s and 2.7 s. The old form (pulse, then a timer) played against the
same presses leaves too early or lags: the simulator sees the difference.
"""

from __future__ import annotations

import functools
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs import post, reader
from workbench.motion.programs.controller_program import (
    Comment,
    MoveInstr,
    PressSignals,
    PulseOutput,
    RobotProgram,
    SetOutput,
    Signal,
    Target,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
)
from workbench.motion.programs.io_playback import Timing, play
from workbench.pressbrake.press_signals import SimulatedPress, press_actions

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from program_round_trip import SAMPLE_JOINTS_DEG  # noqa: E402

DEG = np.pi / 180.0
PRESS = PressSignals(
    Signal("press_start", 2), Signal("press_clamped", 3), Signal("press_done", 4), 30.0
)
FORMATS = ("rapid", "krl", "ls", "urscript", "nachi")
#: the plan's press: the ram reaches the clamping point 1.0 s after the start, bends 0.6 s
PLANNED_APPROACH = 1.0
FOLLOW = 6  # following moves of 0.1 s each


def test_press_actions_hold_start_until_clamped_and_wait_with_the_timeout() -> None:
    close = [a for a in press_actions("press_close", PRESS) if not isinstance(a, Comment)]
    assert [(type(a).__name__, a.signal.name, a.value) for a in close] == [  # type: ignore[union-attr]
        ("SetOutput", "press_start", True),
        ("WaitInput", "press_clamped", True),
        ("SetOutput", "press_start", False),
    ]
    (top,) = [a for a in press_actions("press_open", PRESS) if not isinstance(a, Comment)]
    assert isinstance(top, WaitInput) and top.signal.name == "press_done" and top.timeout == 30.0
    alone = [a for a in press_actions("press_bend", PRESS) if not isinstance(a, Comment)]
    assert len(alone) == 4 and all(isinstance(a, (SetOutput, WaitInput)) for a in alone)
    assert all(a.timeout == 30.0 for a in alone if isinstance(a, WaitInput))
    (note,) = press_actions("press_close", None)
    assert isinstance(note, Comment) and "io.press" in note.text
    with pytest.raises(ValueError, match="press step"):
        press_actions("press_lift", PRESS)


def test_the_simulated_press_answers_in_its_times() -> None:
    press = SimulatedPress("r", PRESS, 1.2, 0.7, 0.8, io_delay=0.01)
    assert press.stroke == pytest.approx(2.7) and press.initial()[("r", 4)] is True
    got = list(press.on_output(5.0, "r", 2, True))
    assert got == pytest.approx(
        [(5.01, "r", 4, False), (6.21, "r", 3, True), (6.91, "r", 3, False), (7.71, "r", 4, True)]
    )
    assert list(press.on_output(6.0, "r", 2, True)) == []  # busy: the ram is moving
    assert list(press.on_output(9.0, "r", 2, False)) == [] and press.strokes == [5.0]


def _program(new: bool) -> RobotProgram:
    """Return a followed bend: to the stop, the press step, FOLLOW timed following moves, the
    press's top dead centre, away. `new`: on the press's signals; else the old pulse + timer."""
    model = preset_robot("mz07")
    tool = ToolData("gripper", np.eye(4), mass=1.0, cog=np.zeros(3))
    q0 = np.array(SAMPLE_JOINTS_DEG["home"]) * DEG

    def move(name: str, k: float, t: float) -> MoveInstr:
        q = q0 + np.array([k, 0.0, 0.0, 0.0, 0.0, 0.0]) * DEG
        return MoveInstr("joint", Target(name, q), 0.05, 0.0, "gripper", "base", t)

    ins: list = [move("at_stop", 10.0, 1.0)]
    if new:
        ins += press_actions("press_close", PRESS)
    else:
        ins += [PulseOutput(PRESS.start, 0.2), WaitTime(PLANNED_APPROACH)]
    ins += [move(f"follow{j}", 10.0 + 2.0 * j, 0.1) for j in range(1, FOLLOW + 1)]
    if new:
        ins += press_actions("press_open", PRESS)
    else:
        ins += [WaitTime(0.8), WaitInput(PRESS.top, True, 30.0)]
    ins.append(move("away", 0.0, 1.0))
    wobj = WorkObject("base", np.eye(4))
    return RobotProgram("bend", (tool,), (wobj,), tuple(ins), model.convention, model.dof, "r")


@functools.cache
def _read(fmt: str, new: bool) -> tuple:
    read = reader(fmt)(post(fmt)(_program(new)).files).instructions
    if fmt != "rapid":
        return read
    # RAPID names its signals (read back with number 0); the controller's I/O configuration
    # maps each name to its channel: here the press's numbers
    numbers = {s.name: s for s in (PRESS.start, PRESS.clamped, PRESS.top)}
    return tuple(
        replace(a, signal=numbers[a.signal.name]) if hasattr(a, "signal") else a for a in read
    )


def _play(fmt: str, new: bool, approach: float, seed: int):  # noqa: ANN202
    """Play the exported program against a press of stroke 2.4 s (approach 1.0 s) or 2.7 s
    (approach 1.2 s): bend 0.6 / 0.7 s, opening 0.8 s."""
    press = SimulatedPress("r", PRESS, approach, 0.6 if approach < 1.1 else 0.7, 0.8, io_delay=0.01)
    pb = play(
        {"r": _read(fmt, new)},
        rng=np.random.default_rng(seed),
        devices=[press],
        initial=press.initial(),
        pulse_blocks=fmt in ("urscript", "nachi"),
        timing=Timing(move_scale=(1.0, 1.0), move=(0.1, 0.1)),
    )
    return pb, press


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("approach", [1.0, 1.2], ids=["press-2.4s", "press-2.7s"])
def test_following_starts_on_the_clamping_signal(fmt: str, approach: float) -> None:
    for seed in range(5):
        pb, press = _play(fmt, True, approach, seed)
        assert not pb.faults and not pb.stuck(), (fmt, pb.faults)
        clamped = pb.first("r", "input", "I3 on")
        follow = pb.first("r", "move", "follow1")
        assert clamped is not None and follow is not None
        assert press.strokes[0] + approach < clamped + 1e-9  # the press clamps, then tells
        # following starts on the signal: one look and the reset of start later (steps <= 12 ms)
        assert clamped <= follow <= clamped + 0.04, (fmt, seed, clamped, follow)
        # the robot leaves the part only after the ram is back at top dead centre
        top = pb.first("r", "input", "I4 on")
        assert top is not None and top <= pb.first("r", "move", "away")  # type: ignore[operator]
        followed = [e.t for e in pb.events if e.kind == "move" and e.detail.startswith("follow")]
        assert followed == sorted(followed) and len(followed) == FOLLOW
        # the order the plan's timeline has (press_events): start, clamped, follow, top
        start = pb.first("r", "set", "O2 on")
        assert start is not None and start < clamped <= follow < top


@pytest.mark.parametrize("fmt", ["rapid", "urscript"])
def test_the_old_timer_leaves_before_the_clamp_or_lags_it(fmt: str) -> None:
    """Twin: the old program (pulse, then the planned approach as a timer) starts following
    before a slower press has clamped, and in URScript 0.2 s late (the pulse blocks)."""
    pb, press = _play(fmt, False, 1.2, 0)
    clamped, follow = pb.first("r", "input", "I3 on"), pb.first("r", "move", "follow1")
    assert clamped is not None and follow is not None
    if fmt == "rapid":
        assert follow < clamped - 0.15  # left 0.2 s before the sheet is clamped
    else:
        pb24, _ = _play(fmt, False, 1.0, 0)
        c24, f24 = pb24.first("r", "input", "I3 on"), pb24.first("r", "move", "follow1")
        assert f24 > c24 + 0.15  # type: ignore[operator]  # with the planned press: 0.2 s late


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ["rapid", "krl", "urscript"])
def test_the_example_cycle_follows_each_bend_on_the_clamping_signal(fmt: str) -> None:
    """The u-channel example's planned cycle: its timeline (`press_events`) and its exported
    program played against a press 10 % slower and 10 % faster than planned."""
    from workbench.pressbrake.cycle import BendingCycle
    from workbench.project.program_io import program_settings

    wb = _example()
    cycle = wb.bending.plan()
    assert isinstance(cycle, BendingCycle)
    events = cycle.press_events()
    kinds = [e.what for e in events]
    assert kinds.count("clamped") >= 1 and kinds.count("start") == kinds.count("top")
    assert [e.t for e in events] == sorted(e.t for e in events)
    for k, e in enumerate(events):  # each followed bend: start, clamped, follow, followed, top
        if e.what == "clamped":
            assert kinds[k - 1 : k + 4] == ["start", "clamped", "follow", "followed", "top"]
    press = program_settings(wb.project).press
    assert isinstance(press, PressSignals)
    (prog,) = wb.bending.robot_programs(cycle)
    read = reader(fmt)(post(fmt)(prog).files).instructions
    if fmt == "rapid":
        named = {s.name: s for s in (press.start, press.clamped, press.top)}
        read = tuple(
            replace(a, signal=named.get(a.signal.name, a.signal)) if hasattr(a, "signal") else a
            for a in read
        )
    wps = cycle.path.waypoints
    close = next(w.hold for w in wps if w.action == "press_close")
    opening = next(w.hold for w in wps if w.action == "press_open")
    for f in (0.9, 1.1):
        sim = SimulatedPress("r", press, close * f, 0.3, opening * f, io_delay=0.01)
        pb = play(
            {"r": read},
            rng=np.random.default_rng(0),
            devices=[sim],
            initial=sim.initial(),
            pulse_blocks=fmt == "urscript",
        )
        assert not pb.faults and not pb.stuck(), pb.faults
        assert len(sim.strokes) == kinds.count("start")
        seen = [
            e.t for e in pb.events if e.kind == "seen" and e.detail == f"I{press.clamped.number} on"
        ]
        moves = [e.t for e in pb.events if e.kind == "move"]
        starts = [k for k, w in enumerate(kinds) if w == "start"]
        followed = [kinds[k + 1] == "clamped" for k in starts]
        for t_start, t_seen, follows in zip(sim.strokes, seen, followed, strict=True):
            assert not [t for t in moves if t_start < t < t_seen]  # no move before clamping
            if follows:  # the first following move: on the signal, one reset step later
                assert min(t for t in moves if t >= t_seen) - t_seen <= 0.04


@functools.cache
def _example():  # noqa: ANN202
    from workbench import Workbench

    return Workbench.open(Path(__file__).resolve().parents[2] / "projects" / "u_channel_cell.json")
