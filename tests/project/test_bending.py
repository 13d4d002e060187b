"""The `bending` section's press brake and bend process (mm, deg, mm/s), converted once to SI."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from workbench.errors import ProjectError
from workbench.pressbrake.airbend import air_bend_radius
from workbench.pressbrake.grasp import Grasp, T_flange_grasp
from workbench.pressbrake.press import punch_profile
from workbench.project.bending import BendingSI, GraspSpec, PartSpec
from workbench.project.io import project_from_dict
from workbench.sheetmetal import SheetMetalPart

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "projects" / "bending_cell.json"
SEED_PART = ROOT / "projects" / "parts" / "seed_part.json"
SEQUENCE = ["b23", "b45", "b12", "b14", "b16", "b17"]  # the seed part's own


def example_dict() -> dict[str, Any]:
    return json.loads(EXAMPLE.read_text())


def inline_dict() -> dict[str, Any]:
    """The example with the seed part inline (so the section's own checks apply at load)."""
    d = example_dict()
    del d["bending"]["part_file"]
    d["bending"]["part"] = json.loads(SEED_PART.read_text())
    return d


def si_of(d: dict[str, Any], base: Path = EXAMPLE.parent) -> BendingSI:
    spec = project_from_dict(d).bending
    assert spec is not None
    return spec.to_si(spec.read_part(base))


def steps(names: list[str], **extra: Any) -> list[dict[str, Any]]:
    return [{"bend": n, "grasp": {"flange": "1"}, **extra} for n in names]


def problems_of(d: dict[str, Any]) -> dict[str, str]:
    with pytest.raises(ProjectError) as info:
        project_from_dict(d)
    return dict(info.value.problems)


# -- defaults in SI ---------------------------------------------------------------------------------
def test_the_default_press_and_process_in_si() -> None:
    d = example_dict()
    d["bending"]["press"] = {}
    si = si_of(d)
    press = si.press
    assert press is not None
    np.testing.assert_allclose(press.T_world_die, si.die.T_world_die, atol=0)
    assert press.die.v_opening == pytest.approx(0.012)
    assert press.die.width == pytest.approx(0.040) and press.die.height == pytest.approx(0.060)
    assert press.die.shoulder_radius == pytest.approx(0.001)
    assert press.die.angle == pytest.approx(np.radians(86.0))
    assert press.punch.tip_angle == pytest.approx(np.radians(86.0))
    assert press.punch.tip_radius == pytest.approx(0.001)
    np.testing.assert_allclose(
        press.punch.profile, punch_profile(0.026, 0.120, np.radians(86.0)), atol=1e-15
    )
    assert press.punch.height == pytest.approx(0.120)
    assert press.ram.bending_speed == pytest.approx(0.01)
    assert press.ram.approach_speed == pytest.approx(0.1) == press.ram.return_speed
    assert press.ram.open == pytest.approx(0.15)
    ((station,),) = [press.stations]
    assert station.name == "S1" and station.x == 0.0
    assert station.punch_length == station.die_length == pytest.approx(si.die.length) == 0.8
    bg = press.backgauge
    np.testing.assert_allclose(bg.finger, (0.02, 0.03, 0.04))
    np.testing.assert_allclose(bg.x_range, (0.005, 0.6))
    np.testing.assert_allclose(bg.r_range, (0.0, 0.1))
    np.testing.assert_allclose(bg.z_range, (-0.4, 0.4))
    assert bg.fingers == 2
    assert press.radius_ratio == 0.16 and press.tolerance == pytest.approx(0.0005)
    assert press.frame_gap == pytest.approx(0.1) and press.beam_height == pytest.approx(0.25)
    np.testing.assert_allclose(press.housing, (0.3, 0.08))
    assert press.where == "bending.press"
    # the bend process
    assert si.steps is None and si.follow is True
    assert si.lift == pytest.approx(0.08)
    np.testing.assert_allclose(si.approach, [0.0, -0.08, 0.03])
    np.testing.assert_allclose(si.blank, np.eye(4), atol=0)
    np.testing.assert_allclose(si.regrip, np.eye(4), atol=0)


def test_no_press_by_default_and_the_example_is_unchanged() -> None:
    si = si_of(example_dict())
    assert si.press is None and si.steps is None
    assert [b.inner_radius for b in si.part.bends] == pytest.approx(
        [0.0015, 0.0015, 0.0015, 0.0015, 0.003, 0.003]
    )


def test_process_fields_in_si() -> None:
    d = example_dict()
    b = d["bending"]
    b["blank"] = {"xyz": [100, -500, 20], "rpy": [0, 0, 90]}
    b["regrip"] = {"xyz": [0, 400, 300], "rpy": [180, 0, 0]}
    b["approach"] = [0, -120, 10]
    b["lift"] = 50
    b["follow"] = False
    si = si_of(d)
    np.testing.assert_allclose(si.blank[:3, 3], [0.1, -0.5, 0.02])
    np.testing.assert_allclose(si.blank[:3, 0], [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(si.regrip[:3, 2], [0, 0, -1], atol=1e-15)
    np.testing.assert_allclose(si.approach, [0, -0.12, 0.01])
    assert si.lift == pytest.approx(0.05) and si.follow is False


# -- a given profile, stations ----------------------------------------------------------------------
PROFILE = [[0, 0], [8, 10], [8, 90], [30, 90], [30, 110], [-10, 110], [-10, 10]]  # CCW, tip at 0


def test_a_custom_profile_and_stations_round_trip() -> None:
    d = example_dict()
    d["bending"]["press"] = {
        "punch": {"profile": PROFILE, "tip_angle": 60},
        "stations": [
            {"name": "L", "x": -250, "punch_length": 200, "die_length": 250},
            {"name": "R", "x": 250, "punch_length": 300, "die_length": 300},
        ],
    }
    project = project_from_dict(d)
    again = project_from_dict(project.model_dump(mode="json", exclude_none=True))
    assert again == project
    assert again.bending is not None and again.bending.press is not None
    assert again.bending.press.punch.profile == PROFILE
    press = si_of(d).press
    assert press is not None
    np.testing.assert_allclose(press.punch.profile, np.array(PROFILE) * 1e-3, atol=1e-15)
    assert press.punch.tip_angle == pytest.approx(np.radians(60))
    assert [(s.name, s.x, s.punch_length, s.die_length) for s in press.stations] == [
        ("L", pytest.approx(-0.25), pytest.approx(0.2), pytest.approx(0.25)),
        ("R", pytest.approx(0.25), pytest.approx(0.3), pytest.approx(0.3)),
    ]
    assert press.length == pytest.approx(0.8)


# -- bad input names the field ----------------------------------------------------------------------
def _press(**kw: Any) -> dict[str, Any]:
    d = example_dict()
    d["bending"]["press"] = kw
    return d


def _inline_steps(names: list[str], **press: Any) -> dict[str, Any]:
    d = inline_dict()
    d["bending"]["steps"] = steps(names)
    if press:
        d["bending"]["press"] = press
    return d


BAD = [
    (
        _press(punch={"profile": PROFILE[::-1]}),
        "bending.press.punch.profile",
        "must be counter-clockwise",
    ),
    (
        _press(punch={"profile": [[-5, 0], [5, 0], [5, 50], [-5, 50]]}),
        "bending.press.punch.profile",
        "the tip must be a vertex at [0, 0]",
    ),
    (
        _press(punch={"profile": [[0, 1], [5, 50], [-5, 50]]}),
        "bending.press.punch.profile",
        "min z = 1 mm",
    ),
    (
        _press(punch={"width": 200, "tip_angle": 30}),
        "bending.press.punch",
        "above the punch's height 120 mm",
    ),
    (
        _press(die={"v_opening": 50}),
        "bending.press.die.v_opening",
        "must be < the die's width 40 mm, got 50",
    ),
    (
        _press(die={"v_opening": 40}),
        "bending.press.die.v_opening",
        "must be < the die's width 40 mm, got 40",
    ),
    (_press(die={"angle": 180}), "bending.press.die.angle", "must be < 180 deg"),
    (_press(punch={"tip_angle": 0}), "bending.press.punch.tip_angle", "out of range"),
    (
        _press(backgauge={"x": [600, 5]}),
        "bending.press.backgauge.x",
        "min <= max, got [600.0, 5.0]",
    ),
    (_press(backgauge={"fingers": 5}), "bending.press.backgauge.fingers", "[1, 4]"),
    (_press(ram={"bending_speed": 0}), "bending.press.ram.bending_speed", "(0, 1000] mm/s"),
    (_press(tolerance=6), "bending.press.tolerance", "(0, 5] mm"),
    (_press(radius_ratio=0), "bending.press.radius_ratio", "out of range"),
    (
        _press(
            stations=[
                {"name": "A", "punch_length": 100, "die_length": 100},
                {"name": "A", "x": 300, "punch_length": 100, "die_length": 100},
            ]
        ),
        "bending.press.stations[1].name",
        "repeats the station 'A'",
    ),
    (
        _inline_steps(SEQUENCE[:2] + ["S9"] + SEQUENCE[3:]),
        "bending.steps[2].bend",
        "expected 'b12', got 'S9'",
    ),
    (
        _inline_steps(["b45", "b23"] + SEQUENCE[2:]),
        "bending.steps[0].bend",
        "expected 'b23', got 'b45'",
    ),
    (_inline_steps(SEQUENCE[:5]), "bending.steps", "add one for each of ['b17']"),
    (_inline_steps([*SEQUENCE, "b17"]), "bending.steps[6].bend", "one step more"),
]


@pytest.mark.parametrize(("data", "field", "words"), BAD)
def test_bad_press_or_steps_name_the_field(data: dict[str, Any], field: str, words: str) -> None:
    problems = problems_of(data)
    assert field in problems, problems
    assert words in problems[field], problems[field]


def test_an_unknown_station_in_steps_names_the_step() -> None:
    d = example_dict()  # part_file: the station is checked at load all the same
    d["bending"]["steps"] = steps(SEQUENCE, station="S2")
    assert problems_of(d)["bending.steps[0].station"] == "no station 'S2'; stations are ['S1']"
    d["bending"]["press"] = {
        "stations": [{"name": "A", "punch_length": 100, "die_length": 100}],
    }
    d["bending"]["steps"][3]["station"] = "A"
    problems = problems_of(d)
    assert problems["bending.steps[0].station"] == "no station 'S2'; stations are ['A']"
    assert "bending.steps[3].station" not in problems


def test_an_unknown_grasp_flange_in_steps_names_the_step() -> None:
    d = _inline_steps(SEQUENCE)
    d["bending"]["steps"][4]["grasp"]["flange"] = "9"
    assert "no flange '9'" in problems_of(d)["bending.steps[4].grasp.flange"]


def test_steps_follow_the_section_sequence_when_it_is_given() -> None:
    seq = ["b12", "b23", "b45", "b14", "b16", "b17"]
    d = _inline_steps(seq)
    d["bending"]["sequence"] = seq
    si = si_of(d)
    assert si.steps is not None and [s.bend for s in si.steps] == seq
    d["bending"]["steps"] = steps(SEQUENCE)  # the part's order no longer applies
    assert "expected 'b12', got 'b23'" in problems_of(d)["bending.steps[0].bend"]


def test_steps_of_a_part_file_are_checked_by_to_si() -> None:
    d = example_dict()
    d["bending"]["steps"] = steps(["b45", "b23"] + SEQUENCE[2:])
    d["bending"]["steps"][1]["grasp"]["flange"] = "9"
    project_from_dict(d)  # the part is not known at load
    with pytest.raises(ProjectError) as info:
        si_of(d)
    problems = dict(info.value.problems)
    assert "expected 'b23', got 'b45'" in problems["bending.steps[0].bend"]
    assert "no flange '9'" in problems["bending.steps[1].grasp.flange"]
    assert str(info.value).startswith("bending.steps[0].bend: expected 'b23'")


def test_steps_in_si_carry_grasp_face_and_station() -> None:
    d = example_dict()
    d["bending"]["press"] = {
        "stations": [
            {"name": "A", "x": -200, "punch_length": 100, "die_length": 100},
            {"name": "B", "x": 200, "punch_length": 100, "die_length": 100},
        ]
    }
    d["bending"]["steps"] = steps(SEQUENCE)
    d["bending"]["steps"][2] = {
        "bend": "b12",
        "grasp": {"flange": "2", "offset": [100, 20], "yaw": 90, "face": "bottom"},
        "station": "B",
    }
    si = si_of(d)
    assert si.steps is not None
    assert [s.bend for s in si.steps] == SEQUENCE
    assert [s.station for s in si.steps] == ["A", "A", "B", "A", "A", "A"]  # None: the first
    g = si.steps[2].grasp
    assert (g.flange, g.face) == ("2", -1) and g.yaw == pytest.approx(np.pi / 2)
    assert g.offset is not None
    np.testing.assert_allclose(g.offset, [0.1, 0.02])
    assert si.steps[0].grasp.face == 1


# -- inner radius from the press's V-opening ----------------------------------------------------------
def test_a_bend_without_inner_radius_takes_the_air_bending_radius() -> None:
    d = inline_dict()
    del d["bending"]["part"]["bends"][4]["inner_radius"]  # b16
    d["bending"]["press"] = {"die": {"v_opening": 16}}
    si = si_of(d)
    radii = {b.name: b.inner_radius for b in si.part.bends}
    assert radii["b16"] == pytest.approx(0.16 * 0.016) == air_bend_radius(0.016, 0.16)
    assert radii["b17"] == pytest.approx(0.003) and radii["b12"] == pytest.approx(0.0015)
    d["bending"]["press"]["radius_ratio"] = 0.2
    assert si_of(d).part.bends[4].inner_radius == pytest.approx(0.2 * 0.016)
    SheetMetalPart.from_spec(si.part)  # the domain part takes it


def test_a_bend_without_inner_radius_and_no_press_names_the_bend() -> None:
    d = inline_dict()
    del d["bending"]["part"]["bends"][2]["inner_radius"]
    assert problems_of(d)["bending.part.bends[2].inner_radius"] == (
        "give inner_radius, or a press (bending.press) whose V-opening sets it"
    )


def test_a_part_file_bend_without_inner_radius_and_no_press_fails_in_to_si(
    tmp_path: Path,
) -> None:
    part = json.loads(SEED_PART.read_text())
    del part["bends"][1]["inner_radius"]
    (tmp_path / "part.json").write_text(json.dumps(part))
    d = example_dict()
    d["bending"]["part_file"] = "part.json"
    with pytest.raises(ProjectError) as info:
        si_of(d, tmp_path)
    assert info.value.problems == [
        (
            "bending.part_file:bends[1].inner_radius",
            "give inner_radius, or a press (bending.press) whose V-opening sets it",
        )
    ]
    d["bending"]["press"] = {}
    assert si_of(d, tmp_path).part.bends[1].inner_radius == pytest.approx(0.16 * 0.012)


def test_an_air_bending_radius_below_table_1_names_the_v_opening() -> None:
    d = inline_dict()
    del d["bending"]["part"]["bends"][0]["inner_radius"]
    d["bending"]["press"] = {"die": {"v_opening": 4}}  # 0.64 mm < 0.5 x 1.5 mm
    assert problems_of(d)["bending.part.bends[0].inner_radius"] == (
        "not given, and the die's V-opening 4 mm gives 0.64 mm (16 % of it): below Table 1's "
        "minimum 0.5 x thickness = 0.75 mm; use a wider die or set inner_radius"
    )
    d["bending"]["part"]["bends"][0]["inner_radius"] = 0.75  # a given radius is kept as is
    assert si_of(d).part.bends[0].inner_radius == pytest.approx(0.00075)


def test_part_to_si_alone_needs_an_air_radius_for_a_bend_without_one() -> None:
    part = json.loads(SEED_PART.read_text())
    del part["bends"][0]["inner_radius"]
    spec = PartSpec.model_validate(part)
    with pytest.raises(ProjectError, match=r"^bending\.part\.bends\[0\]\.inner_radius: give"):
        spec.to_si()
    assert spec.to_si(air_radius=0.002).bends[0].inner_radius == 0.002
    with pytest.raises(ProjectError, match=r"the air-bending radius is 0\.5 mm: below"):
        spec.to_si(air_radius=0.0005)


def test_existing_inner_radius_messages_are_unchanged() -> None:
    d = inline_dict()
    d["bending"]["part"]["bends"][2]["inner_radius"] = 0.5
    assert problems_of(d)["bending.part"] == (
        "bends[2].inner_radius: 0.5 mm is below Table 1's range; the minimum is 0.5 x "
        "thickness = 0.75 mm"
    )


# -- the grasp's face -----------------------------------------------------------------------------------
def test_grasp_face_reaches_the_domain_and_back() -> None:
    spec = GraspSpec(flange="2", offset=[10, 5], yaw=30, face="bottom")
    g = spec.to_si()
    assert g.face == -1
    assert GraspSpec().to_si().face == 1
    other = GraspSpec()
    other.set_si(g)
    assert (other.flange, other.face) == ("2", "bottom")
    assert other.offset == pytest.approx([10, 5]) and other.yaw == pytest.approx(30)
    other.set_si(Grasp("1"))
    assert other.face == "top"
    d = example_dict()
    d["bending"]["grasp"]["face"] = "bottom"
    assert si_of(d).grasp.face == -1
    d["bending"]["grasp"]["face"] = "side"
    assert "bending.grasp.face" in problems_of(d)


@pytest.fixture(scope="module")
def seed_part() -> SheetMetalPart:
    spec = PartSpec.model_validate(json.loads(SEED_PART.read_text()))
    return SheetMetalPart.from_spec(spec.to_si())


@pytest.mark.parametrize("yaw", [0.0, 0.7])
def test_a_bottom_grasp_puts_the_tcp_on_the_bottom_face_looking_up(
    seed_part: SheetMetalPart, yaw: float
) -> None:
    t = seed_part.thickness
    off = np.array([0.05, 0.04])
    top = T_flange_grasp(seed_part, Grasp("1", off, yaw))
    bottom = T_flange_grasp(seed_part, Grasp("1", off, yaw, face=-1))
    np.testing.assert_allclose(top[:3, 3], [*off, t / 2], atol=1e-15)
    np.testing.assert_allclose(top[:3, 2], [0, 0, -1], atol=1e-15)
    np.testing.assert_allclose(bottom[:3, 3], [*off, -t / 2], atol=1e-15)
    np.testing.assert_allclose(bottom[:3, 2], [0, 0, 1], atol=1e-15)  # into the sheet
    np.testing.assert_allclose(bottom[:3, 0], [np.cos(yaw), np.sin(yaw), 0], atol=1e-15)
    np.testing.assert_allclose(bottom[:3, :3] @ bottom[:3, :3].T, np.eye(3), atol=1e-15)
    assert np.linalg.det(bottom[:3, :3]) == pytest.approx(1.0)
    # the two TCPs face each other through the sheet, a thickness apart
    np.testing.assert_allclose(bottom[:3, 3] + t * bottom[:3, 2], top[:3, 3], atol=1e-15)


def test_the_dataclass_defaults_keep_old_callers() -> None:
    si = si_of(example_dict())
    assert si.grasp.face == 1 and Grasp("1").face == 1


def test_flange_holes_in_mm_reach_the_part_in_metres_and_a_part_without_keeps_its_json() -> None:
    data = json.loads(SEED_PART.read_text())
    plain = PartSpec.model_validate(data)
    assert all(
        "holes" not in f for f in plain.model_dump(mode="json", exclude_none=True)["flanges"]
    )
    x, y = np.asarray(data["flanges"][0]["polygon"], dtype=float).mean(axis=0)  # base centre [mm]
    data["flanges"][0]["holes"] = [[[x - 5, y - 3], [x + 5, y - 3], [x + 5, y + 3], [x - 5, y + 3]]]
    part = SheetMetalPart.from_spec(PartSpec.model_validate(data).to_si())
    (hole,) = part.flanges[0].holes
    np.testing.assert_allclose(hole.mean(axis=0), [x * 1e-3, y * 1e-3], atol=1e-15)
    unholed = SheetMetalPart.from_spec(plain.to_si())
    assert unholed.blank_area() - part.blank_area() == pytest.approx(60e-6, rel=1e-9)
    data["flanges"][0]["holes"] = [[[0, 0], [1, 1]]]
    with pytest.raises(ProjectError, match=r"flanges\[0\]\.holes\[0\]"):
        PartSpec.checked(data, "bending.part_file", "seed_part.json")
