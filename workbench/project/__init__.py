"""The project file: pydantic models (mm, deg), loading with migration, atomic saving."""

from __future__ import annotations

from workbench.project.assembly import AssemblySI, AssemblySpec, AssemblyTaskSI
from workbench.project.bending import BendingSI, BendingSpec, PartSI, PartSpec
from workbench.project.collision import CollisionSpec
from workbench.project.io import (
    atomic_write_text,
    json_schema,
    load_project,
    parse_project_json,
    project_from_dict,
    project_to_json,
    save_project,
)
from workbench.project.models import (
    SCHEMA_VERSION,
    Cell,
    CellObject,
    CellObjectSI,
    DHRow,
    MoveSI,
    MoveSpec,
    Pose,
    ProgramSI,
    ProgramSpec,
    Project,
    Robot,
    RobotSI,
    Tool,
    ToolSI,
)
from workbench.project.polishing import PolishingSI, PolishingSpec
from workbench.project.units import DEG, MM, matrix_to_pose, pose_to_matrix, to_deg, to_mm

__all__ = [
    "DEG",
    "MM",
    "SCHEMA_VERSION",
    "AssemblySI",
    "AssemblySpec",
    "AssemblyTaskSI",
    "BendingSI",
    "BendingSpec",
    "Cell",
    "CellObject",
    "CellObjectSI",
    "CollisionSpec",
    "DHRow",
    "MoveSI",
    "MoveSpec",
    "PartSI",
    "PartSpec",
    "PolishingSI",
    "PolishingSpec",
    "Pose",
    "ProgramSI",
    "ProgramSpec",
    "Project",
    "Robot",
    "RobotSI",
    "Tool",
    "ToolSI",
    "atomic_write_text",
    "json_schema",
    "load_project",
    "matrix_to_pose",
    "parse_project_json",
    "pose_to_matrix",
    "project_from_dict",
    "project_to_json",
    "save_project",
    "to_deg",
    "to_mm",
]
