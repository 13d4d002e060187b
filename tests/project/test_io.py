"""Project files: field paths in errors, migration refusal, atomic saves, the published schema."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from workbench.errors import ProjectError, SchemaVersionError, WorkbenchError
from workbench.project import (
    json_schema,
    load_project,
    parse_project_json,
    project_from_dict,
    project_to_json,
    save_project,
)

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "projects").glob("*.json"))


def _base() -> dict:
    return {"schema_version": 1, "robot": {"preset": "mz07"}}


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_examples_round_trip(path: Path, tmp_path: Path) -> None:
    project = load_project(path)
    out = tmp_path / "copy.json"
    save_project(project, out)
    again = load_project(out)
    assert again == project
    assert project_to_json(again) == out.read_text()


@pytest.mark.parametrize(
    ("patch", "field", "words"),
    [
        (
            {
                "cell": {
                    "objects": [
                        {"name": "a", "shape": "box", "size": [1, 2, 3], "pose": {"xyz": [1, 2]}}
                    ]
                }
            },
            "cell.objects[0].pose.xyz",
            "expected 3 numbers",
        ),
        (
            {
                "cell": {
                    "objects": [
                        {"name": "a", "shape": "box", "size": [1, 2, 3], "colour": [1, 2, 3]}
                    ]
                }
            },
            "cell.objects[0].colour",
            "unknown field",
        ),
        (
            {"cell": {"objects": [{"name": "a", "shape": "cylinder", "radius": 5}]}},
            "cell.objects[0]",
            "needs 'height'",
        ),
        (
            {"cell": {"objects": [{"name": "a", "shape": "box", "size": [1, -2, 3]}]}},
            "cell.objects[0].size[1]",
            "-2 mm is out of range; allowed [0.1, 200000] mm",
        ),
        (
            {"robot": {"preset": "mz07", "base": {"rpy": ["x", 0, 0]}}},
            "robot.base.rpy[0]",
            "number",
        ),
        ({"robot": {"preset": "mz07", "dh": []}}, "robot", "exactly one"),
        ({"robot": {}}, "robot", "exactly one"),
        ({"robot": {"preset": "ur5"}}, "robot.preset", "mz07"),
        (
            {"robot": {"preset": "mz07", "max_velocity": [1, 2, 0, 1, 1, 1]}},
            "robot.max_velocity[2]",
            "0 deg/s is out of range",
        ),
        ({"tool": {"tcp": {"xyz": [0, 0, 1e400]}}}, "tool.tcp.xyz[2]", "finite"),
        (
            {
                "cell": {
                    "objects": [
                        {"name": "a", "shape": "box", "size": [1, 1, 1]},
                        {"name": "a", "shape": "box", "size": [1, 1, 1]},
                    ]
                }
            },
            "cell",
            "unique",
        ),
        (
            {
                "cell": {
                    "objects": [
                        {"name": "a", "shape": "box", "size": [1, 1, 1], "color": [0, 0, 300]}
                    ]
                }
            },
            "cell.objects[0].color",
            "0..255",
        ),
    ],
)
def test_bad_fields_are_named(patch: dict, field: str, words: str) -> None:
    data = _base() | patch
    with pytest.raises(ProjectError) as info:
        project_from_dict(data)
    paths = [p for p, _ in info.value.problems]
    assert field in paths, paths
    msg = dict(info.value.problems)[field]
    assert words in msg, msg
    assert field in str(info.value)


def test_broken_json_names_line_and_column() -> None:
    with pytest.raises(ProjectError, match=r"line 2 column 14"):
        parse_project_json('{"schema_version": 1,\n "name": "x",,}')


@pytest.mark.parametrize("literal", ["NaN", "Infinity", "-Infinity"])
def test_nonfinite_json_literals_refused(literal: str) -> None:
    with pytest.raises(ProjectError, match="finite"):
        text = '{"schema_version": 1, "tool": {"tcp": {"xyz": [0, 0, LIT]}}}'
        parse_project_json(text.replace("LIT", literal))


@pytest.mark.parametrize(
    ("data", "words"),
    [
        ({}, "schema_version: missing"),
        ({"schema_version": 99}, "newer workbench"),
        ({"schema_version": 0}, "not a released format"),
        ({"schema_version": "1"}, "integer"),
    ],
)
def test_schema_versions(data: dict, words: str) -> None:
    with pytest.raises(SchemaVersionError, match=words):
        project_from_dict(data)


def test_top_level_must_be_object() -> None:
    with pytest.raises(WorkbenchError, match="JSON object"):
        parse_project_json("[1, 2, 3]")


def test_missing_file() -> None:
    with pytest.raises(ProjectError, match="no such file"):
        load_project("/nonexistent/project.json")


def test_save_is_atomic_when_the_write_fails(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = tmp_path / "p.json"
    good = project_from_dict(_base() | {"name": "good"})
    save_project(good, target)
    before = target.read_bytes()

    def crash(fd: int) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "fsync", crash)
    with pytest.raises(ProjectError, match="cannot save"):
        save_project(project_from_dict(_base() | {"name": "new"}), target)
    assert target.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["p.json"], "temporary file left behind"


def test_published_schema_is_current() -> None:
    published = json.loads((ROOT / "schema" / "project.schema.json").read_text())
    assert published == json_schema(), "run `python -m workbench.project.schema` to refresh it"
