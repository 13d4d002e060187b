"""Collision engine geometry core: LBVH build, sparse SDF build, closest-point queries.

Prints our figure, the peer's figure measured in the same run on the same data, and the
ratio. Peers: python-fcl's BVHModel (OBBRSS) build, trimesh.proximity.closest_point,
python-fcl and coal for the robot check; the SDF build's peer (libigl) is in
benchmarks/sdf.py. Run: ``python benchmarks/collision.py``;
``--only robot`` runs the robot-versus-cell part alone (sphere fits, spheres+SDF against
python-fcl, Workbench.plan_motion with the dense exact check against the fast mode).
"""

from __future__ import annotations

import time

import fcl
import numpy as np
import trimesh

from workbench.geometry.distance import point_triangle_distance2
from workbench.geometry.lbvh import LBVH
from workbench.geometry.sdf import SparseSDF
from workbench.kinematics.robot_library import preset_robot


def _cell(subdivisions: int) -> trimesh.Trimesh:
    """A sphere (most triangles) and two boxes: a small closed 'cell'."""
    sphere = trimesh.creation.icosphere(subdivisions=subdivisions, radius=0.5)
    a = trimesh.creation.box((0.4, 0.8, 0.3))
    a.apply_translation((1.0, 0.1, 0.05))
    b = trimesh.creation.box((2.0, 2.0, 0.1))
    b.apply_translation((0.5, 0.0, -0.7))
    return trimesh.util.concatenate([sphere, a, b])


def _stats(fn, repeat: int) -> tuple[float, float, float]:  # type: ignore[no-untyped-def]
    """Return (best, median, worst) [us per configuration of 10,000] after one warm-up."""
    fn()
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        ts.append((time.perf_counter() - t) / 10_000 * 1e6)
    return min(ts), float(np.median(ts)), max(ts)


def _best_of(fn, repeat: int = 3) -> float:
    best = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return float(best)


def lbvh_build() -> None:
    print("LBVH build (best of 3)               ours tri/s    fcl OBBRSS tri/s   ratio")
    for sub in (5, 6, 7, 8):  # 20k, 82k, 328k, 1.3M triangles
        m = _cell(sub)
        v, f = np.asarray(m.vertices), np.asarray(m.faces)
        ours = _best_of(lambda v=v, f=f: LBVH(v, f))

        def peer(v=v, f=f) -> None:
            bvh = fcl.BVHModel()
            bvh.beginModel(len(v), len(f))
            bvh.addSubModel(v, f)
            bvh.endModel()

        ref = _best_of(peer)
        n = len(f)
        print(
            f"  {n:>9d} triangles            {n / ours:12.3e}   {n / ref:12.3e}   {ref / ours:6.2f}x"
        )


def closest_point_queries() -> None:
    rng = np.random.default_rng(0)
    m = _cell(6)
    bvh = LBVH(m.vertices, m.faces)
    p = m.sample(5000, return_index=False) + rng.normal(0, 0.02, (5000, 3))
    t = time.perf_counter()
    _, d, _ = bvh.closest_points(p)
    ours = time.perf_counter() - t
    t = time.perf_counter()
    _, d_ref, _ = trimesh.proximity.closest_point(m, p)
    ref = time.perf_counter() - t
    # Where the two differ, trimesh missed the nearest triangle: brute force sides with us.
    diff = np.nonzero(~np.isclose(d, d_ref, rtol=0, atol=1e-9))[0]
    tri = m.vertices[m.faces]
    for i in diff:
        q = np.broadcast_to(p[i], (len(tri), 3))
        brute = np.sqrt(point_triangle_distance2(q, tri[:, 0], tri[:, 1], tri[:, 2]).min())
        assert abs(brute - d[i]) < 1e-12 and d_ref[i] > brute
    print(f"closest points, {len(m.faces)} triangles, 5000 near-surface points (same points)")
    print(
        f"  {len(p) - len(diff)} answers equal; {len(diff)} where trimesh is farther (brute force agrees with ours)"
    )
    print(
        f"  ours {len(p) / ours:10.0f} points/s   trimesh.proximity {len(p) / ref:10.0f} points/s   ratio {ref / ours:6.1f}x"
    )


def sdf_build() -> None:
    m = _cell(6)
    print(f"sparse SDF build, {len(m.faces)} triangles (band 0: only cells the surface touches)")
    print(
        "  equivalent  coarse x sub   blocks    time s    memory MB   dense float32 MB   max error mm"
    )
    for coarse, sub in ((16, 4), (32, 4), (64, 4)):
        t = time.perf_counter()
        sdf = SparseSDF.from_mesh(m, resolution=coarse, subdivisions=sub, band=0.0)
        dt = time.perf_counter() - t
        dense = float((sdf.dims * sub + 1).prod() * 4)
        print(
            f"  {coarse * sub:>6d}^3     {coarse:>3d} x {sub}     {sdf.block_count:>7d}  {dt:8.2f}   {sdf.memory_bytes / 1e6:9.1f}   {dense / 1e6:12.1f}       {sdf.max_error * 1e3:6.2f}"
        )
    # The peer of the build (libigl's signed distance at the same corners, one thread) is
    # benchmarks/sdf.py; trimesh's signed_distance, extrapolated from a sample, was a weak one.
    print("  peer: python benchmarks/sdf.py (libigl signed_distance at the same corners)")
    mz07_cell_field()


def mz07_cell_field() -> None:
    """The field of projects/mz07_cell.json's obstacles as the plans' spheres engine builds it."""
    from pathlib import Path

    from workbench.service import Workbench

    project = Path(__file__).resolve().parents[1] / "projects" / "mz07_cell.json"
    parts = []
    for e in Workbench.open(project).checker.scene.static.values():
        m = e.mesh.copy()
        m.apply_transform(e.T)
        parts.append(m)
    cell = trimesh.util.concatenate(parts)
    extent = float(np.ptp(cell.vertices, axis=0).max())
    band = 0.14  # the engine's band: largest sphere radius + margin
    for resolution in (32, 48):
        h = max(extent / resolution, band / 8)  # as CollisionEngine picks the cell size
        sdf = None
        best = np.inf
        for _ in range(3):
            t = time.perf_counter()
            sdf = SparseSDF.from_mesh(cell, cell_size=h, subdivisions=4, band=band)
            best = min(best, time.perf_counter() - t)
        assert sdf is not None
        print(
            f"  MZ07 cell ({len(cell.faces)} triangles: floor, table, boxes), resolution {resolution},"
            f" band {band} m: {best:.2f} s (best of 3), {sdf.block_count} blocks,"
            f" {sdf.memory_bytes / 1e6:.1f} MB"
        )


def robot_checks() -> None:
    """Spheres + SDF (batched) against python-fcl and coal on the same links, cell and poses.

    Both sides answer "does this configuration touch the cell?" for the same 10,000
    configurations, FK included on both sides (ours: the sphere centres; the peers: our
    batched numpy FK of the link frames, the fastest we have, inside the timed call). Ours is
    conservative (spheres enclose the links; a flag may be a near miss), the peers exact on
    surfaces (no containment test): both counts are printed. Peers set up as their docs say:
    collision objects built once and moved with setTransform, transforms from rotation
    matrices (python-fcl README, "Collision Objects": ``fcl.Transform(R, T)`` "from a rotation
    matrix and translation"; no quaternion conversion of ours), a CollisionRequest with
    num_max_contacts=1 and stop at the first colliding link (the question is yes/no), and
    the cell's parts in a DynamicAABBTreeCollisionManager against the links' manager
    (python-fcl README, "Broadphase Checking": ``manager.collide(manager2, cdata,
    fcl.defaultCollisionCallback)``; coal: ``CollisionCallBackDefault``, the C++ callback,
    whose data's request carries num_max_contacts). The fastest peer variant sets the ratio.
    """
    from workbench.collision import RobotCollisionChecker, Solid
    from workbench.collision.engine import CollisionEngine
    from workbench.collision.shapes import bvh_model
    from workbench.kinematics.link_shapes import link_meshes

    robot = preset_robot("mz07")
    meshes = link_meshes(robot)
    parts = []
    for centre, size in (
        ((0.45, 0.0, 0.25), (0.25, 0.5, 0.3)),
        ((0.0, -0.55, 0.6), (0.6, 0.1, 0.5)),
    ):
        b = trimesh.creation.box(size)
        b.apply_translation(centre)
        parts.append(b)
    sph = trimesh.creation.icosphere(subdivisions=3, radius=0.12)
    sph.apply_translation((0.15, 0.45, 0.55))
    parts.append(sph)
    cell = trimesh.util.concatenate(parts)
    t = time.perf_counter()
    exact = RobotCollisionChecker(
        robot, meshes, cell=[(Solid("cell", "mesh", mesh=cell), np.eye(4))]
    )
    checker = CollisionEngine(exact, "spheres", spheres_per_link=6, resolution=24).checker
    assert checker is not None
    setup = time.perf_counter() - t
    rng = np.random.default_rng(0)
    lim = np.asarray(robot.limits)
    n = 10_000
    q = rng.uniform(lim[:, 0], lim[:, 1], (n, 6))
    q[:, 1:3] = rng.uniform(-0.9, 0.9, (n, 2))

    def ours_fn() -> np.ndarray:
        clearance, _ = checker.cell_clearance(q, early_exit=True)
        return clearance <= 0.0

    collides = ours_fn()
    ours = _stats(ours_fn, 5)
    link_ids = range(1, 7)

    # python-fcl ---------------------------------------------------------------------------
    req = fcl.CollisionRequest(num_max_contacts=1)
    links = [fcl.CollisionObject(bvh_model(m.vertices, m.faces)) for m in meshes[1:]]
    cell_obj = fcl.CollisionObject(bvh_model(cell.vertices, cell.faces))
    part_objs = [fcl.CollisionObject(bvh_model(p.vertices, p.faces)) for p in parts]

    def fcl_pairwise() -> np.ndarray:  # each link against the cell's one BVH, first hit stops
        T = robot.link_transforms(q)
        R, p = np.ascontiguousarray(T[..., :3, :3]), np.ascontiguousarray(T[..., :3, 3])
        hits = np.zeros(n, dtype=bool)
        for k in range(n):
            for obj, i in zip(links, link_ids, strict=True):
                obj.setTransform(fcl.Transform(R[k, i], p[k, i]))
                if fcl.collide(obj, cell_obj, req, fcl.CollisionResult()):
                    hits[k] = True
                    break
        return hits

    cell_mgr = fcl.DynamicAABBTreeCollisionManager()
    cell_mgr.registerObjects(part_objs)
    cell_mgr.setup()
    link_mgr = fcl.DynamicAABBTreeCollisionManager()
    link_mgr.registerObjects(links)
    link_mgr.setup()

    def fcl_manager() -> np.ndarray:
        T = robot.link_transforms(q)
        R, p = np.ascontiguousarray(T[..., :3, :3]), np.ascontiguousarray(T[..., :3, 3])
        hits = np.zeros(n, dtype=bool)
        for k in range(n):
            for obj, i in zip(links, link_ids, strict=True):
                obj.setTransform(fcl.Transform(R[k, i], p[k, i]))
            link_mgr.update()
            data = fcl.CollisionData(request=req)
            link_mgr.collide(cell_mgr, data, fcl.defaultCollisionCallback)
            hits[k] = data.result.is_collision
        return hits

    peers = {
        "python-fcl, links x cell BVH, first hit": fcl_pairwise,
        "python-fcl, DynamicAABBTree managers": fcl_manager,
    }

    # coal ---------------------------------------------------------------------------------
    coal_why = ""
    try:
        import coal

        def coal_bvh(m: trimesh.Trimesh):  # type: ignore[no-untyped-def]
            bvh = coal.BVHModelOBBRSS()
            bvh.beginModel(len(m.faces), len(m.vertices))
            bvh.addVertices(np.asarray(m.vertices, float))
            bvh.addTriangles(np.asarray(m.faces, np.int64))
            bvh.endModel()
            return bvh

        c_req = coal.CollisionRequest()
        c_req.num_max_contacts = 1
        c_links = [coal.CollisionObject(coal_bvh(m)) for m in meshes[1:]]
        c_cell = coal.CollisionObject(coal_bvh(cell))
        c_parts = [coal.CollisionObject(coal_bvh(p)) for p in parts]

        def coal_pairwise() -> np.ndarray:
            T = robot.link_transforms(q)
            R, p = np.ascontiguousarray(T[..., :3, :3]), np.ascontiguousarray(T[..., :3, 3])
            hits = np.zeros(n, dtype=bool)
            res = coal.CollisionResult()
            for k in range(n):
                for obj, i in zip(c_links, link_ids, strict=True):
                    obj.setTransform(coal.Transform3s(R[k, i], p[k, i]))
                    res.clear()
                    if coal.collide(obj, c_cell, c_req, res):
                        hits[k] = True
                        break
            return hits

        c_cell_mgr = coal.DynamicAABBTreeCollisionManager()
        for o in c_parts:
            c_cell_mgr.registerObject(o)
        c_cell_mgr.setup()
        c_link_mgr = coal.DynamicAABBTreeCollisionManager()
        for o in c_links:
            c_link_mgr.registerObject(o)
        c_link_mgr.setup()
        cb = coal.CollisionCallBackDefault()
        cb.data.request.num_max_contacts = 1

        def coal_manager() -> np.ndarray:
            T = robot.link_transforms(q)
            R, p = np.ascontiguousarray(T[..., :3, :3]), np.ascontiguousarray(T[..., :3, 3])
            hits = np.zeros(n, dtype=bool)
            for k in range(n):
                for obj, i in zip(c_links, link_ids, strict=True):
                    obj.setTransform(coal.Transform3s(R[k, i], p[k, i]))
                    obj.computeAABB()  # coal's setTransform leaves the AABB stale
                c_link_mgr.update()
                cb.data.result.clear()
                cb.data.done = False
                c_link_mgr.collide(c_cell_mgr, cb)
                hits[k] = cb.data.result.isCollision()
            return hits

        peers["coal, links x cell BVH, first hit"] = coal_pairwise
        peers["coal, DynamicAABBTree managers"] = coal_manager
    except Exception as exc:  # noqa: BLE001 - report why the peer is missing
        coal_why = f"coal not run: {exc!r} (pip install -r benchmarks/requirements.txt)"

    print(
        f"robot vs cell, MZ07 links 1-6 ({len(checker.cell_spheres)} spheres), "
        f"{len(cell.faces)}-triangle cell (3 parts), {n} configurations, setup {setup:.1f} s"
    )
    print("  per configuration [us], FK included, best / median / worst of 5 after a warm-up")
    print(
        f"  {'spheres+SDF batched (ours, early exit per link)':48s} {ours[0]:7.2f} / {ours[1]:7.2f} / {ours[2]:7.2f}"
        f"   flagged {int(collides.sum())}"
    )
    best_peer = np.inf
    reference = fcl_pairwise()
    for name, fn in peers.items():
        hits = fn()
        assert np.array_equal(hits, reference), f"{name} disagrees with python-fcl pairwise"
        missed = int(np.sum(hits & ~collides))
        assert missed == 0, f"{name}: ours missed {missed} contacts"
        st = _stats(fn, 5)
        best_peer = min(best_peer, st[0])
        print(
            f"  {name:48s} {st[0]:7.2f} / {st[1]:7.2f} / {st[2]:7.2f}   hits {int(hits.sum())},"
            f" peer/ours {st[0] / ours[0]:5.2f}x"
        )
    if coal_why:
        print("  " + coal_why)
    print(
        f"  fastest peer / ours (best times): {best_peer / ours[0]:.2f}x; ours missed none of the"
        " peers' contacts (ours flags near misses within the spheres' overshoot too)"
    )


def sphere_fits() -> None:
    """Volume overshoot of the fitted spheres per MZ07 link (and the fit time, no cache)."""
    from workbench.geometry.spheres import fit_spheres
    from workbench.kinematics.link_shapes import link_meshes

    meshes = link_meshes(preset_robot("mz07"))
    print(
        "sphere fits, MZ07 links (volume overshoot = union / mesh volume - 1; fit time, no cache)"
    )
    print("  link    " + "".join(f"  k={k}: overshoot  time s" for k in (4, 6, 8)))
    for i, m in enumerate(meshes):
        row = f"  link{i}  "
        for k in (4, 6, 8):
            t = time.perf_counter()
            s = fit_spheres(m, k)
            row += f"       {s.volume_overshoot:9.2f}  {time.perf_counter() - t:6.2f}"
        print(row)
    # A cache hit re-checks containment (split + one _need) before it trusts the entry.
    import tempfile

    with tempfile.TemporaryDirectory() as cache:
        t = time.perf_counter()
        for m in meshes:
            fit_spheres(m, 6, cache_dir=cache)
        fit_s = time.perf_counter() - t
        t = time.perf_counter()
        for m in meshes:
            fit_spheres(m, 6, cache_dir=cache)
        hit_s = time.perf_counter() - t
    print(
        f"  k=6, 7 links: fit and store {fit_s:6.2f} s, cache hit (load + containment check)"
        f" {hit_s:6.3f} s   ratio {fit_s / hit_s:6.1f}x"
    )


def plan_checks() -> None:
    """Plans of two example projects, dense exact check of every sample against the fast mode."""
    plan_check("mz07_cell.json", "Workbench.plan_motion", lambda wb: wb.plan_motion())
    plan_check("polishing_cell.json", "polishing plan", lambda wb: wb.polishing.plan_motion())


def plan_check(name: str, title: str, run) -> None:  # type: ignore[no-untyped-def]
    """One project's plan `run(wb)`: cold, new session, fast vs dense (plan and check alone)."""
    import os
    import tempfile
    from pathlib import Path

    from workbench.collision import check_trajectory
    from workbench.service import Workbench

    project = Path(__file__).resolve().parents[1] / "projects" / name
    before = os.environ.get("WORKBENCH_CACHE")
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["WORKBENCH_CACHE"] = tmp  # a cold cache: fits and field built here
        t = time.perf_counter()
        cold = run(Workbench.open(project))
        cold_s = time.perf_counter() - t
        wb = Workbench.open(project)  # a new session: spheres and field from the disk cache
        t = time.perf_counter()
        plan = run(wb)
        warm_s = time.perf_counter() - t
        fast = _best_of(lambda: run(wb))
        wb.collision.set_mode("exact")  # the project's policy: the dense exact check
        dense = _best_of(lambda: run(wb))
        wb.collision.set_mode("spheres")
        q, times = plan.positions, plan.times
        exact_s = _best_of(lambda: wb.checker.check_path(q))
        policy = wb.collision_policy
        check_s = _best_of(lambda: check_trajectory(plan.trajectory, times, q, wb.checker, policy))
        if before is None:
            os.environ.pop("WORKBENCH_CACHE", None)
        else:
            os.environ["WORKBENCH_CACHE"] = before
    rep = plan.collision_report
    ref = wb.checker.check_path(q)
    assert rep.colliding_indices == ref.colliding_indices
    print(
        f"{title}, projects/{name} ({len(q)} samples every"
        f" {(times[1] - times[0]) * 1e3:.0f} ms; best of 3)"
    )
    print(f"  dense exact check of every sample (before)      {dense:7.3f} s")
    print(
        f"  fast mode, engine in memory                      {fast:7.3f} s   ratio {dense / fast:5.2f}x"
    )
    print(f"  fast mode, new session (spheres+field from cache) {warm_s:6.3f} s")
    print(f"  fast mode, cold (fits spheres, builds the field) {cold_s:7.3f} s")
    print(
        f"  the check alone: dense exact {exact_s * 1e3:7.1f} ms, fast {check_s * 1e3:7.1f} ms"
        f" (ratio {exact_s / check_s:4.2f}x); {rep.flagged_samples} of {len(q)} samples flagged,"
        f" {rep.exact_pairs} exact pair tests, {rep.evaluated} configurations"
    )
    print(f"  report: {rep.message}")
    print(f"  (cold plan: {cold.collision_report.message})")


def main() -> None:
    import sys

    # --only lbvh,closest,sdf,spheres,robot,plan runs just those sections (saves time under load).
    sections = {"lbvh", "closest", "sdf", "spheres", "robot", "plan"}
    only = set(sections)
    for k, arg in enumerate(sys.argv):
        if arg == "--only" and k + 1 < len(sys.argv):
            only = set(sys.argv[k + 1].split(","))
            if only == {"robot"}:  # the robot-versus-cell part as a whole
                only = {"spheres", "robot", "plan"}
    if "--skip-build" in sys.argv:
        only.discard("lbvh")
    if unknown := only - sections:
        sys.exit(
            f"--only takes a comma-separated subset of {sorted(sections)}, got {sorted(unknown)}"
        )
    if "lbvh" in only:
        lbvh_build()
    if "closest" in only:
        closest_point_queries()
    if "sdf" in only:
        sdf_build()
    if "spheres" in only:
        sphere_fits()
    if "robot" in only:
        robot_checks()
    if "plan" in only:
        plan_checks()


if __name__ == "__main__":
    main()
