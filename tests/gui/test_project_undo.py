"""The Project tab's undo of an applied calibration or touch-up (workbench/gui/project_undo.py)."""

from __future__ import annotations

import pytest

from workbench.errors import InputError
from workbench.gui.csv_box import decode_csv
from workbench.gui.project_undo import DEPTH, ProjectUndo
from workbench.service import Workbench


def _wb() -> Workbench:
    return Workbench.from_dict({"schema_version": 2, "name": "undo"})


def _apply_tcp(wb: Workbench, z_mm: float):  # type: ignore[no-untyped-def]
    """What a calibration's apply does: a new project replaces the old, which is returned."""
    previous = wb.project
    new = previous.model_copy(deep=True)
    new.tool.tcp.xyz = [0.0, 0.0, z_mm]
    wb.replace_project(new)
    return previous


def test_undo_puts_the_project_before_the_apply_back() -> None:
    wb = _wb()
    undo = ProjectUndo(lambda: wb)
    seen: list[str | None] = []
    undo.listeners.append(lambda: seen.append(undo.last))
    undo.push("tcp calibration", _apply_tcp(wb, 150.0))
    undo.push("second tcp calibration", _apply_tcp(wb, 160.0))
    assert wb.project.tool.tcp.xyz == [0.0, 0.0, 160.0]
    wb.set_joints(wb.joints + 0.1)  # a jog is no edit: the undo still applies
    assert undo.undo(wb.replace_project) == "second tcp calibration"
    assert wb.project.tool.tcp.xyz == [0.0, 0.0, 150.0]
    assert undo.undo(wb.replace_project) == "tcp calibration"
    assert wb.project.tool.tcp.xyz == [0.0, 0.0, 0.0]
    assert seen == ["tcp calibration", "second tcp calibration", "tcp calibration", None]
    with pytest.raises(InputError, match="nothing to undo"):
        undo.undo(wb.replace_project)


def test_undo_is_refused_after_another_change_and_keeps_that_change() -> None:
    wb = _wb()
    undo = ProjectUndo(lambda: wb)
    undo.push("tcp calibration", _apply_tcp(wb, 150.0))
    wb.project.tool.mass = 3.0  # an edit after the apply (as the program editor makes them)
    with pytest.raises(InputError, match="changed after 'tcp calibration'"):
        undo.undo(wb.replace_project)
    assert wb.project.tool.mass == 3.0 and wb.project.tool.tcp.xyz == [0.0, 0.0, 150.0]
    assert undo.last == "tcp calibration"  # still there: nothing was taken back
    undo.clear()
    assert undo.last is None


def test_only_the_last_applies_are_kept() -> None:
    wb = _wb()
    undo = ProjectUndo(lambda: wb)
    for k in range(DEPTH + 3):  # pushes only: what an apply returns is not needed here
        undo.push(f"apply {k}", wb.project)
    assert len(undo.stack) == DEPTH
    assert [a.what for a in undo.stack] == [f"apply {k}" for k in range(3, DEPTH + 3)]


def test_an_uploaded_csv_is_text_or_refused_naming_the_box() -> None:
    assert (
        decode_csv("Readings (CSV)", "r.csv", b"\xef\xbb\xbflabel,x\r\na,1\r\n") == "label,x\na,1\n"
    )
    with pytest.raises(InputError, match=r"^Readings \(CSV\): r.csv is not UTF-8 text"):
        decode_csv("Readings (CSV)", "r.csv", b"\xff\xfe\x00a")
    with pytest.raises(InputError, match="binary"):
        decode_csv("Readings (CSV)", "r.csv", b"label\x00")
    with pytest.raises(InputError, match="at most"):
        decode_csv("Readings (CSV)", "r.csv", b"a" * 1_000_001)
