"""wb.touchup: a program touched up on the pendant (the fixture moved by a known transform,
every target re-taught, the controller's work object unchanged) read back in every format the
workbench writes, compared with the project's, fitted and applied."""

from __future__ import annotations

import numpy as np
import pytest

from tests.touchup_cell import CORRECTION, ROOT, WOBJ, cell_data, moved_data, touched_up_files
from workbench.errors import InputError
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.kinematics.robot_library import ROBOT_NAMES, library_robot
from workbench.motion.programs.formats import PROGRAM_FORMATS
from workbench.service import Workbench

# the printed precision of the posts (RAPID: 8 significant digits of mm, quaternions to 1e-9;
# KRL, LS: 1e-6 mm and deg; URScript joints 1e-9 rad, NACHI 1e-6 deg, through FK) is far
# within these
POSITION_TOL = 0.02e-3
ANGLE_TOL = np.radians(0.005)
PICK_ALONE = xyz_rpy_to_transform([0.003, 0.0, 0.0], [0.0, 0.0, 0.0])
MOVED = ("above_left", "pick", "lift", "above_right", "place", "retract")


def _wb() -> Workbench:
    return Workbench.from_dict(cell_data(), base_dir=ROOT / "projects")


@pytest.fixture(scope="module")
def cell() -> Workbench:
    """The cell as the project has it; `compare` never changes it (checked below)."""
    return _wb()


def _close(T: np.ndarray, T_ref: np.ndarray) -> None:
    assert np.linalg.norm(T[:3, 3] - T_ref[:3, 3]) < POSITION_TOL
    c = (np.trace(T[:3, :3].T @ T_ref[:3, :3]) - 1.0) / 2.0
    assert np.arccos(np.clip(c, -1.0, 1.0)) < ANGLE_TOL


@pytest.mark.parametrize("fmt", PROGRAM_FORMATS)
def test_the_fitted_correction_is_the_fixtures_move(fmt: str, cell: Workbench) -> None:
    wb = cell
    before = wb.to_json()
    report = wb.touchup.compare(touched_up_files(fmt))
    c = report.correction
    assert c is not None and c.wobj == WOBJ and c.fitted
    _close(c.T_correction, CORRECTION)
    assert c.outliers == () and c.max < POSITION_TOL
    assert [r.name for r in report.rows if r.moved] == list(MOVED)
    assert all(report.row(n).agrees for n in MOVED)
    assert report.row("home").status == "same"
    assert wb.to_json() == before  # comparing changes nothing
    assert report.notes == ()  # the controller's work object and tool are the project's
    assert "work object fixture: correction [2.100, -1.400, 0.900] mm" in report.summary()


@pytest.mark.parametrize("fmt", PROGRAM_FORMATS)
def test_a_target_moved_alone_is_named_not_folded_in(fmt: str, cell: Workbench) -> None:
    report = cell.touchup.compare(touched_up_files(fmt, alone=("pick", PICK_ALONE)))
    c = report.correction
    assert c is not None and c.outliers == ("pick",)
    _close(c.T_correction, CORRECTION)  # the others still give the fixture's move
    pick = report.row("pick")
    assert pick.moved and pick.agrees is False
    assert "moved alone (not folded into fixture): pick" in report.summary()


@pytest.mark.parametrize("fmt", ["rapid", "nachi"])  # names kept; NACHI: matched in order too
def test_moves_deleted_and_added_on_the_pendant_are_reported_not_mismatched(
    fmt: str, cell: Workbench
) -> None:
    extra = xyz_rpy_to_transform([0.0, 0.04, -0.02], [0.0, 0.0, 0.0])
    files = touched_up_files(fmt, delete="lift", add=("over_place", "above_right", extra))
    report = cell.touchup.compare(files)
    status = {r.name: r.status for r in report.rows}
    assert status["lift"] == "deleted"
    added = [r for r in report.rows if r.status == "added"]
    assert len(added) == 1 and added[0].taught is not None
    paired = [r for r in report.rows if r.planned is not None and r.taught is not None]
    assert [r.name for r in paired] == [
        "above_left",
        "pick",
        "above_right",
        "place",
        "retract",
        "home",
    ]
    c = report.correction
    assert c is not None and c.outliers == ()
    _close(c.T_correction, CORRECTION)


def test_a_program_as_the_project_has_it_moves_nothing() -> None:
    wb = Workbench.from_dict(moved_data(cell_data()), base_dir=ROOT / "projects")
    report = wb.touchup.compare(touched_up_files("krl"))  # the moved cell's own targets
    assert not any(r.moved for r in report.rows)
    assert "none moved" in report.summary()


def test_apply_save_and_reopen_give_the_corrected_work_object_and_the_original_targets(
    tmp_path,
) -> None:
    wb = _wb()
    original = wb.project.model_copy(deep=True)
    report = wb.touchup.compare(touched_up_files("rapid", alone=("pick", PICK_ALONE)))
    previous = wb.touchup.apply(report, mode="work_object", plan=False)
    assert previous.model_dump() == original.model_dump()  # the undo
    path = wb.save(tmp_path / "touched.json")
    again = Workbench.open(path).project
    W_old = _matrix(original.work_objects[0].pose)
    W_new = _matrix(again.work_objects[0].pose)
    _close(np.linalg.inv(W_old) @ W_new, CORRECTION)
    for old, new in zip(original.program.moves, again.program.moves, strict=True):
        if getattr(old, "pose", None) is None:
            assert new.model_dump() == old.model_dump()
            continue
        in_old = np.linalg.inv(W_old) @ _matrix(old.pose)
        in_new = np.linalg.inv(W_new) @ _matrix(new.pose)
        if old.name == "pick":  # kept as taught: its own 3 mm on top of the fixture's move
            _close(np.linalg.inv(W_old) @ _matrix(new.pose), PICK_ALONE @ CORRECTION @ in_old)
        else:  # the original target, in the corrected work object
            np.testing.assert_allclose(in_new, in_old, atol=1e-9)


def test_apply_targets_keeps_the_work_object_and_takes_every_taught_target() -> None:
    wb = _wb()
    report = wb.touchup.compare(touched_up_files("ls"))
    wb.touchup.apply(report, mode="targets", plan=False)
    assert wb.project.work_objects[0].pose.xyz == [430.0, 0.0, 440.0]
    again = wb.touchup.compare(touched_up_files("ls"))
    assert not any(r.moved for r in again.rows)  # the project is now what the pendant taught


def test_malformed_input_names_the_file_and_the_fix(cell: Workbench) -> None:
    wb = cell
    with pytest.raises(InputError, match=r"broken\.mod.*no moves the reader understood"):
        wb.touchup.compare({"broken.mod": "MODULE x\n  PROC main()\n  ENDPROC\nENDMODULE\n"})
    with pytest.raises(InputError, match="no program file given"):
        wb.touchup.compare({})
    with pytest.raises(InputError, match=r"broken\.ls.*check that it is a ls program"):
        wb.touchup.compare({"broken.ls": "/PROG BROKEN\n/MN\n   1:  J P[7] 50% FINE ;\n/END\n"})
    empty = cell_data()
    del empty["program"]
    with pytest.raises(InputError, match="no program moves to compare with"):
        Workbench.from_dict(empty).touchup.compare(touched_up_files("krl"))
    with pytest.raises(InputError, match="mode"):
        wb.touchup.apply(wb.touchup.compare(touched_up_files("krl")), mode="wobj")


def _matrix(pose) -> np.ndarray:
    from workbench.project.units import pose_to_matrix

    return pose_to_matrix(pose)


@pytest.mark.slow
def test_apply_plans_again_and_checks_collisions() -> None:
    wb = _wb()
    report = wb.touchup.compare(touched_up_files("nachi", alone=("pick", PICK_ALONE)))
    wb.touchup.apply(report, mode="work_object")
    applied = wb.touchup.last_applied
    assert applied is not None and applied.plan is not None and applied.plan.ok
    assert wb.last_plan is applied.plan
    assert "collision-free" in applied.summary()


@pytest.mark.parametrize("fmt", ["krl", "urscript"])
def test_a_joint_target_re_taught_is_compared_through_fk_and_kept_as_taught(fmt: str) -> None:
    wb = _wb()
    dq = np.radians([1.0, -0.5, 0.0, 0.0, 0.3, 0.0])
    report = wb.touchup.compare(touched_up_files(fmt, joints=("home", dq)))
    home = report.row("home")
    assert home.moved and home.wobj == "base" and home.agrees is None  # alone in the base
    want = wb.tcp_pose(wb.robot.convention.to_model(np.radians([0, 90, 0, 0, -90, 0])) + dq)
    np.testing.assert_allclose(home.taught.T_world_tcp, want, atol=1e-5)  # type: ignore[union-attr]
    wb.touchup.apply(report, mode="work_object", plan=False)
    taught = wb.robot.convention.to_controller(home.taught.q)  # type: ignore[union-attr]
    home_move = wb.project.program.moves[-1]  # type: ignore[union-attr]
    np.testing.assert_allclose(np.radians(home_move.joints), taught, atol=1e-9)
    with pytest.raises(InputError, match="compare the program again"):
        wb.touchup.apply(report, mode="targets", plan=False)  # the project changed since


def test_a_program_without_its_names_is_matched_in_order(cell: Workbench) -> None:
    # the NACHI program with its comments dropped (a pendant that keeps none): the moves by
    # order and distance, the deleted one still found
    ((name, text),) = touched_up_files("nachi", delete="lift").items()
    bare = "\n".join(line for line in text.splitlines() if not line.startswith("'"))
    report = cell.touchup.compare({name: bare + "\n"})
    assert [r.status for r in report.rows].count("deleted") == 1
    paired = [r for r in report.rows if r.planned is not None and r.taught is not None]
    assert [r.planned.name for r in paired] == [  # type: ignore[union-attr]
        "above_left", "pick", "above_right", "place", "retract", "home"
    ]  # fmt: skip
    c = report.correction
    assert c is not None and c.outliers == ()
    _close(c.T_correction, CORRECTION)


@pytest.mark.slow  # a workbench per robot (about 0.5 s each)
@pytest.mark.parametrize("preset", ROBOT_NAMES)
def test_every_library_robot_in_its_own_language(preset: str) -> None:
    # the vendor's base convention too (FANUC's world at J2 height: in_model_base)
    fmt = library_robot(preset).program_format
    files = touched_up_files(fmt, preset=preset, alone=("pick", PICK_ALONE))
    wb = Workbench.from_dict(cell_data(preset), base_dir=ROOT / "projects")
    report = wb.touchup.compare(files)
    assert report.fmt == fmt and report.notes == ()
    c = report.correction
    assert c is not None and c.outliers == ("pick",)
    _close(c.T_correction, CORRECTION)
