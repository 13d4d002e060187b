"""Loading (parse, migrate, validate) and atomic saving of project files."""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from workbench.atomic_file import atomic_write_text
from workbench.errors import InputError, ProjectError, SchemaVersionError
from workbench.project.bounds import JSON_MAX_DEPTH
from workbench.project.migrate import v1_to_v2
from workbench.project.models import SCHEMA_VERSION, Project
from workbench.project.paths import read_regular_file

# Migrations from version N to N + 1, applied in order on the parsed JSON.
MIGRATIONS: dict[int, Callable[[dict[str, Any]], dict[str, Any]]] = {
    1: v1_to_v2,  # joint values from the kinematic model's convention to the controller's
}


def field_path(loc: tuple[int | str, ...]) -> str:
    """Return a JSON path such as ``cell.objects[2].pose.xyz`` for a pydantic error location."""
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        elif str(part).startswith(("function-after", "function-before", "item:")):
            continue
        else:
            out += ("." if out else "") + str(part)
    return out or "(top level)"


def _message(err: dict[str, Any]) -> str:
    raised = err.get("ctx", {}).get("error")  # what a validator raised, as it said it
    is_raised = err["type"] in ("value_error", "assertion_error") and raised is not None
    msg = str(raised) if is_raised else str(err["msg"])
    if err["type"] == "extra_forbidden":
        msg = "unknown field; remove it or check its spelling"
    elif err["type"] == "finite_number":
        msg = "must be a finite number (NaN and infinity are not allowed)"
    elif err["type"] == "missing":
        msg = "required field is missing"
    elif err["type"] == "literal_error" and err["loc"] == ("schema_version",):
        msg = f"unsupported schema_version; this build reads {SCHEMA_VERSION}"
    return msg


def problems_from(error: ValidationError) -> list[tuple[str, str]]:
    """Return ``(field path, message)`` pairs from a pydantic validation error."""
    return [(field_path(tuple(e["loc"])), _message(dict(e))) for e in error.errors()]


class _NonFinite(ValueError):
    """A NaN or Infinity literal in the JSON text."""


def _reject_nonfinite(value: str) -> float:
    raise _NonFinite(f"{value} is not allowed; numbers must be finite")


_DUPLICATES = object()  # the key under which a parsed object lists its repeated keys


def _pairs(pairs: list[tuple[str, Any]]) -> dict[Any, Any]:
    """Return the object of `pairs`, its repeated keys listed under `_DUPLICATES`."""
    out: dict[Any, Any] = {}
    for key, value in pairs:
        if key in out:
            out.setdefault(_DUPLICATES, []).append(key)
        out[key] = value
    return out


def _check_tree(data: object, source: str) -> None:
    """Refuse repeated keys (naming the key's path) and nesting deeper than JSON_MAX_DEPTH."""
    stack: list[tuple[object, str, int]] = [(data, "", 0)]
    while stack:
        node, path, depth = stack.pop()
        if depth > JSON_MAX_DEPTH:
            raise ProjectError(
                f"{source}: {path or '(top level)'}: nested deeper than {JSON_MAX_DEPTH} levels"
                " (workbench.project.bounds.JSON_MAX_DEPTH); a project is a few levels deep",
                [(path or "(top level)", "nested too deeply")],
            )
        if isinstance(node, dict):
            dup = node.pop(_DUPLICATES, None)
            if dup is not None:
                where = f"{path}.{dup[0]}" if path else str(dup[0])
                raise ProjectError(
                    f"{source}: {where}: the key {dup[0]!r} appears more than once in "
                    f"{path or 'the top-level object'}; keep one (JSON readers differ on which wins)",
                    [(where, "duplicate key")],
                )
            stack.extend((v, f"{path}.{k}" if path else str(k), depth + 1) for k, v in node.items())
        elif isinstance(node, list):
            stack.extend((v, f"{path}[{i}]", depth + 1) for i, v in enumerate(node))


def parse_json(text: str | bytes, *, source: str = "project") -> Any:
    """Return the parsed JSON of a project or part file; `ProjectError` naming what is wrong.

    Refused: text that is not UTF-8 (a binary file), broken JSON (line and column), NaN and
    Infinity, numbers too long to read, repeated keys in an object (the key's path) and
    nesting deeper than `JSON_MAX_DEPTH`."""
    if isinstance(text, bytes | bytearray):
        if b"\x00" in text[:8192]:
            raise ProjectError(
                f"{source}: a binary file (it holds NUL bytes), not JSON text; give a project"
                " JSON file",
                [("(file)", "binary file")],
            )
        try:
            text = bytes(text).decode("utf-8-sig")
        except UnicodeDecodeError as exc:
            raise ProjectError(
                f"{source}: not UTF-8 text (byte 0x{text[exc.start]:02x} at offset {exc.start});"
                " is it a binary file? Give a project JSON file",
                [("(file)", "not UTF-8 text")],
            ) from None
    try:
        data = json.loads(text, parse_constant=_reject_nonfinite, object_pairs_hook=_pairs)
    except json.JSONDecodeError as exc:
        raise ProjectError(
            f"{source}: not valid JSON at line {exc.lineno} column {exc.colno}: {exc.msg}",
            [("(file)", exc.msg)],
        ) from None
    except _NonFinite as exc:  # NaN / Infinity literals
        raise ProjectError(f"{source}: {exc}", [("(file)", str(exc))]) from None
    except RecursionError:
        raise ProjectError(
            f"{source}: nested too deeply to read (more than {JSON_MAX_DEPTH} levels is refused)",
            [("(file)", "nested too deeply")],
        ) from None
    except ValueError as exc:  # e.g. an integer with more digits than Python reads
        raise ProjectError(
            f"{source}: cannot read a value: {exc}", [("(file)", str(exc))]
        ) from None
    _check_tree(data, source)
    return data


def _migrate(data: dict[str, Any]) -> dict[str, Any]:
    if "schema_version" not in data:
        raise SchemaVersionError(
            f'schema_version: missing; add "schema_version": {SCHEMA_VERSION} at the top level',
            [("schema_version", "required field is missing")],
        )
    version = data["schema_version"]
    if not isinstance(version, int) or isinstance(version, bool):
        raise SchemaVersionError(
            f"schema_version: expected an integer, got {version!r}",
            [("schema_version", "expected an integer")],
        )
    if version > SCHEMA_VERSION:
        raise SchemaVersionError(
            f"schema_version: {version} was written by a newer workbench; this build reads up to"
            f" {SCHEMA_VERSION}. Upgrade the workbench to open it.",
            [("schema_version", "newer than supported")],
        )
    if version < 1:
        raise SchemaVersionError(
            f"schema_version: {version} is not a released format (the first is 1)",
            [("schema_version", "unknown old version")],
        )
    while version < SCHEMA_VERSION:
        data = MIGRATIONS[version](data)
        version += 1
        data["schema_version"] = version
    return data


def project_from_dict(data: object, *, source: str = "project") -> Project:
    """Return a validated `Project` from parsed JSON; raises `ProjectError` naming each bad field."""
    if not isinstance(data, dict):
        raise ProjectError(
            f"{source}: expected a JSON object at the top level, got {type(data).__name__}"
        )
    data = _migrate(dict(data))
    try:
        return Project.model_validate(data)
    except ValidationError as exc:
        raise _refusal(source, exc) from None


def _refusal(what: str, error: ValidationError) -> ProjectError:
    """Return the ProjectError listing every field of `error`, headed by `what`."""
    problems = problems_from(error)
    lines = "\n".join(f"  {path}: {msg}" for path, msg in problems)
    return ProjectError(f"{what}: {len(problems)} problem(s)\n{lines}", problems)


def parse_project_json(text: str | bytes, *, source: str = "project") -> Project:
    """Return a validated `Project` from JSON text; broken JSON names the line and column."""
    return project_from_dict(parse_json(text, source=source), source=source)


def load_project(path: str | os.PathLike[str]) -> Project:
    """Return the validated `Project` stored at `path`."""
    p = Path(path)
    try:
        text = read_regular_file(p, kind="project", field=str(p))
    except InputError as exc:
        raise ProjectError(str(exc)) from None
    return parse_project_json(text, source=str(p))


def project_to_json(project: Project) -> str:
    """Return the project as pretty JSON text (stable key order, trailing newline).

    What is written is what loads: the text is validated as the loader would (ProjectError
    naming each field that would be refused, instead of a file that does not open)."""
    data = project.model_dump(mode="json", exclude_none=True)
    for v in _numbers(data):
        if not math.isfinite(v):  # guarded by the models; a second line of defence
            raise ProjectError("refusing to save a non-finite number")
    text = json.dumps(data, indent=2) + "\n"
    try:
        Project.model_validate(json.loads(text))
    except ValidationError as exc:
        raise _refusal("refusing to write a project that would not load", exc) from None
    return text


def _numbers(obj: object) -> list[float]:
    if isinstance(obj, float):
        return [obj]
    if isinstance(obj, dict):
        return [x for v in obj.values() for x in _numbers(v)]
    if isinstance(obj, list):
        return [x for v in obj for x in _numbers(v)]
    return []


def save_project(project: Project, path: str | os.PathLike[str]) -> None:
    """Save `project` to `path` atomically (a crash mid-save leaves the old file intact)."""
    text = project_to_json(project)
    try:
        atomic_write_text(path, text)
    except OSError as exc:
        raise ProjectError(f"{path}: cannot save ({exc.strerror})") from None


def json_schema() -> dict[str, Any]:
    """Return the JSON Schema of the project file."""
    schema = Project.model_json_schema()
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "Robot workbench project"
    return schema
