"""Fig. 12's measurement: the flat per-flange loop agrees with the tree; tests and times per frame."""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation
from twins import load_module

from workbench.geometry import OBB
from workbench.geometry.transforms import make_transform
from workbench.sheetmetal import SheetMetalPart
from workbench.sheetmetal.check_cost import check_cost, flat_loop, time_checks

_tp = load_module("tests/sheetmetal/test_part.py", "part_twin")


def test_flat_loop_equals_the_tree_and_counts_every_pair() -> None:
    tree = SheetMetalPart.from_spec(_tp.seed_spec()).fold(6).obb_tree("1")
    rng = np.random.default_rng(7)
    M, F = 12, 30
    obstacles = OBB(
        rng.uniform(-0.6, 0.6, (M, 3)),
        Rotation.random(M, random_state=rng).as_matrix(),
        rng.uniform(0.01, 0.06, (M, 3)),
    )
    T = make_transform(
        Rotation.random(F, random_state=rng).as_matrix(), rng.uniform(-0.4, 0.4, (F, 3))
    )
    verdict = tree.collide_frames(obstacles, T).collides
    assert verdict.any() and not verdict.all()
    assert [flat_loop(tree, obstacles, T[f]) for f in range(F)] == verdict.tolist()
    cost = check_cost(tree, obstacles, T, repeat=1)
    assert np.all(cost.flat_tests == len(tree.leaves) * M)
    np.testing.assert_array_equal(cost.tree_tests, tree.collide_frames(obstacles, T).n_obb_tests)
    assert np.all(cost.tree_seconds > 0) and np.all(cost.flat_seconds > 0)
    free = ~verdict
    assert cost.ratio(free) == cost.tree_tests[free].sum() / cost.flat_tests[free].sum()
    assert cost.ratio(np.zeros(F, bool)) == 0.0
    tree_s, flat_s = time_checks(tree, obstacles, T[:3], repeat=2)
    assert tree_s.shape == flat_s.shape == (3,) and np.all(np.isfinite(tree_s))
