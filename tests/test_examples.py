"""The scripts in examples/ run headless and print and write what they promise.

Each example is imported from its file and its `main()` called (one also runs as a script,
as a user would); the checks read what it printed and the files it wrote, and compare them
with the public API where a number is involved.
"""

from __future__ import annotations

import ast
import json
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest
from twins import load_module

from workbench import Workbench

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def _load(name: str) -> ModuleType:
    """Import examples/<name>.py (its name starts with a digit: not importable by `import`)."""
    return load_module(f"examples/{name}.py", f"example_{name}")


def _run(name: str, capsys: pytest.CaptureFixture[str], *args: object) -> tuple[object, str]:
    result = _load(name).main(*args)
    return result, capsys.readouterr().out


def check_01_jog_and_ik(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    _, out = _run("01_jog_and_ik", capsys)
    assert "joints [deg]: [20.0, 100.0, -5.0, 0.0, -30.0, 0.0] (controller)" in out
    found = re.search(r"(\d+) configurations reach the pose 50 mm lower", out)
    assert found is not None, out
    n = int(found.group(1))
    wb = Workbench.open(ROOT / "projects" / "mz07_cell.json")
    wb.set_joints(wb.robot.convention.to_model(np.radians([20.0, 100.0, -5.0, 0.0, -30.0, 0.0])))
    target = wb.tcp_pose()
    target[2, 3] -= 0.050
    labels = [s.label for s in wb.ik_solutions(target)]
    assert n == len(labels) >= 2
    for k, label in enumerate(labels):
        assert f"  {k}: {label}" in out
    # Both moves reach the target: the printed TCP error is at rounding level.
    errors = [float(e) for e in re.findall(r"\(error ([0-9.e+-]+)\)", out)]
    assert len(errors) == 2 and max(errors) < 1e-9
    assert f"moved in {labels[-1]}" in out
    assert out.count("collision-free, clearance") == 3


def check_02_plan_and_export(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    written, out = _run("02_plan_and_export", capsys, tmp_path)
    assert "100.0 %  done" in out
    assert re.search(
        r"cycle time \d+\.\d{3} s \(0\.40 s of waits; waits for inputs count 0 s\), 7 moves;"
        r" within joint limits; collision-free",
        out,
    )
    assert "ready to run" in out
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == sorted(p.name for p in written)  # type: ignore[attr-defined]
    lower = {n.lower() for n in names}  # FANUC program names are upper case
    for ext in (".csv", ".json", ".ls", ".mod", ".script", ".src"):
        assert f"pick_place{ext}" in lower, names
    assert (tmp_path / "pick_place.mod").read_text().startswith("MODULE pick_place")
    assert "MoveL" in (tmp_path / "pick_place.mod").read_text()
    assert (tmp_path / "pick_place.src").read_text().startswith("DEF pick_place")
    rows = (tmp_path / "pick_place.csv").read_text().splitlines()
    assert rows[0].startswith("t [s],J1 controller [rad]") and len(rows) > 100
    samples = json.loads((tmp_path / "pick_place.json").read_text())
    assert len(samples["t_s"]) == len(rows) - 1 == len(samples["q_rad"])
    for path in written:  # type: ignore[attr-defined]
        assert f"{path} (" in out


def check_03_bending(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    _, out = _run("03_bending", capsys)
    sequence = Workbench.open(ROOT / "projects" / "bending_cell.json").bending.sequence
    assert f"bend sequence: {', '.join(sequence)}" in out
    assert "refused: sequence: must name every bend exactly once" in out
    assert f"the sequence stays {', '.join(sequence)}" in out
    for bend in sequence:
        assert f"  bend {bend} on the die: joints [deg]" in out
    assert re.search(r"6 bends placed on the die \(.+\); transfer \d+\.\d\d s", out)
    assert "the transfer is collision-free" in out and "first collision" not in out, out


def check_04_assembly(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    written, out = _run("04_assembly", capsys, tmp_path)
    assert "robots: MZ07, MZ07_B" in out
    assert re.search(r"7 part moves \(plate_a → plate_b → screw_0 .*\); cycle time", out)
    assert "collision-free at every sample" in out
    tasks = re.findall(
        r"^  (\S+) +by (\S+) +picked at +([0-9.]+) s, placed at +([0-9.]+) s", out, re.M
    )
    assert [t[0] for t in tasks[:2]] == ["plate_a", "plate_b"] and len(tasks) == 7
    assert all(float(pick) < float(place) for _, _, pick, place in tasks)
    assert {t[1] for t in tasks} == {"MZ07", "MZ07_B"}
    names = sorted(p.name for p in written)  # type: ignore[attr-defined]
    assert names == ["assembly_MZ07.mod", "assembly_MZ07_B.mod"]
    assert sorted(p.name for p in tmp_path.iterdir()) == names
    for robot in ("MZ07", "MZ07_B"):
        text = (tmp_path / f"assembly_{robot}.mod").read_text()
        assert text.startswith(f"MODULE assembly_{robot}") and "WaitSyncTask" in text


def check_05_polishing(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    program, out = _run("05_polishing", capsys, tmp_path)
    assert "workpiece panel.stl: 4602 triangles" in out
    assert re.search(r"tool path:  spiral: \d+ points, .* coverage \d+\.\d %", out)
    assert re.search(r"control:    target 20 N at 40 mm/s .* force within ±\d+\.\d\d N", out)
    assert re.search(r"robot:      cycle time \d+\.\d{3} s, \d+ moves; within joint limits", out)
    assert program.suffix == ".src" and program.parent == tmp_path  # type: ignore[attr-defined]
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == [program.with_suffix(".dat").name, program.name]  # type: ignore[attr-defined]
    text = program.read_text()  # type: ignore[attr-defined]
    assert text.startswith("DEF ") and text.rstrip().endswith("END") and "LIN " in text
    assert f"({len(text.splitlines())} lines)" in out


def check_06_bending_sweep(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    _, out = _run("06_bending_sweep", capsys)
    svc = Workbench.open(ROOT / "projects" / "u_channel_cell.json").bending
    res = svc.find_sequences()
    assert f"part u_channel: bends {', '.join(svc.sequence)}" in out
    assert "(serial, 1 worker(s)" in out
    assert "bA -> bB: bend 'bB': flange 'A' hits the punch" in out
    for rank, plan in enumerate(res.plans, 1):
        assert f"{rank}. {' -> '.join(plan.sequence)}: {plan.regrips} regrip(s)" in out
    if res.plans:
        assert "planned: 2 bends (" in out and "Collision-free." in out, out


def check_07_own_cell(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    _, out = _run("07_own_cell", capsys)
    assert "part: recognised from the STEP solid 'parts/u_channel.step': 3 flanges, 2 bends;" in out
    # The STEP's flat blank is the hand-written U-channel's (projects/parts/u_channel.json).
    twin = Workbench.open(ROOT / "projects" / "u_channel_cell.json").bending.part.blank_area()
    assert f"flat blank: {twin * 1e6:.1f} mm^2" in out
    assert "2 bends (B1 B2), 0 regrip(s)" in out and "Collision-free." in out
    assert "refused: bending.part_import.thickness: missing" in out
    assert "thickness 1.5 mm\n  flanges F1, F2, F3, F4, F5" in out
    assert "obstacle fixture_block: 6 cell bodies; it touches tool" in out
    for choice in Workbench.robot_choices():
        found = re.search(
            rf"{re.escape(choice.label)}: (\d+) configuration\(s\) reach above_left;"
            rf" exports {choice.program_format}\n",
            out,
        )
        assert found is not None and int(found.group(1)) >= 1, choice.name


CHECKS: dict[str, Callable[[pytest.CaptureFixture[str], Path], None]] = {
    "01_jog_and_ik": check_01_jog_and_ik,
    "02_plan_and_export": check_02_plan_and_export,
    "03_bending": check_03_bending,
    "04_assembly": check_04_assembly,
    "05_polishing": check_05_polishing,
    "06_bending_sweep": check_06_bending_sweep,
    "07_own_cell": check_07_own_cell,
}
SLOW = {"04_assembly", "06_bending_sweep"}  # over 5 s here


def test_every_example_has_a_title_a_main_and_a_check() -> None:
    found = sorted(p.stem for p in EXAMPLES.glob("*.py"))
    assert found == sorted(CHECKS)
    for name in found:
        tree = ast.parse((EXAMPLES / f"{name}.py").read_text())
        doc = ast.get_docstring(tree)
        assert doc and doc.splitlines()[0].endswith("."), f"{name}: no docstring title"
        assert any(isinstance(n, ast.FunctionDef) and n.name == "main" for n in tree.body), name
        # The public API only: examples import `workbench` itself, nothing below it.
        imports = [
            n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.module
        ] + [a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names]
        assert not [m for m in imports if m.startswith("workbench.")], name


@pytest.mark.parametrize(
    "name", [pytest.param(n, marks=pytest.mark.slow) if n in SLOW else n for n in sorted(CHECKS)]
)
def test_example_runs_and_prints_what_it_promises(
    name: str, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    CHECKS[name](capsys, tmp_path)


@pytest.mark.slow  # a fresh interpreter imports pinocchio, fcl and trimesh: ~3-8 s
def test_an_example_runs_as_a_script_with_a_project_argument(tmp_path: Path) -> None:
    done = subprocess.run(
        [
            sys.executable,
            str(EXAMPLES / "01_jog_and_ik.py"),
            str(ROOT / "projects" / "mz07_cell.json"),
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("project: MZ07 work cell\n")
    assert list(tmp_path.iterdir()) == []  # it writes nothing


def test_the_readme_project_example_is_a_valid_project() -> None:
    blocks = re.findall(r"```json\n(.*?)```", (ROOT / "README.md").read_text(), re.S)
    assert len(blocks) == 1
    wb = Workbench.from_dict(json.loads(blocks[0]))
    assert wb.project.name == "MZ07 work cell"
    assert wb.project.program is not None and len(wb.project.program.moves) == 3


def _anchors(markdown: str) -> set[str]:
    """Return the anchors GitHub gives the headings of a markdown page."""
    heads = re.findall(r"^#+ (.*)$", markdown, re.M)
    return {re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-") for h in heads}


def test_the_readme_links_stay_in_the_repository() -> None:
    text = (ROOT / "README.md").read_text()
    targets = re.findall(r"\]\(([^)]+)\)", text)
    local = [t for t in targets if not t.startswith("https://")]
    assert local and all((ROOT / t.split("#")[0]).exists() for t in local), local
    assert not [t for t in local if ".." in t]
    for t in local:  # a section link names a heading of that page (GitHub's anchors)
        if "#" in t:
            page, anchor = t.split("#", 1)
            assert anchor in _anchors((ROOT / page).read_text()), f"{t}: no such heading"
    for name in sorted(CHECKS):
        assert f"(examples/{name}.py)" in text, f"the README does not link examples/{name}.py"


def _architecture_tree(doc: str) -> dict[str, str]:
    """Return {path in the tree: its text} from the page's `workbench/` tree.

    An entry is a line with `── name.py` or `── name/`; its place is its indent (four
    characters a level); lines without `──` continue the entry above. A sub-package whose
    modules are listed on its own lines ("planners/  ant.py (...), rrt_connect.py") names them
    in its text.
    """
    block = doc.split("```\nworkbench/\n", 1)[1].split("```", 1)[0]
    entries: dict[str, str] = {}
    stack: list[str] = []
    last = ""
    for line in block.splitlines():
        m = re.match(r"^([│ ]*)[├└]── (\S+)(.*)$", line)
        if not m:
            if last:
                entries[last] += " " + line.strip("│ ")
            continue
        depth = len(m.group(1)) // 4
        stack = stack[:depth] + [m.group(2)]
        last = "/".join(stack).replace("//", "/")
        entries[last] = m.group(3).strip()
    return entries


def test_the_architecture_page_names_every_package_and_module() -> None:
    doc = (ROOT / "docs" / "architecture.md").read_text()
    package = ROOT / "workbench"
    tree = _architecture_tree(doc)
    missing = []
    for p in sorted(package.rglob("*.py")):
        rel = p.relative_to(package)
        if p.name == "__init__.py" and len(rel.parts) > 1:
            continue
        where = "/".join(rel.parts[:-1])
        listed = str(rel) in tree or (
            # a module of a sub-package named in the sub-package's text
            len(rel.parts) > 2 and re.search(rf"\b{re.escape(p.name)}\b", tree.get(where + "/", ""))
        )
        if not listed:
            missing.append(str(rel))
    for d in sorted(package.rglob("*")):
        if (d / "__init__.py").exists() and f"{d.relative_to(package)}/" not in tree:
            missing.append(f"{d.relative_to(package)}/")
    assert missing == [], "docs/architecture.md's tree does not list these under their package"
    gone = [path for path in tree if path.endswith(".py") and not (package / path).exists()]
    assert gone == [], "docs/architecture.md's tree lists modules that do not exist"
    targets = re.findall(r"\]\(([^)]+)\)", doc)
    assert all((ROOT / "docs" / t).exists() for t in targets), targets
