"""Kinematics throughput: our batched/single FK and analytic IK against pinocchio on the same poses.

Peers, measured in the same run on the same 10,000 random MZ07 configurations (seed 0):
- FK: pinocchio ``forwardKinematics`` + ``updateFramePlacement`` of the flange, in a Python loop;
- IK: pinocchio CLIK (damped least squares on log6, full Newton steps) in a Python loop, started
  from a nearby seed (the true solution + N(0, 0.1 rad)); it returns one solution, ours all (<= 8).

Run: ``python benchmarks/kinematics.py`` (``--quick`` for fewer poses).
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable

import numpy as np
import pinocchio as pin

from workbench.kinematics import DHRobot


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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1,000 poses instead of 10,000")
    args = parser.parse_args()
    n = 1000 if args.quick else 10000
    n_single = min(n, 2000)
    n_clik = min(n, 1000)
    robot = DHRobot.mz07()
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


if __name__ == "__main__":
    main()
