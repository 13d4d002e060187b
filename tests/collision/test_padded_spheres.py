"""Tests of workbench/collision/padded_spheres.py: padded spheres placed by one matmul.

Twin: each sphere's centre placed by its own body's frame in a Python loop.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

from workbench.collision.padded_spheres import PaddedSpheres


def test_placement_matches_a_loop_and_padding_never_counts() -> None:
    rng = np.random.default_rng(0)
    B, S, N = 4, 11, 5
    owner = rng.integers(0, B - 1, S)  # the last body has no sphere
    centres, radii = rng.normal(size=(S, 3)), rng.uniform(0.01, 0.1, S)
    ps = PaddedSpheres(centres, radii, owner, B)
    K = int(np.bincount(owner, minlength=B).max())
    assert ps.centres.shape == (B, K, 3) and ps.radii.shape == (B, K)
    assert ps.valid.sum() == S and np.all(np.isneginf(ps.radii[~ps.valid]))
    assert np.array_equal(ps.radii.reshape(-1)[ps.slot], radii)
    T = np.tile(np.eye(4), (N, B, 1, 1))
    T[..., :3, :3] = Rotation.random(N * B, random_state=1).as_matrix().reshape(N, B, 3, 3)
    T[..., :3, 3] = rng.normal(size=(N, B, 3))
    placed = ps.place(T)
    assert placed.shape == (N, B, K, 3)
    flat = ps.unpad(placed)
    for n in range(N):
        for s in range(S):
            want = T[n, owner[s], :3, :3] @ centres[s] + T[n, owner[s], :3, 3]
            assert np.allclose(flat[n, s], want)
    # the (N, B, 3, 4) form of the frames places the same
    assert np.allclose(ps.place(T[..., :3, :]), placed)
