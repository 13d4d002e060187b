"""`workbench calibrate`: the worked example of docs/calibration.md run on its files, the
round trip with --apply (the written project reopens with the new TCP, base and work object),
and refusals as one line with exit code 2."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import numpy as np
import pytest
from cli_run import run_cli

from workbench.service import Workbench

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = "examples/calibration"
DOC = ROOT / "docs" / "calibration.md"


def _commands() -> list[list[str]]:
    """Return the `workbench calibrate ...` commands of the docs' worked example, in order."""
    block = re.search(r"```sh\n(.*?)```", DOC.read_text(), re.S)
    assert block, "docs/calibration.md has no ```sh block"
    lines = " ".join(block.group(1).replace("\\\n", " ").splitlines()).split("workbench ")
    return [line.split() for line in lines if line.strip().startswith("calibrate")]


def test_the_docs_worked_example_runs_and_reopens_calibrated(tmp_path: Path) -> None:
    commands = _commands()
    assert [c[1] for c in commands] == ["tcp", "base", "wobj", "wobj"]
    cell = tmp_path / "cell.json"
    outputs = []
    for args in commands:
        args = [str(cell) if a == "cell.json" else a for a in args]
        args = [
            str(ROOT / "projects" / "mz07_cell.json") if a.endswith("mz07_cell.json") else a
            for a in args
        ]
        done = run_cli(*args)
        assert done.returncode == 0, done.stderr
        outputs.append(done.stdout)
    wb = Workbench.open(cell)
    assert wb.project.tool.tcp.xyz == pytest.approx([1.8, -0.6, 152.4], abs=0.3)  # the truth
    assert wb.project.robot.base.xyz == pytest.approx([2.5, -1.5, 0.0], abs=0.5)
    assert wb.project.robot.base.rpy[2] == pytest.approx(0.3, abs=0.05)
    fixture = {w.name: w.pose for w in wb.project.work_objects or []}["fixture"]
    assert fixture.xyz == pytest.approx([420.0, -80.0, 120.0], abs=0.5)
    assert fixture.rpy == pytest.approx([0.0, 0.0, 15.0], abs=0.15)
    assert "dropped as outliers: hole3" in outputs[3]
    for out in outputs:  # what the page shows is what the command prints
        for line in out.splitlines()[1:3]:
            assert line.strip() in DOC.read_text(), line


def test_the_docs_python_example_runs(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    block = re.search(r"```python\n(.*?)```", DOC.read_text(), re.S)
    assert block, "docs/calibration.md has no ```python block"
    monkeypatch.chdir(ROOT)
    scope: dict[str, object] = {}
    exec(compile(block.group(1), "docs/calibration.md", "exec"), scope)
    assert "TCP of tool 'gripper'" in capsys.readouterr().out
    wb = scope["wb"]
    assert wb.project.tool.tcp.xyz == [0.0, 0.0, 150.0]  # type: ignore[attr-defined]  # undone


def test_apply_writes_out_and_leaves_the_project_alone(tmp_path: Path) -> None:
    project = tmp_path / "p.json"
    shutil.copy(ROOT / "projects" / "mz07_cell.json", project)
    before = project.read_bytes()
    out = tmp_path / "calibrated.json"
    done = run_cli(
        "calibrate",
        "tcp",
        str(project),
        f"{EXAMPLE}/tcp_readings.csv",
        "--apply",
        "--out",
        str(out),
    )
    assert done.returncode == 0, done.stderr
    assert project.read_bytes() == before
    tcp = Workbench.open(out).setup.T_flange_tcp
    assert np.allclose(tcp[:3, 3], [0.0018, -0.0006, 0.1524], atol=3e-4)
    assert "mean error" in done.stdout and "residuals [mm]: p1" in done.stdout


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            ["tcp", "projects/mz07_cell.json", f"{EXAMPLE}/fixture_points.csv"],
            "needs joint readings",
        ),
        (
            ["wobj", "projects/mz07_cell.json", f"{EXAMPLE}/fixture_points.csv", "--name", "f"],
            "three-point labels",
        ),
        (
            [
                "wobj",
                "projects/mz07_cell.json",
                f"{EXAMPLE}/fixture_points.csv",
                "--name",
                "f",
                "--method",
                "fit",
            ],
            "give the known points",
        ),
        (["tcp", "projects/mz07_cell.json", f"{EXAMPLE}/missing.csv"], "no such file"),
        (
            ["tcp", "projects/mz07_cell.json", f"{EXAMPLE}/cell_known.csv"],
            r"cell_known.csv line 2, column 2 \(x\)|needs joint readings",
        ),
        (
            ["tcp", "projects/mz07_cell.json", f"{EXAMPLE}/tcp_readings.csv", "--out", "x.json"],
            "give --apply",
        ),
    ],
)
def test_refusals_are_one_line_and_exit_2(args: list[str], message: str) -> None:
    done = run_cli("calibrate", *args)
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and re.search(message, lines[0]), done.stderr
    assert lines[0].startswith("workbench calibrate: error: ")
