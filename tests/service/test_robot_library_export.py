"""A small project per library robot exported in its vendor's language and read back (issue 23).

Each project (built here from a dict: the preset, a tool with a TCP offset and load, a work
object, joint and linear moves inside that robot's reach) is exported through
`Workbench.export_program` in the robot's default format, read back with that format's
reader, and every Cartesian target re-solved through tool, work object and the written
configuration data (`check_read_back`, tests/program_round_trip.py, the same twin as
tests/test_program_read_back.py) must give the planned joints. A program in another vendor's
language is refused naming the fix; DH robots export any format.
"""

from __future__ import annotations

import copy

import numpy as np
import pytest
from program_round_trip import check_read_back

from workbench import Workbench, WorkbenchError
from workbench.kinematics.robot_library import LIBRARY, ROBOT_NAMES
from workbench.motion.programs import PROGRAM_FORMATS, reader
from workbench.motion.programs.controller_base import in_model_base

# per robot: work-object origin in the base [mm] (targets lie around it), a joint target in
# the controller's convention [deg] (home with the wrist bent down)
CELLS = {
    "irb1200_7_70": ([420.0, 0.0, 250.0], [0.0, 10.0, 10.0, 0.0, 60.0, 0.0]),
    "kr6_r900_2": ([520.0, 0.0, 300.0], [0.0, -80.0, 80.0, 0.0, 60.0, 0.0]),
    "m10ia": ([900.0, 0.0, 500.0], [0.0, 10.0, -10.0, 0.0, -60.0, 0.0]),
    "ur5e": ([-450.0, -150.0, 250.0], [0.0, -90.0, 90.0, -90.0, -90.0, 0.0]),
    "mz07": ([430.0, 0.0, 400.0], [0.0, 90.0, 0.0, 0.0, -90.0, 0.0]),
}
EXPECTED_FORMAT = {
    "irb1200_7_70": "rapid",
    "kr6_r900_2": "krl",
    "m10ia": "ls",
    "ur5e": "urscript",
    "mz07": "nachi",
}
# FANUC: CR in 1 mm steps; a blended joint move is CNT100 (no radius stated)
CHECK_ARGS = {"ls": {"zone_tol": 1e-3, "joint_zones": False}}


def project(preset: str) -> dict:
    """Return a small project for the library robot `preset`."""
    origin, home = CELLS[preset]
    down = [180.0, 0.0, 0.0]

    def pose(x: float, y: float, z: float, rpy: list[float] = down) -> dict:
        # in the base frame (the move's wobj says the frame the program writes it in)
        return {"xyz": [origin[0] + x, origin[1] + y, origin[2] + z], "rpy": rpy}

    return {
        "schema_version": 2,
        "name": f"{preset} cell",
        "robot": {"name": "arm", "preset": preset, "joints": home},
        "tool": {
            "name": "gripper",
            "tcp": {"xyz": [10.0, 0.0, 120.0], "rpy": [0.0, 0.0, 15.0]},
            "mass": 1.5,
            "cog": [0.0, 0.0, 50.0],
        },
        "work_objects": [{"name": "table", "pose": {"xyz": origin, "rpy": [0.0, 0.0, 20.0]}}],
        "program": {
            "name": "pick_place",
            "moves": [
                {"name": "above_a", "type": "joint", "pose": pose(0, 80, 120), "wobj": "table",
                 "speed": 50, "zone": 10},
                {"name": "a", "type": "linear", "pose": pose(0, 80, 40), "wobj": "table",
                 "speed": 150},
                {"name": "lift", "type": "linear", "pose": pose(20, 60, 120, [170, 10, 30]),
                 "wobj": "table", "speed": 250, "zone": 20},
                {"name": "above_b", "type": "linear", "pose": pose(0, -80, 120), "wobj": "table",
                 "speed": 300, "zone": 20},
                {"name": "b", "type": "linear", "pose": pose(0, -80, 40), "wobj": "table",
                 "speed": 150},
                {"name": "home", "type": "joint", "joints": home, "speed": 60},
            ],
        },
    }  # fmt: skip


@pytest.mark.parametrize("preset", ROBOT_NAMES)
def test_export_in_the_vendors_language_reads_back(preset: str) -> None:
    wb = Workbench.from_dict(project(preset))
    fmt = wb.default_program_format()
    assert fmt == EXPECTED_FORMAT[preset] == LIBRARY[preset].program_format
    plan = wb.plan_motion()
    assert plan.ok, plan.summary()
    exported = wb.export_program(fmt)
    (program,) = wb.robot_programs("motion")
    # the files state work objects in the controller's base (FANUC: world at J2 height)
    read = in_model_base(reader(fmt)(dict(exported.files)), LIBRARY[preset].T_base_controller)
    signals_by = "name" if fmt == "rapid" else "number"
    check_read_back(
        program, read, wb.robot, signals_by=signals_by, check_durations=False,
        check_speeds=False, **CHECK_ARGS.get(fmt, {}),
    )  # fmt: skip
    # the joint targets are written in the controller's convention
    assert wb.robot.convention is LIBRARY[preset].convention


@pytest.mark.parametrize("preset", ["irb1200_7_70", "kr6_r900_2", "m10ia", "ur5e", "mz07"])
def test_another_vendors_language_is_refused_naming_the_fix(preset: str) -> None:
    wb = Workbench.from_dict(project(preset))
    own = LIBRARY[preset].program_format
    foreign = next(f for f in PROGRAM_FORMATS if f != own)
    with pytest.raises(WorkbenchError) as err:
        wb.export_program(foreign)
    msg = str(err.value)
    assert LIBRARY[preset].title in msg and LIBRARY[preset].vendor in msg
    assert repr(own) in msg and "any_vendor=True" in msg and "--any-vendor" in msg
    # explicitly allowed, it is written; samples are never refused
    assert wb.export_program(foreign, any_vendor=True).files
    assert wb.export_program("csv").files


def test_dh_robots_have_no_vendor_and_export_any_format() -> None:
    data = project("mz07")
    rows = np.array(LIBRARY["mz07"].dh)
    lim = np.degrees(LIBRARY["mz07"].model_limits)
    data["robot"] = {
        "name": "arm",
        "dh": [
            {"theta_offset": float(np.degrees(r[0])), "d": float(r[1] * 1000),
             "a": float(r[2] * 1000), "alpha": float(np.degrees(r[3])),
             "min": float(lo), "max": float(hi)}
            for r, (lo, hi) in zip(rows, lim, strict=True)
        ],
        "joints": [0.0, 0.0, 0.0, 0.0, -90.0, 0.0],
    }  # fmt: skip
    data["program"]["moves"][-1]["joints"] = [0.0, 0.0, 0.0, 0.0, -90.0, 0.0]
    wb = Workbench.from_dict(data)
    assert wb.default_program_format() is None
    for fmt in PROGRAM_FORMATS:
        assert wb.export_program(fmt, force=True).files


def test_an_unknown_preset_lists_the_library() -> None:
    data = copy.deepcopy(project("mz07"))
    data["robot"]["preset"] = "irb6700"
    with pytest.raises(WorkbenchError) as err:
        Workbench.from_dict(data)
    for name in ROBOT_NAMES:
        assert name in str(err.value)


def test_fanuc_frames_are_stated_in_its_world_frame_at_j2_height() -> None:
    wb = Workbench.from_dict(project("m10ia"))
    text = wb.export_program("ls").text
    # the table lies 500 mm above the robot's foot, 50 mm above FANUC's world (450 mm up)
    assert "PR[90,3]=50" in text.replace(" ", ""), text[:2000]


def test_fanuc_joints_are_checked_against_its_coupled_j3_limits() -> None:
    data = project("m10ia")
    data["robot"]["joints"] = [0.0, -80.0, 250.0, 0.0, -60.0, 0.0]  # J3 in range, J2 + J3 in box
    Workbench.from_dict(data)
    data["robot"]["joints"] = [0.0, 100.0, -200.0, 0.0, -60.0, 0.0]  # J3 below -180 deg
    with pytest.raises(WorkbenchError, match=r"robot.joints\[2\]: -200.000 deg is outside"):
        Workbench.from_dict(data)
