"""Every example project x every workflow it has x every export format, through the service's
export (`wb.export_program`, what `workbench export` writes), read back (issue 12, Done means).

- The example's plan is collision-free and within limits: the export is not refused.
- Robot-program formats: the export's files are exactly the post's files of each robot program
  (one program per robot: the assembly cell gives two), and each program's files read back by
  the format's reader (`motion.programs.reader(fmt)`) pass `check_read_back`
  (tests/program_round_trip.py): targets re-solved by their configuration data give the
  planned joints, poses, actions in order, speeds or durations; signals by name for RAPID, by
  number for the others; FANUC's CNT has 1 mm steps (zone_tol 1 mm).
- Every signal the example's io names for its workflow is used by the program (gripper,
  press handshake, sync handshake): the examples write real I/O, not comments.
- Sample formats (csv, json): the files load back (`load_csv` / `load_json`) to the plan's
  times and joints.

Plans are made once per example and workflow and session (tests/example_plans.py) and shared by
the formats and by tests/test_program_read_back.py.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from example_plans import PROJECTS, planned, slow_marks
from program_round_trip import check_read_back

from workbench import Workbench
from workbench.motion.programs import (
    EXPORT_FORMATS,
    PROGRAM_FORMATS,
    RobotProgram,
    SyncPoint,
    load_csv,
    load_json,
    post,
    reader,
    to_robot_program,
)
from workbench.motion.programs.first_move import safe_start
from workbench.motion.programs.nachi import unit_name, write_nachi
from workbench.motion.programs.readback import in_robot_base
from workbench.motion.programs.urscript import blend_radii
from workbench.project import load_project
from workbench.service.programs import convention_of, latest_plan, robot_models

ROOT = Path(__file__).resolve().parents[1]


def _workflows(path: Path) -> list[str]:
    return load_project(path).workflows()


CASES = [
    pytest.param(path.name, wf, fmt, id=f"{path.stem}-{wf}-{fmt}", marks=slow_marks(path, wf))
    for path in PROJECTS
    for wf in _workflows(path)
    for fmt in EXPORT_FORMATS
]


def _planned(project: str, workflow: str) -> tuple[Workbench, tuple[RobotProgram, ...]]:
    return planned(project, workflow)  # once per session, shared (tests/example_plans.py)


def _model(wb: Workbench, workflow: str, program: RobotProgram):  # noqa: ANN202
    return wb.assembly.arms[program.robot].setup.model if workflow == "assembly" else wb.robot


def _sample_sets(wb: Workbench, workflow: str, plan) -> list[tuple[np.ndarray, np.ndarray]]:  # noqa: ANN001
    """Return the plan's (times [s], joints [rad]) sample sets, one per robot, in the robot's
    controller convention (what the samples state, as the pendant shows joints)."""
    if workflow == "assembly":
        return [
            (np.asarray(m.times), convention_of(wb, name).to_controller(np.asarray(m.joints)))
            for name, m in plan.motions.items()
        ]
    q = plan.positions if hasattr(plan, "positions") else plan.joints  # a MotionPlan: positions
    return [(np.asarray(plan.times), wb.robot.convention.to_controller(np.asarray(q)))]


def _signal_names(program: RobotProgram) -> set[str]:
    names = set()
    for a in program.actions():
        for s in (
            getattr(a, "signal", None),
            getattr(a, "output", None),
            getattr(a, "input", None),
        ):
            if s is not None:
                names.add(s.name)
    return names


def test_every_example_has_a_workflow_and_every_workflow_an_example() -> None:
    found = {wf for path in PROJECTS for wf in _workflows(path)}
    assert found == {"motion", "bending", "assembly", "polishing"}
    assert len(CASES) == sum(len(_workflows(p)) for p in PROJECTS) * len(EXPORT_FORMATS)


@pytest.mark.parametrize(("project", "workflow", "fmt"), CASES)
def test_example_exports_and_reads_back(
    project: str, workflow: str, fmt: str, tmp_path: Path
) -> None:
    wb, programs = _planned(project, workflow)
    plan = latest_plan(wb, workflow)
    assert plan.ok, plan.summary()
    # refused (PlanningError) if not ok; the examples' MZ07 is NACHI: every post allowed
    out = wb.export_program(fmt, workflow=workflow, any_vendor=True)
    assert out.files and all(text.strip() for text in out.files.values())
    if fmt not in PROGRAM_FORMATS:
        written = out.write_to(tmp_path)
        assert len(written) == len(out.files)
        load = load_csv if fmt == "csv" else load_json
        expected = _sample_sets(wb, workflow, plan)
        assert len(written) == len(expected)
        for path in written:
            t, q = load(path)
            head = path.read_text().splitlines()[0] if fmt == "csv" else path.read_text()
            assert (
                ("J1 controller [rad]" in head)
                if fmt == "csv"
                else ('"joints": "controller"' in head)
            )
            assert any(
                t.shape == t0.shape
                and np.allclose(t, t0, atol=1e-6)
                and np.allclose(q, q0, atol=1e-6)
                for t0, q0 in expected
            ), f"{path.name}: not one of the plan's sample sets"
        return
    write, read_fn = post(fmt), reader(fmt)
    assert write is not None and read_fn is not None
    names: set[str] = set()
    if fmt == "nachi":  # named <model>-<unit>-A.001: the unit is the robot's place in the cell
        models = robot_models(wb, list(programs))
        units = {
            p.name: unit_name(m, k)
            for k, (p, m) in enumerate(zip(programs, models, strict=True), 1)
        }
        write = lambda p: write_nachi(p, unit=units[p.name], number=1)  # noqa: E731
        assert all(n.endswith("-A.001") and n.startswith("MZ07-0") for n in out.files), out.files
    for program in programs:
        own = write(program).files
        for name, text in own.items():
            assert out.files.get(name) == text, f"{name}: the export differs from the post's"
        names |= set(own)
        read = read_fn(own)
        if fmt == "rapid":  # MultiMove: the tasks' work objects are in the shared world
            read = in_robot_base(read, program.T_world_base)
        check_read_back(
            program,
            read,
            _model(wb, workflow, program),
            signals_by="name" if fmt == "rapid" else "number",
            zone_tol=1e-3 if fmt == "ls" else 1e-4,
            joint_zones=fmt != "ls",
            zones=blend_radii(safe_start(program)) if fmt == "urscript" else None,
        )
        if fmt == "urscript":
            _check_ur_blends(read, _model(wb, workflow, program))
        assert not read.unknown, read.unknown[:3]
    assert names == set(out.files), "the export holds files no program wrote (or misses some)"


def _check_ur_blends(read, model) -> None:  # noqa: ANN001
    """Brute force over a UR program as read back: every waypoint's TCP from FK of its joints
    (the planned joints the reader returns), and for every pair of neighbouring blends
    r_i + r_(i+1) <= the distance between waypoints i and i+1, each r at most half of either
    segment it touches (UR's rule: blends never overlap)."""
    rp = to_robot_program(read, model)
    pts = []
    for mv in rp.moves:
        tool = rp.tool(mv.tool).T_flange_tcp
        pts.append((model.fk(mv.target.q) @ tool)[:3, 3])
        if mv.kind == "circular":
            raise AssertionError("no circular moves in the examples' UR programs")
    r = [m.zone for m in rp.moves]
    for i in range(len(pts) - 1):
        seg = float(np.linalg.norm(pts[i + 1] - pts[i]))
        assert r[i] + r[i + 1] <= seg + 1e-9, (i, r[i], r[i + 1], seg)
        assert r[i] <= 0.5 * seg + 1e-9 and r[i + 1] <= 0.5 * seg + 1e-9, (i, r[i], r[i + 1], seg)
    assert r[-1] == 0.0


@pytest.mark.parametrize(
    "project",
    [
        pytest.param(p.name, id=p.name, marks=slow_marks(p, _workflows(p)[0]))
        for p in PROJECTS
        if load_project(p).io is not None
    ],
)
def test_the_examples_io_is_used_by_their_programs(project: str) -> None:
    path = ROOT / "projects" / project
    io = load_project(path).io
    assert io is not None
    (workflow,) = _workflows(path)
    _, programs = _planned(project, workflow)
    used = set().union(*(_signal_names(p) for p in programs))
    declared = {s.name for s in io.outputs} | {s.name for s in io.inputs}
    if io.gripper is not None:  # a gripper without its confirming input is not used by "open"
        declared -= {n for n in (io.gripper.opened_input, io.gripper.closed_input) if n is None}
    assert declared <= used, f"declared but not used: {sorted(declared - used)}"
    if workflow == "assembly":
        syncs = [[a.name for a in p.actions() if isinstance(a, SyncPoint)] for p in programs]
        assert len(syncs) == 2 and syncs[0] and syncs[0] == syncs[1]
