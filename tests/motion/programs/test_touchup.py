"""The touch-up comparison on synthetic targets: a known work-object correction with noise and
one target moved alone, recovered over many seeds; the consensus fit against a brute force over
every subset; the move alignment against a brute force over every in-order pairing."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from workbench.errors import InputError
from workbench.geometry.rigid_fit import fit_rigid
from workbench.geometry.transforms import xyz_rpy_to_transform
from workbench.motion.programs import touchup as tu
from workbench.motion.programs.touchup import (
    PlannedTarget,
    TaughtTarget,
    TouchupSettings,
    compare,
    match_moves,
    rotation_angle,
    same_name,
)


def _random_pose(rng: np.random.Generator, scale: float = 0.3) -> np.ndarray:
    return xyz_rpy_to_transform(rng.uniform(-scale, scale, 3), rng.uniform(-np.pi, np.pi, 3))


def _cell(rng: np.random.Generator, n: int, wobj: str = "fixture"):
    """Return a work object frame and n planned targets in it (world poses)."""
    W = _random_pose(rng, 1.0)
    planned = [
        PlannedTarget(k, f"t{k}", "linear", wobj, W @ _random_pose(rng, 0.2)) for k in range(n)
    ]
    return W, planned


def _taught(p: PlannedTarget, T: np.ndarray, name: str | None = None) -> TaughtTarget:
    return TaughtTarget(name or p.name, p.kind, p.wobj, 1, T, np.zeros(6), True)


def _correction(rng: np.random.Generator) -> np.ndarray:
    return xyz_rpy_to_transform(rng.uniform(-0.004, 0.004, 3), np.radians(rng.uniform(-1, 1, 3)))


def _noisy(rng: np.random.Generator, T: np.ndarray, sigma: float) -> np.ndarray:
    d = xyz_rpy_to_transform(rng.normal(0, sigma, 3), rng.normal(0, np.radians(0.005), 3))
    return T @ d


@pytest.mark.parametrize(
    "seed", [*range(14), *(pytest.param(s, marks=pytest.mark.slow) for s in range(14, 200))]
)
def test_a_known_correction_is_recovered_and_the_target_moved_alone_named(seed: int) -> None:
    rng = np.random.default_rng(seed)
    n = int(rng.integers(4, 10))
    W, planned = _cell(rng, n)
    C = _correction(rng)
    D = W @ C @ np.linalg.inv(W)  # the fixture's move in the world
    alone = int(rng.integers(n))
    taught = []
    for k, p in enumerate(planned):
        T = _noisy(rng, D @ p.T_world_tcp, 0.02e-3)
        if k == alone:  # re-taught alone: 2 to 5 mm off along a random direction
            v = rng.normal(size=3)
            T[:3, 3] += v / np.linalg.norm(v) * rng.uniform(2e-3, 5e-3)
        taught.append(_taught(p, T))
    report = compare(planned, taught, {"base": np.eye(4), "fixture": W})
    c = report.correction
    assert c is not None and c.fitted
    assert c.outliers == (f"t{alone}",)
    # the least-squares fit of the true inliers (the twin), which puts every target within the
    # noise of where the fixture's true move puts it
    inliers = [k for k in range(n) if k != alone]
    P = np.array([np.linalg.solve(W, p.T_world_tcp)[:3, 3] for p in planned])
    Q = np.array([np.linalg.solve(W, t.T_world_tcp)[:3, 3] for t in taught])
    np.testing.assert_allclose(c.T_correction, fit_rigid(P[inliers], Q[inliers]).T, atol=1e-9)
    predicted = P @ c.T_correction[:3, :3].T + c.T_correction[:3, 3]
    true = P @ C[:3, :3].T + C[:3, 3]
    assert np.max(np.linalg.norm(predicted - true, axis=1)[inliers]) < 0.1e-3
    assert c.max < 0.1e-3
    rows = {r.name: r for r in report.rows}
    assert rows[f"t{alone}"].agrees is False
    assert all(r.agrees for r in report.rows if r.name != f"t{alone}")
    # the displayed change: in the work object's axes, what W @ C would show
    k = (alone + 1) % n
    want = W[:3, :3].T @ (taught[k].T_world_tcp[:3, 3] - planned[k].T_world_tcp[:3, 3])
    np.testing.assert_allclose(rows[f"t{k}"].delta, want, atol=1e-12)


def _brute_force_largest_agreeing_subset(planned, taught, s: TouchupSettings) -> set[int]:
    """Every subset of at least 3 targets fitted by least squares; the largest whose every
    member is within the tolerances (ties: the smallest rms)."""
    n = len(planned)
    src = np.array([p.T_world_tcp[:3, 3] for p in planned])
    tgt = np.array([t.T_world_tcp[:3, 3] for t in taught])
    best, best_rms = set(), np.inf
    for size in range(n, 2, -1):
        for subset in itertools.combinations(range(n), size):
            try:
                fit = fit_rigid(src[list(subset)], tgt[list(subset)])
            except InputError:
                continue
            R = fit.T[:3, :3]
            ok = all(
                fit.residuals[i] <= s.fit_distance
                and rotation_angle(
                    R @ planned[k].T_world_tcp[:3, :3], taught[k].T_world_tcp[:3, :3]
                )
                <= s.fit_angle
                for i, k in enumerate(subset)
            )
            if ok and fit.rms < best_rms:
                best, best_rms = set(subset), fit.rms
        if best:
            return best
    return best


@pytest.mark.parametrize("seed", range(15))
def test_the_consensus_fit_keeps_the_largest_agreeing_set_as_brute_force_does(seed: int) -> None:
    rng = np.random.default_rng(100 + seed)
    n = int(rng.integers(5, 8))
    W, planned = _cell(rng, n)
    W = np.eye(4)  # compare in the world: the brute force fits world points
    planned = [PlannedTarget(p.index, p.name, p.kind, p.wobj, p.T_world_tcp) for p in planned]
    C = _correction(rng)
    movers = set(rng.choice(n, size=int(rng.integers(0, 3)), replace=False).tolist())
    taught = []
    for k, p in enumerate(planned):
        T = _noisy(rng, C @ p.T_world_tcp, 0.03e-3)
        if k in movers:  # moved alone, some by a turn of the tool only
            if rng.random() < 0.5:
                T[:3, 3] += rng.uniform(1.5e-3, 4e-3) * np.array([0.0, 0.0, 1.0])
            else:
                T = T @ xyz_rpy_to_transform([0, 0, 0], np.radians([0, 0, rng.uniform(2, 5)]))
        taught.append(_taught(p, T))
    s = TouchupSettings()
    rows = compare(planned, taught, {"base": np.eye(4), "fixture": W}).corrections[0]
    kept = {k for k, name in enumerate(rows.names) if name not in rows.outliers}
    assert kept == _brute_force_largest_agreeing_subset(planned, taught, s)
    assert kept == set(range(n)) - movers


def _pairings_brute_force(planned, taught) -> float:
    """The least cost over every in-order pairing: k planned and k taught moves, chosen in
    order, paired in order; the rest deleted or added."""
    by_name = tu.names_kept(planned, taught)
    n, m = len(planned), len(taught)
    best = np.inf

    def pair_cost(p, t) -> float:  # written out again, one pair at a time
        if by_name:
            if p.name.lower() == t.name.lower():
                return 0.0
            return tu.RENAMED_COST if same_name(p.name, t.name) else 3.0 * tu.GAP_COST
        d = np.linalg.norm(p.T_world_tcp[:3, 3] - t.T_world_tcp[:3, 3])
        kind = 0.0 if (p.kind == "joint") == (t.kind == "joint") else 0.25 * tu.GAP_COST
        return 2.0 * tu.GAP_COST * d / tu.REPLACED_DISTANCE + kind

    for k in range(min(n, m) + 1):
        for ps in itertools.combinations(range(n), k):
            for ts in itertools.combinations(range(m), k):
                cost = sum(pair_cost(planned[i], taught[j]) for i, j in zip(ps, ts, strict=True))
                best = min(best, cost + (n - k + m - k) * tu.GAP_COST)
    return best


def _alignment_cost(planned, taught, pairs) -> float:
    costs = tu.pair_costs(planned, taught, tu.names_kept(planned, taught))
    return sum(tu.GAP_COST if i is None or j is None else costs[i, j] for i, j in pairs)


@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("names", [True, False])
def test_the_alignment_is_the_cheapest_in_order_pairing(seed: int, names: bool) -> None:
    rng = np.random.default_rng(200 + seed)
    _, planned = _cell(rng, int(rng.integers(2, 6)))
    kept = [p for p in planned if rng.random() > 0.25]
    taught = [_taught(p, p.T_world_tcp, p.name if names else f"P{k}") for k, p in enumerate(kept)]
    for _ in range(int(rng.integers(0, 2))):  # a move added on the pendant
        at = int(rng.integers(len(taught) + 1))
        extra = planned[0].T_world_tcp @ xyz_rpy_to_transform([1.0, 0, 0], [0, 0, 0])  # far
        taught.insert(
            at,
            TaughtTarget(
                "new_pt" if names else "P9", "linear", "fixture", 1, extra, np.zeros(6), True
            ),
        )
    pairs = match_moves(planned, taught)
    assert [i for i, _ in pairs if i is not None] == list(range(len(planned)))
    assert [j for _, j in pairs if j is not None] == list(range(len(taught)))
    assert _alignment_cost(planned, taught, pairs) == pytest.approx(
        _pairings_brute_force(planned, taught)
    )
    matched = {planned[i].name for i, j in pairs if i is not None and j is not None}
    assert matched == {p.name for p in kept}  # nothing mismatched, nothing lost


def test_numbered_names_pair_exactly_before_as_renamed() -> None:
    # pt_1 .. pt_5 are the same name as renamed ("pt"); pt_3 deleted on the pendant must not
    # shift pt_4 onto pt_3's place
    rng = np.random.default_rng(3)
    _, planned = _cell(rng, 5)
    planned = [
        PlannedTarget(p.index, f"pt_{k + 1}", p.kind, p.wobj, p.T_world_tcp)
        for k, p in enumerate(planned)
    ]
    taught = [_taught(p, p.T_world_tcp) for p in planned if p.name != "pt_3"]
    pairs = match_moves(planned, taught)
    assert (2, None) in pairs
    assert all(
        planned[i].name == taught[j].name for i, j in pairs if i is not None and j is not None
    )


def test_names_as_the_posts_write_them_are_the_same() -> None:
    assert same_name("home", "home_1")  # a reserved word renamed
    assert same_name("above left", "above_left")
    assert same_name("Pick", "PICK")  # FANUC and NACHI upper case
    assert same_name("a_very_long_target_name_beyond", "a_very_long_targ")  # truncated
    assert not same_name("pick", "place")
    assert not same_name("p", "")


def test_settings_and_unknown_work_objects_are_refused_by_name() -> None:
    with pytest.raises(InputError, match="fit_distance"):
        TouchupSettings(fit_distance=0.0)
    p = PlannedTarget(0, "a", "linear", "table", np.eye(4))
    with pytest.raises(InputError, match="no work object 'table'"):
        compare([p], [_taught(p, np.eye(4))], {"base": np.eye(4)})


def test_too_few_targets_give_no_fit_with_the_reason() -> None:
    rng = np.random.default_rng(7)
    W, planned = _cell(rng, 2)
    taught = [
        _taught(p, p.T_world_tcp @ xyz_rpy_to_transform([0.001, 0, 0], [0, 0, 0])) for p in planned
    ]
    report = compare(planned, taught, {"base": np.eye(4), "fixture": W})
    c = report.correction
    assert c is not None and not c.fitted and "at least 3 points" in c.reason
    assert all(r.moved and r.agrees is None for r in report.rows)
    assert "no correction fitted" in report.summary()


def test_each_work_object_gets_its_own_correction() -> None:
    rng = np.random.default_rng(11)
    W_a, a = _cell(rng, 5, "table")
    W_b, b = _cell(rng, 4, "press")
    C_a, C_b = _correction(rng), _correction(rng)
    planned = a + [
        PlannedTarget(5 + p.index, f"b{p.index}", p.kind, p.wobj, p.T_world_tcp) for p in b
    ]
    D = {"table": W_a @ C_a @ np.linalg.inv(W_a), "press": W_b @ C_b @ np.linalg.inv(W_b)}
    taught = [_taught(p, D[p.wobj] @ p.T_world_tcp) for p in planned]
    report = compare(planned, taught, {"base": np.eye(4), "table": W_a, "press": W_b})
    got = {c.wobj: c for c in report.corrections}
    np.testing.assert_allclose(got["table"].T_correction, C_a, atol=1e-9)
    np.testing.assert_allclose(got["press"].T_correction, C_b, atol=1e-9)
    assert report.correction is got["table"]  # the one with the most moves
    np.testing.assert_allclose(got["press"].T_world_wobj_new, W_b @ C_b, atol=1e-12)


@pytest.mark.parametrize("seed", range(12))
def test_positions_re_taught_with_the_tools_orientation_left_as_it_was(seed: int) -> None:
    # the fixture turned by 0.35 deg; the pendant re-taught the positions only (a common
    # practice): every target's own pose change is then a pure shift that fits no other
    # target, but the positions of any three give the fixture's move; t2 moved alone
    rng = np.random.default_rng(300 + seed)
    W, planned = _cell(rng, 6)
    C = xyz_rpy_to_transform([0.002, -0.001, 0.0015], np.radians([0.1, -0.15, 0.3]))
    D = W @ C @ np.linalg.inv(W)
    taught = []
    for k, p in enumerate(planned):
        T = p.T_world_tcp.copy()
        T[:3, 3] = (D @ p.T_world_tcp)[:3, 3] + (np.array([0.003, 0, 0]) if k == 2 else 0.0)
        taught.append(_taught(p, T))
    c = compare(planned, taught, {"base": np.eye(4), "fixture": W}).correction
    assert c is not None and c.outliers == ("t2",)
    np.testing.assert_allclose(c.T_correction, C, atol=1e-9)
