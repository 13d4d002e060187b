"""Morton (Z-order) codes and index-augmented sort keys for LBVH construction.

A key is ``(morton << index_bits) | index`` in a uint64, so keys are unique even where
centroids quantise to the same cell (Karras 2012, section 4: "augment each key with its
index"). The Morton part gets as many bits per axis as fit in 62 bits beside the index.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

U64 = NDArray[np.uint64]


def bits_for(n: int) -> tuple[int, int]:
    """Return (bits per axis, index bits) for `n` primitives so that keys fit in 62 bits."""
    index_bits = max(1, int(n - 1).bit_length())
    per_axis = min(20, (62 - index_bits) // 3)
    return per_axis, index_bits


def spread_bits(x: NDArray[np.uint64], bits: int) -> U64:
    """Return `x` (< 2**bits, bits <= 21) with two zero bits inserted after each bit."""
    x = x.astype(np.uint64)
    out = np.zeros_like(x)
    for k in range(bits):  # bits <= 21: a short loop over bit positions, vectorised over x
        out |= ((x >> np.uint64(k)) & np.uint64(1)) << np.uint64(3 * k)
    return out


def morton_codes(unit_points: NDArray[np.float64], bits: int) -> U64:
    """Return 3*bits-bit Morton codes (M,) of points (M, 3) given in [0, 1]^3 (clipped)."""
    scale = float(1 << bits)
    q = np.clip(np.floor(unit_points * scale), 0.0, scale - 1.0).astype(np.uint64)
    return (
        (spread_bits(q[:, 0], bits) << np.uint64(2))
        | (spread_bits(q[:, 1], bits) << np.uint64(1))
        | spread_bits(q[:, 2], bits)
    )


def highest_bit(x: U64) -> NDArray[np.int64]:
    """Return the index of the highest set bit of each x (x > 0), exactly (no float rounding)."""
    hi = (x >> np.uint64(32)).astype(np.float64)  # < 2**32: exact in float64
    lo = (x & np.uint64(0xFFFFFFFF)).astype(np.float64)
    e_hi = np.frexp(hi)[1].astype(np.int64) - 1
    e_lo = np.frexp(lo)[1].astype(np.int64) - 1
    return np.where(hi > 0, e_hi + 32, e_lo)
