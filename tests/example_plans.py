"""The example projects' plans, made once per test session and shared by the modules that
only read them (tests/test_example_exports.py, tests/test_program_read_back.py): one
`Workbench` per example and workflow, its robot programs planned by `robot_programs`.

Callers must not change the returned workbench (a test that edits or replans opens its own).
"""

from __future__ import annotations

import functools
from pathlib import Path

from workbench import Workbench
from workbench.motion.programs import RobotProgram

ROOT = Path(__file__).resolve().parents[1]


@functools.cache
def planned(project: str, workflow: str) -> tuple[Workbench, tuple[RobotProgram, ...]]:
    """Return the example `project` (a file name in projects/) opened, and the robot programs
    of its `workflow`, planned once per session."""
    wb = Workbench.open(ROOT / "projects" / project)
    return wb, tuple(wb.robot_programs(workflow))
