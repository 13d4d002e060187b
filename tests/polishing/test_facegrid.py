"""Tests of workbench/polishing/facegrid.py: the grid's candidates are complete.

Twin: brute force over every face, the centroids within the square [p - reach, p + reach]
(Chebyshev distance <= reach) must all be candidates of p, and no candidate lies beyond the
3 x 3 block of cells around p (Chebyshev distance < 2 h).
"""

from __future__ import annotations

import numpy as np

from workbench.polishing.facegrid import FaceGrid


def test_candidates_hold_every_near_centroid_brute_force() -> None:
    rng = np.random.default_rng(0)
    for _ in range(10):
        F = int(rng.integers(50, 400))
        cu, cv = rng.uniform(0, 0.3, F), rng.uniform(-0.1, 0.1, F)
        reach = float(rng.uniform(0.01, 0.04))
        grid = FaceGrid.build(cu, cv, reach, max_per_cell=10_000)
        assert grid is not None and grid.h >= reach
        p = np.c_[rng.uniform(-0.05, 0.35, 200), rng.uniform(-0.15, 0.15, 200)]
        owner, face = grid.candidates(p)
        assert np.all(np.diff(owner) >= 0)  # grouped by owner, in order
        for q in range(len(p)):
            got = set(face[owner == q].tolist())
            cheb = np.maximum(np.abs(cu - p[q, 0]), np.abs(cv - p[q, 1]))
            need = set(np.flatnonzero(cheb <= reach).tolist())
            assert need <= got, q
            assert np.all(cheb[list(got)] < 2 * grid.h + 1e-12)
            assert len(got) == len(face[owner == q])  # no face twice


def test_every_face_is_in_one_cell() -> None:
    rng = np.random.default_rng(1)
    cu, cv = rng.uniform(0, 1, 300), rng.uniform(0, 1, 300)
    grid = FaceGrid.build(cu, cv, 0.1, max_per_cell=10_000)
    assert grid is not None
    assert sorted(grid.order.tolist()) == list(range(300))
    for c in range(grid.nx * grid.ny):
        ix, iy = divmod(c, grid.ny)
        for f in grid.order[grid.ptr[c] : grid.ptr[c + 1]]:
            assert int((cu[f] - grid.lo[0]) / grid.h) == ix
            assert int((cv[f] - grid.lo[1]) / grid.h) == iy


def test_crowded_cells_and_huge_charts() -> None:
    cu = np.r_[np.zeros(40), 1.0]
    assert FaceGrid.build(cu, np.zeros(41), 0.1) is None  # 40 faces in one cell > 32
    # a chart needing more than 65,536 cells of side `reach` grows its cells instead
    grid = FaceGrid.build(np.array([0.0, 1.0]), np.array([0.0, 1.0]), 1e-3)
    assert grid is not None and grid.nx * grid.ny <= 1 << 16 and grid.h > 1e-3
