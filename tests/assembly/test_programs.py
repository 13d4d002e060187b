"""The assembly robot programs (issue 12 part 4) against their plan: one program per robot, the
planned joints at the targets, durations adding up to the plan (the sync points make the
sequence's timeline), gripper close and open at the part moves, the same sync names in the same
order in both programs, and the RAPID and KRL posts read back."""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.assembly.programs import assembly_programs
from workbench.errors import InputError
from workbench.motion.programs.controller_program import (
    Gripper,
    MoveInstr,
    ProgramSettings,
    Signal,
    SyncPoint,
    ToolData,
)
from workbench.motion.programs.formats import write_programs
from workbench.motion.programs.krl import write_krl
from workbench.motion.programs.krl_read import read_krl
from workbench.motion.programs.rapid import write_rapid
from workbench.motion.programs.rapid_read import read_rapid
from workbench.motion.programs.readback import in_robot_base
from workbench.project.program_io import program_settings

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from program_round_trip import check_read_back  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CLOSE = Gripper(True, Signal("do_grip", 1), True, Signal("di_closed", 2), 2.0)
OPEN = Gripper(False, Signal("do_grip", 1), False, Signal("di_open", 3), 2.0)


@pytest.fixture(scope="module")
def planned() -> tuple:
    wb = Workbench.open(ROOT / "projects" / "assembly_cell.json")
    plan = wb.assembly.plan_sequence()
    robots = list(wb.assembly.arms)
    sync = {
        r: (Signal(f"do_sync_{r}", 10 + i), Signal(f"di_sync_{r}", 20 + i))
        for i, r in enumerate(robots)
    }
    tool = ToolData("gripper", wb.setup.T_flange_tcp, 1.2, np.array([0.0, 0.0, 0.06]))
    settings = ProgramSettings(tool, close=CLOSE, open=OPEN, sync=sync)
    progs = assembly_programs(plan.tasks, wb.assembly.arms, settings)
    return wb, plan, progs


def test_one_program_per_robot_with_the_planned_joints(planned: tuple) -> None:
    wb, plan, progs = planned
    assert [p.robot for p in progs] == list(wb.assembly.arms)
    by_robot = {p.robot: p for p in progs}
    for task in plan.tasks:
        moves = [
            m
            for m in by_robot[task.robot].moves
            if m.name.startswith(f"t{plan.tasks.index(task) + 1}_")
        ]
        wp = task.trajectory.waypoints
        for m in moves:  # every target is one of the task's planned waypoints, exactly
            assert np.min(np.abs(wp - m.target.q).max(axis=1)) == 0.0
        # the plan's own samples at the pick and place times hold those joints (independent of
        # the waypoints: the timeline's samples)
        motion = plan.motions[task.robot]
        for label, t in (("pick", task.t_pick), ("place", task.t_place)):
            m = next(m for m in moves if m.name.endswith(label))
            k = motion.index_at(t)
            dt = plan.times[1] - plan.times[0]
            assert np.abs(motion.joints[k] - m.target.q).max() < 2.5 * dt  # joints move < 2.5 rad/s
        # the Cartesian targets are the TCP of the planned joints in the robot base
        arm = wb.assembly.arms[task.robot]
        for m in moves:
            if m.target.cartesian:
                T = arm.setup.model.fk(m.target.q) @ arm.setup.T_flange_tcp
                assert np.allclose(T, m.target.T_wobj_tcp, atol=1e-12)


def test_durations_and_sync_points_reproduce_the_timeline(planned: tuple) -> None:
    _, plan, progs = planned
    total = sum(sum(m.duration for m in p.moves) for p in progs)
    assert abs(total - plan.duration) <= 0.01 * plan.duration
    # run the programs as controllers would: a sync point waits for the partner's
    clocks = {p.robot: 0.0 for p in progs}
    pending: dict[str, float] = {}
    starts: dict[str, float] = {}
    cursors = {p.robot: 0 for p in progs}
    progress = True
    while progress:
        progress = False
        for p in progs:
            while cursors[p.robot] < len(p.instructions):
                ins = p.instructions[cursors[p.robot]]
                if isinstance(ins, SyncPoint):
                    key = ins.name
                    if key not in pending:
                        pending[key] = clocks[p.robot]
                        cursors[p.robot] += 1
                        clocks[p.robot] = np.inf  # waits until the partner arrives
                        break
                    t = max(pending.pop(key), clocks[p.robot])
                    other = next(r for r in clocks if r != p.robot and clocks[r] == np.inf)
                    clocks[p.robot] = clocks[other] = t
                elif isinstance(ins, MoveInstr):
                    task = ins.name.split("_")[0]
                    starts.setdefault(task, clocks[p.robot])
                    clocks[p.robot] += ins.duration
                cursors[p.robot] += 1
                progress = True
    assert not pending
    for k, task in enumerate(plan.tasks):
        assert starts[f"t{k + 1}"] == pytest.approx(task.t0, abs=1e-6)
    assert max(clocks.values()) == pytest.approx(plan.duration, rel=0.01)


def test_gripper_and_sync_order(planned: tuple) -> None:
    _, plan, progs = planned
    for p in progs:
        ins = p.instructions
        names = [i.name if isinstance(i, MoveInstr) else i for i in ins]
        for k, task in enumerate(plan.tasks):
            if task.robot != p.robot:
                continue
            pre = f"t{k + 1}_"
            pick = names.index(pre + "pick")
            place = names.index(pre + "place")
            assert ins[pick + 1] is CLOSE  # closes at the pick, before the first carried move
            assert isinstance(ins[pick + 2], MoveInstr) and ins[pick + 2].name.startswith(pre + "c")
            assert ins[place + 1] is OPEN  # opens after the place
            assert ins[place].zone == 0.0 and ins[pick].zone == 0.0
    syncs = [[i.name for i in p.instructions if isinstance(i, SyncPoint)] for p in progs]
    assert syncs[0] == syncs[1] and len(syncs[0]) == sum(
        a.robot != b.robot for a, b in zip(plan.tasks[:-1], plan.tasks[1:], strict=True)
    )


def test_the_project_without_io_writes_comments_and_rapid_names_the_massless_tool(
    planned: tuple,
) -> None:
    wb, plan, _ = planned
    # the example's io has the gripper, its further robot the tool's mass and cog
    full = wb.assembly.robot_programs(plan)
    assert all(any(isinstance(i, Gripper) for i in p.instructions) for p in full)
    b = full[1].tools[0]
    assert b.name == "MZ07_B_tool" and b.mass == 1.2 and np.allclose(b.cog, [0, 0, 0.06])
    assert len(write_programs("rapid", full).files) == 2
    # without them: comments, and RAPID names the massless tool
    bare = replace(program_settings(wb.project), close=None, open=None)
    progs = assembly_programs(plan.tasks, wb.assembly.arms, bare)
    texts = [i.text for i in progs[0].instructions if hasattr(i, "text")]
    assert any("no io.gripper" in t for t in texts)
    with pytest.raises(InputError, match="MZ07_B_tool"):
        write_programs("rapid", progs)


@pytest.mark.parametrize("write, read", [(write_rapid, read_rapid), (write_krl, read_krl)])
def test_rapid_and_krl_read_back(planned: tuple, write, read) -> None:  # noqa: ANN001
    wb, _, progs = planned
    for p in progs:
        tool = p.tools[0]
        if tool.mass is None:  # the further robot's tool has no mass in the project
            p = replace(p, tools=(replace(tool, mass=1.0, cog=np.zeros(3)),))
        back = read(write(p).files)
        if write is write_rapid:  # MultiMove: work objects in the shared world (A's base)
            back = in_robot_base(back, p.T_world_base)
        check_read_back(p, back, wb.assembly.arms[p.robot].setup.model)
    both = write_programs(
        "rapid",
        [replace(p, tools=(replace(p.tools[0], mass=1.0, cog=np.zeros(3)),)) for p in progs],
    )
    assert len(both.files) == 2 and all("WaitSyncTask" in t for t in both.files.values())
