"""Every typed number of every tab in a real Chromium: what the page shows is what the server uses.

Each field gets a normal change, an out-of-range value, a decimal comma ("12,5"), "nan" and
"abc", then a reload; after each, the box (read back from the page), the server's state and the
scene must agree, and a refusal must say which field, the allowed range and the unit. Waits are
for states (the notification, the box's text, the server's value), never for a time.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from browser_helpers import (
    close_notifications,
    number_box,
    type_number,
    wait_for,
)

from workbench.geometry.transforms import wxyz_to_matrix
from workbench.gui.app import WorkbenchApp
from workbench.gui.fields import format_number
from workbench.gui.program_editor import item_label
from workbench.service.program_edit import editor

pytestmark = pytest.mark.e2e
ROOT = Path(__file__).resolve().parents[2]
PROJECTS = ROOT / "projects"
NOTIFICATION = ".mantine-Notification-root"


def _open_tab(page, name: str) -> None:  # type: ignore[no-untyped-def]
    page.get_by_role("tab", name=name).click()


def _agree(page, label: str, server: Callable[[], float], decimals: int = 3) -> None:  # type: ignore[no-untyped-def]
    box = number_box(page, label)
    wait_for(
        lambda: box.input_value() == format_number(server(), decimals),
        what=f"the page's {label!r} box to show the server's {format_number(server(), decimals)}",
    )


def drive(  # type: ignore[no-untyped-def]
    page,
    label: str,
    *,
    good: str,
    bad: str,
    server: Callable[[], float],
    scene_ok: Callable[[], bool],
    unit: str,
    decimals: int = 3,
    extra_bad: tuple[str, ...] = (),
) -> None:
    """A normal change, then refusals; box, server and scene agree after each."""
    type_number(page, label, good)
    wait_for(lambda: abs(server() - float(good)) < 1e-9, what=f"{label} = {good} on the server")
    _agree(page, label, server, decimals)
    wait_for(scene_ok, what=f"the scene after {label} = {good}")
    in_use = server()
    for text in (bad, "12,5", "nan", "abc", *extra_bad):
        type_number(page, label, text)
        note = page.locator(NOTIFICATION).filter(has_text=f"{label}: refused")
        note.first.wait_for()
        body = note.first.inner_text()
        assert "Allowed:" in body and (unit in body), body
        if text == "12,5":
            assert "decimal comma" in body, body
        _agree(page, label, server, decimals)
        assert server() == in_use, f"{label}: the server took the refused {text!r}"
        assert scene_ok(), f"{label}: the scene moved after the refused {text!r}"
        close_notifications(page)


def _reload(page, tab: str) -> None:  # type: ignore[no-untyped-def]
    page.reload()
    page.get_by_role("tab", name="Robot").wait_for()
    _open_tab(page, tab)


def test_robot_tab_joints_and_timeline(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "mz07_cell.json")
    app: WorkbenchApp
    wb = app.wb

    def j1() -> float:
        return float(np.degrees(wb.robot.convention.to_controller(wb.joints)[0]))

    def scene_at_joints() -> bool:
        T = wb.link_poses()[1]
        return bool(np.allclose(app.scene.links["link1"].position, T[:3, 3], atol=1e-9))

    drive(
        page, "J1 [deg]", good="35.5", bad="9999", server=j1, scene_ok=scene_at_joints, unit="deg"
    )
    slider = app.jog.joint_fields[0].slider
    assert abs(float(slider.value) - 35.5) < 1e-9, "the slider follows the box"

    # The timeline refuses a time before any motion, then takes one inside the motion.
    t_box = "Time [s]"
    type_number(page, t_box, "0.5")
    page.locator(NOTIFICATION).filter(has_text=f"{t_box}: refused").first.wait_for()
    _agree(page, t_box, lambda: app.timeline._t, 2)
    close_notifications(page)
    plan = wb.plan_motion()
    app.timeline.load(plan.samples, robot=wb.robot)
    m = plan.samples

    def scene_at_time() -> bool:
        T = wb.link_poses(m.at(app.timeline._t))[1]
        return bool(np.allclose(app.scene.links["link1"].position, T[:3, 3], atol=1e-9))

    drive(
        page,
        t_box,
        good="1.25",
        bad="-5",
        server=lambda: app.timeline._t,
        scene_ok=scene_at_time,
        unit="s",
        decimals=2,
    )
    _reload(page, "Robot")
    _agree(page, "J1 [deg]", j1)
    _agree(page, t_box, lambda: app.timeline._t, 2)


def test_robot_tab_ik_configurations_keep_their_names_and_the_tcp(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "mz07_cell.json")
    jog = app.jog
    options = tuple(jog.config.options)
    assert len(options) >= 2 and not any("elbow A" in o or "elbow B" in o for o in options)
    T = app.wb.tcp_pose()
    target = next(o for o in options if o not in (jog.config.value, "current"))
    shown = "input:not([type=hidden])"
    combo = (
        page.locator("div")
        .filter(has=page.get_by_text("IK configuration", exact=True))
        .filter(has=page.locator(shown))
        .last.locator(shown)
        .first
    )
    combo.click()
    page.get_by_role("option", name=target, exact=True).click()
    wait_for(lambda: jog.config.value == target, what=f"the arm in {target}")
    assert tuple(jog.config.options) == options, "picking neither reorders nor renames the list"
    np.testing.assert_allclose(app.wb.tcp_pose(), T, atol=1e-9)
    wait_for(lambda: combo.input_value() == target, what="the page to show the configuration")


def test_bending_tab_grasp_and_fold_step(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "bending_cell.json")
    _open_tab(page, "Bending")
    svc = app.wb.bending
    panel = app.bending

    def grasp_x() -> float:
        return float(svc.grasp_offset()[0] * 1000.0)

    def robot_holds_the_part() -> bool:
        k = svc.bend_on_die(panel._step)
        q = svc.placements()[0][k].q
        T = app.wb.link_poses(q)[-1]
        return bool(np.allclose(app.scene.links["link6"].position, T[:3, 3], atol=1e-9))

    drive(
        page,
        "Grasp x [mm]",
        good=format_number(grasp_x() + 5.0, 2),
        bad="99999",
        server=grasp_x,
        scene_ok=robot_holds_the_part,
        unit="mm",
        decimals=2,
    )

    def part_on_die() -> bool:
        T = svc.die_part_pose(svc.bend_on_die(panel._step))
        return bool(np.allclose(panel.part_frame.position, T[:3, 3], atol=1e-9))

    drive(
        page,
        "Fold step",
        good="1.5",
        bad="99",
        server=lambda: panel._step,
        scene_ok=part_on_die,
        unit="bends",
    )
    _reload(page, "Bending")
    _agree(page, "Grasp x [mm]", grasp_x, 2)
    _agree(page, "Fold step", lambda: panel._step)


def test_assembly_tab_planner_numbers(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "assembly_cell.json")
    _open_tab(page, "Assembly")
    planner = app.wb.assembly.spec.planner

    def cell() -> float:
        return float(planner.cell_size or 0.0)

    def unchanged_scene() -> bool:
        name = str(app.assembly.part.value)
        T = app.wb.assembly.part(name).start
        return bool(np.allclose(app.assembly.part_nodes[name].position, T[:3, 3], atol=1e-9))

    # 0 is what the hint says it is: automatic (1/20 of the part), stored as no value.
    type_number(page, "Cell size [mm]", "0")
    wait_for(lambda: planner.cell_size is None, what="cell size 0 taken as automatic")
    drive(
        page,
        "Cell size [mm]",
        good="6.5",
        bad="-3",
        server=cell,
        scene_ok=unchanged_scene,
        unit="mm",
    )
    drive(
        page,
        "Step (ant)",
        good="12",
        bad="0",
        server=lambda: float(planner.step),
        scene_ok=unchanged_scene,
        unit="segments",
        extra_bad=("2.5",),
    )
    _reload(page, "Assembly")
    _agree(page, "Cell size [mm]", cell)
    _agree(page, "Step (ant)", lambda: float(planner.step))


def test_polishing_tab_parameters_clear_the_stale_path(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "polishing_cell.json")
    _open_tab(page, "Polishing")
    panel = app.polishing
    spec = lambda: app.wb.project.polishing  # noqa: E731  # replaced on every accepted change
    page.get_by_role("button", name="Plan path").click()
    wait_for(lambda: "path" in panel.nodes, what="the planned path in the scene")

    def no_stale_path() -> bool:
        return "path" not in panel.nodes and app.wb.polishing.last_path is None

    for label, field, good, bad, unit in (
        ("Step [mm]", "step", "2.5", "0", "mm"),
        ("Spacing [mm]", "spacing", "12", "1000000", "mm"),
        ("Force [N]", "force", "25", "-3", "N"),
        ("Feed [mm/s]", "feed", "12", "1e9", "mm/s"),
    ):
        drive(
            page,
            label,
            good=good,
            bad=bad,
            server=lambda f=field: float(getattr(spec(), f)),
            scene_ok=no_stale_path,
            unit=unit,
        )
    assert panel.path_info.content == "" and panel.sim_button.disabled
    _reload(page, "Polishing")
    _agree(page, "Force [N]", lambda: float(spec().force))


def _placed_at(node, T: np.ndarray) -> bool:  # type: ignore[no-untyped-def]
    """Return True when scene `node` stands at the transform `T` (position and rotation)."""
    R = wxyz_to_matrix(np.asarray(node.wxyz, float))
    return bool(
        np.allclose(node.position, T[:3, 3], atol=1e-9) and np.allclose(R, T[:3, :3], atol=1e-6)
    )


def test_assembly_tab_start_and_goal_poses(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "assembly_cell.json")
    _open_tab(page, "Assembly")
    a = app.wb.assembly
    panel = app.assembly
    name = str(panel.part.value)
    k = a.part_names.index(name)

    def pose(which: str):  # type: ignore[no-untyped-def]  # as the project holds it (mm, deg)
        return getattr(a.spec.parts[k], which)

    def scene_at_poses() -> bool:
        part = a.part(name)
        return (
            _placed_at(panel.part_nodes[name], part.start)
            and _placed_at(panel.start_gizmo, part.start)
            and _placed_at(panel.goal_ghost, part.goal)
            and _placed_at(panel.goal_gizmo, part.goal)
        )

    start_before = pose("start").model_copy(deep=True)
    x0 = float(start_before.xyz[0])
    drive(
        page,
        "Start x [mm]",
        good=format_number(x0 + 25.0, 2),
        bad="1e9",
        server=lambda: float(pose("start").xyz[0]),
        scene_ok=scene_at_poses,
        unit="mm",
        decimals=2,
        extra_bad=("12.5, 3",),
    )
    # Only x moved: the other coordinates and the rotation stay as they were.
    np.testing.assert_allclose(pose("start").xyz[1:], start_before.xyz[1:], atol=1e-9)
    np.testing.assert_allclose(pose("start").rpy, start_before.rpy, atol=1e-9)

    yaw0 = float(pose("goal").rpy[2])
    drive(
        page,
        "Goal yaw [deg]",
        good=format_number(yaw0 + 10.0 if yaw0 < 150 else yaw0 - 10.0, 2),
        bad="99999",
        server=lambda: float(pose("goal").rpy[2]),
        scene_ok=scene_at_poses,
        unit="deg",
        decimals=2,
    )
    _reload(page, "Assembly")
    _agree(page, "Start x [mm]", lambda: float(pose("start").xyz[0]), 2)
    _agree(page, "Goal yaw [deg]", lambda: float(pose("goal").rpy[2]), 2)
    assert scene_at_poses()


def test_motion_tab_program_editor_speed_and_zone(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "mz07_cell.json")
    _open_tab(page, "Motion")
    ed = editor(app.wb)
    panel = app.motion.editor

    def field(name: str) -> Callable[[], float]:
        return lambda: float(getattr(ed.item(panel.selected), name))

    def table_shows(unit: str) -> Callable[[], bool]:
        def ok() -> bool:  # the program table (what the Motion tab shows) has the value in use
            it = ed.item(panel.selected)
            zone = "fine" if it.zone == 0 else f"{format_number(it.zone)} mm"
            rows = app.motion.program.content.splitlines()
            line = next(r for r in rows if r.startswith("| ▶ "))  # the selected item's row
            assert f"{it.name or '-'} | {it.type}" in line, line
            return f"{format_number(it.speed)} {unit} | {zone} |" in line

        return ok

    # The selected item at start is the last one: a joint move (speed in % of the joints').
    assert ed.item(panel.selected).type == "joint"
    drive(
        page,
        "Move speed",
        good="55",
        bad="150",
        server=field("speed"),
        scene_ok=table_shows("%"),
        unit="%",
    )
    drive(
        page,
        "Zone [mm]",
        good="12.5",
        bad="5000",
        server=field("zone"),
        scene_ok=table_shows("%"),
        unit="mm",
    )
    # A linear move's speed is in mm/s, with its own range.
    i = next(i for i, it in enumerate(ed.items) if it.type == "linear")
    label = item_label(i, ed.item(i))
    page.get_by_role("combobox", name="Item", exact=True).click()
    page.get_by_role("option", name=label, exact=True).click()
    wait_for(lambda: panel.selected == i, what=f"item {label!r} selected")
    _agree(page, "Move speed", field("speed"))
    drive(
        page,
        "Move speed",
        good="333",
        bad="20000",
        server=field("speed"),
        scene_ok=table_shows("mm/s"),
        unit="mm/s",
        extra_bad=("0",),
    )
    _reload(page, "Motion")
    _agree(page, "Move speed", field("speed"))
    _agree(page, "Zone [mm]", field("zone"))


def test_robot_tab_distance_field_slice_height(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(PROJECTS / "mz07_cell.json")
    panel = app.collision
    page.get_by_label("Show distance field").check()
    wait_for(lambda: panel.field_node is not None, timeout=120, what="the distance-field slice")

    def slice_at_height() -> bool:  # the slice node and its legend at the height in use
        node = panel.field_node
        z = panel._z_mm / 1000.0
        return (
            node is not None
            and abs(float(node.position[2]) - z) < 1e-9
            and f"z = {panel._z_mm:.0f} mm" in panel.legend.content
        )

    drive(
        page,
        "Slice height [mm]",
        good="650",
        bad="5000",
        server=lambda: panel._z_mm,
        scene_ok=slice_at_height,
        unit="mm",
        decimals=1,
        extra_bad=("-10",),
    )
    assert abs(float(panel.height.slider.value) - 650.0) < 1e-9, "the slider follows the box"
    _reload(page, "Robot")
    _agree(page, "Slice height [mm]", lambda: panel._z_mm, 1)
