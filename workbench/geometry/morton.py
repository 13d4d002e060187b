"""Morton (Z-order) codes, a stable radix argsort for them, and the highest set bit.

LBVH construction sorts triangles by the Morton code of their box centres. A stable sort
keeps equal codes in index order, which is exactly Karras' (2012, section 4) index-augmented
key ``(morton << index_bits) | index`` without sorting 64-bit keys: the LSD radix sort below
makes 16-bit passes with numpy's stable (radix) argsort of uint16.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

U64 = NDArray[np.uint64]


def _spread_table(bits: int) -> U64:
    """Return t[x] = x (< 2**bits) with two zero bits inserted after each bit."""
    x = np.arange(1 << bits, dtype=np.uint64)
    out = np.zeros_like(x)
    for k in range(bits):
        out |= ((x >> np.uint64(k)) & np.uint64(1)) << np.uint64(3 * k)
    return out


_SPREAD8 = _spread_table(8)


def spread_bits(x: NDArray[np.uint64], bits: int) -> U64:
    """Return `x` (< 2**bits, bits <= 21) with two zero bits inserted after each bit."""
    x = x.astype(np.uint64)
    out = _SPREAD8[x & np.uint64(0xFF)]
    for k in range(1, (bits + 7) // 8):  # one table look-up per byte
        byte = (x >> np.uint64(8 * k)) & np.uint64(0xFF)
        out |= _SPREAD8[byte] << np.uint64(24 * k)
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


def radix_argsort(codes: U64, bits: int) -> NDArray[np.int64]:
    """Return the stable argsort of `codes` (< 2**bits) by 16-bit LSD radix passes."""
    order = np.argsort((codes & np.uint64(0xFFFF)).astype(np.uint16), kind="stable")
    for shift in range(16, bits, 16):
        digit = ((codes >> np.uint64(shift)) & np.uint64(0xFFFF)).astype(np.uint16)
        order = order[np.argsort(digit[order], kind="stable")]
    return order.astype(np.int64, copy=False)


def highest_bit(x: U64) -> NDArray[np.int64]:
    """Return the index of the highest set bit of each x (x > 0), exactly (no float rounding)."""
    hi = (x >> np.uint64(32)).astype(np.float64)  # < 2**32: exact in float64
    lo = (x & np.uint64(0xFFFFFFFF)).astype(np.float64)
    e_hi = np.frexp(hi)[1].astype(np.int64) - 1
    e_lo = np.frexp(lo)[1].astype(np.int64) - 1
    return np.where(hi > 0, e_hi + 32, e_lo)
