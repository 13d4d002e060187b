"""The layers of docs/architecture.md, read from the source: who may import whom, module sizes.

A domain package that imports the project model, a service module that converts units or
grows past its size, a GUI panel that calls the kinematics: each fails here with the file and
line, so the structure does not erode one convenient import at a time.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "workbench"
DOMAIN = (
    "geometry",
    "kinematics",
    "calibration",
    "collision",
    "motion",
    "sheetmetal",
    "pressbrake",
    "assembly",
    "polishing",
    "cad",
)
SERVICE_MAX_LINES = 300

#: The layers, lowest first (docs/architecture.md, "The layers"). A package may import its own
#: modules and any package of a lower layer; one of its own layer or above is an upward import
#: (or a sideways one: two process packages stay independent). The top-level modules count as
#: packages: `errors` at the bottom, the file and cache helpers and Ray's session, the batch runner.
LAYERS: tuple[tuple[str, ...], ...] = (
    ("errors",),
    ("env_setting",),
    ("atomic_file", "disk_cache", "bounded_cache", "ray_session", "plan_limit"),
    ("batch",),
    ("geometry",),
    ("kinematics",),
    ("calibration",),
    ("motion",),
    ("collision",),
    ("cad",),
    ("sheetmetal",),
    ("pressbrake", "assembly", "polishing"),
    ("project",),
    ("service",),
    ("gui",),
    ("cli_options",),  # options the commands share
    (
        "cli_calibrate",
        "cli_touchup",
        "cli_polishing",
    ),  # commands of the CLI in their own modules (cli.py stays small)
    ("cli",),
    ("__main__", "__init__"),
)
RANK = {name: i for i, layer in enumerate(LAYERS) for name in layer}


def _modules(sub: str) -> list[Path]:
    return sorted((PACKAGE / sub).rglob("*.py"))


def _imports(path: Path) -> list[tuple[int, str]]:
    """Return (line, module) of every import in `path`, relative imports resolved."""
    tree = ast.parse(path.read_text(), filename=str(path))
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module is not None:
            found.append((node.lineno, node.module))
    return found


def _offending(paths: list[Path], bad: re.Pattern[str]) -> list[str]:
    return [
        f"{p.relative_to(PACKAGE.parent)}:{line} imports {mod}"
        for p in paths
        for line, mod in _imports(p)
        if bad.match(mod)
    ]


def test_only_the_gui_imports_viser() -> None:
    below = [p for p in PACKAGE.rglob("*.py") if "gui" not in p.relative_to(PACKAGE).parts]
    assert _offending(below, re.compile(r"viser(\.|$)")) == []


@pytest.mark.parametrize("package", DOMAIN)
def test_domain_packages_know_nothing_of_projects_services_or_the_gui(package: str) -> None:
    bad = re.compile(r"workbench\.(project|service|gui|cli)(\.|$)")
    assert _offending(_modules(package), bad) == []


def test_the_project_model_imports_no_service_or_gui() -> None:
    bad = re.compile(r"workbench\.(service|gui|cli)(\.|$)")
    assert _offending(_modules("project"), bad) == []


def test_the_service_imports_no_gui() -> None:
    assert _offending(_modules("service"), re.compile(r"(workbench\.gui|viser)(\.|$)")) == []


def test_the_gui_calls_the_service_not_the_domain() -> None:
    # The GUI may use the service, error types, its own modules and display-only frame
    # conversions (geometry.transforms: matrix <-> wxyz for scene nodes).
    allowed = re.compile(r"workbench(\.(service|errors|gui|geometry\.transforms)(\.|$)|$)")
    bad = [
        f"{p.relative_to(PACKAGE.parent)}:{line} imports {mod}"
        for p in _modules("gui")
        for line, mod in _imports(p)
        if mod.startswith("workbench") and not allowed.match(mod)
    ]
    assert bad == []


def test_service_modules_are_small() -> None:
    big = {
        str(p.relative_to(PACKAGE.parent)): n
        for p in _modules("service")
        if (n := len(p.read_text().splitlines())) > SERVICE_MAX_LINES
    }
    assert big == {}


def test_no_unit_arithmetic_in_the_service() -> None:
    # mm/deg <-> SI happens in project/ (section.to_si()) and, for display, in gui/.
    unit = re.compile(r"\b(MM|DEG|RAD|MM_PER_M)\b|np\.(radians|degrees|deg2rad|rad2deg)\b")
    hits = [
        f"{p.relative_to(PACKAGE.parent)}:{i}: {line.strip()}"
        for p in _modules("service")
        for i, line in enumerate(p.read_text().splitlines(), 1)
        if unit.search(line.split("#", 1)[0])
    ]
    assert hits == []


def test_the_gui_computes_no_kinematics() -> None:
    calls = re.compile(r"\.(fk|link_transforms|ik|ik_batch|jacobian)\(")
    hits = [
        f"{p.relative_to(PACKAGE.parent)}:{i}: {line.strip()}"
        for p in _modules("gui")
        for i, line in enumerate(p.read_text().splitlines(), 1)
        if calls.search(line)
    ]
    assert hits == []


def _package_of(path: Path) -> str:
    parts = path.relative_to(PACKAGE).parts
    return parts[0] if len(parts) > 1 else path.stem


def _package_imports() -> dict[str, set[str]]:
    """Return {package: packages it imports} over all of `workbench/`."""
    graph: dict[str, set[str]] = {}
    for p in PACKAGE.rglob("*.py"):
        here = _package_of(p)
        for _, mod in _imports(p):
            if mod.startswith("workbench.") and (there := mod.split(".")[1]) != here:
                graph.setdefault(here, set()).add(there)
    return graph


def test_every_package_has_a_layer() -> None:
    names = {_package_of(p) for p in PACKAGE.rglob("*.py")}
    assert sorted(names - set(RANK)) == []


def test_no_import_runs_up_or_across_the_layers() -> None:
    bad = [
        f"{p.relative_to(PACKAGE.parent)}:{line} imports {mod}"
        for p in PACKAGE.rglob("*.py")
        for line, mod in _imports(p)
        if mod.startswith("workbench.")
        and (there := mod.split(".")[1]) != (here := _package_of(p))
        and there in RANK
        and RANK[there] >= RANK[here]
    ]
    assert bad == []


def _cycle(graph: dict[str, set[str]]) -> list[str]:
    """Return one loop of `graph` (a list of packages, first == last) or []."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> list[str]:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt) :] + [nxt]
            if nxt not in state and (loop := visit(nxt)):
                return loop
        stack.pop()
        state[node] = 2
        return []

    for node in sorted(graph):
        if node not in state and (loop := visit(node)):
            return loop
    return []


def test_no_package_loop() -> None:
    assert _cycle(_package_imports()) == []


def test_the_loop_finder_finds_a_loop() -> None:
    # The twin of the test above: a graph with a loop three packages long, and one without.
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b", "c"}, "b": {"c"}, "c": set()}) == []
