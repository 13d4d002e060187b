"""OBB and the separating-axis test against python-fcl (box-box) and brute force."""

from __future__ import annotations

import fcl
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from workbench.errors import InputError
from workbench.geometry import OBB, obb_overlap


def random_boxes(rng: np.random.Generator, n: int, spread: float = 1.2) -> OBB:
    return OBB(
        rng.uniform(-spread, spread, (n, 3)),
        Rotation.random(n, random_state=rng).as_matrix(),
        rng.uniform(0.05, 0.6, (n, 3)),
    )


def fcl_collide(a: OBB, b: OBB) -> np.ndarray:
    out = np.empty(len(a), dtype=bool)
    req = fcl.CollisionRequest()
    for i in range(len(a)):
        oa = fcl.CollisionObject(
            fcl.Box(*(2 * a.half_extents[i])), fcl.Transform(a.rotation[i], a.center[i])
        )
        ob = fcl.CollisionObject(
            fcl.Box(*(2 * b.half_extents[i])), fcl.Transform(b.rotation[i], b.center[i])
        )
        out[i] = fcl.collide(oa, ob, req, fcl.CollisionResult()) > 0
    return out


def slow_separation(a: OBB, b: OBB) -> float:
    """Largest gap [m] over the 15 unit axes, one by one (positive: separated)."""
    A, B = a.rotation, b.rotation
    axes = [A[:, i] for i in range(3)] + [B[:, j] for j in range(3)]
    axes += [np.cross(A[:, i], B[:, j]) for i in range(3) for j in range(3)]
    best = -np.inf
    for ax in axes:
        n = np.linalg.norm(ax)
        if n < 1e-9:
            continue
        ax = ax / n
        ra = np.sum(a.half_extents * np.abs(A.T @ ax))
        rb = np.sum(b.half_extents * np.abs(B.T @ ax))
        best = max(best, abs(ax @ (b.center - a.center)) - ra - rb)
    return best


def test_overlap_equals_fcl_on_random_pairs() -> None:
    rng = np.random.default_rng(0)
    n = 10_000
    a, b = random_boxes(rng, n, 0.7), random_boxes(rng, n, 0.7)
    # A fifth of the pairs share their orientation: every edge pair is parallel.
    a = OBB(a.center, np.concatenate([b.rotation[: n // 5], a.rotation[n // 5 :]]), a.half_extents)
    ours, theirs = obb_overlap(a, b), fcl_collide(a, b)
    assert 0.2 < ours.mean() < 0.8
    for i in np.nonzero(ours != theirs)[0]:
        assert abs(slow_separation(a[i], b[i])) < 1e-9


def test_touching_and_parallel_faces() -> None:
    R = Rotation.from_euler("xyz", [0.3, -0.2, 0.7]).as_matrix()
    e = np.array([0.5, 0.2, 0.1])
    for gap, expect in ((0.0, True), (-1e-6, True), (1e-6, False)):
        # B sits on A's +x face, rotated identically: all 9 cross axes degenerate.
        cb = R @ np.array([1.0 + gap, 0.05, 0.0])
        assert bool(obb_overlap(OBB(np.zeros(3), R, e), OBB(cb, R, e))) is expect
    # Crossed edges (classic edge-edge case): separated only along a cross axis.
    a = OBB(np.zeros(3), np.eye(3), [1, 1, 1])
    Rb = Rotation.from_euler("xz", [45, 45], degrees=True).as_matrix()
    b = OBB([2.05, 2.05, 0], Rb, [1, 1, 1])
    assert bool(obb_overlap(a, b)) == fcl_collide(a.reshape(1), b.reshape(1))[0]


def test_overlap_matches_brute_force_points_and_planes() -> None:
    rng = np.random.default_rng(1)
    a, b = random_boxes(rng, 60, spread=0.9), random_boxes(rng, 60, spread=0.9)
    ours = obb_overlap(a, b)
    g = np.linspace(-1, 1, 21)
    grid = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3)
    k = np.arange(20_000) + 0.5
    phi, z = k * np.pi * (3 - np.sqrt(5)), 1 - 2 * k / 20_000
    dirs = np.c_[np.sqrt(1 - z * z) * np.cos(phi), np.sqrt(1 - z * z) * np.sin(phi), z]
    conclusive = 0
    for i in range(60):
        pts = a.center[i] + (grid * a.half_extents[i]) @ a.rotation[i].T
        if b[i].contains(pts, tol=0).any():
            assert ours[i]
            conclusive += 1
            continue
        ca, cb = a[i].corners() @ dirs.T, b[i].corners() @ dirs.T
        if np.any((ca.max(0) < cb.min(0)) | (cb.max(0) < ca.min(0))):
            assert not ours[i]
            conclusive += 1
    assert conclusive >= 50


def test_broadcast_over_batch_dims() -> None:
    rng = np.random.default_rng(2)
    a, b = random_boxes(rng, 7), random_boxes(rng, 5)
    grid = obb_overlap(a.reshape(7, 1), b.reshape(1, 5))
    assert grid.shape == (7, 5)
    for i in range(7):
        for j in range(5):
            assert grid[i, j] == obb_overlap(a[i], b[j])


def test_helpers_transformed_corners_from_points_record() -> None:
    rng = np.random.default_rng(3)
    box = random_boxes(rng, 4)
    T = np.eye(4)
    T[:3, :3] = Rotation.from_euler("zyx", [0.4, 0.1, -0.3]).as_matrix()
    T[:3, 3] = [0.1, -2.0, 0.5]
    moved = box.transformed(T)
    np.testing.assert_allclose(moved.corners(), box.corners() @ T[:3, :3].T + T[:3, 3], atol=1e-12)
    # from_points contains its points and recovers a box from its own corners.
    pts = rng.normal(size=(200, 3)) * [0.3, 0.1, 0.02]
    fit = OBB.from_points(pts)
    assert fit.contains(pts).all()
    refit = OBB.from_points(box[0].corners(), rotations=box.rotation[0][None])
    np.testing.assert_allclose(refit.volume(), box[0].volume(), rtol=1e-9)
    rec = box.record()
    assert rec.shape == (4, 18)
    back = OBB.from_record(rec)
    np.testing.assert_allclose(back.corners(), box.corners(), atol=1e-12)
    origin = box.center + 0.01
    back2 = OBB.from_record(box.record(origin))
    np.testing.assert_allclose(back2.corners(), box.corners(), atol=1e-12)
    np.testing.assert_allclose(box.record(origin)[:, :3], origin)


def test_selected_and_reshaped_boxes_equal_boxes_made_and_checked_anew() -> None:
    """Twin: indexing and reshaping (which skip the value checks of boxes already checked)
    give the boxes the full constructor makes of the same arrays; an index reaching into a
    box's own coordinates is still refused by that constructor."""
    box = random_boxes(np.random.default_rng(5), 12).reshape(3, 4)
    for index in (1, (2, 3), slice(0, 2), np.array([2, 0]), (slice(None), 1), ...):
        got = box[index]
        want = OBB(box.center[index], box.rotation[index], box.half_extents[index])
        assert got.shape == want.shape
        np.testing.assert_array_equal(got.corners(), want.corners())
    flat = box.reshape(12)
    np.testing.assert_array_equal(flat.corners(), box.corners().reshape(12, 8, 3))
    with pytest.raises(InputError, match="center"):
        box[1, 2, 0]  # a coordinate, not a box


@pytest.mark.parametrize(
    "center, rotation, half, word",
    [
        ([np.nan, 0, 0], np.eye(3), [1, 1, 1], "center"),
        ([0, 0], np.eye(3), [1, 1, 1], "center"),
        ([0, 0, 0], 2 * np.eye(3), [1, 1, 1], "rotation"),
        ([0, 0, 0], -np.eye(3), [1, 1, 1], "rotation"),
        ([0, 0, 0], np.eye(3), [1, -1, 1], "half_extents"),
        (np.zeros((2, 3)), np.eye(3), np.ones((3, 3)), "batch"),
    ],
)
def test_bad_input(center, rotation, half, word) -> None:
    with pytest.raises(InputError, match=word):
        OBB(center, rotation, half)


def test_public_entry_point_equals_the_rt_test_and_its_loop() -> None:
    # sat_overlap_t (obb_overlap's core) builds sat_overlap_rt's inputs; batches of at most
    # FEW_PAIRS pairs take the scalar loop. Vectorised, scalar and small-batch answers must
    # agree exactly, parallel edges included.
    from workbench.geometry import obb as obb_module
    from workbench.geometry.transforms import rpy_to_matrix

    rng = np.random.default_rng(7)
    n = 5000
    Ra = rpy_to_matrix(rng.uniform(-np.pi, np.pi, (n, 3)))
    Rb = rpy_to_matrix(rng.uniform(-np.pi, np.pi, (n, 3)))
    Rb[:1000] = Ra[:1000]
    ca, cb = rng.uniform(-1, 1, (n, 3)), rng.uniform(-1, 1, (n, 3))
    ea, eb = rng.uniform(0.05, 0.6, (n, 3)), rng.uniform(0.05, 0.6, (n, 3))
    f = np.ascontiguousarray
    args = (
        f((cb - ca).T),
        f(np.moveaxis(Ra, (1, 2), (0, 1))),
        f(ea.T),
        f(np.moveaxis(Rb, (1, 2), (0, 1))),
        f(eb.T),
    )
    assert n > obb_module.FEW_PAIRS
    vectorised = obb_module.sat_overlap_t(*args)
    assert 0.1 < vectorised.mean() < 0.9
    a, b = OBB(ca, Ra, ea), OBB(cb, Rb, eb)
    looped = obb_module._sat_rt_few(*_rt_inputs(a, b), obb_module.SAT_EPS)
    np.testing.assert_array_equal(looped, vectorised)
    assert_agrees_with_plain_15_axes(vectorised, a, b)
    # And through the public entry point in batches small enough for the loop.
    for k in range(0, 40, 4):
        sl = slice(k, k + 4)
        small = tuple(x[..., sl] for x in args)
        np.testing.assert_array_equal(obb_module.sat_overlap_t(*small), vectorised[sl])


def plain_separation(a: OBB, b: OBB) -> np.ndarray:
    """Largest gap [m] (P,) over the 15 unit axes of pairs (a[i], b[i]): plain numpy, no eps.

    Positive: separated. Axes shorter than 1e-9 (parallel edges) are skipped: the face axes
    decide those pairs.
    """
    A, B = a.rotation, b.rotation
    axes = [A[..., i] for i in range(3)] + [B[..., j] for j in range(3)]
    axes += [np.cross(A[..., i], B[..., j]) for i in range(3) for j in range(3)]
    L = np.stack(axes, axis=-2)  # (P, 15, 3)
    norm = np.linalg.norm(L, axis=-1)
    L = L / np.maximum(norm, 1e-300)[..., None]
    ra = np.sum(a.half_extents[:, None] * np.abs(L @ A), axis=-1)
    rb = np.sum(b.half_extents[:, None] * np.abs(L @ B), axis=-1)
    gap = np.abs(np.einsum("pkc,pc->pk", L, b.center - a.center)) - ra - rb
    return np.where(norm < 1e-9, -np.inf, gap).max(axis=-1)


def assert_agrees_with_plain_15_axes(verdict: np.ndarray, a: OBB, b: OBB) -> None:
    """The fast verdicts equal the plain test's except within 1e-9 m of touching."""
    gap = plain_separation(a, b)
    differ = verdict != (gap <= 0)
    assert np.all(np.abs(gap[differ]) < 1e-9), gap[differ]


def _rt_inputs(a: OBB, b: OBB) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Return sat_overlap_rt's inputs for pairs (a[i], b[i]), by plain per-pair matrix algebra."""
    cyc = [0, 1, 2, 0, 1]
    At = np.swapaxes(a.rotation, -1, -2)
    R = At @ b.rotation  # R[i, j] = a_i . b_j
    t = (At @ (b.center - a.center)[..., None])[..., 0]
    Rt = np.concatenate([R[:, cyc][:, :, cyc], t[:, cyc, None]], axis=2)  # (P, 5, 6)
    return np.moveaxis(Rt, 0, -1), a.half_extents[:, cyc].T, b.half_extents[:, cyc].T


def _touching_distance(a: OBB, b: OBB, u: np.ndarray) -> float:
    """Return s with b's centre at a's centre + s u touching a (closed form over the 15 axes).

    With equal centres the gap along a unit axis L grows as s |L.u| - r_L (r_L: the two
    projected radii), so the boxes first separate at s = min over axes of r_L / |L.u|.
    """
    A, B = a.rotation, b.rotation
    axes = [A[:, i] for i in range(3)] + [B[:, j] for j in range(3)]
    axes += [np.cross(A[:, i], B[:, j]) for i in range(3) for j in range(3)]
    best = np.inf
    for ax in axes:
        n = np.linalg.norm(ax)
        if n < 1e-6:
            continue
        ax = ax / n
        r = np.sum(a.half_extents * np.abs(A.T @ ax)) + np.sum(b.half_extents * np.abs(B.T @ ax))
        if abs(ax @ u) > 1e-12:
            best = min(best, r / abs(ax @ u))
    return float(best)


def test_rt_path_equals_plain_test_fcl_and_touching_cases() -> None:
    # The tree's exact test (sat_overlap_rt, on A^T [B | d] with cyclic axis order) against
    # the plain 15-axis test, python-fcl and a closed-form touching distance; parallel edges
    # included (a fifth of the pairs share the orientation, a fifth share one axis).
    from workbench.geometry import obb as obb_module

    rng = np.random.default_rng(11)
    n = 20_000
    a, b = random_boxes(rng, n, 0.7), random_boxes(rng, n, 0.7)
    Rb = b.rotation.copy()
    Rb[: n // 5] = a.rotation[: n // 5]
    spin = Rotation.from_euler("z", rng.uniform(-np.pi, np.pi, (n // 5, 1))).as_matrix()
    Rb[n // 5 : 2 * n // 5] = a.rotation[n // 5 : 2 * n // 5] @ spin  # a_z parallel to b_z
    b = OBB(b.center, Rb, b.half_extents)
    fast = obb_module.sat_overlap_rt(*_rt_inputs(a, b))
    assert 0.2 < fast.mean() < 0.8
    np.testing.assert_array_equal(fast, obb_overlap(a, b))  # the public entry point
    assert_agrees_with_plain_15_axes(fast, a, b)
    theirs = fcl_collide(a[:3000], b[:3000])
    for i in np.nonzero(fast[:3000] != theirs)[0]:
        assert abs(slow_separation(a[i], b[i])) < 1e-9
    # Near-touching: b slid out along a random direction to the touching distance s, then
    # s (1 - 1e-6) must overlap, s (1 + 1e-6) must not, and s itself counts as touching.
    m = 600
    a, b = random_boxes(rng, m, 0.0), random_boxes(rng, m, 0.0)
    Rb = b.rotation.copy()
    Rb[: m // 3] = a.rotation[: m // 3]
    b = OBB(b.center, Rb, b.half_extents)
    u = rng.normal(size=(m, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    s = np.array([_touching_distance(a[i], b[i], u[i]) for i in range(m)])
    for scale, expect in ((1 - 1e-6, True), (1.0, True), (1 + 1e-6, False)):
        moved = OBB(a.center + (s * scale)[:, None] * u, b.rotation, b.half_extents)
        fast = obb_module.sat_overlap_rt(*_rt_inputs(a, moved))
        np.testing.assert_array_equal(fast, obb_overlap(a, moved))
        if scale != 1.0:
            assert_agrees_with_plain_15_axes(fast, a, moved)
        assert fast.all() if expect else not fast.any()
        if scale != 1.0:
            np.testing.assert_array_equal(fast, fcl_collide(a, moved))


def test_rt_few_pair_loop_equals_the_vectorised_rt_test() -> None:
    # sat_overlap_rt answers batches of at most FEW_PAIRS pairs with a Python loop; it must
    # agree with the vectorised path exactly: random, parallel-edge and touching pairs.
    from workbench.geometry import obb as obb_module

    rng = np.random.default_rng(12)
    n = 6000
    a, b = random_boxes(rng, n, 0.7), random_boxes(rng, n, 0.7)
    Rb = b.rotation.copy()
    Rb[:1500] = a.rotation[:1500]
    spin = Rotation.from_euler("x", rng.uniform(-np.pi, np.pi, (1500, 1))).as_matrix()
    Rb[1500:3000] = a.rotation[1500:3000] @ spin
    b = OBB(b.center, Rb, b.half_extents)
    # The last 600 pairs touching along a random direction (closed-form distance).
    u = rng.normal(size=(600, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    s = np.array([_touching_distance(a[n - 600 + i], b[n - 600 + i], u[i]) for i in range(600)])
    center = b.center.copy()
    center[n - 600 :] = a.center[n - 600 :] + s[:, None] * u
    b = OBB(center, b.rotation, b.half_extents)
    Rt, ea, eb = _rt_inputs(a, b)
    assert n > obb_module.FEW_PAIRS
    vectorised = obb_module.sat_overlap_rt(Rt, ea, eb)
    assert 0.2 < vectorised.mean() < 0.8 and vectorised[n - 600 :].all()
    np.testing.assert_array_equal(
        obb_module._sat_rt_few(Rt, ea, eb, obb_module.SAT_EPS), vectorised
    )
    # Through the public entry point in small batches, and with A's half extents broadcast.
    k = obb_module.FEW_PAIRS
    for lo in range(0, n, 397):
        sl = slice(lo, lo + k)
        got = obb_module.sat_overlap_rt(Rt[..., sl], ea[:, sl], eb[:, sl])
        np.testing.assert_array_equal(got, vectorised[sl])
    one = np.repeat(ea[:, :1], n, axis=1)
    full = obb_module.sat_overlap_rt(Rt, one, eb)
    np.testing.assert_array_equal(
        obb_module.sat_overlap_rt(Rt[..., :k], ea[:, :1], eb[:, :k]), full[:k]
    )
