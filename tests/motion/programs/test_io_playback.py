"""io_playback: the controller model itself, and two robots' EXPORTED programs (each post's
files read back by its reader) played against each other with random interpreter steps and
I/O delays of 0-100 ms: the four-phase handshake never lets a robot pass a sync point before
its partner reached it and never deadlocks, also with three sync points in a row; the old
handshake (out ON, wait ON, out OFF) and the symmetric four-phase one fail in the same model.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
from program_round_trip import SAMPLE_JOINTS_DEG

from workbench.kinematics.robot_library import preset_robot
from workbench.motion.programs import post, reader
from workbench.motion.programs.controller_program import (
    Action,
    MoveInstr,
    PulseOutput,
    RobotProgram,
    SetOutput,
    Signal,
    SyncPoint,
    Target,
    ToolData,
    WaitInput,
    WorkObject,
)
from workbench.motion.programs.io_playback import Timing, Wire, play, sync_wires
from workbench.motion.programs.sync_handshake import handshake, leads, match_handshake

DEG = np.pi / 180.0
IO_FORMATS = ("krl", "ls", "urscript", "nachi")
SEEDS = 40


def _old(sync: SyncPoint, lead: bool) -> tuple[Action, ...]:
    """The handshake before issue 27: the same for both robots."""
    o, i = sync.output, sync.input
    return (SetOutput(o, True), WaitInput(i, True), SetOutput(o, False))  # type: ignore[arg-type]


def _symmetric(sync: SyncPoint, lead: bool) -> tuple[Action, ...]:
    """A symmetric four-phase handshake (out ON, wait ON, out OFF, wait OFF)."""
    o, i = sync.output, sync.input
    return (SetOutput(o, True), WaitInput(i, True), SetOutput(o, False), WaitInput(i, False))  # type: ignore[arg-type]


# -- the model ---------------------------------------------------------------------------


def test_a_wire_delivers_in_order_after_its_delay() -> None:
    a = [SetOutput(Signal("o", 1), v) for v in (True, False, True, False)]
    b = [WaitInput(Signal("i", 2), v) for v in (True, False, True, False)]
    for seed in range(10):
        timing = Timing(io_delay=(0.05, 0.1))
        pb = play(
            {"a": a, "b": b}, [Wire("a", 1, "b", 2)], rng=np.random.default_rng(seed), timing=timing
        )
        sets = [e.t for e in pb.events if e.robot == "a" and e.kind == "set"]
        arrivals = [e for e in pb.events if e.robot == "b" and e.kind == "input"]
        assert [e.detail for e in arrivals] == ["I2 on", "I2 off", "I2 on", "I2 off"]
        last = 0.0
        for t_set, e in zip(sets, arrivals, strict=True):
            assert e.t >= t_set + 0.05 and e.t <= max(last, t_set + 0.1) and e.t >= last
            last = e.t


def test_a_level_shorter_than_a_look_is_missed_and_the_wait_is_a_deadlock() -> None:
    """b looks at its input every 50 ms; a 10 ms pulse falls between two looks."""
    timing = Timing(step=(0.05, 0.05), io_delay=(0.0, 0.0))
    b = [WaitInput(Signal("i", 1), True)]
    short = [PulseOutput(Signal("o", 1), 0.01)]
    pb = play(
        {"a": short, "b": b}, [Wire("a", 1, "b", 1)], rng=np.random.default_rng(0), timing=timing
    )
    assert pb.stuck() == ["b"] and pb.first("b", "input", "I1 on") is not None
    long = [PulseOutput(Signal("o", 1), 0.2)]
    pb = play(
        {"a": long, "b": b}, [Wire("a", 1, "b", 1)], rng=np.random.default_rng(0), timing=timing
    )
    assert pb.stuck() == [] and pb.first("b", "seen", "I1 on") is not None


def test_a_timed_wait_that_runs_out_is_a_named_fault() -> None:
    b = [WaitInput(Signal("i", 3), True, 0.5), SetOutput(Signal("o", 1), True)]
    pb = play({"b": b}, [Wire("x", 1, "b", 3)], rng=np.random.default_rng(2))
    assert pb.faults == ["b: input 3 not on within 0.5 s"] and pb.stuck() == ["b"]
    assert pb.first("b", "set") is None


def test_a_pulse_does_not_wait_unless_told() -> None:
    a = [PulseOutput(Signal("o", 1), 1.0), SetOutput(Signal("o", 2), True)]
    pb = play({"a": a}, rng=np.random.default_rng(3))
    assert pb.first("a", "set", "O2 on") < 0.1  # type: ignore[operator]
    pb = play({"a": a}, rng=np.random.default_rng(3), pulse_blocks=True)
    assert pb.first("a", "set", "O2 on") > 1.0  # type: ignore[operator]


def test_overtaking_is_found_as_a_brute_force_reading_of_the_events_finds_it() -> None:
    """Twin of `Playback.overtaking`: from the raw event list, every pass of a sync point must
    come after every partner's reach of it."""
    found, pair = 0, _pair_read("krl")
    for seed in range(20):
        pb = play(*pair, rng=np.random.default_rng(seed), sync_actions=_old)
        brute = []
        for e in pb.events:
            if e.kind != "pass":
                continue
            for f in pb.events:
                if f.kind == "reach" and f.detail == e.detail and f.robot != e.robot and f.t >= e.t:
                    brute.append((e.robot, e.detail))
            if not any(
                f.kind == "reach" and f.detail == e.detail and f.robot != e.robot for f in pb.events
            ):
                brute.append((e.robot, e.detail))
        assert len(brute) == len(pb.overtaking()), seed
        found += bool(brute)
    assert found >= 10


# -- the handshake ------------------------------------------------------------------------


def test_handshake_roles_and_their_match() -> None:
    s = SyncPoint("s", ("a", "b"), Signal("o", 1), Signal("i", 2))
    assert leads(s, "a") and not leads(s, "b")
    for lead in (True, False):
        acts = handshake(s, lead)
        assert [type(x).__name__ for x in acts] == [
            "WaitInput",
            "SetOutput",
            "WaitInput",
            "SetOutput",
        ]
        assert acts[0].value is not lead and acts[2].value is lead  # type: ignore[union-attr]
        found = match_handshake(acts)
        assert (
            found is not None and found[0] is lead and found[1].number == 1 and found[2].number == 2
        )
    assert match_handshake(_old(s, True)) is None
    assert match_handshake(_symmetric(s, True)) is None
    with pytest.raises(Exception, match="joins 3 robots"):
        handshake(SyncPoint("s", ("a", "b", "c"), Signal("o", 1), Signal("i", 2)), True)


# -- exported programs played against each other ---------------------------------------

# a: move, s1 s2 s3 in a row, move, s4, move, s5 s6; b moves at other times
LAYOUT = {
    "cell_a": ["home", "s1", "s2", "s3", "p_pick", "s4", "p_place", "s5", "s6", "home"],
    "cell_b": ["p_far", "s1", "p_via", "s2", "s3", "s4", "p_flip", "s5", "s6", "p_far"],
}


def _program(name: str) -> RobotProgram:
    model = preset_robot("mz07")
    tool = ToolData("gripper", np.eye(4), mass=1.0, cog=np.zeros(3))
    out, inp = Signal("do_sync", 10), Signal("di_sync", 11 if name == "cell_a" else 12)
    ins: list = []
    for k, item in enumerate(LAYOUT[name]):
        if item.startswith("s"):
            # the robots named in either order (as the assembly names the pair of each sync)
            pair = ("cell_a", "cell_b") if item in ("s1", "s3", "s4") else ("cell_b", "cell_a")
            ins.append(SyncPoint(item, pair, out, inp))
        else:
            q = np.array(SAMPLE_JOINTS_DEG[item]) * DEG
            ins.append(
                MoveInstr(
                    "joint", Target(f"{item}_{k}", q), 0.5, 0.0, "gripper", "base", 0.2 + 0.1 * k
                )
            )
    wobj = WorkObject("base", np.eye(4))
    return RobotProgram(name, (tool,), (wobj,), tuple(ins), model.convention, model.dof, name)


@functools.cache
def _pair_read(fmt: str) -> tuple[dict, list[Wire]]:
    """Return both programs as written by the `fmt` post and read back, and their wires."""
    read = {}
    for name in LAYOUT:
        files = post(fmt)(_program(name)).files
        read[name] = reader(fmt)(files).instructions
    return read, sync_wires(read)


@pytest.mark.parametrize("fmt", IO_FORMATS)
def test_three_sync_points_in_a_row_never_race_in_the_exported_programs(fmt: str) -> None:
    programs, wires = _pair_read(fmt)
    assert {(w.src, w.output, w.dst, w.input) for w in wires} == {
        ("cell_a", 10, "cell_b", 12),
        ("cell_b", 10, "cell_a", 11),
    }
    for name in LAYOUT:
        syncs = [i for i in programs[name] if isinstance(i, SyncPoint)]
        assert [s.lead for s in syncs] == [name == "cell_a"] * 6  # read from the file
    for seed in range(SEEDS):
        pb = play(
            programs,
            wires,
            rng=np.random.default_rng(seed),
            pulse_blocks=fmt in ("urscript", "nachi"),
        )
        assert pb.overtaking() == [], (fmt, seed)
        assert pb.stuck() == [] and not pb.faults, (fmt, seed, pb.stuck())
        assert len(pb.passed) == 12


def test_the_old_handshake_overtakes_and_deadlocks_in_the_same_model() -> None:
    programs, wires = _pair_read("krl")
    overtook = stuck = 0
    for seed in range(SEEDS):
        pb = play(programs, wires, rng=np.random.default_rng(seed), sync_actions=_old)
        overtook += bool(pb.overtaking())
        stuck += bool(pb.stuck())
    assert overtook >= SEEDS // 2 and stuck >= SEEDS // 4, (overtook, stuck)


def test_the_symmetric_four_phase_handshake_deadlocks_in_the_same_model() -> None:
    """Why the handshake has a lead: a robot that takes its ON back as soon as it sees the
    partner's leaves a partner that has not looked yet waiting for an ON that is gone."""
    programs, wires = _pair_read("krl")
    stuck = sum(
        bool(play(programs, wires, rng=np.random.default_rng(s), sync_actions=_symmetric).stuck())
        for s in range(SEEDS)
    )
    assert stuck >= SEEDS // 2, stuck
