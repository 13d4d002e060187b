"""Readings files: the two headers, units and the joint convention, and every error naming the
file, line and column with what to give."""

from __future__ import annotations

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.kinematics.robot_library import library_robot
from workbench.project.calibration_readings import parse_known, parse_readings, work_object_name
from workbench.project.models import Robot

MZ07 = Robot(preset="mz07")
FANUC = Robot(preset="m10ia")


def _parse(text: str, robot: Robot = MZ07) -> object:
    return parse_readings(text, source="r.csv", robot=robot, dof=6)


def test_joints_go_through_the_controllers_convention() -> None:
    text = "# a comment\nlabel,j1,j2,j3,j4,j5,j6\n\np1, 10, 20, 30, 40, 50, 60\np2,0,0,0,0,0,0\n"
    for robot in (MZ07, FANUC):
        r = _parse(text, robot)
        conv = library_robot(robot.preset or "").convention
        expected = conv.to_model(np.radians([[10, 20, 30, 40, 50, 60], [0, 0, 0, 0, 0, 0]]))
        assert r.kind == "joints" and r.labels == ("p1", "p2") and r.lines == (4, 5)
        assert np.allclose(r.joints, expected)
    fanuc = _parse(text, FANUC).joints
    assert not np.allclose(fanuc[0], np.radians([10, 20, 30, 40, 50, 60]))  # J2/J3 coupled


def test_points_are_millimetres_in_metres_and_the_header_is_case_blind() -> None:
    r = _parse("\ufeffLabel,X,Y,Z\r\norigin,400,0,100.5\r\n")  # a spreadsheet's BOM and CRLF
    assert r.kind == "points" and np.allclose(r.points, [[0.4, 0.0, 0.1005]])
    labels, pts = parse_known("label,x,y,z\na,1,2,3\n", source="k.csv")
    assert labels == ("a",) and np.allclose(pts, [[0.001, 0.002, 0.003]])


@pytest.mark.parametrize(
    ("text", "field", "detail"),
    [
        ("label,a,b\np,1,2\n", "r.csv line 1", "give label,j1,j2,j3,j4,j5,j6"),
        ("label;x;y;z\np;1;2;3\n", "r.csv line 1", "by commas, not ';'"),
        ("label,j1,j2,j3,j4,j5\np,1,2,3,4,5\n", "r.csv line 1", "robot has 6 joints"),
        ("label,x,y,z\np,1,2\n", "r.csv line 2", "2 values after the label but the header names 3"),
        ("label,x,y,z\np,1,nan,3\n", "r.csv line 2, column 3 (y)", "'nan' is not a finite"),
        ("label,x,y,z\np,1,abc,3\n", "r.csv line 2, column 3 (y)", "'abc' is not a finite number"),
        ("label,x,y,z\np,1,,3\n", "r.csv line 2, column 3 (y)", "empty; give a number [mm]"),
        ("label,x,y,z\n,1,2,3\n", "r.csv line 2, column 1 (label)", "empty label"),
        ("label,x,y,z\np,1,2,3\n\np,4,5,6\n", "r.csv line 4, column 1 (label)", "also on line 2"),
        ("label,x,y,z\n", "r.csv", "no readings after the header"),
        ("\n# only a comment\n", "r.csv", "the file is empty"),
        ("label,j1,j2,j3,j4,j5,j6\np,1,2,3,4,5,inf\n", "r.csv line 2, column 7 (j6)", "[deg]"),
    ],
)
def test_errors_name_the_file_line_and_column(text: str, field: str, detail: str) -> None:
    with pytest.raises(InputError) as err:
        _parse(text)
    assert err.value.field == field
    assert detail in err.value.detail


def test_known_points_refuse_joints() -> None:
    with pytest.raises(InputError, match="label,x,y,z") as err:
        parse_known("label,j1,j2,j3\na,1,2,3\n", source="k.csv")
    assert err.value.field == "k.csv line 1"


def test_work_object_names_are_checked() -> None:
    assert work_object_name("fixture 2") == "fixture 2"
    for bad, detail in (("base", "is the robot base"), ("", "1 to 64"), ("a\tb", "printable")):
        with pytest.raises(InputError, match=detail) as err:
            work_object_name(bad)
        assert err.value.field == "work object name"


def test_joints_outside_the_robots_range_are_noted_not_refused() -> None:
    # Readings of a real robot lie within its ranges: one outside says the project's robot (or
    # its convention) is not the one measured. Noted in the summary, not refused: a range in
    # the library may be an estimate.
    lo, hi = library_robot("mz07").controller_limits_deg[1]
    text = f"label,j1,j2,j3,j4,j5,j6\np1,0,{hi + 5},0,0,0,0\np2,0,{lo + 1},0,0,0,0\n"
    r = _parse(text)
    assert len(r.notes) == 1 and r.notes[0].startswith(f"r.csv line 2: p1 j2 = {hi + 5:.3f} deg")
    assert r.joints.shape == (2, 6)
