"""Morton codes, the radix argsort and the highest set bit against plain-Python twins: bits
interleaved one at a time, Python's sort (stable), and int.bit_length."""

from __future__ import annotations

import numpy as np

from workbench.geometry.morton import highest_bit, morton_codes, radix_argsort, spread_bits


def _spread(x: int, bits: int) -> int:
    return sum(((x >> k) & 1) << (3 * k) for k in range(bits))


def test_spread_bits_puts_bit_k_at_3k() -> None:
    rng = np.random.default_rng(0)
    for bits in (1, 8, 10, 16, 21):
        x = rng.integers(0, 1 << bits, 500, dtype=np.uint64)
        got = spread_bits(x, bits)
        assert [int(g) for g in got] == [_spread(int(v), bits) for v in x]


def test_morton_codes_interleave_x_y_z_of_the_quantised_points() -> None:
    rng = np.random.default_rng(1)
    bits = 10
    p = rng.uniform(-0.1, 1.1, (400, 3))  # some outside [0, 1]: clipped
    p[:3] = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [0.5, 0.25, 0.125]]
    got = morton_codes(p, bits)
    for code, point in zip(got, p, strict=True):
        q = [min(max(int(np.floor(c * (1 << bits))), 0), (1 << bits) - 1) for c in point]
        expected = (_spread(q[0], bits) << 2) | (_spread(q[1], bits) << 1) | _spread(q[2], bits)
        assert int(code) == expected
    assert int(got[0]) == 0 and int(got[1]) == (1 << 3 * bits) - 1


def test_radix_argsort_is_the_stable_sort_of_the_codes() -> None:
    rng = np.random.default_rng(2)
    for bits in (12, 30, 48, 63):
        codes = rng.integers(0, 1 << min(bits, 12), 2000, dtype=np.uint64)  # many ties
        codes <<= np.uint64(bits - min(bits, 12))  # the ties in the high digits too
        order = radix_argsort(codes, bits)
        expected = sorted(range(len(codes)), key=lambda i: int(codes[i]))  # stable
        assert order.tolist() == expected


def test_highest_bit_is_bit_length_minus_one() -> None:
    rng = np.random.default_rng(3)
    x = np.concatenate(
        [
            np.uint64(1) << np.arange(64, dtype=np.uint64),
            (np.uint64(1) << np.arange(1, 64, dtype=np.uint64)) - np.uint64(1),
            rng.integers(1, np.iinfo(np.int64).max, 500, dtype=np.int64).astype(np.uint64),
        ]
    )
    assert highest_bit(x).tolist() == [int(v).bit_length() - 1 for v in x]
