"""Run inside a fresh virtual environment (tests/install/test_fresh_install.py): every import the
package makes resolves there, and every example project installed with it opens and reads its
files; each planner (motion, assembly, polishing, bending without and with a press) plans and
exports its first example there. The other examples' plans run the same code and are checked in
the main suite (tests/test_example_exports.py); planning all of them here again cost minutes.

Usage: python fresh_check.py SOURCE_TREE. Prints one line per check and exits 1 on the first
failure. It must import `workbench` from the environment, never from the source tree.
"""

from __future__ import annotations

import ast
import importlib.util
import sys
import sysconfig
from pathlib import Path


def imported_modules(package: Path) -> dict[str, str]:
    """Return {top-level module: first file:line} of every absolute import under `package`,
    function-level (lazy) imports included."""
    found: dict[str, str] = {}
    for path in sorted(package.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            names: list[str] = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                names = [node.module]
            for name in names:
                found.setdefault(
                    name.split(".")[0], f"{path.relative_to(package.parent)}:{node.lineno}"
                )
    return found


def main() -> int:
    source = Path(sys.argv[1]).resolve()
    import workbench

    installed = Path(workbench.__file__).resolve().parent
    if source in installed.parents:
        print(f"FAIL workbench imported from the source tree: {installed}")
        return 1
    missing = [
        f"{mod} (imported at {where})"
        for mod, where in sorted(imported_modules(installed).items())
        if mod not in sys.stdlib_module_names and importlib.util.find_spec(mod) is None
    ]
    if missing:
        print("FAIL not installed by pyproject.toml's dependencies: " + "; ".join(missing))
        return 1
    print(f"ok every import of {installed} resolves")

    from workbench import Workbench
    from workbench.service.programs import plan_workflow

    projects_dir = Path(sysconfig.get_path("data")) / "share" / "workbench" / "projects"
    shipped = sorted(p.name for p in (source / "projects").glob("*.json"))
    projects = sorted(projects_dir.glob("*.json"))
    if sorted(p.name for p in projects) != shipped:
        print(f"FAIL installed examples {[p.name for p in projects]} != source's {shipped}")
        return 1
    planned: set[tuple[str, bool]] = set()
    for path in projects:
        wb = Workbench.open(path)
        native = wb.default_program_format()  # the robot's vendor's language
        for wf in wb.project.workflows():
            _read_inputs(wb, wf)  # the part or workpiece files, STEP and DXF included
            bending = wb.project.bending
            kind = (wf, bending is not None and bending.press is not None)
            if kind in planned:  # the same planner as an example above: read, not planned
                print(f"ok {path.name} {wf}: opened and its files read")
                continue
            planned.add(kind)
            plan_workflow(wb, wf)
            for fmt in ("json", native):  # refused if the plan collides or breaks a limit
                exported = wb.export_program(fmt, wf)
                if not exported.files:
                    print(f"FAIL {path.name} {wf}: the {fmt} export wrote no file")
                    return 1
            print(f"ok {path.name} {wf}: planned and exported ({native}, json)")
    return 0


def _read_inputs(wb: object, workflow: str) -> None:
    """Read the files a workflow reads lazily: the bending part, the polishing workpiece."""
    if workflow == "bending":
        _ = wb.bending.part  # type: ignore[attr-defined]
    elif workflow == "polishing":
        _ = wb.polishing.surface  # type: ignore[attr-defined]


if __name__ == "__main__":
    sys.exit(main())
