"""SampledMotion: a robot motion sampled in time, the one type every workflow plays and plots.

TCP speed has one formula here: central differences of the TCP positions over the sample
times (`np.gradient`, one-sided at the two ends). Central differences are second-order
accurate and centred on the sample they belong to; forward or backward differences are
first-order, lag or lead by half a sample, and put an artificial 0 at one end. The central
speed at a sample is the norm of the mean of its two neighbouring chord velocities, so it
never exceeds the larger chord speed: a bound a test checks on forward differences holds.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.motion.trajectory import Trajectory

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class SampledMotion:
    """A motion sampled at `times` (N,) [s], non-decreasing, from 0 (or any start).

    joints: (N, dof) [rad]; velocities, accelerations: (N, dof) [rad/s, rad/s^2] or None
    (then `velocity`/`acceleration` give central differences); tcp: (N, 3) TCP positions or
    (N, 4, 4) TCP poses [m] (world frame), or None; colliding: (N,) samples in collision
    (or whose interval to the next could not be certified free); name: what it is.
    """

    times: FloatArray
    joints: FloatArray
    velocities: FloatArray | None = field(default=None, repr=False)
    accelerations: FloatArray | None = field(default=None, repr=False)
    tcp: FloatArray | None = field(default=None, repr=False)
    colliding: NDArray[np.bool_] = field(default=None, repr=False)  # type: ignore[arg-type]
    name: str = "motion"

    def __post_init__(self) -> None:
        t = np.asarray(self.times, dtype=float)
        if t.ndim != 1 or len(t) == 0 or not np.all(np.isfinite(t)):
            raise InputError(f"times: expected (N,) finite seconds with N >= 1, got {t.shape}")
        if np.any(np.diff(t) < 0):
            raise InputError("times: expected non-decreasing sample times [s]")
        n = len(t)
        q = np.asarray(self.joints, dtype=float)
        if q.ndim != 2 or q.shape[0] != n:
            raise InputError(f"joints: expected shape ({n}, dof), got {q.shape}")
        object.__setattr__(self, "times", t)
        object.__setattr__(self, "joints", q)
        for name in ("velocities", "accelerations"):
            v = getattr(self, name)
            if v is not None:
                v = np.asarray(v, dtype=float)
                if v.shape != q.shape:
                    raise InputError(f"{name}: expected shape {q.shape}, got {v.shape}")
                object.__setattr__(self, name, v)
        if self.tcp is not None:
            p = np.asarray(self.tcp, dtype=float)
            if p.shape not in ((n, 3), (n, 4, 4)):
                raise InputError(f"tcp: expected shape ({n}, 3) or ({n}, 4, 4), got {p.shape}")
            object.__setattr__(self, "tcp", p)
        c = np.zeros(n, dtype=bool) if self.colliding is None else np.asarray(self.colliding)
        if c.shape != (n,):
            raise InputError(f"colliding: expected shape ({n},), got {c.shape}")
        object.__setattr__(self, "colliding", c.astype(bool, copy=False))

    @classmethod
    def from_trajectory(
        cls,
        trajectory: Trajectory,
        dt: float,
        *,
        tcp_of: Callable[[FloatArray], FloatArray] | None = None,
        name: str = "motion",
    ) -> SampledMotion:
        """Return the trajectory sampled every `dt` [s] (and at its end) with its derivatives.

        tcp_of maps joints (N, dof) [rad] to TCP positions (N, 3) or poses (N, 4, 4) [m].
        """
        t, q, v, a = trajectory.sample(dt)
        return cls(t, q, v, a, None if tcp_of is None else tcp_of(q), name=name)

    @property
    def duration(self) -> float:
        """Return the time from the first to the last sample [s]."""
        return float(self.times[-1] - self.times[0])

    @property
    def dof(self) -> int:
        """Return the number of joints."""
        return int(self.joints.shape[1])

    @property
    def tcp_positions(self) -> FloatArray | None:
        """Return TCP positions (N, 3) [m], or None without TCP samples."""
        if self.tcp is None:
            return None
        return self.tcp if self.tcp.ndim == 2 else self.tcp[:, :3, 3]

    @cached_property
    def tcp_speed(self) -> FloatArray:
        """Return the TCP speed (N,) [m/s] by central differences (zeros without TCP samples)."""
        p = self.tcp_positions
        if p is None or len(p) < 2:
            return np.zeros(len(self.times))
        return np.asarray(np.linalg.norm(_gradient(p, self.times), axis=1))

    @cached_property
    def velocity(self) -> FloatArray:
        """Return joint velocities (N, dof) [rad/s]: `velocities`, else central differences."""
        if self.velocities is not None:
            return self.velocities
        return _gradient(self.joints, self.times)

    @cached_property
    def acceleration(self) -> FloatArray:
        """Return joint accelerations (N, dof) [rad/s^2]: given, else central differences."""
        if self.accelerations is not None:
            return self.accelerations
        return _gradient(self.velocity, self.times)

    def at(self, t: float) -> FloatArray:
        """Return joints (dof,) [rad] at time `t` [s], linear between samples, clamped."""
        t = float(np.clip(t, self.times[0], self.times[-1]))
        return np.array([np.interp(t, self.times, self.joints[:, j]) for j in range(self.dof)])

    def index_at(self, t: ArrayLike) -> NDArray[np.intp]:
        """Return the index of the last sample at or before each time `t` [s] (clamped)."""
        k = np.searchsorted(self.times, np.asarray(t, dtype=float), side="right") - 1
        return np.clip(k, 0, len(self.times) - 1)

    def summary(self) -> str:
        """Return one line: name, duration, samples, collisions."""
        hits = int(self.colliding.sum())
        coll = f"{hits} colliding samples" if hits else "collision-free"
        return f"{self.name}: {self.duration:.3f} s, {len(self.times)} samples, {coll}"


def _gradient(y: FloatArray, t: FloatArray) -> FloatArray:
    """Return dy/dt (N, ...) by central differences; repeated times get one-sided ones."""
    if len(t) < 2:
        return np.zeros_like(y)
    if np.all(np.diff(t) > 0):
        return np.asarray(np.gradient(y, t, axis=0))
    # Duplicate times (a stop joined to the next segment): differentiate the distinct ones.
    keep = np.r_[True, np.diff(t) > 0]
    idx = np.cumsum(keep) - 1
    ys, ts = y[keep], t[keep]
    g = np.gradient(ys, ts, axis=0) if len(ts) > 1 else np.zeros_like(ys)
    return np.asarray(g[idx])
