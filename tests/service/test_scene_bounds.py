"""The boxes the view frames (`service.scene_bounds`), the camera placed from them, the
slice legend and the notifications that close by themselves.

Twins: trimesh's own bounds of each mesh moved to its pose; the camera's distance checked by
projecting the box's corners (every one inside the view)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.geometry.aabb import aabb_union, world_aabb
from workbench.gui.collision_panel import FIELD_SCALE, _colormap, colour_bar, legend_text
from workbench.gui.notify import notify
from workbench.gui.scene import VIEWS, camera_pose
from workbench.service import Workbench
from workbench.service.scene_bounds import FOCUS, scene_bounds

PROJECTS = Path(__file__).resolve().parents[2] / "projects"


def test_world_aabb_is_trimeshs_bounds_of_the_moved_mesh() -> None:
    import trimesh

    rng = np.random.default_rng(0)
    for _ in range(20):
        mesh = trimesh.creation.box(extents=rng.uniform(0.1, 1.0, 3))
        T = trimesh.transformations.random_rotation_matrix(rng.uniform(size=3))
        T[:3, 3] = rng.uniform(-1, 1, 3)
        moved = mesh.copy()
        moved.apply_transform(T)
        assert np.allclose(world_aabb(mesh.vertices, T), moved.bounds, atol=1e-12)
    a, b = np.array([[0, 0, 0], [1, 1, 1.0]]), np.array([[-1, 0.5, 0.2], [0.5, 2, 0.5]])
    assert np.array_equal(aabb_union([a, b]), [[-1, 0, 0], [1, 2, 1]])
    with pytest.raises(ValueError, match="got \\(0, 3\\)"):
        world_aabb(np.zeros((0, 3)))


def test_the_cell_box_holds_the_robot_and_leaves_the_floor_out() -> None:
    wb = Workbench.open(PROJECTS / "mz07_cell.json")
    every = scene_bounds(wb, "all")
    robot = scene_bounds(wb, "robot")
    assert np.all(every.lo <= robot.lo + 1e-12) and np.all(every.hi >= robot.hi - 1e-12)
    # the robot's box holds every link vertex (twin: trimesh bounds of each posed link)
    import trimesh

    for mesh, T in zip(wb.setup.link_meshes, wb.link_poses(), strict=False):
        m = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False)
        m.apply_transform(T)
        assert np.all(m.bounds[0] >= robot.lo - 1e-9) and np.all(m.bounds[1] <= robot.hi + 1e-9)
    # the 2.4 m floor plate is left out: the box is the table, fixtures, pillar and robot
    assert every.size[0] < 1.5 and every.size[1] < 1.5
    assert np.allclose(every.centre, (every.lo + every.hi) / 2)


def test_bending_focus_is_the_die_and_the_part() -> None:
    wb = Workbench.open(PROJECTS / "bending_cell.json")
    box = scene_bounds(wb, "bending")
    die = wb.bending.si().die.T_world_die[:3, 3]
    assert np.all(box.lo - 1e-9 <= die) and np.all(die <= box.hi + 1e-9)
    assert box.size.max() < scene_bounds(wb, "all").size.max()
    with pytest.raises(InputError, match="bending"):
        scene_bounds(Workbench.open(PROJECTS / "mz07_cell.json"), "bending")
    with pytest.raises(InputError, match="focus"):
        scene_bounds(wb, "ceiling")
    assert set(FOCUS) == {"all", "robot", "cell", "bending"}


@pytest.mark.parametrize("view", list(VIEWS))
@pytest.mark.parametrize("aspect", [0.6, 1.0, 16 / 9])
def test_the_camera_sees_every_corner_of_the_box(view: str, aspect: float) -> None:
    lo, hi = np.array([-0.4, -0.4, 0.0]), np.array([0.8, 0.7, 1.6])
    fov = np.radians(50)
    position, look_at = camera_pose(lo, hi, VIEWS[view], fov, aspect)
    forward = (look_at - position) / np.linalg.norm(look_at - position)
    up0 = np.array([0.0, 0.0, 1.0])
    right = np.cross(forward, up0)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    corners = np.array(
        [[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    )
    rel = corners - position
    depth = rel @ forward
    assert np.all(depth > 0)
    tan_v = np.abs(rel @ up) / depth
    tan_h = np.abs(rel @ right) / depth
    assert np.all(tan_v <= np.tan(fov / 2) + 1e-9)
    assert np.all(tan_h <= np.tan(fov / 2) * aspect + 1e-9)
    # and not from far away: the nearest corner is within 3x the box's radius
    assert np.linalg.norm(position - look_at) < 3.5 * np.linalg.norm(hi - lo)


def test_the_slice_legend_matches_the_slice_colours() -> None:
    bar = colour_bar(width=5, height=2)
    assert bar.shape == (2, 5, 3)
    assert np.array_equal(bar[0], _colormap(np.linspace(-FIELD_SCALE, FIELD_SCALE, 5), FIELD_SCALE))
    assert tuple(bar[0, 0]) == (220, 40, 40) and tuple(bar[0, 2]) == (250, 250, 250)
    text = legend_text(np.array([[-0.035, 0.1], [0.612, 0.2]]), 0.4)
    assert "z = 400 mm" in text and "min -35 mm, max 612 mm" in text


class _Client:
    def __init__(self) -> None:
        self.calls: list[dict] = []

    def add_notification(self, title: str, body: str, **kw: object) -> None:
        self.calls.append(kw)


def test_informing_notifications_close_by_themselves_errors_stay() -> None:
    c = _Client()
    for color in ("green", "blue", "yellow", "red"):
        notify(None, c, "t", "b", color=color)  # type: ignore[arg-type]
    closes = [k["auto_close_seconds"] for k in c.calls]
    assert closes[0] and closes[1] and closes[2] is None and closes[3] is None
    assert all(k["with_close_button"] for k in c.calls)
