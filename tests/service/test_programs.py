"""wb.robot_programs / wb.export_program: the Motion workflow's program, refusal of a plan with
problems, the registry's formats, and `workbench export` writing one file, a folder or a zip."""

from __future__ import annotations

import json
import subprocess
import zipfile
from pathlib import Path

import pytest
from cli_run import run_cli

from workbench import Workbench
from workbench.errors import InputError, PlanningError, WorkbenchError
from workbench.motion.programs import EXPORT_FORMATS, PROGRAM_FORMATS

ROOT = Path(__file__).resolve().parents[2]
MZ07 = ROOT / "projects" / "mz07_cell.json"


@pytest.fixture(scope="module")
def wb() -> Workbench:
    w = Workbench.open(MZ07)
    w.plan_motion()
    return w


def test_the_motion_program_is_the_plans(wb: Workbench) -> None:
    (program,) = wb.robot_programs("motion")
    plan = wb.last_plan
    assert plan is not None and program.name == plan.program.name == "pick_place"
    assert [m.name for m in program.moves] == [m.name for m in plan.program.moves]
    assert program.tools[0].mass == 2.0 and program.robot == "MZ07"
    # the moves and the waits (the gripper's settle times) take the plan's time
    assert program.cycle_time == pytest.approx(plan.cycle_time)
    assert sum(m.duration for m in program.moves) < plan.cycle_time
    assert [type(a).__name__ for a in program.actions()].count("SetOutput") == 2  # grip, release


@pytest.mark.parametrize("fmt", sorted(EXPORT_FORMATS))
def test_every_format_exports_files_with_names(wb: Workbench, fmt: str) -> None:
    out = wb.export_program(fmt, any_vendor=True)  # the MZ07 is NACHI: every post
    assert out.files and all(name and text.strip() for name, text in out.files.items())
    if fmt in PROGRAM_FORMATS:
        text = "\n".join(out.files.values())
        assert "pick" in text.lower() or fmt == "nachi"


def test_bad_format_and_workflow_are_named(wb: Workbench) -> None:
    with pytest.raises(
        InputError, match="format: 'gcode' is not one of rapid, krl, ls, urscript, nachi"
    ):
        wb.export_program("gcode")
    with pytest.raises(InputError, match="workflow: 'welding' is not one of motion, bending"):
        wb.robot_programs("welding")


def test_a_colliding_plan_is_refused_unless_forced() -> None:
    data = json.loads(MZ07.read_text())
    data["cell"]["objects"].append(
        {"name": "crate", "shape": "box", "size": [200, 120, 200], "pose": {"xyz": [430, 0, 580]}}
    )
    wb = Workbench.from_dict(data, base_dir=MZ07.parent)
    with pytest.raises(PlanningError, match="the plan has problems: .*crate.*force=True"):
        wb.export_program("rapid", any_vendor=True)
    assert wb.last_plan is not None and not wb.last_plan.ok
    assert "MoveL" in wb.export_program("rapid", force=True, any_vendor=True).text


def test_a_plan_closer_than_the_margin_is_refused_naming_the_pair(wb: Workbench) -> None:
    """The example keeps the default margin; a margin above its clearance refuses the export,
    naming the pair and the distance (the figure is python-fcl's over the plan's samples)."""
    plan = wb.last_plan
    assert plan is not None and plan.ok
    near = plan.collision_report.nearest
    assert near is not None and near.pair is not None and near.keeps_margin
    assert near.margin == pytest.approx(0.0005)  # the default, 0.5 mm
    data = json.loads(MZ07.read_text())
    data["collision"] = {"margin": near.distance * 1e3 + 5.0}  # mm
    tight = Workbench.from_dict(data, base_dir=MZ07.parent)
    a, b = near.pair
    with pytest.raises(PlanningError, match=f"{a} comes within .* mm of {b}.*force=True"):
        tight.export_program("csv")
    assert tight.last_plan is not None and not tight.last_plan.ok
    assert tight.last_plan.collision_report.collision_free  # no contact: the margin only
    assert tight.export_program("csv", force=True).files
    # The margin set through the service is the one the next export uses.
    tight.collision.set_margin(near.distance / 2)
    assert tight.export_program("csv").files


@pytest.mark.parametrize("bad", [float("nan"), -1.0, 1e6])
def test_a_bad_margin_is_refused_naming_the_field(bad: float) -> None:
    data = json.loads(MZ07.read_text())
    data["collision"] = {"margin": 1.0}
    w = Workbench.from_dict(data, base_dir=MZ07.parent)
    with pytest.raises(InputError, match=r"collision\.margin"):
        w.collision.set_margin(bad / 1e3)
    assert w.collision.margin == pytest.approx(0.001)
    data["collision"] = {"margin": bad}
    with pytest.raises(WorkbenchError, match="margin"):
        Workbench.from_dict(data, base_dir=MZ07.parent)


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    return run_cli("export", str(MZ07), *args)  # in this process (tests/cli_run.py)


def test_cli_writes_a_file_a_folder_or_a_zip(tmp_path: Path) -> None:
    res = _cli("--format", "rapid", "--any-vendor", "--out", str(tmp_path / "cell.mod"))
    assert res.returncode == 0, res.stderr
    assert (tmp_path / "cell.mod").read_text().startswith("MODULE pick_place")
    res = _cli("--format", "krl", "--any-vendor", "--out", str(tmp_path / "krl"))
    assert res.returncode == 0, res.stderr
    assert sorted(p.name for p in (tmp_path / "krl").iterdir()) == [
        "pick_place.dat",
        "pick_place.src",
    ]
    res = _cli(
        "--format", "krl", "--any-vendor", "--workflow", "motion", "--out", str(tmp_path / "krl.zip")
    )  # fmt: skip
    assert res.returncode == 0, res.stderr
    with zipfile.ZipFile(tmp_path / "krl.zip") as zf:
        assert sorted(zf.namelist()) == ["pick_place.dat", "pick_place.src"]
        assert (
            zf.read("pick_place.src").decode() == (tmp_path / "krl" / "pick_place.src").read_text()
        )


def test_cli_out_folder_gets_the_exports_own_file_names(tmp_path: Path) -> None:
    # DIR/ (a trailing slash): created, with its parents, and the export's file names in it
    res = _cli("--out", f"{tmp_path / 'new' / 'nachi'}/")
    assert res.returncode == 0, res.stderr
    names = sorted(p.name for p in (tmp_path / "new" / "nachi").iterdir())
    assert names == ["MZ07-01-A.001"]  # the one file the MZ07's NACHI export writes
    # an existing folder (no slash) is a folder too, also for a one-file export
    (tmp_path / "rapid").mkdir()
    res = _cli("--format", "rapid", "--any-vendor", "--out", str(tmp_path / "rapid"))
    assert res.returncode == 0, res.stderr
    assert [p.name for p in (tmp_path / "rapid").iterdir()] == ["pick_place.mod"]
    text = (tmp_path / "rapid" / "pick_place.mod").read_text()
    assert text.startswith("MODULE pick_place")
    # a name with a dot and a slash is a folder, not a file with a suffix
    res = _cli("--format", "krl", "--any-vendor", "--out", f"{tmp_path / 'krl.v2'}/")
    assert res.returncode == 0, res.stderr
    assert sorted(p.name for p in (tmp_path / "krl.v2").iterdir()) == [
        "pick_place.dat",
        "pick_place.src",
    ]


def test_cli_force_writes_a_plan_with_problems_and_exits_0(tmp_path: Path) -> None:
    data = json.loads(MZ07.read_text())
    data["cell"]["objects"].append(
        {"name": "crate", "shape": "box", "size": [200, 120, 200], "pose": {"xyz": [430, 0, 580]}}
    )
    project = tmp_path / "crate.json"
    project.write_text(json.dumps(data))
    out = tmp_path / "out" / "pick_place.001"
    (tmp_path / "out").mkdir()
    refused = run_cli("export", str(project), "--out", str(out))
    assert refused.returncode == 1 and not out.exists()
    assert "crate" in refused.stdout and "--force" in refused.stderr
    forced = run_cli("export", str(project), "--out", str(out), "--force")
    assert forced.returncode == 0, forced.stderr
    assert out.read_text().startswith("' PROGRAM ")
    assert "crate" in forced.stdout and "written anyway (--force)" in forced.stderr


def test_cli_takes_the_vendors_format_and_refuses_another_unless_any_vendor(
    tmp_path: Path,
) -> None:
    res = _cli("--out", str(tmp_path / "nachi"))  # no --format: the MZ07's NACHI
    assert res.returncode == 0, res.stderr
    assert "(motion, nachi)" in res.stdout
    res = _cli("--format", "rapid", "--out", str(tmp_path / "cell.mod"))
    assert res.returncode != 0 and not (tmp_path / "cell.mod").exists()
    assert "'NACHI MZ07'" in res.stderr and "'nachi'" in res.stderr and "--any-vendor" in res.stderr
