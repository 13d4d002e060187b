"""The hybrid force control run over a polishing path and its figures after the force builds up.

The figures are read in a window: from the settle time (the dwell, when the force has
built up; without a dwell, a short start-up) until the feed reaches the path's end.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workbench.polishing.force_control import (
    ForceControlResult,
    HybridForceParams,
    simulate_hybrid_force_control,
)
from workbench.polishing.process_path import PolishingPath

_MM = 1e-3  # the summary speaks millimetres


@dataclass(frozen=True)
class PolishingSimulation:
    """Force/position hybrid control along the path: the record and its figures.

    `result.t` [s], `result.force` [N], `result.tracking_error` [m],
    `result.orientation_error` [rad]; `max_force_error` [N] is the largest |F - F_target|
    and `max_orientation_error` [rad] the largest tilt of the tool z from the actual surface
    normal, both after `settle_time` [s] (the dwell, when the force has built up) until the
    feed ends; `max_tracking_error` [m] over the whole run.
    """

    result: ForceControlResult
    target_force: float
    feed: float  # [m/s]
    settle_time: float
    max_force_error: float
    max_tracking_error: float
    max_orientation_error: float

    def summary(self) -> str:
        """Return a one-line human summary."""
        return (
            f"target {self.target_force:g} N at {self.feed / _MM:g} mm/s over "
            f"{self.result.t[-1]:.1f} s: force within ±{self.max_force_error:.2f} N after "
            f"{self.settle_time:g} s, tracking error ≤ {self.max_tracking_error / _MM:.3f} mm, "
            f"tool axis within {np.degrees(self.max_orientation_error):.2f}° of the normal"
        )


def settle_time(dwell: float, duration: float) -> float:
    """Return when the force has built up [s]: the dwell, or without one the first tenth of
    the run (at most 0.5 s)."""
    return dwell if dwell > 0 else min(0.5, 0.1 * duration)


def simulate_process(
    path: PolishingPath,
    force: float,
    feed: float,
    dwell: float,
    params: HybridForceParams,
) -> PolishingSimulation:
    """Return the `PolishingSimulation` of the hybrid force control over the process points of
    `path` at target `force` [N] and `feed` [m/s] after `dwell` [s] at the first point.

    Raises `InputError` for values the controller refuses (`simulate_hybrid_force_control`)."""
    proc = path.path.is_process
    res = simulate_hybrid_force_control(
        path.path.points[proc],
        path.path.normals[proc],
        force,
        feed,
        params=params,
        dwell=dwell,
    )
    settle = settle_time(dwell, float(res.t[-1]))
    feed_end = dwell + path.length / feed
    window = (res.t >= settle) & (res.t <= feed_end)
    ferr = float(np.max(np.abs(res.force[window] - force))) if window.any() else np.nan
    oerr = float(np.max(res.orientation_error[window])) if window.any() else np.nan
    return PolishingSimulation(
        result=res,
        target_force=float(force),
        feed=feed,
        settle_time=float(settle),
        max_force_error=ferr,
        max_tracking_error=float(res.tracking_error.max()),
        max_orientation_error=oerr,
    )
