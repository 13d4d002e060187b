"""The press-brake cycle's waypoints and phases (`pressbrake.cycle_path.cycle_path`).

Twins: the poses where the gripper and the press act (the pick, the stop at the back-gauge,
the end of each bend, the put-down on the pallet) are recomputed from the pieces
(`fold_state`, `bend_pose`, `T_part_tcp`) without the path builder; the regrips are counted
from the steps' grasps; each bend's following segments last the ram's time for the bend's
depth; every straight move near the die and the tables is split every `line_step` or less.
"""

from __future__ import annotations

import dataclasses
import itertools
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.pressbrake.bend_setup import bend_pose
from workbench.pressbrake.cycle_path import CycleCell, CycleStep, T_part_tcp, cycle_path
from workbench.pressbrake.grasp import Grasp
from workbench.service.bending_process import cycle_cell, cycle_steps
from workbench.sheetmetal.folding import fold_state
from workbench.sheetmetal.part import SheetMetalPart

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def pan() -> tuple[SheetMetalPart, list[CycleStep], CycleCell]:
    """Return the pan cell's part, steps (a regrip between its first two bends) and cell."""
    svc = Workbench.open(ROOT / "projects" / "pan_cell.json").bending
    return svc.part, cycle_steps(svc), cycle_cell(svc)


def _same_grasp(a: Grasp, b: Grasp) -> bool:
    off = [None if g.offset is None else np.round(g.offset, 9).tolist() for g in (a, b)]
    return (a.flange, off[0], round(a.yaw, 9), a.face) == (
        b.flange,
        off[1],
        round(b.yaw, 9),
        b.face,
    )


def _tcp_on_die(part: SheetMetalPart, cell: CycleCell, st: CycleStep, k: int, f: float):
    """Return the TCP (world) of step k's grasp with bend k at fraction f on the die."""
    press = cell.press
    state = fold_state(part, k + f, check=False)
    on_die = bend_pose(state, k, st.grasp, press, press.station(st.station))
    return press.T_world_die @ on_die.T_die_part @ T_part_tcp(part, st.grasp, k + f)


@pytest.mark.parametrize("follow", [True, False])
def test_the_acting_poses_are_the_pieces_put_together(pan, follow: bool) -> None:
    part, steps, cell = pan
    cell = dataclasses.replace(cell, follow=follow)
    path = cycle_path(part, steps, cell)
    by_label = {w.label: w for w in path.waypoints}
    assert path.waypoints[0].label == path.waypoints[-1].label == "home"
    pick = by_label["pick the blank"]
    np.testing.assert_allclose(
        pick.T_world_tcp, cell.T_world_blank @ T_part_tcp(part, steps[0].grasp, 0), atol=1e-12
    )
    assert (pick.action, pick.hold) == ("grip", cell.settle)
    for k, st in enumerate(steps):
        stop = by_label[f"bend {st.bend!r} against the back-gauge"]
        np.testing.assert_allclose(stop.T_world_tcp, _tcp_on_die(part, cell, st, k, 0.0), atol=1e-9)
        assert stop.action == ("press_close" if follow else "release")
        end = path.waypoints[next(p.end for p in path.phases if p.kind == "bend" and p.bend == k)]
        np.testing.assert_allclose(end.T_world_tcp, _tcp_on_die(part, cell, st, k, 1.0), atol=1e-9)
        assert end.action == ("press_open" if follow else "grip")
    drop = by_label["put the part on the pallet"]
    nb = len(part.bends)
    np.testing.assert_allclose(
        drop.T_world_tcp, cell.T_world_pallet @ T_part_tcp(part, steps[-1].grasp, nb), atol=1e-12
    )
    changes = sum(not _same_grasp(a.grasp, b.grasp) for a, b in itertools.pairwise(steps))
    assert changes > 0  # the example regrips
    puts = [w for w in path.waypoints if w.label == "put the part on the regrip station"]
    assert len(puts) == changes
    kinds = [p.kind for p in path.phases]
    assert kinds.count("bend") == nb and kinds.count("rest") == 2 + changes
    assert [p.start for p in path.phases] == sorted(p.start for p in path.phases)


def test_each_bend_lasts_the_rams_time_and_straight_moves_are_split(pan) -> None:
    part, steps, cell = pan
    path = cycle_path(part, steps, cell)
    ram = cell.press.ram
    for k, st in enumerate(steps):
        phase = next(p for p in path.phases if p.kind == "bend" and p.bend == k)
        seconds = sum(w.bend_time for w in path.waypoints[phase.start + 1 : phase.end + 1])
        state = fold_state(part, k + 1.0, check=False)
        depth = bend_pose(state, k, st.grasp, cell.press, cell.press.station(st.station)).depth
        assert seconds == pytest.approx(depth / ram.bending_speed, rel=1e-9)
        assert len(path.bend_poses[k]) == cell.follow_steps + 1
    # the numbered waypoints of a straight move: no step longer than line_step
    for a, b in itertools.pairwise(path.waypoints):
        if b.label.endswith(")") and a.T_world_tcp is not None and b.T_world_tcp is not None:
            step = np.linalg.norm(b.T_world_tcp[:3, 3] - a.T_world_tcp[:3, 3])
            assert step <= cell.line_step + 1e-9, (a.label, b.label, step)


def test_steps_out_of_sequence_order_are_an_input_error(pan) -> None:
    part, steps, cell = pan
    from workbench.errors import InputError

    with pytest.raises(InputError, match="steps: expected one per bend in sequence order"):
        cycle_path(part, steps[::-1], cell)
