"""The project file: pydantic models (mm, deg), loading with migration, atomic saving."""

from __future__ import annotations

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
    DHRow,
    Pose,
    Project,
    Robot,
    Tool,
)

__all__ = [
    "SCHEMA_VERSION",
    "Cell",
    "CellObject",
    "DHRow",
    "Pose",
    "Project",
    "Robot",
    "Tool",
    "atomic_write_text",
    "json_schema",
    "load_project",
    "parse_project_json",
    "project_from_dict",
    "project_to_json",
    "save_project",
]
