"""The exception hierarchy of the workbench: every domain error is a `WorkbenchError`.

Messages say what was given and what is allowed, and name the field (a JSON path such
as ``cell.objects[2].pose.xyz``) where the input came from a project file.
"""

from __future__ import annotations


class WorkbenchError(Exception):
    """Base of all errors the workbench raises on bad input or impossible requests."""


class InputError(WorkbenchError, ValueError):
    """An argument has the wrong shape, type or value (NaN, out of range, ...)."""


class ProjectError(WorkbenchError):
    """A project file or dict is malformed. `problems` lists ``(field, message)`` pairs."""

    def __init__(self, message: str, problems: list[tuple[str, str]] | None = None) -> None:
        super().__init__(message)
        self.problems: list[tuple[str, str]] = list(problems or [])


class SchemaVersionError(ProjectError):
    """The project file was written by a schema version this build cannot read."""


class MeshError(WorkbenchError):
    """A mesh file is missing, unreadable, empty or unusable."""


class KinematicsError(WorkbenchError):
    """Base of kinematic failures."""


class UnreachableError(KinematicsError):
    """A pose has no inverse-kinematics solution within the joint limits."""


class JointLimitError(KinematicsError):
    """A joint configuration lies outside the robot's joint limits."""


class PlanningError(WorkbenchError):
    """A planner or trajectory generator could not produce a valid motion."""


class CollisionError(WorkbenchError):
    """A requested state or motion is in collision where it must not be."""


class ServerError(WorkbenchError):
    """The GUI server could not start (port busy, bad host)."""
