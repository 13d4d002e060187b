"""The press-brake process through the service: bad inputs get clear errors or notes that name
the bend, the tool, the field or the address (issue 13, Done means)."""

from __future__ import annotations

import json
import socket
import time
from pathlib import Path
from typing import Any

import pytest

from workbench import Workbench
from workbench.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
CELL = ROOT / "projects" / "u_channel_cell.json"


def _project(**bending: Any) -> dict[str, Any]:
    data = json.loads(CELL.read_text())
    if "part" in bending:  # another part: the cell's planned order and steps do not apply
        data["bending"].pop("sequence", None)
        data["bending"].pop("steps", None)
    data["bending"].update(bending)
    return data


def _open(data: dict[str, Any]) -> Workbench:
    return Workbench.from_dict(data, base_dir=ROOT / "projects")


def _u_part(a: float, b: float) -> dict[str, Any]:
    part = json.loads((ROOT / "projects/parts/u_channel.json").read_text())
    part["flanges"][1]["polygon"] = [[0, 0], [200, 0], [200, a], [0, a]]
    part["flanges"][2]["polygon"] = [[0, 0], [200, 0], [200, b], [0, b]]
    return part


def test_a_flange_shorter_than_half_the_v_opening_is_refused_naming_it() -> None:
    press = json.loads(CELL.read_text())["bending"]["press"]
    press["die"] = {"v_opening": 70, "width": 100, "height": 80}
    wb = _open(_project(press=press))
    with pytest.raises(InputError) as err:
        wb.bending.find_sequences()
    msg = str(err.value)
    assert "bend 'bB': flange 'B' reaches 25.0 mm from the bend line" in msg
    assert "V/2 = 35 mm" in msg and "bending.press.die.v_opening" in msg
    with pytest.raises(InputError, match="flange 'B' reaches 25.0 mm"):
        wb.bending.plan()


def test_return_flanges_taller_than_the_punch_allows_leave_no_plan_and_name_the_punch() -> None:
    # Both flanges tall: whichever is bent first tilts into the punch when the other is bent.
    data = _project(part=_u_part(110, 110), part_file=None)
    res = _open(data).bending.find_sequences()
    assert res.plans == []
    assert "no feasible sequence" in res.note
    second = {branch: reason for branch, reason in res.rejected if len(branch) == 2}
    assert set(second) == {("bA", "bB"), ("bB", "bA")}
    assert "hits the punch" in second[("bA", "bB")] and "hits the punch" in second[("bB", "bA")]


def test_an_unreachable_back_gauge_stop_names_the_bend_and_the_axis() -> None:
    press = json.loads(CELL.read_text())["bending"]["press"]
    press["backgauge"] = {"x": [5, 20]}
    res = _open(_project(press=press)).bending.find_sequences()
    assert res.plans == []
    reasons = " ".join(r for _, r in res.rejected)
    assert "the back-gauge stop X = " in reasons
    assert "outside its range 5..20 mm (bending.press.backgauge.x)" in reasons


@pytest.mark.slow
def test_twelve_bends_are_bounded_by_the_time_limit() -> None:
    # A corrugated strip: 13 flanges in a chain, 12 gentle bends alternately up and down; far
    # more orders than the limit lets the search try. 25 mm flanges: with 40 mm ones (a 520 mm
    # strip) every grasp the blank allows folds the arm into itself (link2 against link4) in
    # front of the die, and the cheap stage prunes all before the limit.
    n = 12
    flanges = [
        {"name": f"f{i}", "polygon": [[0, 0], [200, 0], [200, 25], [0, 25]]} for i in range(n + 1)
    ]
    bends = [
        {
            "name": f"b{i}",
            "parent": f"f{i}",
            "parent_edge": 2,
            "child": f"f{i + 1}",
            "child_edge": 0,
            "included_angle": 150,
            "direction": "up" if i % 2 else "down",
        }
        for i in range(n)
    ]
    part = {"name": "strip", "thickness": 1.5, "flanges": flanges, "bends": bends}
    wb = _open(_project(part=part, part_file=None, grasp={"flange": "f0"}))
    t0 = time.perf_counter()
    res = wb.bending.find_sequences(time_limit=8.0)
    took = time.perf_counter() - t0
    assert "stopped at the time limit of 8 s" in res.note, res.note
    # the limit bounds the search; a complete order found is still checked once after it
    assert took < 8.0 + 60.0, took
    assert res.stats.candidates > 0
    if not res.plans:
        assert "The deepest order reached: b" in res.note


def _closed_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def test_a_ray_address_that_does_not_answer_is_named() -> None:
    addr = f"127.0.0.1:{_closed_port()}"
    with pytest.raises(InputError, match=addr.replace(".", r"\.")):
        Workbench.open(CELL).bending.find_sequences(engine="ray", address=addr)
