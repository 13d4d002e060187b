"""`thin_matmul` in blocks equals the plain product, for row counts below, at and across the
block size and with a remainder block."""

from __future__ import annotations

import numpy as np

from workbench.collision.thin_matmul import BLOCK, THREADED, thin_matmul


def test_thin_matmul_equals_the_plain_product() -> None:
    rng = np.random.default_rng(0)
    for k, m in ((6, 7), (3, 500), (6, 5000)):
        rows = max(1, min(BLOCK, THREADED // (k * m)))
        for n in (1, rows - 1, rows, rows + 1, 3 * rows, 5 * rows + 7):
            a, b = rng.normal(size=(max(n, 1), k)), rng.normal(size=(k, m))
            expected = np.einsum("nk,km->nm", a, b)
            np.testing.assert_allclose(thin_matmul(a, b), expected, rtol=1e-12, atol=1e-12)
