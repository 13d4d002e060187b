"""`workbench touchup PROJECT PROGRAM_FILE...`: the table and the fit printed, `--apply MODE
--out` written with the project's save, refusals in one line with exit 2."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tests.cli_run import run_cli
from tests.touchup_cell import CORRECTION, cell_data, touched_up_files
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.project import load_project
from workbench.project.units import pose_to_matrix


@pytest.fixture
def touched(tmp_path: Path) -> tuple[Path, list[str]]:
    """A project and its program touched up on the pendant (KRL: .src and .dat), pick moved
    alone on top of the fixture's move."""
    project = tmp_path / "cell.json"
    project.write_text(json.dumps(cell_data()))
    alone = ("pick", xyz_rpy_to_transform([0.003, 0.0, 0.0], [0.0, 0.0, 0.0]))
    names = []
    for name, text in touched_up_files("krl", alone=alone).items():
        (tmp_path / name).write_text(text)
        names.append(str(tmp_path / name))
    return project, names


def test_touchup_prints_the_table_and_the_fit_and_writes_nothing(touched) -> None:
    project, files = touched
    before = project.read_text()
    r = run_cli("touchup", str(project), *files)
    assert r.returncode == 0, r.stderr
    assert "pick" in r.stdout and "does not fit" in r.stdout
    assert "work object fixture: correction [2.100, -1.400, 0.900] mm" in r.stdout
    assert "moved alone (not folded into fixture): pick" in r.stdout
    assert project.read_text() == before


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--apply", "work_object"], "--apply needs --out"),
        (["--out", "x.json"], "nothing to write without --apply"),
        (["--format", "rapid"], "check that it is a rapid program"),
    ],
)
def test_touchup_refusals_are_one_line_with_exit_2(touched, extra, message) -> None:
    project, files = touched
    r = run_cli("touchup", str(project), *files, *extra)
    assert r.returncode == 2
    assert message in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_a_malformed_program_is_refused_naming_the_file(touched, tmp_path: Path) -> None:
    project, _ = touched
    bad = tmp_path / "broken.ls"
    bad.write_text("/PROG BROKEN\n/MN\n   1:  J P[7] 50% FINE ;\n/END\n")
    r = run_cli("touchup", str(project), str(bad))
    assert r.returncode == 2
    assert r.stderr.startswith("workbench touchup: error: broken.ls:"), r.stderr


@pytest.mark.slow  # plans the touched-up program (about 2 s)
def test_touchup_apply_writes_the_corrected_project_atomically(touched, tmp_path: Path) -> None:
    project, files = touched
    before = project.read_text()
    out = tmp_path / "touched.json"
    r = run_cli("touchup", str(project), *files, "--apply", "work_object", "--out", str(out))
    assert r.returncode == 0, r.stderr
    assert "applied (work_object)" in r.stdout and "collision-free" in r.stdout
    assert project.read_text() == before  # the original stays
    W_old = pose_to_matrix(load_project(project).work_objects[0].pose)
    W_new = pose_to_matrix(load_project(out).work_objects[0].pose)
    np.testing.assert_allclose(np.linalg.inv(W_old) @ W_new, CORRECTION, atol=2e-5)
