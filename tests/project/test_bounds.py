"""Issue 16, parts 3 and 7 at load: every number of the project file has a range, checked with
its field path; the parser refuses repeated keys, binary files and deep nesting; the ranges
and work budgets are listed in docs/security.md exactly as the code has them."""

from __future__ import annotations

import ast
import copy
import importlib
import json
from pathlib import Path
from typing import Any

import pytest
from cli_run import run_cli

import workbench.project.bounds as B
from workbench.errors import ProjectError
from workbench.project.io import parse_project_json, project_from_dict

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("mz07_cell", "bending_cell", "assembly_cell", "polishing_cell")
SECTION = "## Input bounds"


def _example(name: str) -> dict[str, Any]:
    return json.loads((ROOT / "projects" / f"{name}.json").read_text())


# -- the docs list the code's ranges and budgets, and nothing else -----------------------------------
def _fmt(name: str, v: Any) -> str:
    if isinstance(v, tuple):
        left = "(" if name.endswith("_OPEN") else "["
        return left + ", ".join(_fmt("", x) for x in v) + "]"
    if isinstance(v, dict):
        return ", ".join(f"{k}: {_fmt('', x)}" for k, x in v.items())
    if isinstance(v, int) or (isinstance(v, float) and v.is_integer() and abs(v) < 1e7):
        return f"{int(v):,}"
    return f"{v:g}"


def _constants(module: Any, names: list[str] | None = None) -> list[tuple[str, Any, str]]:
    """Return (name, value, docstring) of a module's upper-case constants (or of `names`)."""
    body = ast.parse(Path(module.__file__).read_text()).body
    out = []
    for i, node in enumerate(body):
        if not (isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Name)):
            continue
        name = node.targets[0].id
        if not name.isupper() or name == "BUDGETS" or (names is not None and name not in names):
            continue
        nxt = body[i + 1] if i + 1 < len(body) else None
        doc = (
            nxt.value.value
            if isinstance(nxt, ast.Expr) and isinstance(nxt.value, ast.Constant)
            else ""
        )
        out.append((name, getattr(module, name), " ".join(str(doc).split())))
    return out


def expected_rows() -> list[str]:
    """Return the table rows docs/security.md must hold: the ranges, then the budgets."""
    rows = [f"| `{n}` | {_fmt(n, v)} | {d} |" for n, v, d in _constants(B)]
    for dotted in B.BUDGETS:
        mod, name = dotted.rsplit(".", 1)
        ((_, v, d),) = _constants(importlib.import_module(mod), [name])
        rows.append(f"| `{dotted.removeprefix('workbench.')}` | {_fmt(name, v)} | {d} |")
    return rows


def test_docs_list_every_range_and_budget_as_the_code_has_them() -> None:
    text = (ROOT / "docs" / "security.md").read_text()
    assert SECTION in text
    section = text.split(SECTION, 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("| `")]
    want = expected_rows()
    missing = [r for r in want if r not in rows]
    extra = [r for r in rows if r not in want]
    assert not missing and not extra, (
        "docs/security.md 'Input bounds' differs from workbench/project/bounds.py; "
        f"missing {missing}, not in the code {extra}"
    )
    assert all(d for *_, d in _constants(B)), "every constant in bounds.py has a docstring"


def test_every_budget_names_an_existing_setting() -> None:
    for dotted in B.BUDGETS:
        mod, name = dotted.rsplit(".", 1)
        assert hasattr(importlib.import_module(mod), name), dotted


# -- the examples lie inside the ranges; values outside are refused with the field ---------------------
@pytest.mark.parametrize("name", EXAMPLES)
def test_examples_load_within_the_bounds(name: str) -> None:
    project_from_dict(_example(name))


CASES = [
    (
        "mz07_cell",
        ["robot", "base", "xyz", 0],
        1e9,
        "robot.base.xyz[0]",
        "1e+09 mm is out of range",
    ),
    (
        "mz07_cell",
        ["cell", "objects", 3, "radius"],
        1e-9,
        "cell.objects[3].radius",
        "[0.1, 200000] mm",
    ),
    (
        "mz07_cell",
        ["cell", "objects", 1, "size", 0],
        1e308,
        "cell.objects[1].size[0]",
        "out of range",
    ),
    ("mz07_cell", ["tool", "size", 2], 0, "tool.size[2]", "0 mm is out of range"),
    ("mz07_cell", ["tool", "size", 2], -5, "tool.size[2]", "-5 mm is out of range"),
    ("bending_cell", ["tool", "size", 2], 1e5, "tool.size[2]", "[0.1, 5000] mm"),
    ("mz07_cell", ["robot", "joints", 0], 1e16, "robot.joints[0]", "[-720, 720] deg"),
    (
        "mz07_cell",
        ["robot", "max_acceleration"],
        [0.001] * 6,
        "robot.max_acceleration[0]",
        "deg/s²",
    ),
    (
        "polishing_cell",
        ["polishing", "controller", "latency"],
        1e9,
        "polishing.controller.latency",
        "ms",
    ),
    ("polishing_cell", ["polishing", "dwell"], 1e9, "polishing.dwell", "[0, 60] s"),
    ("polishing_cell", ["polishing", "spacing"], 1e-9, "polishing.spacing", "[0.5, 10000] mm"),
    ("polishing_cell", ["polishing", "tool_radius"], 1e-9, "polishing.tool_radius", "mm"),
    (
        "assembly_cell",
        ["assembly", "planner", "step"],
        1_000_000,
        "assembly.planner.step",
        "[1, 1000]",
    ),
    (
        "assembly_cell",
        ["assembly", "planner", "cell_size"],
        0.05,
        "assembly.planner.cell_size",
        "mm",
    ),
    (
        "assembly_cell",
        ["assembly", "parts", 0, "goal", "xyz", 2],
        1e9,
        "assembly.parts[0].goal.xyz[2]",
        "mm",
    ),
    ("bending_cell", ["bending", "die", "length"], 0, "bending.die.length", "[1, 200000] mm"),
]


def _set(data: dict[str, Any], path: list[Any], value: Any) -> dict[str, Any]:
    data = copy.deepcopy(data)
    node = data
    for k in path[:-1]:
        node = node[k]
    node[path[-1]] = value
    return data


@pytest.mark.parametrize(("name", "path", "value", "field", "words"), CASES)
def test_a_value_outside_its_range_names_the_field(
    name: str, path: list[Any], value: Any, field: str, words: str
) -> None:
    with pytest.raises(ProjectError) as info:
        project_from_dict(_set(_example(name), path, value))
    problems = dict(info.value.problems)
    assert field in problems, problems
    assert words in problems[field], problems[field]


def test_latency_cycles_over_the_budget_are_refused_before_the_stability_check() -> None:
    data = _set(_example("polishing_cell"), ["polishing", "controller", "latency"], 500)
    data = _set(data, ["polishing", "controller", "control_rate"], 1000)
    with pytest.raises(ProjectError, match=r"500 control cycles, above the 100"):
        project_from_dict(data)


def test_a_range_is_published_in_the_schema() -> None:
    from workbench.project.io import json_schema

    pose = json_schema()["$defs"]["Pose"]["properties"]["xyz"]["items"]
    assert pose["minimum"] == -B.CELL_HALF_EXTENT_MM and pose["maximum"] == B.CELL_HALF_EXTENT_MM


def test_range_edges_are_allowed_and_open_ends_excluded() -> None:
    r = B.span((0.0, 100.0), "%", lo_open=True)
    assert r.check(100.0) == 100.0 and r.check(1e-12) == 1e-12
    for bad in (0.0, -1.0, 100.0000001):
        with pytest.raises(ValueError, match=r"out of range; allowed \(0, 100\] %"):
            r.check(bad)
    assert B.symmetric(5.0).check(-5.0) == -5.0


# -- the parser --------------------------------------------------------------------------------------
def test_a_repeated_key_is_refused_with_its_path() -> None:
    text = (ROOT / "projects" / "mz07_cell.json").read_text()
    bad = text.replace('"radius": 50,', '"radius": 50, "radius": 5,', 1)
    with pytest.raises(ProjectError) as info:
        parse_project_json(bad)
    assert "cell.objects[3].radius: the key 'radius' appears more than once" in str(info.value)
    with pytest.raises(ProjectError, match=r"^project: name: the key 'name' appears"):
        parse_project_json('{"schema_version": 1, "name": "a", "name": "b"}')


@pytest.mark.parametrize(
    ("data", "words"),
    [
        (b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", "a binary file (it holds NUL bytes), not JSON"),
        (b"\xff\xfe{}", "not UTF-8 text (byte 0xff at offset 0)"),
        (b"[" * 100_000 + b"]" * 100_000, "nested too deeply"),
        (("[" * 70 + "]" * 70).encode(), "nested deeper than 64 levels"),
        (b'{"schema_version": 1, "name": NaN}', "NaN is not allowed; numbers must be finite"),
        (b'{"schema_version": 1, "name": ' + b"9" * 5000 + b"}", "cannot read a value"),
    ],
)
def test_unreadable_files_are_project_errors_saying_why(data: bytes, words: str) -> None:
    with pytest.raises(ProjectError) as info:
        parse_project_json(data)
    assert words in str(info.value)
    assert "numbers must be finite" not in str(info.value) or b"NaN" in data


# -- workbench check exits 2 on bad input, without a traceback --------------------------------------
@pytest.mark.parametrize(
    "content",
    [
        b"\x89PNG\r\n\x1a\n\x00\x00",
        b"[" * 100_000 + b"]" * 100_000,
        b'{"schema_version": 1, "name": "a", "name": "b"}',
        json.dumps(_set(_example("mz07_cell"), ["cell", "objects", 3, "radius"], 1e-9)).encode(),
    ],
    ids=["binary", "deep", "duplicate", "tiny-cylinder"],
)
def test_check_exits_2_without_a_traceback(tmp_path: Path, content: bytes) -> None:
    path = tmp_path / "bad.json"
    path.write_bytes(content)
    res = run_cli("check", str(path))  # in this process (tests/cli_run.py)
    assert res.returncode == 2, res.stderr
    assert "Traceback" not in res.stderr and res.stderr.startswith("workbench check: error:")
