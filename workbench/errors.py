"""The exception hierarchy of the workbench: every domain error is a `WorkbenchError`.

Messages say what was given and what is allowed, and name the field (a JSON path such
as ``cell.objects[2].pose.xyz``) where the input came from a project file. The field is
data, not text: an error keeps it as `WorkbenchError.field` and its message without it as
`WorkbenchError.detail`, and ``str(exc)`` is built from the two (``"field: detail"``). A
caller that knows where the input sat re-roots the error with `WorkbenchError.within`
instead of editing its text.
"""

from __future__ import annotations

from typing import Self


def join_field(prefix: str, field: str | None) -> str:
    """Return the JSON path of `field` (or of nothing: `prefix`) under `prefix`.

    ``join_field("polishing", "units")`` is ``"polishing.units"``; an index joins without a
    dot (``join_field("cell.objects", "[2].pose")`` is ``"cell.objects[2].pose"``).
    """
    if not field:
        return prefix
    return f"{prefix}{field}" if field.startswith("[") else f"{prefix}.{field}"


class WorkbenchError(Exception):
    """Base of all errors the workbench raises on bad input or impossible requests.

    `field` is the JSON path of the input at fault (None: none in particular), `detail` the
    message without it; ``str(exc)`` is ``f"{field}: {detail}"`` (only `detail` without a field).
    """

    def __init__(self, message: str = "", *, field: str | None = None) -> None:
        self.field: str | None = field or None
        self.detail: str = message
        super().__init__(self._text())

    def _text(self) -> str:
        return f"{self.field}: {self.detail}" if self.field else self.detail

    def __str__(self) -> str:
        return self._text()

    def within(self, prefix: str) -> Self:
        """Return this error re-rooted under `prefix`: the same class, detail and data, the
        field ``prefix.field`` (`prefix` when it had none); its cause is this error.

        The text is built, never edited: ``raise exc.within("polishing") from exc`` where the
        caller knows the input sat under ``polishing``; the traceback shows the original raise
        as the cause.
        """
        cls = type(self)
        out = cls.__new__(cls)
        out.__dict__.update(self.__dict__)
        out._reroot(prefix)
        out.args = (out._text(),)
        out.__cause__ = self
        return out

    def _reroot(self, prefix: str) -> None:
        self.field = join_field(prefix, self.field)


class InputError(WorkbenchError, ValueError):
    """An argument has the wrong shape, type or value (NaN, out of range, ...)."""


class ProjectError(WorkbenchError):
    """A project file or dict is malformed. `problems` lists ``(field, message)`` pairs.

    Without `problems`, an error with a `field` has the one problem ``(field, detail)``;
    `within` re-roots every problem's field with the error's (``(top level)`` becomes the
    prefix; ``(file)``, the file as a whole, stays).
    """

    def __init__(
        self,
        message: str = "",
        problems: list[tuple[str, str]] | None = None,
        *,
        field: str | None = None,
    ) -> None:
        super().__init__(message, field=field)
        if problems is None and self.field is not None:
            problems = [(self.field, self.detail)]
        self.problems: list[tuple[str, str]] = list(problems or [])

    @classmethod
    def of(cls, exc: WorkbenchError) -> ProjectError:
        """Return `exc` as a ProjectError: its field and detail, and the one problem
        ``(field, detail)`` when it has a field (re-root it first: ``exc.within(...)``)."""
        return cls(exc.detail, field=exc.field)

    def _reroot(self, prefix: str) -> None:
        super()._reroot(prefix)
        self.problems = [
            (
                path
                if path == "(file)"
                else join_field(prefix, None if path == "(top level)" else path),
                msg,
            )
            for path, msg in self.problems
        ]


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


class PlanLimitError(PlanningError):
    """A plan ended by its time limit (`field`: the setting) or by cancel (`cancelled`).

    Never caught as a verdict: a planner that turns a PlanningError into "no path here"
    re-raises this one, so a limit ends the plan instead of changing it. Its field is the
    setting's path at the project's top level, kept when a caller re-roots it (`within`)."""

    def __init__(self, message: str = "", *, field: str | None = None, cancelled: bool = False):
        super().__init__(message, field=field)
        self.cancelled = cancelled

    def _reroot(self, prefix: str) -> None:
        if self.field is None:
            super()._reroot(prefix)


class CollisionError(WorkbenchError):
    """A requested state or motion is in collision where it must not be."""


class ServerError(WorkbenchError):
    """The GUI server could not start (port busy, bad host)."""
