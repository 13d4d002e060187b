"""project.touchup: the program's moves as the comparison takes them, and a comparison applied
in each mode (the work object corrected, targets as taught), checked in the work object's
frame against the known correction."""

from __future__ import annotations

import numpy as np
import pytest

from tests.touchup_cell import CORRECTION, ROOT, cell_data, touched_up_files
from workbench.errors import InputError
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.motion.programs.touchup import TaughtTarget, compare
from workbench.project import project_from_dict
from workbench.project.touchup import planned_targets, touched_up_project, work_object_frames
from workbench.project.units import pose_to_matrix
from workbench.service import Workbench

PICK_ALONE = xyz_rpy_to_transform([0.003, 0.0, 0.0], [0.0, 0.0, 0.0])


@pytest.fixture(scope="module")
def compared():
    wb = Workbench.from_dict(cell_data(), base_dir=ROOT / "projects")
    return wb, wb.touchup.compare(touched_up_files("krl", alone=("pick", PICK_ALONE)))


def test_planned_targets_are_the_moves_tcp_poses(compared) -> None:
    wb, _ = compared
    targets = planned_targets(wb.project, wb.robot)
    assert [t.name for t in targets] == [
        "above_left", "pick", "lift", "above_right", "place", "retract", "home"
    ]  # fmt: skip
    assert [t.index for t in targets] == [1, 2, 4, 5, 6, 8, 9]  # actions skipped
    home = targets[-1]  # a joint target: through FK and the tool, as the jog shows it
    np.testing.assert_allclose(home.T_world_tcp, wb.tcp_pose(home.joints), atol=1e-12)
    pick = wb.project.program.moves[2]
    np.testing.assert_allclose(targets[1].T_world_tcp, pose_to_matrix(pick.pose), atol=1e-12)
    assert set(work_object_frames(wb.project)) == {"base", "fixture"}


def _in_fixture(data: dict, k: int) -> np.ndarray:
    project = project_from_dict(data)
    W = pose_to_matrix(project.work_objects[0].pose)
    return np.linalg.solve(W, pose_to_matrix(project.program.moves[k].pose))


@pytest.mark.parametrize("mode", ["work_object", "targets", "both"])
def test_each_mode_moves_the_work_object_and_the_targets_as_it_says(compared, mode) -> None:
    wb, report = compared
    data, notes = touched_up_project(wb.project, report, mode, wb.robot.convention)
    original = wb.project.model_dump(mode="json", exclude_none=True)
    W_old = pose_to_matrix(wb.project.work_objects[0].pose)
    W_new = pose_to_matrix(project_from_dict(data).work_objects[0].pose)
    if mode == "targets":
        np.testing.assert_allclose(W_new, W_old, atol=1e-12)
    else:
        np.testing.assert_allclose(np.linalg.solve(W_old, W_new), CORRECTION, atol=2e-5)
    for k in (1, 2, 4, 5, 6, 8):  # the pose targets in the fixture
        before, after = _in_fixture(original, k), _in_fixture(data, k)
        taught_old = (PICK_ALONE if k == 2 else np.eye(4)) @ CORRECTION @ before  # pendant's
        if mode == "targets":  # the fixture unchanged: where the pendant put it
            want = taught_old
        elif mode == "work_object" and k != 2:  # its coordinates kept in the corrected fixture
            want = before
        else:  # as taught, seen from the corrected fixture (pick: its own 3 mm on top)
            want = np.linalg.solve(CORRECTION, taught_old)
        np.testing.assert_allclose(after, want, atol=2e-5)
    assert data["program"]["moves"][9] == original["program"]["moves"][9]  # home: not moved
    assert any("pick" in n for n in notes)


def test_a_bad_mode_is_refused_by_field(compared) -> None:
    wb, report = compared
    with pytest.raises(InputError, match="mode: 'wobj' is not one of work_object, targets, both"):
        touched_up_project(wb.project, report, "wobj")


def test_moves_in_the_robot_base_are_kept_as_taught_with_a_note() -> None:
    # the shipped MZ07 cell states its targets in the robot base: a shared shift is found but
    # has no work object to go into
    wb = Workbench.open(ROOT / "projects" / "mz07_cell.json")
    planned = planned_targets(wb.project, wb.robot)
    shift = xyz_rpy_to_transform([0.002, 0.0, 0.0], [0.0, 0.0, 0.0])
    taught = [
        TaughtTarget(p.name, p.kind, "base", 1, shift @ p.T_world_tcp, np.zeros(6), True)
        for p in planned
        if p.joints is None  # the pose targets; home (joints) left out: deleted
    ]
    report = compare(planned, taught, work_object_frames(wb.project))
    c = report.correction
    assert c is not None and c.wobj == "base" and c.significant(report.settings)
    data, notes = touched_up_project(wb.project, report, "work_object", wb.robot.convention)
    assert any("no work object to fold it into" in n for n in notes)
    assert any("home: deleted on the pendant" in n for n in notes)
    moved = project_from_dict(data)
    for p in planned[:-1]:
        np.testing.assert_allclose(
            pose_to_matrix(moved.program.moves[p.index].pose), shift @ p.T_world_tcp, atol=1e-9
        )
