"""The Assembly tab in a real Chromium: pick a planner, plan a part, see interference, play, export."""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

import numpy as np
import pytest
from browser_helpers import (
    canvas_png,
    close_notifications,
    save_screenshot,
    set_slider,
    steady_picture,
    type_number,
    wait_for,
    wait_for_new_picture,
    wait_for_timeline,
)

pytestmark = pytest.mark.e2e

ROOT = Path(__file__).resolve().parents[2]


def test_plan_a_part_show_interference_play_the_sequence_and_export(launch) -> None:  # type: ignore[no-untyped-def]
    app, page = launch(ROOT / "projects" / "assembly_cell.json")
    a = app.wb.assembly
    page.get_by_role("tab", name="Assembly").click()
    page.get_by_text("Plan part").wait_for()

    # Change a control: the planner.
    page.get_by_role("combobox", name="Planner").click()
    page.get_by_role("option", name="rrt_connect", exact=True).click()
    wait_for(lambda: app.assembly.planner.value == "rrt_connect", what="the planner on the server")

    before = steady_picture(lambda: canvas_png(page))
    plots_before = app.timeline.plots
    page.get_by_role("button", name="Plan part").click()
    wait_for(lambda: app.assembly.plan is not None, timeout=90, what="the part plan on the server")
    pp = a.last_part_plan
    assert pp is not None and pp.part == "plate_a" and pp.path.planner == "rrt_connect"
    np.testing.assert_allclose(pp.key_points[-1], a.part("plate_a").goal, atol=1e-12)
    page.get_by_text(f"{len(pp.key_points)} key points").first.wait_for()
    plan = app.assembly.plan
    # The panel shows the plan before it loads the timeline: wait for the load to finish.
    wait_for_timeline(app, plots_before, what="the part plan on the timeline")
    assert app.timeline.motion is not None
    assert app.timeline.motion.duration == pytest.approx(plan.duration, abs=1e-9)
    page.get_by_text(f"{plan.duration:.2f} s, collision-free").first.wait_for()
    wait_for_new_picture(lambda: canvas_png(page), before, what="the path did not appear")

    # Scrub: the carried plate follows the robot's FK at the typed time.
    t = round(0.5 * (plan.tasks[0].t_pick + plan.tasks[0].t_place), 2)
    set_slider(page, "Time [s]", t)
    wait_for(lambda: abs(app.timeline.time.value - t) < 1e-6, what="the timeline at the typed time")
    i = int(np.searchsorted(plan.times, t, side="right")) - 1  # the sample at or before t
    expected = plan.part_poses["plate_a"][i][:3, 3]
    wait_for(
        lambda: np.allclose(app.assembly.part_nodes["plate_a"].position, expected, atol=1e-6),
        what="plate_a carried along its path",
    )

    # Export: the downloaded CSV is the server's export of the key points.
    with page.expect_download() as dl:
        page.get_by_role("button", name="Download key points").click()
    text = Path(dl.value.path()).read_text()
    assert text == a.export_key_points("csv")
    assert text.startswith("index,x,y,z,roll,pitch,yaw")

    # Interference shown as found: a typed goal inside the table is reported and refused.
    z_goal = round(float(a.part("plate_a").goal[2, 3]) * 1000, 3)
    type_number(page, "Goal z [mm]", "690")
    wait_for(lambda: abs(a.part("plate_a").goal[2, 3] - 0.690) < 1e-9, what="the typed goal")
    page.get_by_text("Goal interferes with table").first.wait_for()
    assert a.interference("plate_a", a.part("plate_a").goal) == ["table"]
    page.get_by_role("button", name="Plan part").click()
    page.get_by_text("interferes with ['table']").first.wait_for()
    type_number(page, "Goal z [mm]", f"{z_goal}")
    wait_for(lambda: a.interference("plate_a", a.part("plate_a").goal) == [], what="goal clear")

    # The whole sequence (plates first, then screws) on the timeline, with both arms.
    plots_before = app.timeline.plots
    page.get_by_role("button", name="Plan sequence").click()
    wait_for(
        lambda: app.assembly.plan is not None and len(app.assembly.plan.tasks) == 7,
        timeout=120,
        what="the sequence plan",
    )
    seq = app.assembly.plan
    assert [task.part for task in seq.tasks][:2] == ["plate_a", "plate_b"] and seq.ok
    page.get_by_text(f"cycle time {seq.duration:.3f} s").first.wait_for()
    wait_for_timeline(app, plots_before, what="the sequence on the timeline")
    task = seq.tasks[1]  # plate_b, carried by the second arm
    t = round(0.5 * (task.t_pick + task.t_place), 2)
    set_slider(page, "Time [s]", t)
    wait_for(lambda: abs(app.timeline.time.value - t) < 1e-6, what="the time in the sequence")
    arm = a.arms["MZ07_B"]
    T = arm.setup.T_world_base @ arm.setup.model.link_transforms(seq.joints_at("MZ07_B", t))
    wait_for(
        lambda: np.allclose(app.assembly.arm_nodes["MZ07_B"][3].position, T[3][:3, 3], atol=1e-6),
        what="the second arm at its planned joints",
    )
    # Close the notifications (the refused goal's, handled above) for the screenshot.
    close_notifications(page)
    steady_picture(lambda: canvas_png(page))
    save_screenshot(page, "assembly.png")

    # Every robot's share of the sequence, as NACHI programs (the MZ07's vendor's language,
    # the dropdown's default) in one zip: the server's export.
    assert app.assembly.prog_format.value == "nachi" == app.wb.default_program_format()
    with page.expect_download() as dl:
        page.get_by_role("button", name="Download robot programs").click()
    with zipfile.ZipFile(io.BytesIO(Path(dl.value.path()).read_bytes())) as z:
        files = {name: z.read(name).decode() for name in z.namelist()}
    exported = app.wb.export_program("nachi", "assembly")
    assert files == exported.files and len(files) == len(a.arms) >= 2
    b_program = next(t for t in files.values() if t.startswith("' PROGRAM assembly_MZ07_B"))
    assert "MOVEX" in b_program and "M1J" in b_program

    # The joint-space planner: the carrying robot's joints, robot and part checked together.
    page.get_by_role("combobox", name="Planner").click()
    page.get_by_role("option", name="joint_rrt_connect").click()
    wait_for(lambda: app.assembly.planner.value == "joint_rrt_connect", what="the joint planner")
    page.get_by_role("button", name="Plan part").click()
    wait_for(
        lambda: (
            app.assembly.plan is not None
            and app.assembly.plan.tasks[0].part_plan.path.planner == "joint_rrt_connect"
        ),
        timeout=120,
        what="the joint-space part plan on the server",
    )
    jp = app.assembly.plan
    pp = jp.tasks[0].part_plan
    assert pp.part == "plate_a" and pp.path.joints is not None and jp.ok
    arm = a.arms[pp.robot]
    T = arm.setup.T_world_base @ arm.setup.model.fk(pp.joints) @ arm.setup.T_flange_tcp
    np.testing.assert_allclose(T @ np.linalg.inv(a.part("plate_a").T_part_tcp), pp.samples)
    page.get_by_text(f"(joint_rrt_connect): {len(pp.key_points)} key points").first.wait_for()
    page.get_by_text(f"{jp.duration:.2f} s, collision-free").first.wait_for()
