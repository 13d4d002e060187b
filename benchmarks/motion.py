"""Benchmark: flowing trajectories vs stop-and-go ruckig on the same waypoint sets.

Prints the cycle time of `smooth_joint_path` against plain ruckig called rest-to-rest
for every segment (the peer), their ratio, and the computation time per trajectory.
Run: python benchmarks/motion.py
"""

from __future__ import annotations

import time

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


def stop_and_go(q: np.ndarray) -> float:
    """Return the cycle time [s] of plain ruckig, rest to rest at every waypoint."""
    otg, inp = ruckig.Ruckig(6), ruckig.InputParameter(6)
    inp.max_velocity, inp.max_acceleration, inp.max_jerk = V.tolist(), A.tolist(), J.tolist()
    total = 0.0
    for a, b in zip(q[:-1], q[1:], strict=True):
        inp.current_position, inp.target_position = a.tolist(), b.tolist()
        tr = ruckig.Trajectory(6)
        assert otg.calculate(inp, tr) == ruckig.Result.Working
        total += tr.duration
    return total


def main() -> None:
    rng = np.random.default_rng(0)
    print("waypoints  sets  flowing[s]  stop-and-go[s]  ratio(mean/max)  ours[ms]  peer[ms]")
    for n in (10, 50):
        sets = [gentle_path(n, rng) for _ in range(30)]
        ours, peer, t_ours, t_peer = [], [], [], []
        for q in sets:
            t0 = time.perf_counter()
            ours.append(smooth_joint_path(q, V, A, J).duration)
            t1 = time.perf_counter()
            peer.append(stop_and_go(q))
            t_ours.append(t1 - t0)
            t_peer.append(time.perf_counter() - t1)
        r = np.array(ours) / np.array(peer)
        print(
            f"{n:9d}  {len(sets):4d}  {np.mean(ours):10.3f}  {np.mean(peer):14.3f}  "
            f"{r.mean():6.3f}/{r.max():6.3f}  {1e3 * np.median(t_ours):8.2f}  "
            f"{1e3 * np.median(t_peer):8.2f}"
        )
    print(f"limits: v={V[0]} rad/s, a={A[0]} rad/s^2, j={J[0]} rad/s^3; steps 0.1-0.3 rad")


if __name__ == "__main__":
    main()
