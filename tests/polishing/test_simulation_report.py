"""The force-control run over a polishing path and its figures (`simulation_report.py`).

Twin: `simulate_hybrid_force_control` called directly and the window read by hand.
"""

from __future__ import annotations

import numpy as np
import pytest

from workbench.polishing import Coverage, HybridForceParams, ToolPath, simulate_hybrid_force_control
from workbench.polishing.process_path import PolishingPath
from workbench.polishing.simulation_report import settle_time, simulate_process
from workbench.polishing.toolpath import LEAD_IN, LEAD_OUT, PROCESS


def _line_path(n: int = 31, length: float = 0.06) -> PolishingPath:
    x = np.linspace(0.0, length, n)
    pts = np.stack([x, np.zeros(n), np.zeros(n)], axis=1)
    pts = np.vstack([pts[:1] + [0, 0, 0.01], pts, pts[-1:] + [0, 0, 0.01]])
    kind = np.r_[LEAD_IN, np.full(n, PROCESS), LEAD_OUT].astype(np.int8)
    normals = np.tile([0.0, 0.0, 1.0], (n + 2, 1))
    path = ToolPath(
        pts, normals, kind, np.zeros(n + 2, np.int64), np.zeros((n + 2, 3)), "line", 0.002, 0.01, 1
    )
    cov = Coverage(1.0, 0.0, 0.0, 0.01, samples=np.zeros((1, 3)), distance=np.zeros(1))
    return PolishingPath(path, cov, 20.0, 0.004, pts)


@pytest.mark.parametrize("dwell", [0.5, 0.0])
def test_figures_are_read_after_the_force_builds_up_until_the_feed_ends(dwell: float) -> None:
    pp = _line_path()
    params = HybridForceParams(noise_std=0.2)
    sim = simulate_process(pp, 20.0, 0.02, dwell, params)
    proc = pp.path.is_process
    twin = simulate_hybrid_force_control(
        pp.path.points[proc], pp.path.normals[proc], 20.0, 0.02, params=params, dwell=dwell
    )
    np.testing.assert_array_equal(sim.result.force, twin.force)
    settle = dwell if dwell > 0 else min(0.5, 0.1 * twin.t[-1])
    assert sim.settle_time == settle == settle_time(dwell, float(twin.t[-1]))
    window = (twin.t >= settle) & (twin.t <= dwell + 0.06 / 0.02)
    assert window.sum() > 100
    assert sim.max_force_error == np.abs(twin.force[window] - 20.0).max()
    assert sim.max_orientation_error == twin.orientation_error[window].max()
    assert sim.max_tracking_error == twin.tracking_error.max()
    assert (sim.target_force, sim.feed) == (20.0, 0.02)
    assert sim.summary().startswith("target 20 N at 20 mm/s over ")
