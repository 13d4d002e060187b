"""Carried-part collision checks over a press-brake -> pallet transfer (seed 000, Fig. 10-12).

Prints, per frame of a 22-frame transfer of the seed's folded part through a cell of boxes,
the OBB tests and the check time of: the hierarchical OBB tree (batched over frames and
one frame at a time), the flat per-flange loop, python-fcl box-box pairwise collide and
python-fcl's DynamicAABBTreeCollisionManager, with the ratios to the tree. Then the same
comparison on the example project's planned transfer (`wb.bending.check_cost`: the tree/flat
ratio a plan's summary used to carry; plans no longer time their checks).

Run: python benchmarks/bending.py
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import fcl
import numpy as np
import trimesh

from workbench import Workbench
from workbench.collision.shapes import bvh_model
from workbench.geometry import OBB
from workbench.geometry.transforms import make_transform, rot_z
from workbench.project.bending import PartSpec
from workbench.sheetmetal import SheetMetalPart
from workbench.sheetmetal.check_cost import flat_loop as flat_loop_one

ROOT = Path(__file__).resolve().parents[1]


def seed_part() -> SheetMetalPart:
    """Return seed 000's Fig. 7 part from its project file (mm/deg converted as the service does)."""
    data = json.loads((ROOT / "projects" / "parts" / "seed_part.json").read_text())
    return SheetMetalPart.from_spec(PartSpec.model_validate(data).to_si())


def cell() -> tuple[OBB, list[str]]:
    """Boxes [m] of a plausible bending cell: press brake, flip rack with suction cups, pallet."""
    boxes = {  # name: (centre, half extents), axis-aligned; robot base at the origin
        "brake_upper_beam": ([1.30, 0.0, 1.60], [0.25, 1.20, 0.30]),
        "brake_punch": ([1.20, 0.0, 1.20], [0.03, 1.00, 0.10]),
        "brake_die": ([1.20, 0.0, 0.85], [0.05, 1.00, 0.05]),
        "brake_bed": ([1.30, 0.0, 0.40], [0.20, 1.20, 0.40]),
        "brake_frame_left": ([1.40, 1.30, 1.00], [0.30, 0.10, 1.00]),
        "brake_frame_right": ([1.40, -1.30, 1.00], [0.30, 0.10, 1.00]),
        "rack_frame": ([0.30, -1.10, 0.45], [0.35, 0.05, 0.45]),
        "rack_post_left": ([-0.05, -1.10, 0.55], [0.03, 0.03, 0.55]),
        "rack_post_right": ([0.65, -1.10, 0.55], [0.03, 0.03, 0.55]),
        "rack_cup_1": ([0.10, -1.02, 0.95], [0.03, 0.03, 0.03]),
        "rack_cup_2": ([0.50, -1.02, 0.95], [0.03, 0.03, 0.03]),
        "rack_cup_3": ([0.10, -1.02, 0.70], [0.03, 0.03, 0.03]),
        "rack_cup_4": ([0.50, -1.02, 0.70], [0.03, 0.03, 0.03]),
        "pallet": ([-0.90, -0.60, 0.10], [0.40, 0.60, 0.10]),
        "robot_pedestal": ([0.0, 0.0, 0.25], [0.25, 0.25, 0.25]),
        "fence_post": ([-1.50, 1.20, 1.00], [0.05, 0.05, 1.00]),
    }
    c = np.array([v[0] for v in boxes.values()])
    h = np.array([v[1] for v in boxes.values()])
    return OBB(c, np.broadcast_to(np.eye(3), (len(c), 3, 3)), h), list(boxes)


def transfer(n: int = 22) -> np.ndarray:
    """Return (n, 4, 4) T_world_grasp: from the die front, swinging towards the flip rack."""
    s = np.linspace(0.0, 0.72, n)  # stops where the part's wall meets a suction cup
    ang = -np.pi / 2 * s  # swing about the robot base
    radius = 0.85 - 0.05 * s
    p = np.c_[radius * np.cos(ang), radius * np.sin(ang), 1.05 - 0.10 * s]
    return make_transform(rot_z(ang), p)


REPEAT = 30  # best of 30: the fast rows are ~0.1 ms per call on a shared, loaded machine


def best_of(fn, repeat: int | None = None) -> float:
    repeat = repeat or REPEAT
    fn()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def run(n_frames: int, repeat: int) -> None:
    """Print the comparison table for the transfer sampled at `n_frames` frames."""
    state = seed_part().fold(6)
    tree = state.obb_tree("1")
    obstacles, names = cell()
    T = transfer(n_frames)
    F, M = len(T), len(names)
    leaves = tree.boxes[tree.leaves]  # flange boxes in the grasp frame
    nflange = len(tree.leaves)

    rep = tree.collide_frames(obstacles, T)
    flat = tree.flat_collide_frames(obstacles, T)

    def flat_loop() -> list[bool]:  # the seed's "traditional" method: loop over flanges
        return [flat_loop_one(tree, obstacles, T[f]) for f in range(F)]

    def per_frame_tree() -> list[bool]:
        return [tree.collide(obstacles, T[f]).collides for f in range(F)]

    # python-fcl with the same boxes.
    req = fcl.CollisionRequest()
    obs_objs = [
        fcl.CollisionObject(
            fcl.Box(*(2 * obstacles.half_extents[o])),
            fcl.Transform(obstacles.rotation[o], obstacles.center[o]),
        )
        for o in range(M)
    ]
    part_objs = [
        fcl.CollisionObject(fcl.Box(*(2 * leaves.half_extents[k]))) for k in range(nflange)
    ]
    world_all = leaves.reshape(1, -1).transformed(T[:, None])

    def fcl_pairwise() -> list[bool]:
        out = []
        for f in range(F):
            for k, obj in enumerate(part_objs):
                obj.setTransform(fcl.Transform(world_all.rotation[f, k], world_all.center[f, k]))
            out.append(any(fcl.collide(a, b, req) > 0 for a in part_objs for b in obs_objs))
        return out

    obs_mgr = fcl.DynamicAABBTreeCollisionManager()
    obs_mgr.registerObjects(obs_objs)
    obs_mgr.setup()
    part_mgr = fcl.DynamicAABBTreeCollisionManager()
    part_mgr.registerObjects(part_objs)
    part_mgr.setup()

    def fcl_manager() -> list[bool]:
        out = []
        for f in range(F):
            for k, obj in enumerate(part_objs):
                obj.setTransform(fcl.Transform(world_all.rotation[f, k], world_all.center[f, k]))
            part_mgr.update()
            data = fcl.CollisionData()
            part_mgr.collide(obs_mgr, data, fcl.defaultCollisionCallback)
            out.append(bool(data.result.is_collision))
        return out

    def manager_narrow_tests() -> int:  # narrow-phase pairs the broad phase hands over
        count = 0

        def cb(o1, o2, _data):
            nonlocal count
            count += 1
            return False

        for f in range(F):
            for k, obj in enumerate(part_objs):
                obj.setTransform(fcl.Transform(world_all.rotation[f, k], world_all.center[f, k]))
            part_mgr.update()
            part_mgr.collide(obs_mgr, None, cb)
        return count

    # The part as one rigid fcl BVH: the seven flange boxes as one triangle mesh in the grasp
    # frame, one transform per frame (fcl.Transform(R, t) from the matrix), against the cell's
    # boxes in their own manager (python-fcl README, "Broadphase Checking": a manager can
    # collide with a single object, ``manager.collide(obj, cdata, callback)``), the request
    # stopping at the first contact (num_max_contacts=1: the question is yes/no).
    part_mesh = trimesh.util.concatenate(
        [
            trimesh.creation.box(
                2 * leaves.half_extents[k],
                transform=make_transform(leaves.rotation[k], leaves.center[k]),
            )
            for k in range(nflange)
        ]
    )
    part_bvh = fcl.CollisionObject(bvh_model(part_mesh.vertices, part_mesh.faces))
    req1 = fcl.CollisionRequest(num_max_contacts=1)
    R_all = np.ascontiguousarray(T[:, :3, :3])
    p_all = np.ascontiguousarray(T[:, :3, 3])

    def fcl_bvh_manager() -> list[bool]:
        out = []
        for f in range(F):
            part_bvh.setTransform(fcl.Transform(R_all[f], p_all[f]))
            data = fcl.CollisionData(request=req1)
            obs_mgr.collide(part_bvh, data, fcl.defaultCollisionCallback)
            out.append(bool(data.result.is_collision))
        return out

    def fcl_bvh_pairwise() -> list[bool]:
        out = []
        for f in range(F):
            part_bvh.setTransform(fcl.Transform(R_all[f], p_all[f]))
            out.append(
                any(fcl.collide(part_bvh, b, req1, fcl.CollisionResult()) > 0 for b in obs_objs)
            )
        return out

    peers = {
        "python-fcl part BVH vs cell manager": fcl_bvh_manager,
        "python-fcl part BVH vs each box, 1st hit": fcl_bvh_pairwise,
    }
    try:
        import coal

        def coal_box(h: np.ndarray, R: np.ndarray, c: np.ndarray):  # type: ignore[no-untyped-def]
            return coal.CollisionObject(coal.Box(*(2 * h)), coal.Transform3s(R, c))

        c_obs = [
            coal_box(obstacles.half_extents[o], obstacles.rotation[o], obstacles.center[o])
            for o in range(M)
        ]
        for o in c_obs:
            o.computeAABB()
        c_obs_mgr = coal.DynamicAABBTreeCollisionManager()
        for o in c_obs:
            c_obs_mgr.registerObject(o)
        c_obs_mgr.setup()
        c_bvh = coal.BVHModelOBBRSS()
        c_bvh.beginModel(len(part_mesh.faces), len(part_mesh.vertices))
        c_bvh.addVertices(np.asarray(part_mesh.vertices, float))
        c_bvh.addTriangles(np.asarray(part_mesh.faces, np.int64))
        c_bvh.endModel()
        c_part = coal.CollisionObject(c_bvh)
        c_flanges = [
            coal.CollisionObject(coal.Box(*(2 * leaves.half_extents[k]))) for k in range(nflange)
        ]
        c_part_mgr = coal.DynamicAABBTreeCollisionManager()
        for o in c_flanges:
            c_part_mgr.registerObject(o)
        c_part_mgr.setup()
        cb = coal.CollisionCallBackDefault()  # coal's C++ callback: no Python per pair
        cb.data.request.num_max_contacts = 1

        def coal_bvh_manager() -> list[bool]:
            out = []
            for f in range(F):
                c_part.setTransform(coal.Transform3s(R_all[f], p_all[f]))
                c_part.computeAABB()  # coal's setTransform leaves the AABB stale
                cb.data.result.clear()
                cb.data.done = False
                c_obs_mgr.collide(c_part, cb)
                out.append(cb.data.result.isCollision())
            return out

        wR = np.ascontiguousarray(world_all.rotation)
        wc = np.ascontiguousarray(world_all.center)

        def coal_manager() -> list[bool]:
            out = []
            for f in range(F):
                for k, obj in enumerate(c_flanges):
                    obj.setTransform(coal.Transform3s(wR[f, k], wc[f, k]))
                    obj.computeAABB()
                c_part_mgr.update()
                cb.data.result.clear()
                cb.data.done = False
                c_part_mgr.collide(c_obs_mgr, cb)
                out.append(cb.data.result.isCollision())
            return out

        peers["coal part BVH vs cell manager"] = coal_bvh_manager
        peers["coal flange boxes, two managers"] = coal_manager
    except ImportError as exc:
        print(f"coal not importable ({exc!r}): pip install -r benchmarks/requirements.txt")

    verdicts = {
        **{name: fn() for name, fn in peers.items()},
        "tree": rep.collides.tolist(),
        "flat": flat.collides.tolist(),
        "flat loop": flat_loop(),
        "tree per frame": per_frame_tree(),
        "fcl pairwise": fcl_pairwise(),
        "fcl manager": fcl_manager(),
    }
    assert all(v == verdicts["tree"] for v in verdicts.values()), verdicts
    first = int(np.argmax(rep.collides)) if rep.collides.any() else -1
    hit = rep.frame(first) if first >= 0 else None

    rows = [
        (
            "OBB tree, batched over frames (ours)",
            rep.n_obb_tests.mean(),
            best_of(lambda: tree.collide_frames(obstacles, T)),
        ),
        (
            "OBB tree, one frame per call (ours)",
            rep.n_obb_tests.mean(),
            best_of(per_frame_tree, repeat),
        ),
        (
            "flat: all flanges x obstacles, batched",
            flat.n_obb_tests.mean(),
            best_of(lambda: tree.flat_collide_frames(obstacles, T)),
        ),
        (
            "flat per-flange loop (seed's baseline)",
            flat.n_obb_tests.mean(),
            best_of(flat_loop, repeat),
        ),
        ("python-fcl box-box pairwise", nflange * M, best_of(fcl_pairwise)),
        (
            "python-fcl DynamicAABBTree manager (*)",
            manager_narrow_tests() / F,
            best_of(fcl_manager),
        ),
        *((name, float("nan"), best_of(fn)) for name, fn in peers.items()),
    ]
    free = ~rep.collides
    print(
        f"part: seed 000 Fig. 7 (7 flanges, 6 bends), grasp flange '1'; cell: {M} boxes; {F} frames"
    )
    if hit is not None:
        print(
            f"first collision: frame {first + 1}/{F}, flange(s) "
            f"{[state.part.flanges[i].name for i in hit.hit_flanges]} with {[names[o] for o in hit.hit_obstacles]}"
        )
    print(
        f"collision-free frames: {int(free.sum())}; OBB tests there: tree {rep.n_obb_tests[free].sum()}, "
        f"flat {flat.n_obb_tests[free].sum()} (ratio {rep.n_obb_tests[free].sum() / flat.n_obb_tests[free].sum():.3f})"
    )
    tree_t = rows[0][2] / F
    print(f"{'method':42s} {'tests/frame':>11s} {'us/frame':>9s} {'vs tree':>8s}")
    for name, tests, total in rows:
        print(f"{name:42s} {tests:11.1f} {total / F * 1e6:9.1f} {total / F / tree_t:7.1f}x")
    print("(*) tests/frame of the manager: box-box pairs its AABB tree hands to the narrow phase")
    fastest = min(rows[4:], key=lambda r: r[2])
    print(
        f"fastest peer: {fastest[0]} at {fastest[2] / F * 1e6:.1f} us/frame; tree batched"
        f" {tree_t * 1e6:.1f} us/frame: peer/tree {fastest[2] / F / tree_t:.2f}x"
    )


def example(repeat: int = 3) -> None:
    """Print tree vs flat on the free frames of the example project's planned transfer."""
    wb = Workbench.open(ROOT / "projects" / "bending_cell.json")
    plan = wb.bending.plan()
    cost = wb.bending.check_cost(plan, repeat)
    free = ~plan.part_colliding
    F = len(plan.times)
    print(f"example projects/bending_cell.json: {F} frames, {int(free.sum())} free")
    print(
        f"OBB tests on free frames: tree/flat = {cost.ratio(free):.2f}; check time per frame "
        f"(best of {repeat}): tree {cost.tree_seconds.mean() * 1e6:.1f} us, "
        f"flat loop {cost.flat_seconds.mean() * 1e6:.1f} us "
        f"({cost.flat_seconds.sum() / cost.tree_seconds.sum():.1f}x)"
    )


def main() -> None:
    """Run the seed's 22-frame transfer, the same path sampled 10x denser, then the example."""
    run(22, REPEAT)
    print()
    run(220, 2)
    print()
    example()


if __name__ == "__main__":
    main()
