"""Products with a thin inner dimension (joints, xyz) over many rows, in blocks BLAS keeps to one thread.

The path certifier multiplies (rows, 6) joint steps by (6, items) levers and (rows, 3) points
by (3, faces) half-space normals, with rows up to the number of samples and subdivisions.
OpenBLAS runs a product of more than 4 x 65536 multiply-adds on its worker threads, whose
busy-wait after each call (about 0.1 s) takes the second core of a loaded 2-core machine:
there the certifier's cost per sample grew 2.5-3.1x per doubling of the samples (the MZ07
program run 1x..4x: 312, 550, 610 us per sample; with one BLAS thread 280, 261, 249).
Multiplying blocks of `BLOCK` rows as one stacked matmul keeps every BLAS call below that
threshold at the cost of a copy; the inner dimension is small, so the
product is memory-bound and gains nothing from more threads anyway.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
#: Multiply-adds per BLAS call above which OpenBLAS starts its threads (4 x 65536).
THREADED = 262144
#: Rows per BLAS call at most (fewer where the columns are many).
BLOCK = 128


def thin_matmul(a: FloatArray, b: FloatArray) -> FloatArray:
    """Return ``a @ b`` for a (n, k) and b (k, m), k small, in blocks of `BLOCK` rows of a."""
    a = np.asarray(a, float)
    n, k = a.shape
    m = b.shape[1]
    rows = max(1, min(BLOCK, THREADED // max(k * m, 1)))
    if n <= rows:
        return a @ b
    full = n - n % rows
    out = np.empty((n, m))
    out[:full] = (a[:full].reshape(-1, rows, k) @ b).reshape(full, m)
    if full < n:
        out[full:] = a[full:] @ b
    return out
