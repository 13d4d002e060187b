"""The part against the press and the cell while a bend is made: `check_states` against a
python-fcl brute force over every obstacle.

The twin: the folded solid as one fcl BVH (plus containment both ways: a vertex of the solid
inside the obstacle, a vertex of the obstacle inside the solid) against every obstacle's
exact geometry (boxes as `fcl.Box`, the die's and punch's non-rectangular pieces as their
BVH plus containment), nothing excluded. An obstacle whose world AABB misses the solid's
is apart (no test needed), every other one is tested.

What must agree, and what may not:
- every obstacle the brute force finds colliding is reported (strict);
- the press's tools (punch, die, back-gauge fingers) are confirmed on the exact solid, so a
  reported tool is one the brute force finds (strict);
- a cell box (frame, bed, beam, cell objects) is decided by the flange's OBB alone (as on the
  transfer), so the tree may report one the solid misses, but only within the OBBs' growth:
  the farthest any point of a flange's OBB lies from the solid, bounded here by sampling
  each OBB on a grid and adding the grid cell's half diagonal (distance is 1-Lipschitz).
"""

from __future__ import annotations

from pathlib import Path

import fcl
import numpy as np
import pytest
import trimesh
from scipy.spatial.transform import Rotation

from workbench import Workbench
from workbench.collision.shapes import bvh_model, fcl_transform
from workbench.geometry.transforms import make_transform
from workbench.pressbrake.bend_setup import (
    PressObstacles,
    bend_line_frame,
    bend_pose,
    contact_zone,
    gauge_stop,
    merge_obstacles,
    part_points,
)
from workbench.pressbrake.grasp import Grasp
from workbench.pressbrake.obstacles import Obstacles, cell_obstacles
from workbench.pressbrake.press import PressBrake
from workbench.pressbrake.press_check import check_states, frames_report, is_tool
from workbench.sheetmetal.folding import FoldedState, fold_state
from workbench.sheetmetal.part import SheetMetalPart

ROOT = Path(__file__).resolve().parents[2]


def brute_hits(state: FoldedState, T_world_part: np.ndarray, obs: Obstacles) -> set[int]:
    """Return the indices of the obstacles the folded solid at `T_world_part` touches."""
    mesh = state.solid()
    world = mesh.copy()
    world.apply_transform(T_world_part)
    lo, hi = world.bounds
    a = fcl.CollisionObject(bvh_model(mesh.vertices, mesh.faces), fcl_transform(T_world_part))
    out: set[int] = set()
    for i in range(len(obs.names)):
        box, shape = obs.boxes[i], obs.exact[i]
        if shape is None:
            pts = box.corners()
            b = fcl.CollisionObject(
                fcl.Box(*(2.0 * np.asarray(box.half_extents))),
                fcl.Transform(np.asarray(box.rotation), np.asarray(box.center)),
            )
        else:
            assert shape.mesh is not None, "the press's and cell's non-boxes are closed meshes"
            pts = np.asarray(shape.mesh.vertices)
            b = fcl.CollisionObject(shape.geometry, fcl_transform(shape.T_world))
        if np.any(pts.max(axis=0) < lo - 1e-9) or np.any(pts.min(axis=0) > hi + 1e-9):
            continue  # world AABBs apart: nothing to touch
        if fcl.collide(a, b, fcl.CollisionRequest()) > 0:
            out.add(i)
            continue
        # no surface contact: one solid inside the other, or apart
        v = world.vertices[:1]
        if shape is None:
            local = (v - box.center) @ np.asarray(box.rotation)
            inside = bool(np.all(np.abs(local) <= box.half_extents))
        else:
            inside = bool(trimesh.proximity.signed_distance(shape.mesh, v)[0] > 0)
        inside |= bool(trimesh.proximity.signed_distance(world, pts[:1])[0] > 0)
        if inside:
            out.add(i)
    return out


_GROWTH: dict[int, float] = {}


def obb_growth(state: FoldedState, step: float = 0.004) -> float:
    """Return an upper bound [m] on how far a point of any flange OBB lies from the solid."""
    if id(state) in _GROWTH:
        return _GROWTH[id(state)]
    boxes = state.flange_obbs()
    mesh = state.solid()
    worst = 0.0
    for f in range(len(boxes.center)):
        h = boxes.half_extents[f]
        n = np.maximum(np.ceil(2 * h / step).astype(int), 1)  # cells per axis
        axes = [np.linspace(-h[j], h[j], n[j] + 1) for j in range(3)]
        grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
        pts = grid @ boxes.rotation[f].T + boxes.center[f]
        d = np.abs(trimesh.proximity.signed_distance(mesh, pts))
        cell = np.linalg.norm(2 * h / n) / 2
        worst = max(worst, float(d.max()) + cell)
    _GROWTH[id(state)] = worst
    return worst


def fcl_distance(state: FoldedState, T_world_part: np.ndarray, obs: Obstacles, i: int) -> float:
    """Return the distance [m] between the solid and obstacle i (a box)."""
    mesh = state.solid()
    a = fcl.CollisionObject(bvh_model(mesh.vertices, mesh.faces), fcl_transform(T_world_part))
    box = obs.boxes[i]
    b = fcl.CollisionObject(
        fcl.Box(*(2.0 * np.asarray(box.half_extents))),
        fcl.Transform(np.asarray(box.rotation), np.asarray(box.center)),
    )
    return float(fcl.distance(a, b, fcl.DistanceRequest(), fcl.DistanceResult()))


Scene = tuple[SheetMetalPart, PressBrake, PressObstacles, Obstacles]
Frames = tuple[list[FoldedState], np.ndarray, list[Obstacles], list[str]]


@pytest.fixture(scope="module")
def scene() -> Scene:
    """Return the U-channel, its cell's press, the press's obstacles and the cell's."""
    svc = Workbench.open(ROOT / "projects" / "u_channel_cell.json").bending
    press = svc.si().press
    assert press is not None
    return svc.part, press, PressObstacles(press), cell_obstacles(svc.part_cell_bodies())


def _frames(scene: Scene, rng: np.random.Generator) -> Frames:
    """Return (states, T_world_part, obstacles, kinds) of seeded frames around the die."""
    part, press, press_obs, cell = scene
    station = press.stations[0]
    states: list[FoldedState] = []
    poses: list[np.ndarray] = []
    obstacles: list[Obstacles] = []
    kinds: list[str] = []
    for k in range(len(part.bends)):
        cut = contact_zone(float(part.bend_allowances[k]), part.thickness, press.tolerance)
        flat = fold_state(part, k, 0.0)
        for frac in (0.0, 0.3, 0.65, 1.0):
            state = fold_state(part, k, frac)
            b = part.bends[k]
            for g in (part.flanges[b.child].name, part.flanges[b.parent].name):
                grasp = Grasp(g)
                start = bend_pose(flat, k, grasp, press, station)
                pts = part_points(flat)
                pts = pts @ start.T_die_part[:3, :3].T + start.T_die_part[:3, 3]
                stop = gauge_stop(pts, press, station)
                pose = bend_pose(state, k, grasp, press, station)
                obs = merge_obstacles(press_obs.at(station, pose.punch_z, cut, stop), cell)
                # the apex frame: moves about the bend's apex on the die's top
                apex = make_transform(np.eye(3), [station.x, 0.0, -pose.depth])
                for kind in ("nominal", "clear", "penetrating", "penetrating", "wild", "wild"):
                    if kind == "nominal":
                        M = np.eye(4)
                    elif kind == "clear":
                        M = make_transform(
                            Rotation.from_rotvec(rng.normal(size=3) * 0.01).as_matrix(),
                            [rng.uniform(-0.01, 0.01), rng.uniform(-0.002, 0.002), 0.004],
                        )
                    elif kind == "penetrating":
                        M = make_transform(
                            Rotation.from_rotvec(rng.normal(size=3) * 0.02).as_matrix(),
                            [
                                rng.uniform(-0.01, 0.01),
                                rng.uniform(-0.004, 0.004),
                                -rng.uniform(0.001, 0.005),
                            ],
                        )
                    else:  # anywhere in and around the press: its frame, beam and fingers
                        M = make_transform(
                            Rotation.random(random_state=rng).as_matrix(),
                            rng.uniform([-0.6, -0.3, -0.2], [0.6, 0.4, 0.5]),
                        )
                    T_die_part = apex @ M @ np.linalg.inv(apex) @ pose.T_die_part
                    states.append(state)
                    poses.append(press.T_world_die @ T_die_part)
                    obstacles.append(obs)
                    kinds.append(kind)
    # the folded bend's apex on and over the cell's boxes (decided by the OBB alone): the
    # flange boxes reach past the outer arc at the bend (the half-bend corner lies 0.29 (r + t)
    # under the arc), so a gap under a millimetre there is a hit of the OBB only
    folded = fold_state(part, 1, 0.0)
    T_part_line = bend_line_frame(folded, 0)
    for i in range(len(cell.names)):
        top = cell.boxes.center[i] + cell.boxes.rotation[i] @ [0, 0, cell.boxes.half_extents[i][2]]
        for gap in (-0.001, 0.0003, 0.0006, 0.003):
            T_world_line = make_transform(
                Rotation.from_euler("z", rng.uniform(0, 2 * np.pi)).as_matrix(),
                top + [rng.uniform(-0.02, 0.02), rng.uniform(-0.02, 0.02), gap],
            )
            states.append(folded)
            poses.append(T_world_line @ np.linalg.inv(T_part_line))
            obstacles.append(cell)
            kinds.append("cell")
    return states, np.array(poses), obstacles, kinds


def test_check_states_against_fcl_brute_force(scene: Scene) -> None:
    rng = np.random.default_rng(20)
    states, T, obstacles, kinds = _frames(scene, rng)
    hits = check_states(states, T, obstacles)
    assert len(hits) == len(T)
    np.testing.assert_array_equal(frames_report(hits), [h is not None for h in hits])
    counts = {"free": 0, "tool": 0, "cell": 0, "loose": 0}
    for i, (state, obs, hit) in enumerate(zip(states, obstacles, hits, strict=True)):
        brute = brute_hits(state, T[i], obs)
        brute_names = {obs.names[o] for o in brute}
        reported = set(hit.obstacles) if hit is not None else set()
        where = (
            f"frame {i} ({kinds[i]}): brute force {sorted(brute_names)}, tree {sorted(reported)}"
        )
        # strict: whatever the solid touches is reported
        assert brute_names <= reported, where
        # strict: a tool is reported only when the solid touches it
        assert {n for n in reported if is_tool(n)} <= brute_names, where
        # a cell box the solid misses: only within the OBBs' growth
        for name in reported - brute_names:
            assert not is_tool(name)
            idx = [o for o in range(len(obs.names)) if obs.names[o] == name]
            d = min(fcl_distance(state, T[i], obs, o) for o in idx)
            g = obb_growth(state)
            assert d <= g, (
                f"{where}: {name!r} is {d * 1e3:.2f} mm from the solid, growth {g * 1e3:.2f} mm"
            )
            counts["loose"] += 1
        if hit is None:
            counts["free"] += 1
        elif any(is_tool(n) for n in brute_names):
            counts["tool"] += 1
        elif brute_names:
            counts["cell"] += 1
        if hit is not None:
            assert hit.frame == i
            assert hit.flanges and all(
                f in {fl.name for fl in state.part.flanges} for f in hit.flanges
            )
    # the nominal placements of the first bend are the process: the flat part lies on the
    # die, free (after bA, flange A stands in the upper beam's way: the U-channel's bad order)
    nominal = [
        h for h, k, s in zip(hits, kinds, states, strict=True) if k == "nominal" and s.step < 1
    ]
    assert all(h is None for h in nominal), [h.describe() for h in nominal if h is not None]
    # the seeded frames cover free, tool and cell-box collisions
    print(counts)
    assert counts["free"] >= 10 and counts["tool"] >= 10 and counts["cell"] >= 3, counts
