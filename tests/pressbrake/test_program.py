"""The bending robot program (issue 12 part 4) against its plan: the placements' and the
transfer's planned joints at the targets, the transfer's planned durations, the actions in order
(gripper close before the first move, press handshake at each bend, open at the pallet), and the
RAPID and KRL posts read back."""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.motion.programs.controller_program import (
    Comment,
    Gripper,
    MoveInstr,
    PressSignals,
    PulseOutput,
    Signal,
    WaitInput,
)
from workbench.motion.programs.krl import write_krl
from workbench.motion.programs.krl_read import read_krl
from workbench.motion.programs.rapid import write_rapid
from workbench.motion.programs.rapid_read import read_rapid
from workbench.pressbrake.program import bending_program
from workbench.project.program_io import program_settings

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from program_round_trip import check_read_back  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CLOSE = Gripper(True, Signal("do_grip", 1), True)
OPEN = Gripper(False, Signal("do_grip", 1), False)


@pytest.fixture(scope="module")
def planned() -> tuple:
    wb = Workbench.open(ROOT / "projects" / "bending_cell.json")
    plan = wb.bending.plan()
    base = program_settings(wb.project)
    settings = replace(
        base,
        close=CLOSE,
        open=OPEN,
        press=PressSignals(
            Signal("do_bend_start", 5), Signal("di_clamped", 7), Signal("di_bend_done", 6), 20.0
        ),
    )
    prog = bending_program(plan, wb.setup, wb.bending.si(), settings, wb.joints)
    return wb, plan, prog


def test_targets_hold_the_planned_joints_and_the_transfer_its_times(planned: tuple) -> None:
    wb, plan, prog = planned
    moves = {m.name: m for m in prog.moves}
    for k, pl in enumerate(plan.placements):
        m = moves[f"b{k + 1}_bend"]
        assert np.array_equal(m.target.q, pl.q)
        assert m.kind == "linear"
        # the target is the placement's TCP pose (world -> robot base)
        T_world = wb.setup.T_world_base @ m.target.T_wobj_tcp
        assert np.allclose(T_world, pl.T_world_tcp, atol=1e-9)
    wp, wt = plan.trajectory.waypoints, plan.trajectory.waypoint_times
    assert np.array_equal(moves[f"b{len(plan.placements)}_retreat"].target.q, wp[0])
    transfer = [moves[f"transfer{j}"] for j in range(1, len(wp) - 1)] + [moves["pallet"]]
    for j, m in enumerate(transfer, 1):
        assert np.array_equal(m.target.q, wp[j])
        assert m.duration == pytest.approx(wt[j] - wt[j - 1], abs=1e-12)
    assert sum(m.duration for m in transfer) == pytest.approx(plan.trajectory.duration, rel=0.01)
    # the die moves are timed stop to stop: each at least the closed-form bound of its largest
    # joint step at the limits' speed
    vmax = np.asarray(wb.robot.max_velocity) * 0.5
    q_prev = wb.joints
    for m in prog.moves:
        if m.name.startswith("b"):
            assert m.duration >= np.max(np.abs(m.target.q - q_prev) / vmax) - 1e-9
        q_prev = m.target.q
    assert prog.cycle_time > plan.trajectory.duration


def test_actions_in_order(planned: tuple) -> None:
    _, plan, prog = planned
    ins = prog.instructions
    first_move = next(i for i, x in enumerate(ins) if isinstance(x, MoveInstr))
    assert ins.index(CLOSE) < first_move
    for k in range(len(plan.placements)):
        i = next(
            i for i, x in enumerate(ins) if isinstance(x, MoveInstr) and x.name == f"b{k + 1}_bend"
        )
        # start held until the press clamps, then the ram back at top dead centre: no pulse
        got = [(type(x).__name__, x.signal.name, x.value) for x in ins[i + 1 : i + 5]]  # type: ignore[union-attr]
        assert got == [
            ("SetOutput", "do_bend_start", True),
            ("WaitInput", "di_clamped", True),
            ("SetOutput", "do_bend_start", False),
            ("WaitInput", "di_bend_done", True),
        ]
        assert all(x.timeout == 20.0 for x in ins[i + 1 : i + 5] if isinstance(x, WaitInput))
        assert isinstance(ins[i + 5], MoveInstr) and ins[i + 5].name == f"b{k + 1}_retreat"
    pallet = next(i for i, x in enumerate(ins) if isinstance(x, MoveInstr) and x.name == "pallet")
    assert ins[pallet + 2] is OPEN and ins[-1].name == "home"


def test_without_io_the_program_says_which_signals_are_missing(planned: tuple) -> None:
    # the example's io has the gripper and the press signals: the service's program uses them
    (full,) = planned[0].bending.robot_programs(planned[1])
    used = {x.signal.name for x in full.actions() if hasattr(x, "signal")}
    assert {"vacuum", "vacuum_ok", "press_start", "press_clamped", "press_done"} <= used
    wb, plan, _ = planned
    bare = replace(
        program_settings(wb.project), close=None, open=None, outputs={}, inputs={}, press=None
    )
    prog = bending_program(plan, wb.setup, wb.bending.si(), bare, wb.joints)
    texts = [x.text for x in prog.instructions if isinstance(x, Comment)]
    assert any("no press section" in t for t in texts)
    assert any("no io.gripper" in t for t in texts)
    assert not any(isinstance(x, (PulseOutput, WaitInput, Gripper)) for x in prog.instructions)


def test_rapid_read_back(planned: tuple) -> None:
    wb, _, prog = planned
    check_read_back(prog, read_rapid(write_rapid(prog).files), wb.robot)


def test_krl_read_back(planned: tuple) -> None:
    wb, _, prog = planned
    check_read_back(prog, read_krl(write_krl(prog).files), wb.robot)
