"""Robot programs: the program model, its construction from a plan, the posts (RAPID, KRL,
FANUC LS, URScript, NACHI) and readers behind one registry, and joint samples (CSV, JSON)."""

from __future__ import annotations

from workbench.motion.programs.controller_program import (
    Comment,
    Gripper,
    MotionLimits,
    MoveInstr,
    PulseOutput,
    ReadMove,
    ReadProgram,
    ReadTarget,
    RobotProgram,
    SetOutput,
    Signal,
    SyncPoint,
    Target,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
    check_program,
)
from workbench.motion.programs.exported import ExportedProgram, merge_exports
from workbench.motion.programs.formats import (
    EXPORT_FORMATS,
    PROGRAM_FORMATS,
    SAMPLE_FORMATS,
    post,
    reader,
    write_programs,
    write_samples,
)
from workbench.motion.programs.from_plan import robot_program
from workbench.motion.programs.readback import to_robot_program
from workbench.motion.programs.samples import (
    csv_text,
    json_text,
    load_csv,
    load_json,
    save_csv,
    save_json,
)

__all__ = [
    "EXPORT_FORMATS",
    "PROGRAM_FORMATS",
    "SAMPLE_FORMATS",
    "Comment",
    "ExportedProgram",
    "Gripper",
    "MotionLimits",
    "MoveInstr",
    "PulseOutput",
    "ReadMove",
    "ReadProgram",
    "ReadTarget",
    "RobotProgram",
    "SetOutput",
    "Signal",
    "SyncPoint",
    "Target",
    "ToolData",
    "WaitInput",
    "WaitTime",
    "WorkObject",
    "check_program",
    "csv_text",
    "json_text",
    "load_csv",
    "load_json",
    "merge_exports",
    "post",
    "reader",
    "robot_program",
    "save_csv",
    "save_json",
    "to_robot_program",
    "write_programs",
    "write_samples",
]
