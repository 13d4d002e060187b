"""The press-brake cycle's free moves routed around obstacles (`sheetmetal.transit`).

Twins: a blocked move in a toy joint space (a wall in the plane) is replaced by vias whose
every leg a brute-force dense check finds free; the transit space's verdict on a real cell
equals python-fcl's robot check (`RobotCollisionChecker.check`) plus the part's frame check
(`check_states`) at the same configurations; a cycle whose turn in front of the die sweeps
the part through the press gets a detour and replays collision-free.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.pressbrake.cycle import PressObstacles, _last_stop, _PressScene
from workbench.pressbrake.cycle_path import CyclePath, Phase, T_part_tcp, Waypoint, cycle_path
from workbench.pressbrake.obstacles import cell_obstacles
from workbench.pressbrake.press_check import check_states
from workbench.pressbrake.transit import (
    DETOUR_STEP,
    Carried,
    TransitSpace,
    _densify,
    route_transits,
)
from workbench.service.bending_process import cycle_cell, cycle_steps
from workbench.sheetmetal.folding import fold_state

ROOT = Path(__file__).resolve().parents[2]


class _Wall:
    """A 2-joint space with a wall |q0| < 0.3, q1 < 1.5 that a straight move from
    (-1, 0) to (1, 0) crosses."""

    dof = 2
    limits = np.array([[-2.0, 2.0], [-2.0, 2.0]])

    def distance(self, qa: np.ndarray, qb: np.ndarray) -> np.ndarray:
        return np.abs(np.asarray(qb) - np.asarray(qa)).sum(axis=-1)

    def valid(self, q: np.ndarray) -> bool:
        q = np.asarray(q)
        return bool(np.all(np.abs(q) <= 2.0) and not (abs(q[0]) < 0.3 and q[1] < 1.5))

    def explain(self, q: np.ndarray) -> str:
        return "" if self.valid(q) else "the wall"

    def motion_free(self, qa: np.ndarray, qb: np.ndarray) -> bool:
        u = np.linspace(0.0, 1.0, 200)[:, None]
        return all(self.valid(q) for q in np.asarray(qa) + u * (np.asarray(qb) - np.asarray(qa)))


def _dense_free(space: _Wall, qa: np.ndarray, qb: np.ndarray) -> bool:
    u = np.linspace(0.0, 1.0, 5001)[:, None]
    return all(space.valid(q) for q in qa + u * (qb - qa))


def test_a_blocked_move_gets_vias_whose_every_leg_is_free() -> None:
    space = _Wall()
    T = np.eye(4)
    wps = (
        Waypoint(T, "start", stop=True),
        Waypoint(T, "across", stop=True, free=True),
        Waypoint(T, "up", stop=True),
    )
    phases = (Phase("carried", 0, 1, 0.0, None), Phase("rest", 1, 2, 0.0, None))
    path = CyclePath(wps, phases, np.zeros(2), ())
    q = np.array([[-1.0, 0.0], [1.0, 0.0], [1.0, 1.0]])
    assert not _dense_free(space, q[0], q[1])
    new, q2, rep = route_transits(path, q, lambda k: space, lambda qi: T)  # type: ignore[arg-type, return-value]
    assert len(new.waypoints) == len(q2) > 3
    assert [label for label, _ in rep.rerouted] == ["across"] and not rep.blocked
    for a, b in zip(q2[:-1], q2[1:], strict=True):
        assert _dense_free(space, a, b)
    assert np.abs(np.diff(q2[:-1], axis=0)).max() <= DETOUR_STEP + 1e-12  # the detour's legs
    # the ends and the waypoints after the detour are the ones given, in order
    np.testing.assert_array_equal(q2[0], q[0])
    np.testing.assert_array_equal(q2[-2:], q[1:])
    assert new.waypoints[-2] is wps[1] and new.waypoints[-1] is wps[2]
    assert all(w.label.startswith("across (around ") for w in new.waypoints[1:-2])
    # the phases still start and end at the same waypoints
    for old, ph in zip(phases, new.phases, strict=True):
        assert new.waypoints[ph.start] is wps[old.start]
        assert new.waypoints[ph.end] is wps[old.end]
    # the same inputs give the same detour (seeded, bounded by a node count)
    again = route_transits(path, q, lambda k: space, lambda qi: T)  # type: ignore[arg-type, return-value]
    np.testing.assert_array_equal(again[1], q2)


def test_a_free_move_is_left_alone_and_a_blocked_end_is_reported() -> None:
    space = _Wall()
    T = np.eye(4)
    wps = (Waypoint(T, "a"), Waypoint(T, "b", free=True), Waypoint(T, "c", free=True))
    path = CyclePath(wps, (Phase("carried", 0, 2, 0.0, None),), np.zeros(2), ())
    q = np.array([[-1.0, 0.0], [-1.0, 1.0], [0.0, 0.0]])  # the last end is in the wall
    new, q2, rep = route_transits(path, q, lambda k: space, lambda qi: T)  # type: ignore[arg-type, return-value]
    assert new is path and q2 is q
    assert not rep.rerouted and [label for label, _ in rep.blocked] == ["c"]
    assert "the wall" in rep.blocked[0][1]
    assert "c: no detour" in rep.describe()


def test_densify_keeps_the_points_and_bounds_the_step() -> None:
    rng = np.random.default_rng(3)
    q = rng.uniform(-2, 2, (5, 6))
    d = _densify(q, 0.1)
    assert np.abs(np.diff(d, axis=0)).max() <= 0.1 + 1e-12
    for row in q:
        assert np.any(np.all(np.isclose(d, row, atol=1e-12), axis=1))
    np.testing.assert_array_equal(d[0], q[0])
    np.testing.assert_array_equal(d[-1], q[-1])


@pytest.fixture(scope="module")
def pan() -> Workbench:
    return Workbench.open(ROOT / "projects" / "pan_cell.json")


def _carried_space(wb: Workbench) -> tuple[TransitSpace, Carried, Phase]:
    svc = wb.bending
    part, steps, cell = svc.part, cycle_steps(svc), cycle_cell(svc)
    path = cycle_path(part, steps, cell)
    ph = next(p for p in path.phases if p.kind == "carried" and p.step == 1.0)
    scene = _PressScene(
        part, path, cell, cell_obstacles(svc.part_cell_bodies()), PressObstacles(cell.press)
    )
    k = int(ph.step)
    grasp = ph.grasp or steps[k].grasp
    carried = Carried(
        fold_state(part, ph.step, check=False),
        T_part_tcp(part, grasp, ph.step),
        scene.at(
            ph.station or steps[k].station,
            cell.press.ram.open + part.thickness,
            _last_stop(path, ph),
            -1,
        ),
    )
    setup = wb.setup
    space = TransitSpace(
        wb.robot, setup.T_world_base, setup.T_flange_tcp, wb.checker, wb.collision_policy, carried
    )
    return space, carried, ph


def test_the_transit_space_agrees_with_fcl_and_the_part_check(pan: Workbench) -> None:
    space, carried, _ = _carried_space(pan)
    model, setup = pan.robot, pan.setup
    lim = np.asarray(model.limits, float)
    rng = np.random.default_rng(7)
    q = rng.uniform(lim[:, 0], lim[:, 1], (60, model.dof))
    q[:20] = np.asarray(pan.joints) + rng.normal(0.0, 0.3, (20, model.dof))  # near home
    q = np.clip(q, lim[:, 0], lim[:, 1])
    T_part = (
        setup.T_world_base @ model.fk(q) @ setup.T_flange_tcp @ np.linalg.inv(carried.T_part_tcp)
    )
    part_hit = check_states([carried.state] * len(q), T_part, [carried.obstacles] * len(q))
    seen = set()
    for qi, hit in zip(q, part_hit, strict=True):
        robot_hit = bool(pan.checker.check(qi, distance=False).colliding)
        expect = not (robot_hit or hit is not None)
        assert space.valid(qi) == expect, (np.degrees(qi), robot_hit, hit)
        seen.add(expect)
    assert seen == {True, False}  # both verdicts occur among the samples


@pytest.mark.slow
def test_a_straight_move_is_free_only_if_its_dense_samples_are(pan: Workbench) -> None:
    space, carried, _ = _carried_space(pan)
    q_home = np.asarray(pan.joints, float)
    rng = np.random.default_rng(11)
    verdicts = set()
    for _ in range(6):
        qb = q_home + rng.normal(0.0, 0.6, q_home.shape)
        if not space.valid(qb):
            continue
        free = space.motion_free(q_home, qb)
        u = np.linspace(0.0, 1.0, 400)[:, None]
        dense = [space.valid(qi) for qi in q_home + u * (qb - q_home)]
        if free:
            assert all(dense)
        verdicts.add(free)
    assert verdicts  # at least one move was tried
