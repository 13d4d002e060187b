"""Die placement: each bend line of the seed part lies on the die's x axis, outer side down."""

from __future__ import annotations

import numpy as np
import pytest
from seed_part import seed_spec

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform, make_transform, rot_z
from workbench.pressbrake.die import (
    Die,
    bend_on_die,
    die_boxes,
    die_part_pose,
    die_placements,
    die_targets,
)
from workbench.pressbrake.grasp import Grasp, T_part_grasp
from workbench.sheetmetal import SheetMetalPart

DIE = Die(make_transform(rot_z(-np.pi / 2), [0.7, 0.0, 0.35]), 0.8, "bending.die.length")


@pytest.fixture(scope="module")
def part() -> SheetMetalPart:
    return SheetMetalPart.from_spec(seed_spec())


@pytest.mark.parametrize("grasp", ["1", "4"])
def test_bend_lines_lie_on_the_die_axis_with_the_grasp_on_the_robot_side(part, grasp: str) -> None:  # type: ignore[no-untyped-def]
    g = Grasp(grasp)
    for step, b in enumerate(part.bends):
        T = die_part_pose(part, step, DIE, g)
        state = part.fold(step)
        poly = part.flanges[b.parent].polygon
        a, c = poly[b.parent_edge], poly[(b.parent_edge + 1) % len(poly)]
        d = (c - a) / np.linalg.norm(c - a)
        n = np.array([d[1], -d[0]])  # outward normal of the CCW polygon's edge
        s = b.direction * part.thickness / 2
        ends = [p + n * part.bend_allowances[step] / 2 for p in (a, c)]
        local = np.array([[p[0], p[1], -s, 1.0] for p in ends])  # the sheet's outer side
        in_die = (invert_transform(DIE.T_world_die) @ T @ state.T_part_flange[b.parent] @ local.T).T
        np.testing.assert_allclose(in_die[:, 1:3], 0.0, atol=1e-9)
        assert in_die[:, 0].sum() == pytest.approx(0.0, abs=1e-9)
        # The gripped flange's TCP is on the robot's (-y) side of the die.
        tcp = invert_transform(DIE.T_world_die) @ T @ T_part_grasp(part, g, step)
        assert tcp[1, 3] <= 1e-9


def test_targets_and_placements(part) -> None:  # type: ignore[no-untyped-def]
    g = Grasp("1")
    T_part, T_tcp, names = die_targets(part, DIE, g)
    assert names[0] == "bend 'b23' (step 1) on the die" and len(names) == len(part.bends)
    for s in range(len(part.bends)):
        np.testing.assert_allclose(T_tcp[s], T_part[s] @ T_part_grasp(part, g, s), atol=1e-15)
    q = np.arange(len(part.bends) * 6, dtype=float).reshape(-1, 6)
    pl = die_placements(part, T_part, T_tcp, q)
    assert [p.bend for p in pl] == [b.name for b in part.bends] and pl[2].step == 2
    np.testing.assert_array_equal(pl[2].q, q[2])


def test_a_short_die_and_a_bad_step_are_refused(part) -> None:  # type: ignore[no-untyped-def]
    short = Die(DIE.T_world_die, 0.25, "bending.die.length")
    with pytest.raises(
        InputError, match=r"bend 'b23'.*300\.0 mm long; the die is 250 mm \(bending\.die\.length\)"
    ):
        die_part_pose(part, 0, short, Grasp("1"))
    with pytest.raises(InputError, match=r"step: must be in 0\.\.5, got 6"):
        die_part_pose(part, 6, DIE, Grasp("1"))


def test_bend_on_die() -> None:
    assert [bend_on_die(s, 6) for s in (0.0, 0.5, 1.0 - 1e-12, 2.5, 5.99, 6.0)] == [
        0,
        0,
        1,
        2,
        5,
        5,
    ]


def test_die_boxes_hold_the_flat_part_on_the_die_and_the_bend_line(part) -> None:  # type: ignore[no-untyped-def]
    g = Grasp("1")
    flat, line = die_boxes(part, DIE, g)
    # the twin: every vertex of the flat solid placed by hand, min and max taken in a loop
    T = die_part_pose(part, 0, DIE, g)
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for v in part.fold(0.0).solid().vertices:
        w = T[:3, :3] @ v + T[:3, 3]
        lo, hi = np.minimum(lo, w), np.maximum(hi, w)
    np.testing.assert_allclose(flat, [lo, hi], atol=1e-12)
    a = DIE.T_world_die[:3, 3] - DIE.T_world_die[:3, 0] * DIE.length / 2
    b = DIE.T_world_die[:3, 3] + DIE.T_world_die[:3, 0] * DIE.length / 2
    np.testing.assert_allclose(line, [np.minimum(a, b), np.maximum(a, b)], atol=1e-12)
