"""The logic behind the GUI defects of issue 30 part 4 (their browser checks:
tests/e2e/test_gui_defects.py): notifications in plain text, tooltips that follow the range."""

from __future__ import annotations

import ast
import json
import re
import socket
from collections.abc import Iterator
from pathlib import Path

import pytest
import viser

from workbench.gui.fields import NumberField
from workbench.gui.notify import plain_text


def test_notifications_drop_markdown_marks_and_keep_the_words() -> None:
    md = "**Collision**: `bending.press` needs a [press](https://example.org/p)  \nnext"
    assert plain_text(md) == "Collision: bending.press needs a press (https://example.org/p)\nnext"
    # what is not markdown stays: a lone asterisk, underscores in a name, a product
    for text in ("3 * 4 mm", "u_channel_cell", "__init__", "a*b*c", "50 % of [0, 1] s"):
        assert plain_text(text) == text
    # the twin: no mark of the three kinds survives, whatever is nested
    nested = "**a `b` [c](d)** and **e**"
    out = plain_text(nested)
    assert "**" not in out and "`" not in out and "](" not in out
    assert out == "a b c (d) and e"


@pytest.fixture
def server() -> Iterator[viser.ViserServer]:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = int(s.getsockname()[1])
    srv = viser.ViserServer(host="127.0.0.1", port=port, verbose=False)
    yield srv
    srv.stop()


def test_the_tooltip_follows_the_range_allowed_now(server: viser.ViserServer) -> None:
    state: dict[str, float | None] = {"max": None}

    def allowed() -> str:
        return (
            "none until a motion is planned" if state["max"] is None else f"[0, {state['max']}] s"
        )

    field = NumberField(server, "Time [s]", get=lambda: 0.0, put=lambda v: None, allowed=allowed)
    assert field.text.hint == "allowed none until a motion is planned"
    state["max"] = 2.5
    field.refresh()
    assert field.text.hint == "allowed [0, 2.5] s"
    given = NumberField(server, "x", get=lambda: 0.0, put=lambda v: None, allowed=allowed, hint="h")
    given.refresh()
    assert given.text.hint == "h"  # a hint given by the panel is kept


RESEARCH = re.compile(r"\b[Ss]eed \d{3}\b|\bFig\. ?\d|\bSec\. ?\d")
ROOT = Path(__file__).resolve().parents[2]


def _strings(tree: ast.AST) -> list[str]:
    """Return the string literals of a module, docstrings left out (they are not shown)."""
    docs = {
        id(n.body[0].value)
        for n in ast.walk(tree)
        if isinstance(n, ast.Module | ast.ClassDef | ast.FunctionDef)
        and n.body
        and isinstance(n.body[0], ast.Expr)
        and isinstance(n.body[0].value, ast.Constant)
    }
    return [
        n.value
        for n in ast.walk(tree)
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docs
    ]


def test_the_gui_and_the_examples_speak_without_research_labels() -> None:
    assert RESEARCH.search("Assembly cell (seed 003, Fig. 11)")  # the pattern finds the old one
    shown = []
    for path in sorted((ROOT / "workbench" / "gui").glob("*.py")):
        shown += [(path.name, s) for s in _strings(ast.parse(path.read_text()))]
    for path in sorted((ROOT / "projects").glob("*.json")):
        data = json.loads(path.read_text())
        shown += [(path.name, str(data.get(k, ""))) for k in ("name", "description")]
    assert [(f, s) for f, s in shown if RESEARCH.search(s)] == []


def test_a_refused_plan_leaves_no_plan_to_export() -> None:
    """A refused "Plan sequence" (or part) drops the last plan: the Assembly tab's Download
    cannot write the previous plan's program; the Bending tab's Plan likewise."""
    from workbench.errors import InputError as Refused
    from workbench.service import Workbench

    wb = Workbench.open(ROOT / "projects" / "assembly_cell.json")
    a = wb.assembly
    first = a.part_names[0]
    plan = a.plan_sequence([first])
    assert a.last_plan is plan and a.last_part_plan is not None
    with pytest.raises(Refused, match="nope"):
        a.plan_sequence(["nope"])
    assert a.last_plan is None and a.last_part_plan is None


class _Plan:
    ok = False

    def summary(self) -> str:
        return "1 colliding sample"


class _Wb:
    def __init__(self) -> None:
        self.forced: list[bool] = []

    def default_program_format(self) -> str:
        return "csv"

    def export_program(self, fmt: str, workflow: str, *, force: bool = False) -> object:
        self.forced.append(force)
        return object()


def test_a_refused_export_offers_export_anyway(
    server: viser.ViserServer, monkeypatch: pytest.MonkeyPatch
) -> None:
    from workbench.errors import PlanningError
    from workbench.gui import program_download

    monkeypatch.setattr(program_download, "latest_plan", lambda wb, workflow: _Plan())
    wb = _Wb()
    d = program_download.ProgramDownload(server, lambda: wb, "assembly", disabled=False)  # type: ignore[arg-type,return-value]
    assert not d.anyway.visible
    with pytest.raises(PlanningError, match='press "Export anyway"') as refused:
        d.export()
    assert "--force" not in str(refused.value)  # the GUI has its own button
    assert d.anyway.visible and wb.forced == []
    d.export(force=True)
    assert wb.forced == [True]
    d.disabled = False  # a new plan: the button belongs to the refused one
    assert not d.anyway.visible


def test_no_box_of_the_gui_reads_a_comma_as_nothing() -> None:
    """viser's number and vector boxes drop a ',' ("12,5" arrives as 125): the GUI types
    numbers only in strict text boxes (`NumberField`), which refuse a decimal comma."""
    from workbench.errors import InputError as Refused
    from workbench.gui.fields import parse_number

    lax = re.compile(r"\.add_(number|vector2|vector3)\(")
    used = [p.name for p in (ROOT / "workbench" / "gui").glob("*.py") if lax.search(p.read_text())]
    assert used == []
    with pytest.raises(Refused, match="decimal comma"):
        parse_number("12,5", "Obstacle at x [mm]")


def test_the_obstacle_position_is_checked_by_the_projects_bounds() -> None:
    from workbench.errors import InputError as Refused
    from workbench.project.common import Pose
    from workbench.service.project_imports import obstacle_coordinate

    assert obstacle_coordinate(1, -12.5) == -12.5
    big = 10 * max(
        abs(v)
        for v in Pose.model_json_schema()["properties"]["xyz"]["items"].values()
        if isinstance(v, (int, float))
    )
    with pytest.raises(Refused, match=r"cell\.objects\[\]\.pose\.xyz\[2\]"):
        obstacle_coordinate(2, big)


def test_the_example_dropdown_finds_the_open_example() -> None:
    from workbench.gui.picker import example_index, examples

    found = examples()
    assert len(found) >= 2
    for i, e in enumerate(found):  # the twin: the list's own order
        assert example_index(found, e.path) == i
        # the same file by another spelling of its path
        assert example_index(found, e.path.parent / ".." / e.path.parent.name / e.path.name) == i
    assert example_index(found, None) is None
    assert example_index(found, ROOT / "README.md") is None
