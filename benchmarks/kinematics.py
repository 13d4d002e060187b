"""Kinematics throughput: our batched/single FK and analytic IK against pinocchio on the same poses.

Peers, measured in the same run on the same 10,000 random MZ07 configurations (seed 0):
- FK: pinocchio ``forwardKinematics`` + ``updateFramePlacement`` of the flange, in a Python loop;
- IK: pinocchio CLIK (damped least squares on log6, full Newton steps) in a Python loop, started
  from a nearby seed (the true solution + N(0, 0.1 rad)); it returns one solution, ours all (<= 8).
- py-opw-kinematics (Rust rs-opw-kinematics behind PyO3; ``pip install -r
  benchmarks/requirements.txt``): an analytic OPW solver like ours, configured with the
  MZ07's OPW parameters derived from our DH rows (`opw_peer`); both solvers' solution sets
  are compared on 1,000 poses before anything is timed. IK: ``Robot.reach`` (all eight
  branches of N poses in one call, threads=1) and ``Robot.inverse`` (all solutions of one
  pose); FK: ``Robot.batch_forward`` and ``Robot.forward``.

Run: ``python benchmarks/kinematics.py`` (``--quick`` for fewer poses; ``--no-opw`` skips
py-opw-kinematics).
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable

import numpy as np
import pinocchio as pin

from workbench.kinematics import DHRobot
from workbench.kinematics.robot_library import preset_robot


def best_of(fn: Callable[[], object], repeat: int) -> float:
    """Return the best wall time [s] of `repeat` runs of fn."""
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def clik(
    model: pin.Model, data: pin.Data, fid: int, target: pin.SE3, q0: np.ndarray
) -> tuple[np.ndarray, bool]:
    """Return (q, converged): pinocchio's CLIK example with full steps, |log6| < 1e-9."""
    q = q0.copy()
    for _ in range(100):
        pin.forwardKinematics(model, data, q)
        dMi = target.actInv(pin.updateFramePlacement(model, data, fid))
        err = pin.log6(dMi).vector
        if np.linalg.norm(err) < 1e-9:
            return q, True
        J = pin.Jlog6(dMi) @ pin.computeFrameJacobian(model, data, q, fid, pin.LOCAL)
        q = pin.integrate(model, q, -J.T @ np.linalg.solve(J @ J.T + 1e-12 * np.eye(6), err))
    return q, False


def times_of(fn: Callable[[], object], repeat: int) -> tuple[float, float, float]:
    """Return (best, median, worst) wall time [s] of `repeat` runs of fn after one warm-up."""
    fn()
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return min(ts), float(np.median(ts)), max(ts)


def opw_peer(robot: DHRobot):  # type: ignore[no-untyped-def]
    """Return a py_opw_kinematics.Robot (radians) with the MZ07's OPW parameters.

    From our DH rows (`opw_geometry`, m): a1 = a1 = 0.05 (J2 ahead of J1's axis),
    a2 = -a3 = -0.045 (J3 -> wrist offset; OPW's sign is negative for the usual elbow),
    b = d2 + d3 = 0, c1 = d1 = 0.34, c2 = a2 = 0.33, c3 = d4 = 0.34, c4 = |d6| = 0.09.
    Offsets and flip_axes map our joint zeros and directions onto OPW's; they were found by
    matching the wrist centre (joints 1-3) and then the flange pose (4-6) on random
    configurations, and are re-checked here on every run (`check_opw`). The package's README
    configures robots the same way: ``KinematicModel(a1=..., a2=..., b=..., c1=..., c2=...,
    c3=..., c4=..., offsets=..., flip_axes=...)`` then ``Robot(kinematic_model, degrees=...)``
    (github.com/CEAD-group/py-opw-kinematics README, "Usage").
    """
    from py_opw_kinematics import KinematicModel, Robot

    g = robot.opw
    assert g is not None
    km = KinematicModel(
        a1=g.a1,
        a2=-g.a3,
        b=g.b,
        c1=g.d1,
        c2=g.a2,
        c3=g.d4,
        c4=abs(g.w6[2]),
        offsets=(0.0, 0.0, -np.pi / 2, 0.0, -np.pi / 2, np.pi),
        flip_axes=(False, True, True, False, False, True),
    )
    return Robot(km, degrees=False)


def _wrap(x: np.ndarray) -> np.ndarray:
    return (x + np.pi) % (2 * np.pi) - np.pi


def check_opw(robot: DHRobot, peer, Q: np.ndarray) -> str:  # type: ignore[no-untyped-def]
    """Assert that FK agrees and both IKs give the same solution sets on poses fk(Q)."""
    from scipy.spatial.transform import RigidTransform

    T = robot.fk(Q)
    P = peer.batch_forward(Q).as_matrix()
    fk_err = float(np.abs(P - T).max())
    assert fk_err < 1e-9, f"py-opw FK differs from ours by {fk_err:.2e}"
    reach = peer.reach(RigidTransform.from_matrix(T), threads=1)
    qb, valid = robot.ik_batch(T)
    lo, hi = robot.limits[:, 0], robot.limits[:, 1]
    n_sol = 0
    for i in range(len(T)):
        ours = qb[i][valid[i]]
        theirs = reach.joints[i][~np.isnan(reach.joints[i]).any(axis=1)]
        # py-opw wraps angles to (-pi, pi] and applies no limits: keep the branches that have
        # a turn within our limits (J4 +-190 deg, J5 -210..30 deg, J6 +-360 deg).
        k = np.arange(-2, 3)[:, None, None] * 2 * np.pi
        fits = ((theirs + k >= lo - 1e-9) & (theirs + k <= hi + 1e-9)).any(axis=0).all(axis=1)
        theirs = theirs[fits]

        def distinct(S: np.ndarray) -> np.ndarray:
            keep: list[np.ndarray] = []
            for s in S:
                if all(np.abs(_wrap(s - t)).max() > 1e-7 for t in keep):
                    keep.append(s)
            return np.array(keep).reshape(-1, 6)

        a, b = distinct(ours), distinct(theirs)
        assert len(a) == len(b), f"pose {i}: ours {len(a)} solutions, py-opw {len(b)}"
        d = np.abs(_wrap(a[:, None] - b[None])).max(axis=-1)
        assert d.min(axis=1).max() < 1e-7, f"pose {i}: solution sets differ ({d.min(axis=1)})"
        n_sol += len(a)
    return (
        f"py-opw vs ours on {len(T)} poses: FK max |dT| {fk_err:.1e}; same solution sets "
        f"(mod 2 pi, within limits; {n_sol} solutions, {n_sol / len(T):.2f} per pose)"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1,000 poses instead of 10,000")
    parser.add_argument("--no-opw", action="store_true", help="skip py-opw-kinematics")
    args = parser.parse_args()
    n = 1000 if args.quick else 10000
    n_single = min(n, 2000)
    n_clik = min(n, 1000)
    robot = preset_robot("mz07")
    rng = np.random.default_rng(0)
    Q = rng.uniform(robot.limits[:, 0], robot.limits[:, 1], (n, 6))
    T = robot.fk(Q)
    model, data = robot.pinocchio_model()
    fid = model.getFrameId("flange")
    rows: list[tuple[str, float, float]] = []

    # FK ---------------------------------------------------------------------------------
    ours_fk_batch = best_of(lambda: robot.fk(Q), 5) / n

    def ours_fk_single() -> None:
        for q in Q[:n_single]:
            robot.fk(q)

    def pin_fk() -> None:
        for q in Q:
            pin.forwardKinematics(model, data, q)
            pin.updateFramePlacement(model, data, fid)

    ours_fk_one = best_of(ours_fk_single, 3) / n_single
    pin_fk_one = best_of(pin_fk, 3) / n
    rows += [
        ("FK batched (10k)" if n == 10000 else f"FK batched ({n})", ours_fk_batch, pin_fk_one),
        ("FK single call", ours_fk_one, pin_fk_one),
    ]

    # IK ---------------------------------------------------------------------------------
    ours_ik_batch = best_of(lambda: robot.ik_batch(T), 5) / n

    def ours_ik_single() -> None:
        for Ti in T[:n_single]:
            robot.ik(Ti)

    ours_ik_one = best_of(ours_ik_single, 3) / n_single
    targets = [pin.SE3(Ti[:3, :3].copy(), Ti[:3, 3].copy()) for Ti in T[:n_clik]]
    seeds = Q[:n_clik] + rng.normal(0.0, 0.1, (n_clik, 6))
    converged = 0

    def pin_ik() -> None:
        nonlocal converged
        converged = 0
        for target, seed in zip(targets, seeds, strict=False):
            converged += clik(model, data, fid, target, seed)[1]

    pin_ik_one = best_of(pin_ik, 2) / n_clik
    rows += [
        ("IK all solutions, batched", ours_ik_batch, pin_ik_one),
        ("IK all solutions, single call", ours_ik_one, pin_ik_one),
    ]

    # Accuracy of ours on the same poses.
    qb, valid = robot.ik_batch(T)
    fk_err = np.abs(robot.fk(np.where(valid[..., None], qb, 0.0)) - T[:, None]).max(axis=(2, 3))[
        valid
    ]
    d = np.abs((qb - Q[:, None, :] + np.pi) % (2 * np.pi) - np.pi).max(axis=-1)
    found = np.nanmin(np.where(valid, d, np.inf), axis=1) < 1e-9

    print(f"MZ07, {n} random poses within limits (seed 0); times are per pose, best of repeats")
    print(
        f"{'case':34s} {'ours [us]':>10s} {'pinocchio [us]':>15s} {'ratio pin/ours':>15s} {'ours poses/s':>13s}"
    )
    for name, ours, peer in rows:
        print(
            f"{name:34s} {ours * 1e6:10.3f} {peer * 1e6:15.3f} {peer / ours:15.2f} {1.0 / ours:13.0f}"
        )
    print(
        f"pinocchio CLIK: {converged}/{n_clik} converged from seeds 0.1 rad away (one solution each)"
    )
    print(
        f"ours: mean {valid.sum(1).mean():.2f} solutions per pose within limits, max |fk - T| "
        f"{fk_err.max():.1e}, original configuration found for {found.mean() * 100:.1f} % of poses"
    )
    if not args.no_opw:
        opw_section(robot, Q, T, n_single)


def opw_section(robot: DHRobot, Q: np.ndarray, T: np.ndarray, n_single: int) -> None:
    """Ours against py-opw-kinematics (Rust), same poses, same process."""
    try:
        peer = opw_peer(robot)
        from scipy.spatial.transform import RigidTransform
    except ImportError as exc:
        print(
            f"py-opw-kinematics not importable ({exc!r}): pip install -r benchmarks/requirements.txt"
        )
        return
    print(check_opw(robot, peer, Q[:1000]))
    n = len(T)
    RT = RigidTransform.from_matrix(T)  # the peer's pose type, built outside the timings
    singles = [RT[i] for i in range(n_single)]
    mats = [np.ascontiguousarray(Ti) for Ti in T[:n_single]]
    qs = [tuple(q) for q in Q[:n_single].tolist()]
    core = peer._robot  # the Rust object behind the wrapper: matrices in, matrices/lists out

    def ours_ik_single() -> None:
        for Ti in mats:
            robot.ik(Ti)

    def opw_ik_single() -> None:
        for p in singles:
            peer.inverse(p)

    def opw_core_ik_single() -> None:
        for Ti in mats:
            core.inverse(Ti, None, None)

    def ours_fk_single() -> None:
        for q in Q[:n_single]:
            robot.fk(q)

    def opw_fk_single() -> None:
        for q in qs:
            peer.forward(q)

    def opw_core_fk_single() -> None:
        for q in qs:
            core.forward(q, None)

    cases = [
        (
            "IK all solutions, batched",
            n,
            lambda: robot.ik_batch(T),
            "reach(threads=1)",
            lambda: peer.reach(RT, threads=1),
        ),
        (
            "IK batched (peer: 1 per pose)",
            n,
            lambda: robot.ik_batch(T),
            "batch_inverse",
            lambda: peer.batch_inverse(RT),
        ),
        (
            "IK all solutions, single call",
            n_single,
            ours_ik_single,
            "inverse(RigidTransform)",
            opw_ik_single,
        ),
        (
            "IK all solutions, single call",
            n_single,
            ours_ik_single,
            "Rust core inverse(4x4)",
            opw_core_ik_single,
        ),
        ("FK batched", n, lambda: robot.fk(Q), "batch_forward", lambda: peer.batch_forward(Q)),
        ("FK single call", n_single, ours_fk_single, "forward -> RigidTransform", opw_fk_single),
        (
            "FK single call",
            n_single,
            ours_fk_single,
            "Rust core forward -> 4x4",
            opw_core_fk_single,
        ),
    ]
    print(
        f"py-opw-kinematics: per pose [us], best / median / worst of 7 runs after a warm-up"
        f" ({n} poses batched, {n_single} single calls)"
    )
    print(f"{'case':31s} {'ours':>22s}  {'py-opw call':25s} {'py-opw':>22s} {'py-opw/ours':>11s}")
    for name, count, ours_fn, peer_name, peer_fn in cases:
        o = [x / count * 1e6 for x in times_of(ours_fn, 7)]
        p = [x / count * 1e6 for x in times_of(peer_fn, 7)]
        print(
            f"{name:31s} {o[0]:6.2f} / {o[1]:6.2f} / {o[2]:6.2f}  {peer_name:25s}"
            f" {p[0]:6.2f} / {p[1]:6.2f} / {p[2]:6.2f} {p[0] / o[0]:11.2f}"
        )
    print(
        "  reach also returns per-branch limit margins, Jacobian sigma_min and |sin t5| (work"
        " ours does not do); batch_inverse (the README's batch IK) returns one solution per pose,"
        " the one nearest the previous; batch_forward returns a scipy RigidTransform (no matrix"
        " copy timed); the Rust core rows skip the wrapper's scipy conversions"
    )


if __name__ == "__main__":
    main()
