"""Importing robot programs: what the posts write comes back as the same program (targets re-solved
through tool, work object and configuration), hand-written forms are read, and what the reader
does not understand is listed by line."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
PROJECT = ROOT / "projects" / "mz07_cell.json"


@pytest.fixture(scope="module")
def planned() -> Workbench:
    wb = Workbench.open(PROJECT)
    wb.plan_motion()
    return wb


@pytest.mark.parametrize("fmt", ["rapid", "krl", "ls", "urscript", "nachi"])
def test_an_exported_program_imports_back_to_the_same_targets(planned: Workbench, fmt: str) -> None:
    out = planned.export_program(fmt, any_vendor=True)  # the MZ07 is NACHI: every post
    wb = Workbench.open(PROJECT)
    start_only = wb.project.program.model_copy(update={"moves": []})  # the cell's start stays
    wb.replace_project(wb.project.model_copy(update={"program": start_only}))
    notes = wb.import_program(out.files)
    assert not [n for n in notes if "not understood" in n], notes
    # the linear targets carry the configuration the program's data selected, before any plan
    planned_confs = [m.configuration for m in planned.project.program.moves if m.type == "linear"]
    imported = [m for m in wb.project.program.moves if m.type == "linear"]
    assert [m.configuration for m in imported] == planned_confs
    assert wb.project.program.start == planned.project.program.start
    # the imported program reaches the planned joints at every target, in order
    a = planned.robot_programs()[0]
    plan = wb.plan_motion()
    b = wb.robot_programs(plan=plan)[0]
    assert [m.kind for m in b.moves] == [m.kind for m in a.moves]
    for ma, mb in zip(a.moves, b.moves, strict=True):
        assert np.max(np.abs(ma.target.q - mb.target.q)) < 1e-6, (fmt, ma.name)
    assert [type(x).__name__ for x in b.actions()] == [type(x).__name__ for x in a.actions()]
    if fmt != "rapid":  # RAPID states joint moves by time (\\T) only: planned at 100 %
        # the first move is written at the safe first-move speed (first_move.py) and imported
        # at it; every later move keeps the planned time
        after_first = [sum(m.duration for m in p.moves[1:]) for p in (a, b)]
        assert after_first[1] == pytest.approx(after_first[0], rel=0.01)


def test_unknown_instructions_are_listed_by_line_and_the_project_stays_on_errors() -> None:
    wb = Workbench.open(PROJECT)
    module = """MODULE hand
    CONST robtarget p1:=[[430,180,580],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        MoveJ p1, v500, z10, tool0;
        ConfL \\Off;
        MoveL Offs(p1, 0, 0, -50), v100, fine, tool0;
    ENDPROC
ENDMODULE
"""
    notes = wb.import_program({"hand.mod": module})
    assert any("line 5" in n and "ConfL" in n for n in notes), notes
    moves = [m for m in wb.project.program.moves if getattr(m, "type", "") in ("joint", "linear")]
    assert [m.type for m in moves] == ["joint", "linear"]
    z = moves[1].pose.xyz[2]
    # tool0 is the flange: the project's tool takes its (identity) TCP, and the Offs target is
    # 50 mm below p1 in the base frame
    assert wb.project.tool.tcp.xyz == pytest.approx([0.0, 0.0, 0.0])
    base_z = wb.project.robot.base.xyz[2]
    assert z == pytest.approx(base_z + 530.0, abs=1e-6)
    before = wb.project
    with pytest.raises(InputError, match="line"):
        wb.import_program(
            {
                "bad.mod": "MODULE x\n PROC main()\n  MoveL nowhere, v100, fine, tool0;\n ENDPROC\nENDMODULE\n"
            }
        )
    assert wb.project is before


def test_a_krl_src_without_its_dat_says_which_file_is_missing() -> None:
    wb = Workbench.open(PROJECT)
    out = Workbench.open(PROJECT).export_program("krl", any_vendor=True)
    src = {k: v for k, v in out.files.items() if k.endswith(".src")}
    with pytest.raises(InputError, match=r"\.dat"):
        wb.import_program(src)


def test_a_file_of_no_known_format_is_refused_naming_it() -> None:
    wb = Workbench.open(PROJECT)
    with pytest.raises(InputError, match="notes.txt"):
        wb.import_program({"notes.txt": "hello"})
