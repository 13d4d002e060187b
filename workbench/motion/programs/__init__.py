"""Robot programs: the program model, its construction from a plan, the posts (RAPID, KRL,
FANUC LS, URScript, NACHI) and readers behind one registry, and joint samples (CSV, JSON)."""

from __future__ import annotations

from workbench.motion.programs.exported import (
    ExportedProgram,
    ReadMove,
    ReadProgram,
    ReadTarget,
    merge_exports,
)
from workbench.motion.programs.fanuc import to_ls
from workbench.motion.programs.formats import (
    EXPORT_FORMATS,
    PROGRAM_FORMATS,
    SAMPLE_FORMATS,
    export,
    post,
    reader,
    write_programs,
    write_samples,
)
from workbench.motion.programs.from_plan import motion_program, robot_program
from workbench.motion.programs.krl import to_krl
from workbench.motion.programs.model import (
    Comment,
    Gripper,
    MotionLimits,
    MoveInstr,
    PulseOutput,
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
from workbench.motion.programs.rapid import to_rapid
from workbench.motion.programs.readback import to_robot_program
from workbench.motion.programs.samples import (
    csv_text,
    json_text,
    load_csv,
    load_json,
    save_csv,
    save_json,
)
from workbench.motion.programs.urscript import to_urscript

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
    "export",
    "json_text",
    "load_csv",
    "load_json",
    "merge_exports",
    "motion_program",
    "post",
    "reader",
    "robot_program",
    "save_csv",
    "save_json",
    "to_krl",
    "to_ls",
    "to_rapid",
    "to_robot_program",
    "to_urscript",
    "write_programs",
    "write_samples",
]
