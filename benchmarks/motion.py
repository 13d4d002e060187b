"""Benchmark: flowing trajectories vs stop-and-go ruckig and TOPP-RA's time-optimal bound.

For every waypoint set it prints the cycle time of `smooth_joint_path`, of plain ruckig
called rest-to-rest for every segment (stop-and-go), and of TOPP-RA (velocity and
acceleration limits, no jerk: a lower bound for any jerk-limited motion along its path)
along the cubic spline through the same waypoints, as toppra's documentation sets a path
up; the ratios; and the computation time of ours per segment against ruckig's own time
per segment (one `calculate` of the stop-and-go peer).

Sets: the benchmark's gentle random walks (10 and 50 waypoints, steps 0.1-0.3 rad, equal
limits) and "random": 2-25 waypoints, steps 0.05-0.6 rad, random per-joint limits.
Run: python benchmarks/motion.py [--no-toppra] [--sets N]
(toppra: pip install -r benchmarks/requirements.txt)
"""

from __future__ import annotations

import argparse
import time
from dataclasses import dataclass

import numpy as np
import ruckig

from workbench.motion.trajectory import smooth_joint_path

V, A, J = np.full(6, 2.0), np.full(6, 8.0), np.full(6, 60.0)


def gentle_path(
    n: int, rng: np.random.Generator, step: tuple[float, float] = (0.1, 0.3)
) -> np.ndarray:
    """Return (n, 6) waypoints [rad]: a random walk whose direction turns gently (~0.15 rad/step)."""
    d = rng.uniform(-1, 1, 6)
    pts = [np.zeros(6)]
    for _ in range(n - 1):
        d = d / np.linalg.norm(d) + rng.normal(0, 0.15, 6)
        pts.append(pts[-1] + d / np.linalg.norm(d) * rng.uniform(*step))
    return np.array(pts)


@dataclass
class Problem:
    q: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray


def benchmark_sets(n_sets: int, seed: int = 0) -> dict[str, list[Problem]]:
    """Return the named waypoint sets with their limits."""
    rng = np.random.default_rng(seed)
    out: dict[str, list[Problem]] = {}
    for n in (10, 50):
        out[f"gentle {n}"] = [Problem(gentle_path(n, rng), V, A, J) for _ in range(n_sets)]
    rnd = []
    for _ in range(3 * n_sets):
        n = int(rng.integers(2, 26))
        q = gentle_path(n, rng, (0.05, 0.6))
        lim = (rng.uniform(0.5, 3.0, 6), rng.uniform(2.0, 20.0, 6), rng.uniform(20.0, 300.0, 6))
        rnd.append(Problem(q, *lim))
    out["random 2-25"] = rnd
    return out


def stop_and_go(p: Problem) -> tuple[float, float]:
    """Return (cycle time [s], ruckig calculate time [s] summed) rest to rest at every waypoint."""
    otg, inp = ruckig.Ruckig(6), ruckig.InputParameter(6)
    inp.max_velocity, inp.max_acceleration, inp.max_jerk = p.v.tolist(), p.a.tolist(), p.j.tolist()
    total, spent = 0.0, 0.0
    tr = ruckig.Trajectory(6)
    for a, b in zip(p.q[:-1], p.q[1:], strict=True):
        inp.current_position, inp.target_position = a.tolist(), b.tolist()
        t0 = time.perf_counter()
        res = otg.calculate(inp, tr)
        spent += time.perf_counter() - t0
        assert res == ruckig.Result.Working
        total += tr.duration
    return total, spent


def toppra_time(p: Problem) -> float:
    """Return TOPP-RA's time-optimal duration [s] along the spline through the waypoints."""
    import toppra as ta
    import toppra.algorithm as algo
    import toppra.constraint as constraint

    ta.setup_logging("WARNING")
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p.q, axis=0), axis=1))])
    path = ta.SplineInterpolator(s / s[-1], p.q)
    pc_vel = constraint.JointVelocityConstraint(np.stack([-p.v, p.v], axis=1))
    pc_acc = constraint.JointAccelerationConstraint(np.stack([-p.a, p.a], axis=1))
    inst = algo.TOPPRA([pc_vel, pc_acc], path, parametrizer="ParametrizeConstAccel")
    traj = inst.compute_trajectory(0, 0)
    if traj is None:
        return float("nan")
    return float(traj.duration)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--no-toppra", action="store_true", help="skip the TOPP-RA bound")
    ap.add_argument("--sets", type=int, default=30, help="sets per gentle row (random: 3x)")
    args = ap.parse_args()
    print(
        "set          n  ours/s&g(median/max)  ours/TOPP-RA(median/max)  "
        "ours[ms]  ours/ruckig per segment"
    )
    for name, probs in benchmark_sets(args.sets).items():
        r_sg, r_tp, t_ours, t_rk = [], [], [], []
        for p in probs:
            t0 = time.perf_counter()
            ours = smooth_joint_path(p.q, p.v, p.a, p.j).duration
            t_ours.append(time.perf_counter() - t0)
            sg, spent = stop_and_go(p)
            t_rk.append(spent)
            r_sg.append(ours / sg)
            if not args.no_toppra:
                r_tp.append(ours / toppra_time(p))
        r_sg_a, t_o, t_r = np.array(r_sg), np.array(t_ours), np.array(t_rk)
        tp = f"{np.nanmedian(r_tp):6.3f}/{np.nanmax(r_tp):6.3f}" if r_tp else "      -/     -"
        print(
            f"{name:11s} {len(probs):3d}  {np.median(r_sg_a):8.3f}/{r_sg_a.max():6.3f}       "
            f"{tp:>14s}           {1e3 * np.median(t_o):7.2f}  {np.median(t_o / t_r):8.1f}"
        )
    print(
        f"gentle: v={V[0]} rad/s, a={A[0]} rad/s^2, j={J[0]} rad/s^3, steps 0.1-0.3 rad; "
        "random: v 0.5-3, a 2-20, j 20-300 per joint, steps 0.05-0.6 rad"
    )


if __name__ == "__main__":
    main()
