"""Grasp frames on the seed part: the TCP on the gripped flange's top face, z into the sheet."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from seed_part import seed_spec

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform
from workbench.pressbrake.grasp import (
    Grasp,
    T_flange_grasp,
    T_part_grasp,
    check_flange,
    checked_grasp,
    grasp_point,
)
from workbench.sheetmetal import SheetMetalPart


@pytest.fixture(scope="module")
def part() -> SheetMetalPart:
    return SheetMetalPart.from_spec(seed_spec())


def test_default_point_is_the_centroid_and_the_tcp_looks_into_the_sheet(part) -> None:  # type: ignore[no-untyped-def]
    g = Grasp("1")
    c = shapely.Polygon(part.flanges[0].polygon).centroid
    np.testing.assert_allclose(grasp_point(part, g), [c.x, c.y], atol=1e-15)
    T = T_flange_grasp(part, g)
    np.testing.assert_allclose(T[:3, 3], [c.x, c.y, part.thickness / 2], atol=1e-15)
    np.testing.assert_allclose(T[:3, 2], [0, 0, -1], atol=1e-15)
    np.testing.assert_allclose(T[:3, :3].T @ T[:3, :3], np.eye(3), atol=1e-15)


def test_offset_and_yaw(part) -> None:  # type: ignore[no-untyped-def]
    g = Grasp("1", np.array([0.05, 0.04]), np.pi / 2)
    T = T_flange_grasp(part, g)
    np.testing.assert_allclose(T[:2, 3], [0.05, 0.04], atol=1e-15)
    # Yaw turns the gripper about the flange normal: its x axis goes from +x to +y.
    np.testing.assert_allclose(T[:3, 0], [0, 1, 0], atol=1e-15)


@pytest.mark.parametrize("step", [0, 3, 6])
def test_part_frame_grasp_follows_the_folded_flange(part, step: int) -> None:  # type: ignore[no-untyped-def]
    g = Grasp("5")
    state = part.fold(step)
    T = T_part_grasp(part, g, step)
    T_flange = state.T_part_flange[part.flange_index("5")]
    np.testing.assert_allclose(invert_transform(T_flange) @ T, T_flange_grasp(part, g), atol=1e-12)


def test_bad_grasps_name_the_field(part) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(InputError, match=r"^grasp\.flange: no flange '9'; flanges are \['1'"):
        checked_grasp(part, "9")
    with pytest.raises(InputError, match=r"^bending\.grasp\.flange: no flange '9'"):
        check_flange(part, "9", "bending.grasp.flange")
    with pytest.raises(
        InputError, match=r"grasp\.offset: \(500\.0, 100\.0\) mm lies outside flange '1'"
    ):
        checked_grasp(part, "1", [0.5, 0.1])
    with pytest.raises(InputError, match=r"grasp\.offset: expected 2 finite numbers"):
        checked_grasp(part, "1", [0.1, np.nan])
    with pytest.raises(InputError, match=r"grasp\.yaw: must be finite"):
        checked_grasp(part, "1", None, np.inf)
    g = checked_grasp(part, "1", [0.1, 0.08], 0.25)
    assert g.flange == "1" and g.yaw == 0.25
    np.testing.assert_array_equal(g.offset, [0.1, 0.08])
