"""The example projects' plans, made once per test session and shared by the modules that
only read them (tests/test_example_exports.py, tests/test_program_read_back.py): one
`Workbench` per example and workflow, its robot programs planned by `robot_programs`; and one
bending plan per press-cell example (`bending_plan`), which the press-brake tests compare with
what they build themselves (a press cycle takes seconds to plan).

Callers must not change the returned workbench (a test that edits or replans opens its own).
"""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from workbench import Workbench
from workbench.motion.programs import RobotProgram
from workbench.pressbrake.result import BendingResult
from workbench.project import load_project

ROOT = Path(__file__).resolve().parents[1]
PROJECTS = sorted((ROOT / "projects").glob("*.json"))


def slow_marks(path: Path, workflow: str) -> tuple[pytest.MarkDecorator, ...]:
    """Return the marks of an example x workflow case: `slow` for

    - a press cell's bending program, which replans its whole cycle (a minute of frames);
    - polishing a panel read from a STEP file (step_cell): once the panel is meshed, its path,
      program and posts are the same code as the STL panel's (polishing_cell, in the unit suite),
      and tests/cad/test_step.py checks that the two panels polish alike. Its cases cost ~18 s of
      the unit suite (issue 26 part 8 moved them to the slow run).
    """
    p = load_project(path)
    press = workflow == "bending" and p.bending is not None and p.bending.press is not None
    step_panel = (
        workflow == "polishing"
        and p.polishing is not None
        and Path(p.polishing.workpiece).suffix.lower() in {".step", ".stp"}
    )
    return (pytest.mark.slow,) if press or step_panel else ()


@functools.cache
def planned(project: str, workflow: str) -> tuple[Workbench, tuple[RobotProgram, ...]]:
    """Return the example `project` (a file name in projects/) opened, and the robot programs
    of its `workflow`, planned once per session."""
    wb = Workbench.open(ROOT / "projects" / project)
    return wb, tuple(wb.robot_programs(workflow))


@functools.cache
def bending_plan(project: str) -> tuple[Workbench, BendingResult]:
    """Return the example `project` opened, and its bending workflow planned once per session
    by the service (`wb.bending.plan()`)."""
    wb = Workbench.open(ROOT / "projects" / project)
    return wb, wb.bending.plan()
