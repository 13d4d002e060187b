"""The transfer's first collision (part or robot, at a frame or between two), and the plan's records."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from seed_part import seed_spec

from workbench.geometry import OBB
from workbench.geometry.transforms import make_transform
from workbench.pressbrake.plan import BendingPlan, FirstCollision, first_collision, playback
from workbench.sheetmetal import SheetMetalPart

F = 10
TIMES = np.linspace(0.0, 0.9, F)


@pytest.fixture(scope="module")
def part_report():  # type: ignore[no-untyped-def]
    """The folded seed part moved along +x through a box it meets from frame 6 on."""
    part = SheetMetalPart.from_spec(seed_spec())
    tree = part.fold(6).obb_tree("1")
    box = OBB(np.array([[1.5, 0.1, 0.0]]), np.eye(3)[None], np.array([[0.2, 0.5, 0.5]]))
    T = make_transform(
        np.broadcast_to(np.eye(3), (F, 3, 3)), np.c_[np.linspace(0, 1.8, F), 0 * TIMES, 0 * TIMES]
    )
    rep = tree.collide_frames(box, T)
    assert rep.collides.any() and not rep.collides[:3].any()
    return rep


def path(**kw):  # type: ignore[no-untyped-def]
    base = dict(between=False, first_index=None, first_time=None, link=None, obstacle=None)
    return SimpleNamespace(**{**base, **kw})


NAMES = [str(i) for i in range(1, 8)]


def no_pairs(f: int) -> list[tuple[str, str]]:
    raise AssertionError("robot pairs asked for a part hit")


def test_none_when_all_is_free(part_report) -> None:  # type: ignore[no-untyped-def]
    free = SimpleNamespace(collides=np.zeros(F, bool))
    assert first_collision(TIMES, free, np.zeros(F, bool), path(), NAMES, ["box"], no_pairs) is None  # type: ignore[arg-type]


def test_the_first_part_hit_names_flanges_and_obstacles(part_report) -> None:  # type: ignore[no-untyped-def]
    f0 = int(np.argmax(part_report.collides))
    robot = np.zeros(F, bool)
    robot[f0 + 1] = True  # a later robot hit does not matter
    first = first_collision(TIMES, part_report, robot, path(), NAMES, ["box"], no_pairs)  # type: ignore[arg-type]
    fr = part_report.frame(f0)
    assert first == FirstCollision(
        f0, TIMES[f0], "part", tuple(NAMES[i] for i in fr.hit_flanges), ("box",)
    )
    assert first.describe().startswith(f"frame {f0 + 1} (t = {TIMES[f0]:.3f} s): flange ")


def test_an_earlier_robot_hit_names_the_robot_pairs(part_report) -> None:  # type: ignore[no-untyped-def]
    robot = np.zeros(F, bool)
    robot[1] = True
    first = first_collision(
        TIMES,
        part_report,
        robot,
        path(),
        NAMES,
        ["box"],
        lambda f: [("link3", "fence"), ("tool", "bed")],
    )  # type: ignore[arg-type]
    assert first == FirstCollision(1, TIMES[1], "robot", ("link3", "tool"), ("fence", "bed"))
    assert first.describe() == "frame 2 (t = 0.100 s): robot link3, tool hits 'fence', 'bed'"


def test_a_robot_hit_between_frames_wins_only_when_earlier(part_report) -> None:  # type: ignore[no-untyped-def]
    robot = np.zeros(F, bool)
    early = path(between=True, first_index=1, first_time=0.15, link="link2", obstacle="rack")
    first = first_collision(TIMES, part_report, robot, early, NAMES, ["box"], no_pairs)  # type: ignore[arg-type]
    assert first == FirstCollision(1, 0.15, "robot", ("link2",), ("rack",), between=True)
    assert first.describe().startswith(
        "between frames 2 and 3 (t = 0.150 s): robot link2 hits 'rack'"
    )
    late = path(between=True, first_index=8, first_time=0.85, link="link2", obstacle="rack")
    assert first_collision(TIMES, part_report, robot, late, NAMES, ["box"], no_pairs).kind == "part"  # type: ignore[arg-type, union-attr]
    unsure = path(between=True, first_index=0, first_time=0.05)
    first = first_collision(TIMES, part_report, robot, unsure, NAMES, ["box"], no_pairs)  # type: ignore[arg-type]
    assert first is not None and "treat it as touching" in first.describe()


def test_plan_records_frames_summary_and_playback(part_report) -> None:  # type: ignore[no-untyped-def]
    class Line:  # a 1-joint trajectory q = t over 0.9 s
        duration = 0.9

        def sample(self, dt: float):  # type: ignore[no-untyped-def]
            t = np.linspace(0.0, 0.9, 46)
            return t, t[:, None], np.ones((46, 1)), np.zeros((46, 1))

    hit = part_report.collides
    plan = BendingPlan(
        placements=(),
        configuration="lefty",
        trajectory=Line(),  # type: ignore[arg-type]
        times=TIMES,
        joints=TIMES[:, None],
        T_world_grasp=np.zeros((F, 4, 4)),
        T_world_part=np.zeros((F, 4, 4)),
        part_report=part_report,
        part_colliding=hit,
        robot_colliding=np.zeros(F, bool),
        first_collision=None,
        obstacle_names=("box",),
    )
    assert (
        plan.summary()
        == "0 bends placed on the die (lefty); transfer 0.90 s, 10 frames checked. Collision-free."
    )
    np.testing.assert_array_equal(plan.tree_tests, part_report.n_obb_tests)
    assert plan.nearest_frame(0.26) == 3 and plan.nearest_frame(5.0) == F - 1
    np.testing.assert_array_equal(
        plan.frame_at(np.array([-1.0, 0.0, 0.19, 0.2, 2.0])), [0, 0, 1, 2, F - 1]
    )

    def tcp(q: np.ndarray) -> np.ndarray:  # the TCP moves 2 m per unit of q along x
        return make_transform(
            np.broadcast_to(np.eye(3), (len(q), 3, 3)), np.c_[2 * q[:, 0], 0 * q, 0 * q]
        )

    pb = playback(plan, tcp, dt=0.02)
    np.testing.assert_allclose(pb.tcp_speed, 2.0)  # the one TCP-speed formula (SampledMotion)
    np.testing.assert_allclose(pb.joints, pb.times[:, None])
    assert pb.name == "bending transfer"
    np.testing.assert_array_equal(pb.colliding, hit[plan.frame_at(pb.times)])
