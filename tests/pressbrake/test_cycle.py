"""The planned and checked press-brake cycle (`pressbrake.cycle.check_cycle`).

Twins: frame by frame, the part's pose is recomputed from the pieces without the cycle's
frame loop: where it rests, the phase's pose; carried, the robot's TCP by forward
kinematics (`model.fk`) times the grasp on the part folded to the frame's step; bent, the
die's pose of the part (`bend_pose`), and the following robot's stray from its grasp by
forward kinematics again. The punch stands open outside bends; the frames hold every
waypoint's time; the first problem is None exactly when no frame collides.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.geometry.transforms import invert_transform
from workbench.pressbrake.bend_setup import bend_pose
from workbench.pressbrake.cycle import BendingCycle
from workbench.pressbrake.cycle_path import T_part_tcp
from workbench.service.bending_process import cycle_cell, plan_cycle
from workbench.sheetmetal.folding import fold_state

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def planned() -> tuple[Workbench, BendingCycle]:
    wb = Workbench.open(ROOT / "projects" / "u_channel_cell.json")
    return wb, plan_cycle(wb.bending)


@pytest.mark.slow
def test_every_frames_part_pose_is_the_pieces_put_together(planned) -> None:
    wb, cyc = planned
    part, steps, path, frames = cyc.part, cyc.steps, cyc.path, cyc.frames
    press = cycle_cell(wb.bending).press
    setup = wb.setup
    T_tcp = setup.T_world_base @ wb.robot.fk(frames.joints) @ setup.T_flange_tcp
    kinds = set()
    for n in range(len(frames.times)):
        phase = path.phases[int(frames.phase[n])]
        kinds.add(phase.kind)
        s = float(frames.step[n])
        state = fold_state(part, s, check=False)
        if phase.kind == "rest":
            expected = phase.T_world_part
        elif phase.kind == "bend":
            k = phase.bend
            on_die = bend_pose(state, k, steps[k].grasp, press, press.station(phase.station))
            expected = press.T_world_die @ on_die.T_die_part
            grip = expected @ T_part_tcp(part, steps[k].grasp, s)
            stray = np.linalg.norm(grip[:3, 3] - T_tcp[n][:3, 3])
            assert frames.follow_error[n] == pytest.approx(stray, abs=1e-9)
        else:
            grasp = phase.grasp or steps[min(int(np.floor(s + 1e-9)), len(steps) - 1)].grasp
            expected = T_tcp[n] @ invert_transform(T_part_tcp(part, grasp, s))
            assert frames.punch_z[n] == pytest.approx(press.ram.open + part.thickness)
        np.testing.assert_allclose(frames.T_world_part[n], expected, atol=1e-9)
    assert kinds == {"rest", "carried", "bend"}
    assert np.all(np.diff(frames.step) >= -1e-12)  # the part only ever folds further
    arrivals = np.asarray(cyc.trajectory.waypoint_times, float)
    assert np.all(np.isin(arrivals, frames.times))
    assert (cyc.first_problem is None) == (not cyc.colliding.any())
